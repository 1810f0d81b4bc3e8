#!/bin/sh
# Configure and build vtkshadow into build/ (tools in build/bin).
set -eu
cd "$(dirname "$0")/.."
# VTKSHADOW_PARAVIEW: the ParaView plugin too (scripts/install-paraview.sh).
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DVTKSHADOW_PARAVIEW=ON
cmake --build build -j"$(nproc)"
