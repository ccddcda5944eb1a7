#!/usr/bin/env bash
# Install YADE's build tree into its prefix without rewriting a file a running yade has mapped.
#   scripts/install-yade.sh <build dir> <prefix> <staging dir>
# `cmake --install` rewrites a changed library in place (same inode), which can crash a yade
# process that has it mapped, e.g. a simulation running while a second clone is set up. Here
# cmake installs into a staging tree, and each file that differs from the installed one is
# copied beside it and renamed over it: a new inode, while running processes keep the old.
set -euo pipefail
build=$1 prefix=$2 stage=$3
DESTDIR="$stage" cmake --install "$build" | { grep -v -- '-- Up-to-date:' || true; }  # a failed install still fails
cd "$stage$prefix"
replaced=0
while IFS= read -r -d '' file; do
  target="$prefix/${file#./}"
  cmp -s "$file" "$target" && continue
  mkdir -p "$(dirname "$target")"
  cp -a "$file" "$target.installing"
  mv -f "$target.installing" "$target"
  replaced=$((replaced + 1))
done < <(find . \( -type f -o -type l \) -print0)
echo "install-yade: $replaced file(s) replaced in $prefix"
