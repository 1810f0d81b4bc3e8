#!/bin/sh
# The main job: install, build, then render every scene in scenes/ with every
# technique into out/render/<scene>/<technique>/ (image, per-light visibility
# and mask, stats).
set -eu
cd "$(dirname "$0")/.."
sh scripts/install-deps.sh
sh scripts/build.sh
sh tests/gl-run.sh sh scripts/render-scenes.sh out/render scenes
