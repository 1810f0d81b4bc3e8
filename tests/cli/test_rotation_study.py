"""bench/rotation_study.py end to end on a small grid: one table row per N,
every pen_mae a number in (0, 1) that falls with N for the fixed pattern,
the per-pixel turn within 15 % (relative) of the fixed pattern (the study's
finding, docs/soft-shadows.md "Per-pixel rotation: what it buys"), and bad
options exit 2 naming the option.

  vtkshadow-python tests/cli/test_rotation_study.py --source SRC
"""
import argparse
import os
import re
import subprocess
import sys

ap = argparse.ArgumentParser()
ap.add_argument("--source", required=True)
args = ap.parse_args()
script = os.path.join(args.source, "bench", "rotation_study.py")
failures = []

r = subprocess.run([sys.executable, script, "--size", "64", "--samples", "8,32"],
                   stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
print(r.stdout, r.stderr[-2000:])
if r.returncode != 0:
    failures.append("rotation_study.py exited %d" % r.returncode)
rows = {}
for line in r.stdout.splitlines():
    m = re.match(r"\| (\d+) \| ([0-9.]+) \| ([0-9.]+) \| ([0-9.]+) \|$", line)
    if m:
        rows[int(m.group(1))] = [float(v) for v in m.groups()[1:]]
if sorted(rows) != [8, 32]:
    failures.append("rows for N = %s, expected 8 and 32" % sorted(rows))
else:
    for n, (fixed, turned, mixed) in rows.items():
        if not all(0.0 < v < 1.0 for v in (fixed, turned, mixed)):
            failures.append("N = %d: pen_mae out of (0, 1): %s" % (n, rows[n]))
        elif abs(turned - fixed) > 0.15 * fixed:
            failures.append("N = %d: turned %g is not within 15 %% of fixed %g" % (n, turned, fixed))
    if not rows[32][0] < rows[8][0]:
        failures.append("fixed pattern: pen_mae did not fall from N = 8 to 32: %s" % rows)

for bad, name in ((["--size", "3"], "--size"), (["--samples", "x"], "--samples"),
                  (["--samples", "0"], "--samples")):
    b = subprocess.run([sys.executable, script] + bad, stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, text=True)
    if b.returncode != 2 or name not in b.stderr:
        failures.append("%s: status %d, expected 2 naming %s" % (" ".join(bad), b.returncode, name))

for f in failures:
    print("FAIL:", f)
print("cli.rotation_study: %s" % ("FAILED" if failures else "passed"))
sys.exit(1 if failures else 0)
