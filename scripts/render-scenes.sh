#!/bin/sh
# render-scenes.sh OUTDIR SCENEDIR: every scene x technique x light, with
# progress output. Exit status non-zero if any render failed (the others go on).
# Needs an X display: main.sh runs it under tests/gl-run.sh (one Xvfb for all).
set -u
out=${1:-out/render}
scenes=${2:-scenes}
bin="$(cd "$(dirname "$0")/.." && pwd)/build/bin"
techniques="none vtk planar"
status=0
count=0
failed=0
for scene in $(find "$scenes" -name '*.json' | sort); do
  name=$(echo "${scene#"$scenes"/}" | sed 's/\.json$//; s|/|-|g')
  lights=$("$bin/vtkshadow-python" -c "import json,sys; print(len(json.load(open(sys.argv[1]))['lights']))" "$scene" 2>/dev/null || echo 1)
  for technique in $techniques; do
    dir="$out/$name/$technique"
    mkdir -p "$dir"
    k=0
    while [ "$k" -lt "$lights" ]; do
      count=$((count + 1))
      echo "[$count] $scene: $technique, light $k"
      stats=""
      [ "$k" -eq 0 ] && stats="--stats $dir/stats.json"
      # shellcheck disable=SC2086
      if ! "$bin/vtkshadow-render" "$scene" \
          --technique "$technique" --image "$dir/image.png" --light "$k" \
          --visibility "$dir/light${k}_visibility.png" --mask "$dir/light${k}_mask.png" \
          $stats --quiet; then
        echo "FAILED: $scene $technique light $k" >&2
        failed=$((failed + 1))
        status=1
      fi
      k=$((k + 1))
    done
  done
done
echo "rendered $((count - failed)) of $count into $out"
exit $status
