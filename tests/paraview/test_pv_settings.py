"""The ParaView view's shadow properties (RenderViewWithShadows.xml) that
set a technique setting use that setting's row of the settings table as
`vtkshadow-render --list-settings` prints it: Int for integer keys, Double
otherwise, the range domain's min and max (or every enumerated value) the
row's range, the default the row's default. Every property with a Set
command must be in PROPERTIES below, so a new one cannot skip the check."""
import argparse
import os
import subprocess
import sys
import xml.etree.ElementTree as ET

# command -> (technique whose row it follows, key); vtkPVRenderViewWithShadows
# passes each value to SetOption under this key.
PROPERTIES = {
    "SetShadowMaxError": ("auto", "max_error"),
    "SetShadowCascades": ("csm", "cascades"),
    "SetShadowMapResolution": ("csm", "map_resolution"),
    "SetShadowFilter": ("csm", "filter"),
}
NOT_SETTINGS = {"SetShadowTechnique"}

parser = argparse.ArgumentParser()
parser.add_argument("--bin", required=True)
parser.add_argument("--xml", required=True)
args = parser.parse_args()
env = dict(os.environ)
env.pop("DISPLAY", None)
out = subprocess.run([os.path.join(args.bin, "vtkshadow-render"), "--list-settings"],
                     capture_output=True, text=True, env=env, timeout=120, check=True).stdout
table = {(r[0], r[1]): r for r in (line.split("\t") for line in out.splitlines())}
failures = []
seen = set()
for prop in ET.parse(args.xml).getroot().iter():
    command = prop.get("command", "")
    if not prop.tag.endswith("VectorProperty") or not command.startswith("Set"):
        continue
    if command in NOT_SETTINGS:
        continue
    if command not in PROPERTIES:
        failures.append(f"{prop.get('name')}: {command} is not mapped to a setting")
        continue
    seen.add(command)
    technique, key = PROPERTIES[command]
    _, _, rng, integer, default, _ = table[(technique, key)]
    lo, hi = (float(x) for x in rng[1:-1].split(", "))
    want_tag = "IntVectorProperty" if integer == "yes" else "DoubleVectorProperty"
    if prop.tag != want_tag:
        failures.append(f"{prop.get('name')}: {prop.tag}, the setting wants {want_tag}")
    if float(prop.get("default_values")) != float(default):
        failures.append(f"{prop.get('name')}: default {prop.get('default_values')}, "
                        f"{technique} {key} has {default}")
    ranges = [d for d in prop if d.tag.endswith("RangeDomain")]
    enums = [d for d in prop if d.tag == "EnumerationDomain"]
    if ranges:
        got = (float(ranges[0].get("min")), float(ranges[0].get("max")))
        if got != (lo, hi) or rng[0] == "(" or rng[-1] == ")":
            failures.append(f"{prop.get('name')}: domain {got}, {technique} {key} is {rng}")
    elif enums:
        values = sorted(float(e.get("value")) for e in enums[0] if e.tag == "Entry")
        if integer != "yes" or values != [float(v) for v in range(int(lo), int(hi) + 1)]:
            failures.append(f"{prop.get('name')}: entries {values}, {technique} {key} is {rng}")
    else:
        failures.append(f"{prop.get('name')}: no range or enumeration domain")
missing = set(PROPERTIES) - seen
if missing:
    failures.append(f"mapped commands not in the XML: {sorted(missing)}")
for f in failures:
    print("FAIL:", f)
print(f"pv_settings: {len(seen)} properties checked, {len(failures)} failures")
sys.exit(1 if failures else 0)
