#!/bin/sh
# The whole test suite: install what it needs, build, run ctest (every test,
# including the sanitizer build and the GL tests under xvfb-run).
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
ctest --test-dir build --output-on-failure -j2 --timeout 1500 --no-tests=error
