"""Render test: the depth buffer's error stays well inside the tolerance
raytrace's refinement (and its classifier's tubes) allow.

Each pixel's surface point comes from the depth buffer, and a primary ray
through the pixel centre, limited to the depth tolerance around it, lands on
the exact triangle (docs/raytraced-shadows.md, "Per pixel"). For each SCENE (a
library scene, or raytrace:CASE for a scene of test_raytrace.py's cases),
vtkshadow-render traces every pixel (classify=0) and reports landed_px (hits
on a mesh) and landed_beyond_half_tolerance_px (hits farther from the depth
point than half the tolerance). The tolerance holds with a margin of two
when at most MAX_FRACTION of the landed hits (and at most a few pixels on
silhouettes, where the ray and the rasterizer may disagree) lie beyond half,
and when nearly every drawn pixel landed.

  test_depth_error.py --bin BUILD/bin --out DIR [--size WxH]
      [--max-fraction F] SCENE...
"""
import argparse
import json
import os
import subprocess
import sys

SCENES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scenes")


def scene_file(args, scene):
    """The scene's file: a library scene's, or test_raytrace.py's case
    written into the output folder."""
    if not scene.startswith("raytrace:"):
        return os.path.join(SCENES, scene + ".json")
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import test_raytrace  # noqa: E402
    build = test_raytrace.CASES[scene.split(":", 1)[1]][0]
    path = os.path.join(args.out, scene.replace(":", "_") + ".json")
    with open(path, "w") as f:
        json.dump(build(), f)
    return path


def stats_of(args, scene):
    base = os.path.join(args.out, scene.replace("/", "_").replace(":", "_"))
    cmd = [os.path.join(args.bin, "vtkshadow-render"), scene_file(args, scene),
           "--technique", "raytrace", "--set", "classify=0", "--image", base + ".png",
           "--size", args.size, "--stats", base + ".json", "--frames", "2", "--rounds", "1",
           "--warmup", "1", "--quiet"]
    subprocess.run(cmd, check=True)
    with open(base + ".json") as f:
        return json.load(f)["technique_stats"]


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--size", default="800x600")
    p.add_argument("--max-fraction", type=float, default=1e-4)
    p.add_argument("scenes", nargs="+")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    failures = []
    for scene in args.scenes:
        t = stats_of(args, scene)
        surface, landed = t["surface_pixels"], t["landed_px"]
        beyond = t["landed_beyond_half_tolerance_px"]
        allowed = max(4, args.max_fraction * landed)
        print("%s: %d of %d drawn pixels landed, %d beyond half the tolerance (at most %g), "
              "%d missed" % (scene, landed, surface, beyond, allowed, t["refine_misses_px"]))
        if landed < 0.99 * surface:
            failures.append("%s: only %d of %d drawn pixels landed" % (scene, landed, surface))
        if beyond > allowed:
            failures.append("%s: %d landings beyond half the depth tolerance (at most %g)" %
                            (scene, beyond, allowed))
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
