"""bench/bench_growth.py end to end on a tiny configuration (two triangle
counts, two window sizes, one and two lights, two view angles, 2 rounds of
2 frames): the structure of what it
writes, never a speed. growth.json has one row per case with every
registered technique and none#2, each a finite positive (ms, ratio, min ms,
max ms) with min <= median <= max, none's ratio exactly 1 and a boolean
too_noisy that agrees with none#2's ratio, and cost details (volume's
silhouette edges growing with triangles, its fill growing as the view
narrows; raytrace's rays per second per thread); growth.md has the four
tables with one column per technique plus the noise-floor and detail
columns, one row per case, and cells that read back as the numbers of
growth.json. A bad option exits 2
naming it.

  vtkshadow-python tests/cli/test_bench_growth.py --source SRC --out DIR
"""
import argparse
import json
import math
import os
import re
import subprocess
import sys

import vtkshadow

ap = argparse.ArgumentParser()
ap.add_argument("--source", required=True)
ap.add_argument("--out", required=True)
args = ap.parse_args()
bench = os.path.join(args.source, "bench", "bench_growth.py")
techniques = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
failures = []


def check(cond, what):
    if not cond:
        failures.append(what)
        print("FAIL:", what)


def finite_positive(v):
    return isinstance(v, (int, float)) and math.isfinite(v) and v > 0


TOLERANCE = 0.03
cmd = [sys.executable, bench, "--out", args.out, "--frames", "2", "--rounds", "2",
       "--warmup", "1", "--triangles", "200,800", "--sizes", "64x48,96x72",
       "--base-size", "64x48", "--base-triangles", "200", "--lights", "1,2",
       "--view-angles", "30,15",
       "--noise-tolerance", repr(TOLERANCE)]
growth_json = os.path.join(args.out, "growth.json")
growth_md = os.path.join(args.out, "growth.md")
for path in (growth_json, growth_md):
    if os.path.exists(path):
        os.remove(path)
p = subprocess.run(cmd, capture_output=True, text=True, timeout=1500)
check(p.returncode == 0, f"bench_growth: status {p.returncode}: {p.stderr[-3000:]}")
doc = json.load(open(growth_json)) if os.path.exists(growth_json) else {}
md = open(growth_md).read() if os.path.exists(growth_md) else ""

# growth.json: rows and their figures.
tri_labels = [k for k in doc if k.endswith(" triangles")]
px_labels = [k for k in doc if k.endswith(" px)")]
light_labels = [k for k in doc if k.endswith(" light") or k.endswith(" lights")]
angle_labels = [k for k in doc if k.startswith("view angle ")]
check(len(doc) == 8 and len(tri_labels) == 2 and px_labels == ["64x48 (3,072 px)",
                                                                "96x72 (6,912 px)"]
      and light_labels == ["1 light", "2 lights"]
      and angle_labels == ["view angle 30 deg", "view angle 15 deg"],
      f"growth.json rows: {list(doc)}")
counts = [int(k.split()[0].replace(",", "")) for k in tri_labels]
check(len(counts) == 2 and counts[0] < counts[1] and abs(counts[0] - 200) < 100
      and abs(counts[1] - 800) < 100, f"triangle counts near 200 and 800: {counts}")
for label, row in doc.items():
    check(sorted(k for k in row if k not in ("too_noisy", "details")) ==
          sorted(techniques + ["none#2"]),
          f"{label}: techniques {sorted(row)}, expected {techniques} and none#2")
    for t in techniques + ["none#2"]:
        v = row.get(t)
        ok = isinstance(v, list) and len(v) == 4 and all(map(finite_positive, v))
        check(ok and v[2] <= v[0] <= v[3], f"{label} {t}: (ms, ratio, min, max) = {v}")
    check(row.get("none", [0, 0])[1] == 1, f"{label}: none against itself {row.get('none')}")
    floor = (row.get("none#2") or [0, float("nan")])[1]
    check(isinstance(row.get("too_noisy"), bool) and
          row["too_noisy"] == (abs(floor - 1) > TOLERANCE + 1e-9),
          f"{label}: too_noisy {row.get('too_noisy')} for floor {floor}")

