#!/bin/sh
# Cost of planar mirrors: median ms per frame (vtkshadow-render --stats,
# "shadowed" figure) for a technique with reflections off, on with shadows
# in the reflection, and on without them, against `none` without mirrors.
# Usage: sh scripts/bench-reflections.sh [BUILD] [SCENE] [FRAMES] [TECHNIQUES...]
# Timings on a shared, loaded machine are noisy: compare within one run.
set -e
build=${1:-build}; scene=${2:-scenes/mirror/sphere-mirror-floor.json}; frames=${3:-30}
shift 3 2>/dev/null || shift $#
techniques=${*:-none planar csm}
out=$(mktemp -d)
printf "technique\treflections\tmedian_ms\n"
for t in $techniques; do
  for r in off no-shadows on; do
    "$build/bin/vtkshadow-render" "$scene" --technique "$t" --reflections "$r" \
      --image "$out/i.png" --stats "$out/s.json" --frames "$frames" --quiet
    ms=$(/usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(d['shadowed_ms']['median'])" "$out/s.json")
    printf "%s\t%s\t%s\n" "$t" "$r" "$ms"
  done
done
rm -rf "$out"
