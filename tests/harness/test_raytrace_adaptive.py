"""raytrace's adaptive ray counts (issue 15, "more samples only where the
penumbra is") against the exact penumbra.

    test_raytrace_adaptive.py --bin BUILD/bin --out DIR

The scene of test_soft.py (a sphere over a plane, disk lights of radius 0.5
and 0.35 and a sun of 6 degrees), rendered per light by vtkshadow-render
--technique raytrace --set samples=64 with adaptive=1 and adaptive=0 at
160x120, each compared by exact_penumbra (the unoccluded fraction of the
light, integrated per pixel, vsh_soft). Per light:

- adaptive pen_mae within PEN_MAE_TOL (0.002) of the non-adaptive pen_mae at
  the same N (measured: equal to 1e-4; a decision from each pixel's own
  8-ray batch alone, without its neighbours, measured 0.013 against 0.008
  on light 0 and fails this), and within 0.02 of the exact penumbra;
- --stats' rays per pixel of the light: exactly 64 with adaptive=0, at most
  RAYS_MAX_FRACTION (0.4) of 64 with adaptive=1 (measured 10-14: 8 rays
  everywhere, 64 on the 4-11% of pixels near a penumbra), and at least the
  first batch of 8.

Prints every figure; exits 1 when any bound fails.
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import soft_penumbra_common as common  # noqa: E402
from soft_penumbra_common import parse_args, verdict  # noqa: E402
from soft_penumbra_common import SCENE, SIZE, failures, run, scene_with  # noqa: E402

SAMPLES = 64
PEN_MAE_TOL = 0.002
PEN_MAE_MAX = 0.02
RAYS_MAX_FRACTION = 0.4
BATCH = 8


def render(args, scene, adaptive, k):
    stem = os.path.join(args.out, "a%d_light%d" % (adaptive, k))
    vis, mask, image, stats = stem + "_vis.png", stem + "_mask.png", stem + ".png", stem + ".json"
    run([os.path.join(args.bin, "vtkshadow-render"), scene, "--technique", "raytrace",
         "--set", "samples=%d" % SAMPLES, "--set", "adaptive=%d" % adaptive, "--light", str(k),
         "--size", SIZE, "--visibility", vis, "--mask", mask, "--image", image,
         "--stats", stats, "--frames", "1", "--rounds", "1", "--warmup", "0", "--quiet"])
    m = common.exact(args.bin, scene, k, vis, mask)
    try:
        with open(stats) as f:
            rays = json.load(f)["technique_stats"]["rays_per_pixel_light"][k]
    except (OSError, ValueError, KeyError, IndexError) as e:
        failures.append("adaptive=%d light %d: no rays_per_pixel_light in --stats (%s)" % (adaptive, k, e))
        rays = None
    print("raytrace samples=%d adaptive=%d light %d: rays/pixel %s, %s" % (SAMPLES, adaptive, k, rays, m),
          flush=True)
    return m, rays


def check_light(args, scene, k):
    (ma, ra), (m0, r0) = render(args, scene, 1, k), render(args, scene, 0, k)
    if not ma or not m0 or ma["pen_pixels"] < 100:
        failures.append("light %d: no penumbra measured" % k)
        return
    if not abs(ma["pen_mae"] - m0["pen_mae"]) <= PEN_MAE_TOL:
        failures.append("light %d: adaptive pen_mae %g vs %g non-adaptive (tolerance %g)"
                        % (k, ma["pen_mae"], m0["pen_mae"], PEN_MAE_TOL))
    if not ma["pen_mae"] <= PEN_MAE_MAX:
        failures.append("light %d: adaptive pen_mae %g > %g" % (k, ma["pen_mae"], PEN_MAE_MAX))
    if r0 is not None and r0 != SAMPLES:
        failures.append("light %d: adaptive=0 traced %g rays per pixel, not %d" % (k, r0, SAMPLES))
    if ra is not None and not BATCH <= ra <= RAYS_MAX_FRACTION * SAMPLES:
        failures.append("light %d: adaptive traced %g rays per pixel, not in [%d, %g]"
                        % (k, ra, BATCH, RAYS_MAX_FRACTION * SAMPLES))


def main():
    args = parse_args()
    scene = scene_with(args.out, "soft", None)
    for k in range(len(SCENE["lights"])):
        check_light(args, scene, k)
    return verdict("harness.raytrace_adaptive")


if __name__ == "__main__":
    sys.exit(main())
