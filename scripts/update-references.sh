#!/bin/sh
# update-references.sh: render the shipped references, scenes/references
# (docs/harness.md, "Shipped references"), after a change that gives a scene
# another content key (the scene or its meshes, the export, the renderer
# settings, render_cycles.py, the POV-Ray or Blender version).
#
# POV-Ray and Cycles render every scene of scenes/ at the library's scale,
# 0.4 (320x240 for a 800x600 scene), the scale of the tests' library run
# (scripts/library-run.sh) and of the main job (scripts/main.sh). Entries
# whose key is unchanged are kept without rendering; entries no scene uses
# any more are deleted. Commit scenes/references afterwards. Needs the build
# (sh scripts/build.sh); the whole library from nothing takes about 10
# minutes on 2 cores (8 of them Cycles' soft scenes at 1,024 samples per
# pixel centre), an unchanged one seconds.
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${VTKSHADOW_BIN:-$here/build/bin}
refs=$here/scenes/references
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT INT TERM
"$bin/vtkshadow-compare" "$here/scenes" --out "$work" --renderers povray,cycles --scale 0.4 \
  --cache "$refs" --no-references --no-report
python3 - "$refs" "$work/results.json" <<'EOF'
import json, os, shutil, sys
refs, used = sys.argv[1], set()
for path in sys.argv[2:]:
    with open(path) as f:
        for s in json.load(f)["scenes"]:
            used.update(os.path.join(r, k) for r, k in s["reference_keys"].items())
removed = 0
for renderer in sorted(os.listdir(refs)):
    for key in sorted(os.listdir(os.path.join(refs, renderer))):
        if os.path.join(renderer, key) not in used:
            shutil.rmtree(os.path.join(refs, renderer, key))
            removed += 1
print("update-references: %d entries in %s, %d unused removed" % (len(used), refs, removed),
      file=sys.stderr)
EOF
