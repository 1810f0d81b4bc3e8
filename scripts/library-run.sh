#!/bin/sh
# library-run.sh OUT [GROUP|all] [vtkshadow-compare options...]
#
# The library run of the test suite (docs/harness.md, "The library run"):
# the scenes of scenes/GROUP (default all: basic scivis cad hard mirror soft
# translucent primitives)
# at --scale 0.4 (320x240), every registered technique, against the shipped
# references of scenes/references (--require-references: a reference that
# is not shipped fails its scene and names scripts/update-references.sh).
# The soft scenes also run the sampled lights at 64 samples and raytrace
# with one ray (vtk/raytrace:samples=1, a hard shadow: update_thresholds.py
# requires every soft row's limits to fail it). Results go to OUT/GROUP/.
# The harness.library.<group> tests run this with --check.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${VTKSHADOW_BIN:-$here/build/bin}
if [ $# -lt 1 ]; then
  echo "usage: library-run.sh OUT [GROUP|all] [vtkshadow-compare options...]" >&2
  exit 2
fi
out=$1
shift
groups="basic scivis cad hard mirror soft translucent primitives"
if [ $# -gt 0 ] && [ "${1#-}" = "$1" ]; then
  [ "$1" = all ] || groups=$1
  shift
fi
status=0
for group in $groups; do
  if [ ! -d "$here/scenes/$group" ]; then
    echo "library-run.sh: no scene group '$group' in $here/scenes" >&2
    exit 2
  fi
  techniques=""
  [ "$group" = soft ] &&
    techniques="--techniques all,volume:soft_samples=64,planar:soft_samples=64,raytrace:samples=1"
  # A run that stops early must not leave an earlier run's results looking new.
  rm -f "$out/$group/results.json"
  # shellcheck disable=SC2086
  "$here/tests/gl-run.sh" "$bin/vtkshadow-compare" "$here/scenes/$group" --out "$out/$group" \
    --scale 0.4 --require-references --thresholds "$here/scenes/thresholds.json" $techniques \
    "$@" || status=$?
done
exit $status
