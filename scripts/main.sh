#!/bin/sh
# The main job: install, build, then run the reference harness on every scene
# in scenes/: each VTK technique, POV-Ray and Blender Cycles, per-light
# visibility, metrics against POV-Ray (and POV-Ray against Cycles), and a
# report. Prints the path of out/compare/index.html at the end.
# At the library's scale, 0.4 (320x240 for an 800x600 scene), where the
# POV-Ray and Cycles references are shipped in scenes/references (keyed by
# scene content, renderer version and settings): only a scene that changed
# is rendered by them, and cached in out/compare/cache. Options are passed
# to vtkshadow-compare (e.g. --scale 1 for the scenes' own sizes, whose
# references are rendered on the first run).
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
status=0
sh tests/gl-run.sh build/bin/vtkshadow-compare scenes --out out/compare --scale 0.4 "$@" ||
  status=$?
echo "report: $(pwd)/out/compare/index.html"
exit $status
