"""The committed limits fail a lost shadow and a hard shadow, through --check.

    test_controls.py --bin BIN --source SRC --out DIR

For each technique T of ours, a copy of scenes/thresholds.json gives T's
limits of a scene to a control row of the same scene, and vtkshadow-compare
--check (at the library's scale, against the shipped references) must fail
it, naming the metric that caught it:

- hard/thin-plate (a shadow of 48 pixels, 0.06 % of the frame) and
  basic/sphere-plane: vtk/none, a render with no shadow, under T's limits;
- soft/sphere-disk and soft/sun-angle (lights with a size):
  vtk/raytrace:samples=1, one ray per pixel (a hard shadow), under T's
  limits.

And the committed file itself passes the controls' own rows, so what fails
is the swapped limits, not the run. Exit 0 pass, 1 fail.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

TECHNIQUES = ("planar", "csm", "auto", "volume", "raytrace")
HARD = "raytrace:samples=1"
CASES = (("hard/thin-plate", "none", ("wrong_of_shadow_pct",)),
         ("basic/sphere-plane", "none", ("wrong_of_shadow_pct",)),
         ("soft/sphere-disk", HARD, ("pen_mae", "pen_contour_")),
         ("soft/sun-angle", HARD, ("pen_mae", "pen_contour_")))


def library_view(a):
    """A folder of links to the library's scene groups, meshes and shipped
    references: a thresholds file written there governs the scenes under
    their library ids (hard/thin-plate), as scenes/thresholds.json does."""
    view = os.path.join(a.out, "library")
    os.makedirs(view)
    for name in ("basic", "hard", "soft", "meshes", "references"):
        os.symlink(os.path.abspath(os.path.join(a.source, "scenes", name)),
                   os.path.join(view, name))
    return view


def check(a, scene, control, thresholds, known, out):
    cmd = [os.path.join(a.bin, "vtkshadow-compare"),
           os.path.join(os.path.dirname(thresholds), scene + ".json"), "--out", out,
           "--techniques", control, "--scale", "0.4", "--require-references",
           "--thresholds", thresholds, "--known-failures", known, "--check", "--no-report"]
    return subprocess.run(cmd, capture_output=True, text=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--thresholds", help="limits to test (default: scenes/thresholds.json)")
    a = ap.parse_args()
    shutil.rmtree(a.out, ignore_errors=True)
    os.makedirs(a.out)
    with open(a.thresholds or os.path.join(a.source, "scenes", "thresholds.json")) as f:
        committed = json.load(f)
    known = os.path.join(a.source, "scenes", "known-failures.json")
    view = library_view(a)
    failures, caught = [], 0
    for scene, control, metrics in CASES:
        # The control's own committed limits pass: the run itself is sound.
        own = os.path.join(view, "committed.json")
        with open(own, "w") as f:
            json.dump(committed, f)
        p = check(a, scene, control, own, known, os.path.join(a.out, "own"))
        if p.returncode != 0:
            failures.append("%s: vtk/%s fails its own committed limits (exit %d):\n%s"
                            % (scene, control, p.returncode, p.stderr[-1500:]))
            continue
        for t in TECHNIQUES:
            limits = committed["scenes"][scene].get("vtk/" + t)
            if limits is None:
                failures.append("%s: no limits for vtk/%s" % (scene, t))
                continue
            swapped = json.loads(json.dumps(committed))
            swapped["scenes"][scene]["vtk/" + control] = limits
            path = os.path.join(view, "swapped.json")
            with open(path, "w") as f:
                json.dump(swapped, f)
            p = check(a, scene, control, path, os.path.join(a.out, "no-known.json"),
                      os.path.join(a.out, "swapped"))
            lines = [l for l in p.stderr.splitlines() if "CHECK FAILED" in l]
            # Every light T has limits for must be caught on a metric of the case.
            lights = sorted({k for v in limits.values() if isinstance(v, list)
                             for k, x in enumerate(v) if x is not None})
            missed = []
            for k in lights:
                named = [l for l in lines if ", light %d, vtk/%s:" % (k, control) in l
                         and any(m in l for m in metrics)]
                if named:
                    print("%s: vtk/%s under the limits of vtk/%s: %s"
                          % (scene, control, t, named[0].split("CHECK FAILED ", 1)[1]))
                else:
                    missed.append(k)
            if p.returncode != 3 or missed or not lights:
                failures.append("%s: vtk/%s passed the limits of vtk/%s on light(s) %s (exit "
                                "%d; no failure on %s)" % (scene, control, t, missed,
                                                           p.returncode, " or ".join(metrics)))
            else:
                caught += 1
    for f in failures:
        print("FAIL: " + f, file=sys.stderr)
    if failures:
        sys.exit(1)
    print("PASS: %d swapped limit sets, every one failed by its control" % caught)


if __name__ == "__main__":
    main()
