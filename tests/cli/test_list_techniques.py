"""vtkshadow-render --list-techniques prints the registry: every technique
once, in table order, each with its description, and exits 0 without a
display (it renders nothing)."""
import argparse
import os
import subprocess
import sys

import vtkshadow

parser = argparse.ArgumentParser()
parser.add_argument("--bin", required=True)
args = parser.parse_args()

env = dict(os.environ)
env.pop("DISPLAY", None)  # listing must not need an X server
run = subprocess.run([os.path.join(args.bin, "vtkshadow-render"), "--list-techniques"],
                     capture_output=True, text=True, env=env, timeout=60)
failures = []
if run.returncode != 0:
    failures.append(f"exit status {run.returncode}: {run.stderr}")
rows = [line.split("\t") for line in run.stdout.splitlines()]
registry = vtkshadow.vtkShadowTechniqueRegistry
expected = [[registry.GetName(i), registry.GetDescription(i)]
            for i in range(registry.GetNumberOfTechniques())]
if rows != expected:
    failures.append(f"printed {rows}\nregistry {expected}")
if len(rows) < 5:
    failures.append(f"only {len(rows)} techniques listed")
for f in failures:
    print("FAIL:", f)
print(f"list_techniques: {len(rows)} techniques, {len(failures)} failures")
sys.exit(1 if failures else 0)
