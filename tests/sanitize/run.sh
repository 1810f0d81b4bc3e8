#!/bin/sh
# run.sh SOURCE_DIR BUILD_DIR [core|product]
#
# core (default): build the C libraries (core, scene parser, metrics) and
# their unit tests with -fsanitize=address,undefined into BUILD_DIR and run
# the unit tests.
#
# product: build what the C API tests, the command-line tests and a handful
# of render and harness tests (NOGL_TESTS and GL_TESTS below) run
# (PRODUCT_TARGETS: the VTK module, the C API and the tools) with
# -fsanitize=address,undefined into BUILD_DIR and run those tests there.
# Only our binaries are instrumented: Mesa, VTK and Python are not (Mesa's
# leaks: below and lsan.supp). The Python test drivers run Debian's python3
# without the ASan runtime and start our instrumented tools as subprocesses.
#
# UBSan findings abort (-fno-sanitize-recover), ASan and LSan findings make
# the process exit non-zero, so any finding fails the test that ran it.
set -eu
source_dir=$1
build_dir=$2
mode=${3:-core}
here=$(cd "$(dirname "$0")" && pwd)

# The product tests. Without GL: the CLI's bad input (every error path must
# exit 2, not crash or leak; no display) and the harness's error paths (fake
# POV-Ray, hostile scene, unknown renderer). With GL: the C API (both
# techniques' C tests), the CLI's outputs and interleaved timing, one render test per technique and
# light type (planar; csm directional / point / spot and two lights, light 1;
# auto on the thin plate).
NOGL_TESTS='^(cli\.bad_input|harness\.(crash|hostile|renderers))$'
GL_TESTS='^(capi\.c|capi\.c\.planar|cli\.outputs|cli\.timing'\
'|render\.planar\.sphere-floor-directional-4x3'\
'|render\.csm\.(sphere-floor-directional-4x3|sphere-floor-point-4x3|box-tilted-plane-spot|two-lights-light1)'\
'|render\.auto\.thin-plate)$'
# What those tests run, and nothing else: the Python wrapping (the ASan
# runtime cannot load into Debian's python3, so no test here imports it),
# the unit tests (core mode runs them) and the other test programs stay
# unbuilt. vtkshadow-render: cli.*, render.* and vtkshadow-compare's VTK
# renders; vtkshadow-compare: harness.*; vtkshadow-metrics: render.*
# (test_planar.py); test_capi, test_capi_planar: capi.c, capi.c.planar.
# A test whose program is not built fails (not found); it cannot pass.
PRODUCT_TARGETS='vtkshadow-render vtkshadow-compare vtkshadow-metrics test_capi test_capi_planar'

case $mode in
  core)
    config="-DVTKSHADOW_CORE_ONLY=ON"
    targets="" ;;
  product)
    config="-DVTKSHADOW_CORE_ONLY=OFF -DVTKSHADOW_PARAVIEW=OFF"
    targets="--target $PRODUCT_TARGETS" ;;
  *)
    echo "run.sh: unknown mode '$mode' (core or product)" >&2
    exit 2 ;;
esac

# -O1: the VTK module under ASan at -O0 makes the render tests several times
# slower for no gain in what is found.
# shellcheck disable=SC2086
cmake -S "$source_dir" -B "$build_dir" $config -DVTKSHADOW_SANITIZE=ON \
  -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-g -O1" -DCMAKE_CXX_FLAGS_DEBUG="-g -O1" \
  >"$build_dir.configure.log" 2>&1 || { cat "$build_dir.configure.log"; exit 1; }
start=$(date +%s)
# shellcheck disable=SC2086
cmake --build "$build_dir" -j2 $targets >"$build_dir.build.log" 2>&1 || {
  tail -50 "$build_dir.build.log"; exit 1; }
echo "run.sh: $mode build took $(( $(date +%s) - start )) s"

asan=abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
LSAN_OPTIONS=suppressions=$here/lsan.supp:print_suppressions=0
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS UBSAN_OPTIONS
# --no-tests=error: a selection that matches nothing is a failure, not a pass.
if [ "$mode" = core ]; then
  ASAN_OPTIONS=detect_leaks=1:$asan ctest --test-dir "$build_dir" -L unit --no-tests=error \
    --output-on-failure
  exit
fi
# Leaks are checked in every process that opens no GL context. A process
# that does leaks 2 to 14 blocks of 56 bytes allocated inside Mesa's
# swrast_dri.so (found with gdb: a breakpoint on calloc of 56 bytes), which
# GLX dlclose()s before LeakSanitizer reports at exit, so the report names
# no module or function that a suppression could match (lsan.supp explains).
# There ASan (memory errors) and UBSan stay fully on; only leak detection is
# off.
status=0
ASAN_OPTIONS=detect_leaks=1:$asan ctest --test-dir "$build_dir" -R "$NOGL_TESTS" \
  --no-tests=error --output-on-failure || status=1
ASAN_OPTIONS=detect_leaks=0:$asan ctest --test-dir "$build_dir" -R "$GL_TESTS" \
  --no-tests=error --output-on-failure || status=1
exit $status
