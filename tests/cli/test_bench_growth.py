"""bench/bench_growth.py end to end on a tiny configuration (two triangle
counts, two window sizes, 2 rounds of 2 frames): the structure of what it
writes, never a speed. growth.json has one row per case with every
registered technique and none#2, each a finite positive (ms, ratio, min ms,
max ms) with min <= median <= max, none's ratio exactly 1 and a boolean
too_noisy that agrees with none#2's ratio; growth.md has the two tables with
one column per technique plus the noise-floor column, one row per case, and
cells that read back as the numbers of growth.json. A bad option exits 2
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
       "--base-size", "64x48", "--base-triangles", "200",
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
check(len(doc) == 4 and len(tri_labels) == 2 and px_labels == ["64x48 (3,072 px)",
                                                                "96x72 (6,912 px)"],
      f"growth.json rows: {list(doc)}")
counts = [int(k.split()[0].replace(",", "")) for k in tri_labels]
check(len(counts) == 2 and counts[0] < counts[1] and abs(counts[0] - 200) < 100
      and abs(counts[1] - 800) < 100, f"triangle counts near 200 and 800: {counts}")
for label, row in doc.items():
    check(sorted(k for k in row if k != "too_noisy") == sorted(techniques + ["none#2"]),
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

# growth.md: two tables, a column per technique and the noise floor, cells
# that agree with growth.json.
tables = [t for t in re.split(r"\n\n", md) if t.startswith("| ")]
check(len(tables) == 2, f"growth.md: {len(tables)} tables")
for table, labels in zip(tables, (tri_labels, px_labels)):
    lines = table.strip().splitlines()
    head = [c.strip() for c in lines[0].strip("|").split("|")]
    check(head[1:] == [f"{t} ms (x none)" for t in techniques] +
          ["noise floor none#2 / none"], f"growth.md header {head}")
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
        m = re.fullmatch(r"(\d+\.\d\d\d)( TOO NOISY)?", cells[-1])
        check(m is not None and bool(m.group(2)) == noisy,
              f"growth.md {label} noise floor {cells[-1]!r} (too_noisy {noisy})")
check("noise floor" in md and f"1.00 +- {TOLERANCE:.2f}" in md, "growth.md: the floor's rule")

# Bad options: exit status 2, the option and the value named, nothing run.
for bad, name in ((["--sizes", "64x0"], "--sizes"), (["--triangles", "12,abc"], "--triangles"),
                  (["--rounds", "0"], "--rounds")):
    q = subprocess.run([sys.executable, bench, "--out", os.path.join(args.out, "bad")] + bad,
                       capture_output=True, text=True, timeout=120)
    check(q.returncode == 2 and name in q.stderr and bad[1].split(",")[-1] in q.stderr,
          f"bench_growth {bad}: status {q.returncode}, {q.stderr.strip()[-300:]}")

print("cli.bench_growth:", "FAILED (%d)" % len(failures) if failures else "ok")
sys.exit(1 if failures else 0)
