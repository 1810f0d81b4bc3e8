#!/bin/sh
# run_ranks.sh BIN SOURCE OUT: the scene split over 1 and 2 pvbatch ranks
# (tests/paraview/test_pv_ranks.py): csm across 2 ranks must equal 1 rank
# with the shadow present; planar on 2 ranks must say it fell back to csm; a
# rank with nothing on screen (no data, or data behind the camera) must still
# join the reductions: a timeout turns the deadlock it would cause into a
# failure.
set -eu
bin=$1 source=$2 out=$3
scene="$source/scenes/basic/sphere-directional.json"
test="$source/tests/paraview/test_pv_ranks.py"
rm -rf "$out"
mkdir -p "$out"
# Open MPI refuses root without these (CI runs as root); --oversubscribe
# lets 2 ranks run on fewer free cores.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpi="timeout 300 mpiexec --oversubscribe -np 2"
"$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render none
"$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render csm
$mpi "$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render csm
$mpi "$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render planar
$mpi "$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render csm empty
"$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render none offscreen
"$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render csm offscreen
$mpi "$bin/vtkshadow-pvbatch" "$test" "$scene" "$out" render csm offscreen
pixel=$(python3 -c "import json,sys; print(json.dumps(json.load(open(sys.argv[1]))['shadow_pixel']))" "$out/1-csm.json")
"$bin/vtkshadow-pvpython" "$test" compare "$out/1-csm.png" "$out/2-csm.png" "$out/1-none.png" "$pixel"
"$bin/vtkshadow-pvpython" "$test" compare "$out/1-csm.png" "$out/2-planar.png" "$out/1-none.png" "$pixel"
"$bin/vtkshadow-pvpython" "$test" compare "$out/1-csm.png" "$out/2-csm-empty.png" "$out/1-none.png" "$pixel"
pixel=$(python3 -c "import json,sys; print(json.dumps(json.load(open(sys.argv[1]))['shadow_pixel']))" "$out/1-csm-offscreen.json")
"$bin/vtkshadow-pvpython" "$test" compare "$out/1-csm-offscreen.png" "$out/2-csm-offscreen.png" \
  "$out/1-none-offscreen.png" "$pixel"
grep -q '"fallback": "planar is not right across 2 ranks: using csm"' "$out/2-planar.json" || {
  echo "run_ranks.sh: 2-planar.json does not report the fallback:" >&2
  cat "$out/2-planar.json" >&2
  exit 1
}
echo "run_ranks.sh: csm across 2 ranks equals 1 rank (also with a rank that has nothing on screen); planar falls back to csm"
