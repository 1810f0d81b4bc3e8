"""Per-channel visibility and colour_mae on a tinted scene (docs/harness.md,
"Tinted shadows: colour_mae").

    test_tinted.py --bin BUILD/bin --source SRC --out DIR

Runs vtkshadow-compare on scenes/translucent/coloured-filter.json (a red
filter slab beside a grey one) with POV-Ray, Cycles and VTK none and
raytrace at --scale 0.25, no shipped references, and requires:

- every renderer wrote light0_visibility_g.png and light0_visibility_b.png
  beside light0_visibility.png and light0_mask.png;
- POV-Ray against Cycles: colour_mae < GOOD (the two references tint the
  shadow alike);
- vtk/none: colour_mae > BAD (it has no shadow at all, tinted or not);
- scenes/update_thresholds.py writes colour_mae limits for the technique
  row (vtk/raytrace) and the cycles row, none for the control vtk/none, and
  --verify accepts them;
- a POV-Ray whose export loses the tint (filter 0: a grey shadow, through a
  wrapper that rewrites scene.pov before running the real POV-Ray) is caught:
  --check with those limits fails the cycles row on colour_mae (exit 3),
  while the red channel alone (vis_mae) hardly moves.
vtk/raytrace's colour_mae is printed, not bounded (its shadow is grey).
The scene is copied into DIR/lib so that the limits file beside it names it
"coloured-filter".
"""
import argparse
import json
import os
import shutil
import stat
import subprocess
import sys

SCENE = "scenes/translucent/coloured-filter.json"
GOOD = 0.01
BAD = 0.02
RENDERERS = ("povray", "cycles", "vtk/none", "vtk/raytrace")

# A POV-Ray that turns every rgbft filter into transmit (filter 0, the same
# light through each crossing in every channel), then runs the real one.
GREY_POVRAY = r'''#!/usr/bin/env python3
import os, re, sys
if os.path.exists("scene.pov"):
    text = open("scene.pov").read()
    def grey(m):
        c = m.group(1).split(",")
        return "rgbft <%s,%s,%s,0,%r>" % (c[0], c[1], c[2], float(c[3]) + float(c[4]))
    open("scene.pov", "w").write(re.sub(r"rgbft <([^>]*)>", grey, text))
os.execv(%(real)r, [%(real)r] + sys.argv[1:])
'''


def run(a, scene, out, extra=(), status=0):
    cmd = [os.path.join(a.bin, "vtkshadow-compare"), scene, "--out", out, "--scale", "0.25",
           "--renderers", "vtk,povray,cycles", "--techniques", "none,raytrace",
           "--no-references", "--no-report"] + list(extra)
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if p.returncode != status:
        sys.stderr.write(p.stderr)
        raise SystemExit("FAIL: vtkshadow-compare exited %d, not %d" % (p.returncode, status))
    with open(os.path.join(out, "results.json")) as f:
        results = json.load(f)["scenes"][0]["results"]
    return {r["test"]: r for r in results}, p.stderr


def limits_of(a, results, thresholds):
    """update_thresholds.py --write, then --verify; the scene's limits."""
    script = os.path.join(a.source, "scenes", "update_thresholds.py")
    for args in (["--write", thresholds], ["--verify", thresholds]):
        p = subprocess.run([sys.executable, script, results] + args, stdout=subprocess.PIPE,
                           stderr=subprocess.PIPE, text=True)
        if p.returncode != 0:
            sys.stderr.write(p.stderr)
            raise SystemExit("FAIL: update_thresholds.py %s exited %d" % (args[0], p.returncode))
    with open(thresholds) as f:
        return json.load(f)["scenes"]["coloured-filter"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    for option in ("--bin", "--source", "--out"):
        ap.add_argument(option, required=True)
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    failures = []

    lib = os.path.join(a.out, "lib")
    os.makedirs(lib)
    scene = os.path.join(lib, "coloured-filter.json")
    shutil.copyfile(os.path.join(a.source, SCENE), scene)
    rows, _ = run(a, scene, os.path.join(a.out, "run"))
    folder = os.path.join(a.out, "run", "coloured-filter")
    for r in RENDERERS:
        for name in ("light0_visibility.png", "light0_visibility_g.png",
                     "light0_visibility_b.png", "light0_mask.png"):
            if not os.path.isfile(os.path.join(folder, r, name)):
                failures.append("%s/%s missing" % (r, name))
    for test in ("cycles", "vtk/none", "vtk/raytrace"):
        print("colour_mae %-13s %s  (vis_mae %.4f)"
              % (test, rows[test].get("colour_mae"), rows[test]["vis_mae"]))
    cyc, none = rows["cycles"].get("colour_mae"), rows["vtk/none"].get("colour_mae")
    if cyc is None or not cyc < GOOD:
        failures.append("POV-Ray vs Cycles colour_mae %s, not < %g" % (cyc, GOOD))
    if none is None or not none > BAD:
        failures.append("vtk/none colour_mae %s, not > %g" % (none, BAD))

    limits = limits_of(a, os.path.join(a.out, "run", "results.json"),
                       os.path.join(lib, "thresholds.json"))
    for test, want in (("cycles", True), ("vtk/raytrace", True), ("vtk/none", False)):
        got = limits.get(test, {}).get("colour_mae")
        print("colour_mae limit %-13s %s" % (test, got))
        if (got is not None) != want:
            failures.append("%s: colour_mae limit %s, expected %s" % (test, got, want))

    # The tint lost in one reference: the metric must see it.
    wrapper = os.path.join(a.out, "grey-povray")
    real = shutil.which("povray") or "/usr/bin/povray"
    with open(wrapper, "w") as f:
        f.write(GREY_POVRAY.replace("%(real)r", repr(real)))
    os.chmod(wrapper, os.stat(wrapper).st_mode | stat.S_IXUSR)
    grey, log = run(a, scene, os.path.join(a.out, "grey"),
                    ["--povray-binary", wrapper, "--no-cache", "--check"], status=3)
    cyc = grey["cycles"]
    print("colour_mae cycles against a grey POV-Ray: %s (red channel vis_mae %.4f); check: %s"
          % (cyc.get("colour_mae"), cyc["vis_mae"], cyc["check"]))
    if not cyc["check"].startswith("FAILED") or "colour_mae" not in cyc["check"]:
        failures.append("a POV-Ray without the tint: the cycles row's check is %r, not a "
                        "colour_mae failure" % cyc["check"])
    if "CHECK FAILED" not in log:
        failures.append("a POV-Ray without the tint: no CHECK FAILED line")

    for f in failures:
        print("FAIL: " + f)
    print("test_tinted: %s" % ("FAILED" if failures else "ok"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