# What the exact techniques' cost is made of: volume's silhouette edges
# and fill, raytrace's rays per second per thread, where registered. The
# sphere's silhouette grows with its tessellation, and a narrower view
# angle (the sphere bigger on screen) makes the volume cover more pixels.
details = {label: row.get("details") or {} for label, row in doc.items()}
if "volume" in techniques:
    edges = [details[k].get("volume_silhouette_edges") or 0 for k in tri_labels]
    check(len(edges) == 2 and 0 < edges[0] < edges[1], f"volume silhouette edges grow: {edges}")
    fill = [details[k].get("volume_fill_px") or 0 for k in angle_labels]
    check(len(fill) == 2 and 0 < fill[0] < fill[1], f"volume fill grows with coverage: {fill}")
if "raytrace" in techniques:
    rays = [details[k].get("raytrace_rays_per_s_per_thread") for k in doc]
    check(all(finite_positive(v) for v in rays), f"raytrace rays/s per thread: {rays}")

# growth.md: four tables, a column per technique, the noise floor and the
# cost details, cells that agree with growth.json.
tables = [t for t in re.split(r"\n\n", md) if t.startswith("| ")]
check(len(tables) == 4, f"growth.md: {len(tables)} tables")
for table, labels in zip(tables, (tri_labels, px_labels, light_labels, angle_labels)):
    lines = table.strip().splitlines()
    head = [c.strip() for c in lines[0].strip("|").split("|")]
    check(head[1:] == [f"{t} ms (x none)" for t in techniques] +
          ["noise floor none#2 / none", "volume silhouette edges", "volume fill px",
           "raytrace rays/s per thread"], f"growth.md header {head}")
    check(len(lines) == 2 + len(labels), f"growth.md: {len(lines) - 2} rows for {labels}")
    for line, label in zip(lines[2:], labels):
        cells = [c.strip() for c in line.strip("|").split("|")]
        check(cells[0] == label, f"growth.md row {cells[0]!r}, expected {label!r}")
        for t, cell in zip(techniques, cells[1:]):
            m = re.fullmatch(r"(\d+\.\d) \((\d+\.\d\d)\)", cell)
            want = doc.get(label, {}).get(t) or [0, 0]
            check(m is not None and abs(float(m.group(1)) - want[0]) <= 0.05 + 1e-9 and
                  abs(float(m.group(2)) - want[1]) <= 0.005 + 1e-9,
                  f"growth.md {label} {t}: {cell!r} against {want[:2]}")
        noisy = doc.get(label, {}).get("too_noisy")
        floor_cell = cells[1 + len(techniques)]
        m = re.fullmatch(r"(\d+\.\d\d\d)( TOO NOISY)?", floor_cell)
        check(m is not None and bool(m.group(2)) == noisy,
              f"growth.md {label} noise floor {floor_cell!r} (too_noisy {noisy})")
check("noise floor" in md and f"1.00 +- {TOLERANCE:.2f}" in md, "growth.md: the floor's rule")

# Bad options: exit status 2, the option and the value named, nothing run.
for bad, name in ((["--sizes", "64x0"], "--sizes"), (["--triangles", "12,abc"], "--triangles"),
                  (["--rounds", "0"], "--rounds"), (["--lights", "1,5"], "--lights"),
                  (["--view-angles", "0.5"], "--view-angles")):
    q = subprocess.run([sys.executable, bench, "--out", os.path.join(args.out, "bad")] + bad,
                       capture_output=True, text=True, timeout=120)
    check(q.returncode == 2 and name in q.stderr and bad[1].split(",")[-1] in q.stderr,
          f"bench_growth {bad}: status {q.returncode}, {q.stderr.strip()[-300:]}")

print("cli.bench_growth:", "FAILED (%d)" % len(failures) if failures else "ok")
sys.exit(1 if failures else 0)
