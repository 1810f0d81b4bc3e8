"""bench/bench_soft.py end to end on one soft scene at a tiny size (1 round
of 2 frames, POV-Ray as the only harness renderer): the structure of what it
writes, never a speed. soft.json has a row per configuration of CONFIGS
whose technique is registered, each with a finite time ratio and finite
penumbra figures against POV-Ray's area light; the sampled techniques get
closer to the reference with more samples (planar 64 and raytrace 64 have a
lower pen_mae than their 1-sample hard shadow: a bench that scored the
wrong image would fail here); the Pareto front is non-empty and sorted;
soft.md has one table row per configuration. A bad option exits 2 naming
it, and nothing is written.

  vtkshadow-python tests/cli/test_bench_soft.py --source SRC --out DIR
"""
import argparse
import json
import math
import os
import shutil
import subprocess
import sys

import vtkshadow

ap = argparse.ArgumentParser()
ap.add_argument("--source", required=True)
ap.add_argument("--out", required=True)
args = ap.parse_args()
bench = os.path.join(args.source, "bench", "bench_soft.py")
scene = os.path.join(args.source, "scenes", "soft", "sphere-disk.json")
registered = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def finite(v):
    return isinstance(v, (int, float)) and math.isfinite(v)


shutil.rmtree(args.out, ignore_errors=True)
cmd = [sys.executable, bench, scene, "--out", args.out, "--frames", "2", "--rounds", "1",
       "--warmup", "0", "--scale", "0.25", "--timing-scale", "0.25", "--renderers", "povray",
       "--cache", os.path.join(args.out, "cache")]
p = subprocess.run(cmd, capture_output=True, text=True, timeout=1500)
check(p.returncode == 0, f"bench_soft: status {p.returncode}: {p.stderr[-3000:]}")
path = os.path.join(args.out, "soft.json")
doc = json.load(open(path)) if os.path.exists(path) else []
check(len(doc) == 1 and doc[0].get("scene") == "soft-sphere-disk", f"scenes: {doc and doc[0].get('scene')}")
rows = {r["config"]: r for r in (doc[0]["rows"] if doc else [])}
sys.path.insert(0, os.path.join(args.source, "bench"))
from bench_soft import CONFIGS  # noqa: E402
want = ["%s%s" % (t, (":" + ",".join("%s=%s" % kv for kv in v)) if v else "")
        for t, v in CONFIGS if t in registered]
check(sorted(rows) == sorted(want), f"configurations {sorted(rows)}, expected {sorted(want)}")
for label, r in rows.items():
    check(finite(r.get("ratio")) and r["ratio"] > 0 and finite(r.get("ms")),
          f"{label}: time {r.get('ms')} ratio {r.get('ratio')}")
    check(finite(r.get("pen_mae")) and 0 <= r["pen_mae"] <= 1 and finite(r.get("pen_bias"))
          and (r.get("pen_pixels") or 0) > 0, f"{label}: penumbra figures {r}")
for tech, key in (("planar", "soft_samples"), ("raytrace", "samples"), ("volume", "soft_samples")):
    lo, hi = rows.get(f"{tech}:{key}=1"), rows.get(f"{tech}:{key}=64")
    if tech in registered:
        check(lo and hi and hi["pen_mae"] < 0.5 * lo["pen_mae"],
              f"{tech}: 64 samples ({hi and hi['pen_mae']}) not well below 1 "
              f"({lo and lo['pen_mae']})")
front = [r for r in rows.values() if r.get("front")]
check(front and all(a["pen_mae"] > b["pen_mae"] for a, b in zip(
    sorted(front, key=lambda r: r["ratio"]), sorted(front, key=lambda r: r["ratio"])[1:])),
    f"front: {[(r['config'], r['ratio'], r['pen_mae']) for r in front]}")
md = open(os.path.join(args.out, "soft.md")).read() if os.path.exists(
    os.path.join(args.out, "soft.md")) else ""
check(md.startswith("## Soft shadows: penumbra error against frame time") and
      all(f"| {label} |" in md for label in want), "soft.md: title and one row per configuration")

# Bad options: status 2, the option and value named, nothing written.
for bad, name in ((["--scale", "0"], "--scale"), (["--renderers", "cycles"], "--renderers"),
                  (["--rounds", "0"], "--rounds")):
    out = os.path.join(args.out, "bad")
    q = subprocess.run([sys.executable, bench, scene, "--out", out] + bad,
                       capture_output=True, text=True, timeout=120)
    check(q.returncode == 2 and name in q.stderr and bad[1] in q.stderr and not os.path.exists(out),
          f"bench_soft {bad}: status {q.returncode}, {q.stderr.strip()[-300:]}")

print("cli.bench_soft:", "FAILED (%d)" % len(failures) if failures else "ok")
sys.exit(1 if failures else 0)
