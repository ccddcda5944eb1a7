#!/usr/bin/env bash
# Fetch YADE's upstream source tarball from Debian's archive (the trixie source package)
# and unpack it into <dest>/trunk-<version>.  The archive host is read from this machine's
# own apt sources; the apt configuration used is private (nothing in /etc is changed).
# Usage: fetch-yade-source.sh <version> <dest>
set -euo pipefail
version=$1 dest=$2
tree="$dest/trunk-$version"
patches=$(cd "$(dirname "${BASH_SOURCE[0]}")/../patches" && pwd)

# Our patches (patches/*.patch, each says why), applied once: a tree that has one reverses it cleanly.
apply_patches() {
  for p in "$patches"/*.patch; do
    if patch -d "$tree" -p1 -R --dry-run -s -f < "$p" > /dev/null 2>&1; then continue; fi
    patch -d "$tree" -p1 -s -f < "$p" || { echo "fetch-yade-source: $p does not apply to $tree" >&2; exit 1; }
    echo "YADE source: applied $(basename "$p")"
  done
}
[ -f "$tree/CMakeLists.txt" ] && { echo "YADE source: $tree (cached)"; apply_patches; exit 0; }

uri=$(awk '/^URIs:/{print $2; exit}' /etc/apt/sources.list.d/*.sources 2>/dev/null || true)
[ -n "$uri" ] || uri=$(awk '$1=="deb"{print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
[ -n "$uri" ] || { echo "fetch-yade-source: no Debian archive URI in /etc/apt sources" >&2; exit 1; }

apt_dir="$dest/apt"
mkdir -p "$apt_dir/lists/partial" "$apt_dir/parts" "$dest"
cat > "$apt_dir/parts/trixie-src.sources" <<SRC
Types: deb-src
URIs: $uri
Suites: trixie
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SRC
apt_opts=(-o "Dir::Etc::SourceParts=$apt_dir/parts" -o "Dir::Etc::SourceList=/dev/null"
          -o "Dir::State::Lists=$apt_dir/lists" -o "APT::Sandbox::User=root")
apt-get "${apt_opts[@]}" -qq update
(cd "$dest" && apt-get "${apt_opts[@]}" source --download-only --tar-only "yade=$version-1")
tar -xjf "$dest/yade_$version.orig.tar.bz2" -C "$dest"
[ -f "$tree/CMakeLists.txt" ] || { echo "fetch-yade-source: $tree not found after unpacking" >&2; exit 1; }
echo "YADE source: $tree"
apply_patches
