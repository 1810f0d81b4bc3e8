#!/bin/sh
# Regenerate docs/results.md: speed against error of every technique on every
# scene in scenes/ (bench/vtkshadow-bench, with POV-Ray references and the
# Blender EEVEE peer through vtkshadow-compare), how cost grows with triangles
# and pixels (bench/bench_growth.py), assembled by bench/make_results.py.
# About 25 minutes on 2 cores; progress goes to stderr. Run from anywhere,
# after the README's main command (`sh scripts/main.sh`: it installs
# POV-Ray, Blender and gnuplot, which this needs, and builds).
# OUT (default out/results) keeps the raw runs: bench.csv, plots, stats. It
# is emptied first, so every reference is rendered fresh.
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
sh tests/gl-run.sh build/bin/vtkshadow-python bench/vtkshadow_bench.py scenes \
  --out "$OUT/bench" --scale 0.5 --frames 30 --grid small --rounds 1 \
  --peers basic,scivis,cad > "$OUT/bench.txt"
sh tests/gl-run.sh build/bin/vtkshadow-python bench/bench_growth.py \
  --out "$OUT/growth" --frames 30 --rounds 2 > "$OUT/growth.txt"
/usr/bin/python3 bench/make_results.py --bench "$OUT/bench" --growth "$OUT/growth" \
  --command "sh scripts/results.sh" --output docs/results.md
