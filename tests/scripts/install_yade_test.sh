#!/usr/bin/env bash
# scripts/install-yade.sh on a one-file cmake project: an unchanged file is left alone (same
# inode), a changed one is renamed into place (new inode) while a reader holding the old one
# still reads the old content.
set -euo pipefail
repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'exec 3<&-; rm -rf "$work"' EXIT
cd "$work"
printf 'cmake_minimum_required(VERSION 3.15)\nproject(t NONE)\ninstall(FILES lib.so keep.txt DESTINATION lib)\n' > CMakeLists.txt
echo old > lib.so
echo same > keep.txt
cmake -S . -B build -DCMAKE_INSTALL_PREFIX="$work/prefix" > /dev/null
"$repo/scripts/install-yade.sh" build "$work/prefix" "$work/stage" > /dev/null
lib_inode=$(stat -c %i prefix/lib/lib.so)
keep_inode=$(stat -c %i prefix/lib/keep.txt)
exec 3< prefix/lib/lib.so  # a running process with the library open
sleep 1 && echo new > lib.so
out=$("$repo/scripts/install-yade.sh" build "$work/prefix" "$work/stage")
fail() { echo "FAIL: $*"; exit 1; }
[ "$(cat prefix/lib/lib.so)" = new ] || fail "the changed file was not installed"
[ "$(stat -c %i prefix/lib/lib.so)" != "$lib_inode" ] || fail "the changed file was rewritten in place"
[ "$(cat <&3)" = old ] || fail "the open file changed under its reader"
[ "$(stat -c %i prefix/lib/keep.txt)" = "$keep_inode" ] || fail "an unchanged file was replaced"
case "$out" in *"1 file(s) replaced"*) ;; *) fail "expected one file replaced, got: $out" ;; esac
echo "install-yade: ok"
