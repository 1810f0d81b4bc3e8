#!/bin/sh
# The VTK layer (vtkshadow/vtk), the product's tools (tools/) and the harness
# (compare/) follow VTK's clang-format style (.clang-format at the top): any
# C++ file there that clang-format would change fails. Every .cxx/.h below
# tools/ and compare/ is checked, new folders too; C folders with a style of
# their own (compare/metrics, tools/timing) switch formatting off in their
# own .clang-format.
set -eu
root=$1
clang_format=${2:-clang-format}
command -v "$clang_format" >/dev/null 2>&1 || {
  echo "style.clang_format: $clang_format not found (apt-get install clang-format)"; exit 2; }
cd "$root"
files=$(ls vtkshadow/vtk/*.h vtkshadow/vtk/*.cxx
  find tools compare -type f \( -name '*.cxx' -o -name '*.h' -o -name '*.hxx' \) | sort)
count=0
bad=0
for f in $files; do
  count=$((count + 1))
  if ! "$clang_format" --style=file --dry-run -Werror "$f" >/dev/null 2>&1; then
    echo "not formatted: $f (run: $clang_format -i --style=file $f)"
    bad=$((bad + 1))
  fi
done
echo "style.clang_format: $count files, $bad not formatted"
[ "$count" -gt 40 ] || { echo "too few files found ($count)"; exit 1; }
[ "$bad" -eq 0 ]
