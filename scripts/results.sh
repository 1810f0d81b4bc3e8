#!/bin/sh
# Regenerate docs/results.md: speed against error of every technique on every
# scene in scenes/ (bench/vtkshadow-bench, with POV-Ray references and the
# Blender EEVEE peer through vtkshadow-compare), how cost grows with triangles,
# pixels, lights and coverage (bench/bench_growth.py), assembled by
# bench/make_results.py; penumbra error against time for lights with a size
# (bench/bench_soft.py); raytrace's classifier against every pixel traced,
# volume, csm and auto at two targets on the scivis and cad scenes
# (bench/bench_classify.py, its own section, written last).
# Timing: per scene (and per growth row) one vtkshadow-render process times
# every configuration in one window, interleaved in blocks (3 warm-up frames
# each, 4 rounds of 10 frames, the order changed every round; the growth and
# soft benches 2 warm-up frames and 3 rounds of 8) at the scenes' own size (800x600), with
# none timed twice as the noise floor
# (docs/performance.md, "How frames are timed"); errors are measured at half
# size against POV-Ray; for lights with a size (scenes/soft, bench/bench_soft.py)
# the penumbra error against POV-Ray's area light, with Cycles and EEVEE as peers.
# About an hour on 2 otherwise idle cores (the timing runs every configuration at
# 800x600; much longer on a loaded machine); progress goes to stderr. Run from anywhere,
# after the README's main command (`sh scripts/main.sh`: it installs
# POV-Ray, Blender and gnuplot, which this needs, and builds).
# OUT (default out/results) keeps the raw runs: bench.csv, plots, stats; it
# is emptied first. The POV-Ray references are cached in out/results-cache
# (keyed by scene content, renderer version and settings).
set -eu
cd "$(dirname "$0")/.."
OUT=${OUT:-out/results}
for tool in build/bin/vtkshadow-render build/bin/vtkshadow-compare build/bin/vtkshadow-python; do
  if [ ! -x "$tool" ]; then
    echo "results.sh: missing $tool: build first (sh scripts/build.sh)" >&2
    exit 2
  fi
done
rm -rf "$OUT"
mkdir -p "$OUT"
# EEVEE's seconds per frame are measured only when it renders, so its cache
# entries go; POV-Ray's references stay cached.
rm -rf out/results-cache/eevee out/results-cache/eevee-best
sh tests/gl-run.sh build/bin/vtkshadow-python bench/vtkshadow_bench.py scenes \
  --out "$OUT/bench" --scale 0.5 --timing-scale 1 --frames 10 --rounds 4 --warmup 3 \
  --grid small \
  --peers basic,scivis,cad --cache out/results-cache > "$OUT/bench.txt"
sh tests/gl-run.sh build/bin/vtkshadow-python bench/bench_growth.py \
  --out "$OUT/growth" --frames 8 --rounds 3 --warmup 2 > "$OUT/growth.txt"
sh tests/gl-run.sh build/bin/vtkshadow-python bench/bench_soft.py \
  --out "$OUT/soft" --frames 8 --rounds 3 --warmup 2 --cache out/results-cache > "$OUT/soft.txt"
/usr/bin/python3 bench/make_results.py --bench "$OUT/bench" --growth "$OUT/growth" \
  --soft "$OUT/soft" --command "sh scripts/results.sh" --output docs/results.md
sh tests/gl-run.sh /usr/bin/python3 bench/bench_classify.py --bin build/bin --out "$OUT/classify" \
  --results docs/results.md scenes/scivis/*.json scenes/cad/*.json \
  scenes/primitives/molecule-spheres.json scenes/primitives/streamlines-tubes.json \
  scenes/primitives/particle-cloud.json > "$OUT/classify.txt"
