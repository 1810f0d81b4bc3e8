"""Render test: raytrace's classifier (setting classify, on by default) gives
the image every pixel's own ray gives, and keeps its maps while only the
camera moves.

For each CASE (a library scene and a light), vtkshadow-render draws the
light's 16-bit visibility with classify=1 and with classify=0, and the two
must be equal in every pixel. Then a timed run over vtkshadow-render's camera
orbit (--stats) must report the classifier in use, its maps built once per
hard light over the whole orbit (none in the last frame), and a traced
fraction below MAX_TRACED for the light: a classifier that decides nothing
fails.

  test_raytrace_classify.py --bin BUILD/bin --out DIR --case SCENE:LIGHT:MAX_TRACED
      [--case ...] [--size WxH]
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import read_png  # noqa: E402

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes")


def render(args, scene, light, settings, tag, stats=False):
    """The light's visibility (array) and, with stats, the stats JSON."""
    base = os.path.join(args.out, "%s-%d-%s" % (scene.replace("/", "_"), light, tag))
    cmd = [os.path.join(args.bin, "vtkshadow-render"), os.path.join(SCENES, scene + ".json"),
           "--technique", "raytrace", "--image", base + ".png", "--visibility", base + "-vis.png",
           "--light", str(light), "--size", args.size, "--quiet"]
    for s in settings:
        cmd += ["--set", s]
    if stats:
        cmd += ["--stats", base + ".json", "--frames", "4", "--rounds", "1", "--warmup", "2"]
    subprocess.run(cmd, check=True)
    data = json.load(open(base + ".json")) if stats else None
    return read_png(base + "-vis.png"), data


def check_case(args, case):
    scene, light, max_traced = case.split(":")
    light, max_traced = int(light), float(max_traced)
    failures = []
    classified, _ = render(args, scene, light, [], "classify")
    traced, _ = render(args, scene, light, ["classify=0"], "traced")
    differ = int(np.count_nonzero(classified != traced))
    print("%s light %d: %d of %d pixels differ from every pixel traced" %
          (scene, light, differ, traced.size))
    if differ:
        failures.append("%s light %d: %d pixels differ" % (scene, light, differ))
    _, stats = render(args, scene, light, [], "orbit", stats=True)
    t = stats["technique_stats"]
    fraction = t["traced_fraction_light"][light]
    hard = len(t["traced_fraction_light"])
    print("  orbit: classify %s, maps built %d (last frame %d), traced fraction %.3f "
          "(block-decided px %d, px without rays %d of %d), trace %.1f ms" %
          (t["classify"], t["classify_maps_built"], t["classify_maps_built_last_frame"], fraction,
           t["block_decided_pixels"], t["pixels_without_rays"], t["surface_pixels"],
           t["trace_ms"]))
    if not t["classify"]:
        failures.append("%s: the classifier was not used" % scene)
    if t["classify_maps_built"] != hard or t["classify_maps_built_last_frame"] != 0:
        failures.append("%s: maps built %d times (want %d, once per light) over the orbit" %
                        (scene, t["classify_maps_built"], hard))
    if not fraction < max_traced:
        failures.append("%s light %d: traced fraction %.3f >= %.3f" %
                        (scene, light, fraction, max_traced))
    return failures


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--bin", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--case", action="append", required=True,
                   help="SCENE:LIGHT:MAX_TRACED, e.g. scivis/isosurface:1:0.6")
    p.add_argument("--size", default="400x300")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    failures = []
    for case in args.case:
        failures += check_case(args, case)
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
