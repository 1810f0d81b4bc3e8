#!/bin/sh
# The main job: install, build, then run the reference harness on every scene
# in scenes/: each VTK technique, POV-Ray and Blender Cycles, per-light
# visibility, metrics against POV-Ray (and POV-Ray against Cycles), and a
# report. Prints the path of out/compare/index.html at the end.
# Renders are cached in out/compare/cache (keyed by scene content, renderer
# version and settings), so a second run only re-renders what changed.
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
status=0
sh tests/gl-run.sh build/bin/vtkshadow-compare scenes --out out/compare "$@" || status=$?
echo "report: $(pwd)/out/compare/index.html"
exit $status
