"""Regenerate scenes/thresholds.json (the --check limits) from a harness run.

    build/bin/vtkshadow-compare scenes --out /tmp/t --scale 0.4 --no-cache
    python3 scenes/update_thresholds.py /tmp/t/results.json > scenes/thresholds.json

POV-Ray against Cycles ("cycles") keeps the fixed trust limit of 0.1% wrong
pixels. Each VTK technique gets, per scene, its measured worst-light
wrong_pct and false_shadow_pct times 1.25 plus 0.25 percentage points, so a
regression fails --check while renderer noise does not. vtk/none is not
checked (it has no shadows by definition). Run it after a deliberate change
of a technique, and review the diff: a limit that goes up is a regression.
"""
import json
import math
import sys

res = json.load(open(sys.argv[1]))
out = {
    "description": "Per-scene --check limits of vtkshadow-compare (docs/harness.md); measured at --scale 0.4",
    "default": {"cycles": {"wrong_pct": 0.1}},
    "scenes": {},
}
for scene in res["scenes"]:
    limits = {}
    for r in scene["results"]:
        t = r["test"]
        if t in ("cycles", "vtk/none") or r["status"] != "ok":
            continue
        entry = limits.setdefault(t, {})
        for metric in ("wrong_pct", "false_shadow_pct"):
            v = math.ceil((r[metric] * 1.25 + 0.25) * 100) / 100
            entry[metric] = max(entry.get(metric, 0), min(v, 100.0))
    out["scenes"][scene["scene"]] = limits
json.dump(out, sys.stdout, indent=1, sort_keys=True)
sys.stdout.write("\n")
