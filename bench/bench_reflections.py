"""Cost of planar mirrors (issue 17, item 5): each technique with reflections
off, on (the technique's shadows in the reflection) and no-shadows (the
reflection drawn without them), against `none` without mirrors.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_reflections.py --out DIR
      [--scene scenes/mirror/sphere-mirror-floor.json] [--techniques none,planar,csm]
      [--frames 15] [--rounds 4] [--warmup 5] [--noise-tolerance 0.03]

One vtkshadow-render --stats process per (technique, reflections): the
project's interleaved timing (tools/timing) alternates the configuration
with `none` and `none#2` (both without mirrors: the timed entries other than
the main one are plain technique passes) in blocks, the order rotated per
round; for `none` itself the installed pass is the reference, so its ratio
is taken against none#2 (a plain none pass). The figure to compare is the median over rounds of the ratio to that
run's own `none` (the machine is shared and noisy; ms are printed too). A
run whose none#2 / none is outside 1 +- tolerance is marked noisy.
Writes DIR/reflections.json and prints a table.
"""
import argparse
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtkshadow_bench  # noqa: E402
from vtkshadow_bench import log  # noqa: E402

ap = argparse.ArgumentParser()
ap.add_argument("--out", required=True)
ap.add_argument("--scene", default="scenes/mirror/sphere-mirror-floor.json")
ap.add_argument("--techniques", default="none,planar,csm")
ap.add_argument("--frames", type=int, default=15)
ap.add_argument("--rounds", type=int, default=4)
ap.add_argument("--warmup", type=int, default=5)
ap.add_argument("--noise-tolerance", type=float, default=0.03)
a = ap.parse_args()


def run(technique, reflections, d):
    """vtkshadow_bench.run_timing's command with the technique as the main
    entry and --reflections (its stats JSON, or None)."""
    os.makedirs(d, exist_ok=True)
    stats = os.path.join(d, "timing.json")
    cmd = [os.path.join(vtkshadow_bench.BIN, "vtkshadow-render"), a.scene, "--technique",
           technique, "--reflections", reflections, "--image", os.path.join(d, "timing.png"),
           "--stats", stats, "--frames", str(a.frames), "--rounds", str(a.rounds),
           "--warmup", str(a.warmup), "--noise-tolerance", repr(a.noise_tolerance), "--quiet"]
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    with open(os.path.join(d, "timing.log"), "w") as f:
        f.write(" ".join(cmd) + "\n" + p.stderr)
    if p.returncode != 0 or not os.path.exists(stats):
        sys.exit("bench_reflections: failed: " + " ".join(cmd) + "\n" + p.stderr)
    with open(stats) as f:
        return json.load(f)


rows = []
for t in a.techniques.split(","):
    for r in ("off", "no-shadows", "on"):
        st = run(t, r, os.path.join(a.out, "runs", f"{t}-{r}"))
        entries = st["timing"]["entries"]
        by = {e["label"]: e for e in entries}
        if t == "none":
            # The installed pass (with the mirror pass when on) is the
            # reference itself: compare with none#2, a plain none pass.
            ms = by["none"]["ms"]["median"]
            ratio = 1.0 / by["none#2"]["ratio_to_none"]["median"]
        else:
            main = next(e for e in entries if e["label"] not in ("none", "none#2"))
            ms, ratio = main["ms"]["median"], main["ratio_to_none"]["median"]
        rows.append({"technique": t, "reflections": r, "ms": ms, "ratio_to_none": ratio,
                     "noisy": st["noise_floor"]["too_noisy"]})
        log(f"{t} reflections={r}: {rows[-1]['ms']:.2f} ms, x{rows[-1]['ratio_to_none']:.2f} "
            f"of none without mirrors{' (noisy)' if rows[-1]['noisy'] else ''}")
os.makedirs(a.out, exist_ok=True)
with open(os.path.join(a.out, "reflections.json"), "w") as f:
    json.dump({"scene": a.scene, "rows": rows}, f, indent=1)
print("technique\treflections\tmedian_ms\tratio_to_none\tnoisy")
for row in rows:
    print(f"{row['technique']}\t{row['reflections']}\t{row['ms']:.2f}\t"
          f"{row['ratio_to_none']:.2f}\t{row['noisy']}")
