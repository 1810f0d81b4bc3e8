"""The settings tables (vtkShadowSettings.h) as the binary lists them and as
vtkShadowTechnique.SetOption takes them agree, for every technique:

- every listed key is accepted at its range's closed ends (just inside an
  open end), refused just outside each finite end, for NaN, and for a
  non-integer where the key is integer; its listed default is in range (or the doc line says it means unset);
- every key SetOption takes is listed: no key that any technique lists, nor
  a key some pass took before the tables (scripts/probe-settings.py), is
  accepted by a technique that does not list it;
- vtkShadowTechnique.GetSettingsListing() is what --list-settings prints.

Not a comparison with a stored copy of our own output: each check follows
from the listed row alone."""
import argparse
import math
import os
import subprocess
import sys

import vtkshadow

# Keys some pass took before the tables (scripts/probe-settings.py) and a
# few no pass has: none may be taken without being listed.
OLD_KEYS = """cast_headlight residual_light map_resolution cascades ratio_per_cascade
split lambda split_fraction_0 split_fraction_6 split_fraction_7 split_fraction_
stable max_texel_px memory_budget bias_scale filter pcf_size poisson_radius
blend_band max_distance fade debug_cascades resolve tap_texel_px tile_cull soft
soft_samples adaptive pcss_blocker_taps pcss_filter_taps pcss_max_texels
detect_receivers plane_tolerance samples threads light_radius light_angle
depth_bias slope_bias force_zfail facing_test max_error penumbra_target bogus
""".split()

parser = argparse.ArgumentParser()
parser.add_argument("--bin", required=True)
args = parser.parse_args()
env = dict(os.environ)
env.pop("DISPLAY", None)  # listing must not need an X server
run = subprocess.run([os.path.join(args.bin, "vtkshadow-render"), "--list-settings"],
                     capture_output=True, text=True, env=env, timeout=120)
failures = []
if run.returncode != 0:
    failures.append(f"--list-settings: exit status {run.returncode}: {run.stderr}")
if run.stdout != vtkshadow.vtkShadowTechnique.GetSettingsListing():
    failures.append("--list-settings differs from vtkShadowTechnique.GetSettingsListing()")
rows = [line.split("\t") for line in run.stdout.splitlines()]


def accepts(technique, key, value):
    t = vtkshadow.vtkShadowTechnique()
    t.SetName(technique)
    return bool(t.SetOption(key, value))


def expect(technique, key, value, want, why):
    if accepts(technique, key, value) != want:
        failures.append(f"{technique} {key}={value!r}: {'refused' if want else 'taken'}"
                        f" ({why})")


def check_row(technique, key, rng, integer, default, doc):
    lo, hi = (float(x) for x in rng[1:-1].split(", "))
    lo_open, hi_open = rng[0] == "(", rng[-1] == ")"
    for end, is_open, inward, outward in ((lo, lo_open, math.inf, -math.inf),
                                          (hi, hi_open, -math.inf, math.inf)):
        if math.isinf(end):
            expect(technique, key, end, not is_open, f"infinite end of {rng}")
            continue
        inside = math.nextafter(end, inward)
        expect(technique, key, end, not is_open, f"end of {rng}")
        if not integer:
            expect(technique, key, inside, True, f"just inside {rng}")
        step = 1.0 if integer else abs(end - math.nextafter(end, outward))
        expect(technique, key, end + math.copysign(step, outward), False, f"outside {rng}")
    expect(technique, key, math.nan, False, "NaN")
    if integer:
        expect(technique, key, lo + 0.5, False, "not an integer")
    # A default outside the range must say so: split_fraction_<i> is unset
    # (0, the practical split there) until given.
    if "unset: " + default not in doc:
        expect(technique, key, float(default), True, "the listed default")


listed = {}
for row in rows:
    if len(row) != 6:
        failures.append(f"not 6 columns: {row}")
        continue
    technique, key, rng, integer, default, doc = row
    listed.setdefault(technique, {})[key] = row
    if integer not in ("yes", "no") or not doc:
        failures.append(f"{technique} {key}: integer {integer!r}, doc {doc!r}")
    check_row(technique, key, rng, integer == "yes", default, doc)

registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
if list(listed) != names:
    failures.append(f"techniques listed {list(listed)}, registry {names}")
candidates = sorted(set(OLD_KEYS) | {k for keys in listed.values() for k in keys})
probes = [0.0, 0.5, 1.0, 2.0, 16.0, 64.0, 2048.0, 65536.0]
for technique in names:
    for key in candidates:
        if key not in listed.get(technique, {}):
            for value in probes:
                expect(technique, key, value, False, "key not listed")
checked = sum(len(keys) for keys in listed.values())
for f in failures:
    print("FAIL:", f)
print(f"settings: {checked} rows of {len(listed)} techniques, {len(candidates)} keys probed, "
      f"{len(failures)} failures")
sys.exit(1 if failures else 0)
