"""volume on casters that are not closed, against POV-Ray
(docs/shadow-volumes.md, "Z-pass or z-fail, per caster and light").

    test_open_casters.py --bin BUILD/bin --out DIR [--spec volume]

scenes/hard/open-casters (an open bowl the camera looks into, isosurface
blobs cut open at the bottom, a sphere, a floor; two lights) through
vtkshadow-compare at the library's scale (0.4: 320x240) with the shipped
POV-Ray reference (--require-references). Per light, the wrong_pct of
SPEC must be at most MAX_WRONG_PCT. volume's default counts the open
casters z-pass with the caps of the faces seen from their unlit side
(unlit_caps): 0.002 and 0.004, the figures raytrace gets; z-fail with every
cap (--spec volume:unlit_caps=0) the same. Counted z-pass without those
caps (--spec volume:unlit_caps=0:open_zfail=0) the open casters' volumes
measure 0.059 and 0.033 (false shadows where the camera sees the bowl's
inner wall, turned away from light 0) and the test fails.

Prints every figure; exits 1 when a bound fails or a light is missing.
"""
import argparse
import json
import os
import subprocess
import sys

MAX_WRONG_PCT = 0.02
SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes", "hard",
                     "open-casters.json")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--spec", default="volume")
    args = ap.parse_args()
    techniques = {"vtk/" + args.spec: MAX_WRONG_PCT}
    os.makedirs(args.out, exist_ok=True)
    cmd = [os.path.join(args.bin, "vtkshadow-compare"), os.path.abspath(SCENE), "--out", args.out,
           "--scale", "0.4", "--renderers", "vtk,povray", "--techniques", args.spec,
           "--require-references", "--no-report"]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout + run.stderr)
        print(f"FAIL: vtkshadow-compare exited {run.returncode}")
        return 1
    with open(os.path.join(args.out, "results.json")) as f:
        scene = json.load(f)["scenes"][0]
    rows = [r for r in scene["results"] if r["test"] in techniques and r["reference"] == "povray"]
    failed = len(rows) != 2 * len(techniques)
    if failed:
        print(f"FAIL: {len(rows)} rows against POV-Ray (want {2 * len(techniques)}: "
              f"{', '.join(techniques)}, two lights)")
    for r in rows:
        bound = techniques[r["test"]]
        ok = r["wrong_pct"] <= bound
        print(f"light {r['light']}: {r['test']} wrong_pct {r['wrong_pct']:.4f} (false shadow "
              f"{r['false_shadow_pct']:.4f}, false light {r['false_light_pct']:.4f}), "
              f"bound {bound}: {'ok' if ok else 'FAIL'}")
        failed |= not ok
    print("harness.open_casters: " + ("FAIL" if failed else "ok"))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
