#!/bin/sh
# Build the C libraries (core, scene parser, metrics) and their unit tests with
# -fsanitize=address,undefined into a separate tree and run the unit tests.
# UBSan findings abort (-fno-sanitize-recover), so any finding fails the test.
set -eu
source_dir=$1
build_dir=$2
cmake -S "$source_dir" -B "$build_dir" -DVTKSHADOW_CORE_ONLY=ON -DVTKSHADOW_SANITIZE=ON \
  -DCMAKE_BUILD_TYPE=Debug >"$build_dir.configure.log" 2>&1 || { cat "$build_dir.configure.log"; exit 1; }
cmake --build "$build_dir" -j2 >"$build_dir.build.log" 2>&1 || { tail -50 "$build_dir.build.log"; exit 1; }
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
  ctest --test-dir "$build_dir" -L unit --output-on-failure
