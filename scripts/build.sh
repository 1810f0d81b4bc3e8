#!/bin/sh
# Configure and build vtkshadow into build/ (tools in build/bin).
set -eu
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)"
