#!/bin/sh
# Install the build tree into a prefix, then configure, build and run a tiny
# downstream C project against it with find_package(vtkshadow).
set -eu
build=$1
source=$2
scene=$3
prefix="$build/test-install"
work="$build/test-downstream"
rm -rf "$prefix" "$work"
cmake --install "$build" --prefix "$prefix" >/dev/null
cmake -S "$source" -B "$work" -DCMAKE_PREFIX_PATH="$prefix" >"$work.log" 2>&1 || { cat "$work.log"; exit 1; }
cmake --build "$work" >>"$work.log" 2>&1 || { cat "$work.log"; exit 1; }
# DISPLAY comes from gl-run.sh, which runs this script.
"$work/downstream" "$scene" "$work/downstream.png"
test -s "$work/downstream.png"
