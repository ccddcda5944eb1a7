#!/usr/bin/env bash
# Install the Debian packages, fetch YADE's source and build YADE with the plugin.
# Idempotent: a second run (or a second clone on the same machine) reuses the cache in
# ${TOPPLING_CACHE:-~/.cache/toppling} and recompiles only what changed.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
start=$(date +%s)
sudo_cmd=(); [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)

mapfile -t packages < <(grep -v '^\s*#' "$repo/scripts/apt-packages.txt" | sed '/^\s*$/d')
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Debian's python3-paraview conflicts with python3-vtk9, which YADE's VTK export and ours need:
# unpacked into the cache instead, for pvbatch alone (scripts/env.sh: TOPPLING_PARAVIEW_PYTHON).
paraview_python="${TOPPLING_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/toppling}/paraview"
if [ ! -d "$paraview_python/usr/lib/python3/dist-packages/paraview" ]; then
  download=$(mktemp -d)
  mkdir -p "$paraview_python"  # dpkg-deb -x makes the last folder only; a fresh machine has no cache yet
  (cd "$download" && { apt-get download -q python3-paraview || { "${sudo_cmd[@]}" apt-get update -qq &&
    apt-get download -q python3-paraview; }; } && dpkg-deb -x python3-paraview_*.deb "$paraview_python")
  rm -rf "$download"
fi

# Debian's python first: YADE's cmake must not see a pyenv interpreter.
export PATH="/usr/bin:$PATH"
cmake -S "$repo" -B "$repo/build" -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build "$repo/build" -j 2
echo "setup: done in $(( $(date +%s) - start )) s"
