"""raytrace on a curved caster's own terminator (issue 15; docs/soft-shadows.md,
"Against both references").

    test_rt_terminator.py --bin BUILD/bin --out DIR

The scene of test_soft.py (a sphere over a plane, disk lights of radius 0.5
and 0.35 and a sun of 6 degrees), rendered per light by vtkshadow-render
--technique raytrace at 160x120. exact_terminator integrates, on the sphere's
pixels where the light straddles the horizon, both definitions of the
visibility: weighted (sum of the free samples' max(0, N.L) over the sum of
all weights: I_on / I_off, as Cycles renders it; 1 there, only the sphere
shadows itself) and the plain free fraction (the part above the horizon,
what raytrace computed before it weighted its rays). Per light:

- at least MIN_PIXELS terminator pixels;
- mean absolute error against the weighted value <= WEIGHTED_MAX (measured
  below 1e-8 on 44, 31 and 19 pixels: every free ray is above the facet);
- and at most a third of the error against the plain fraction (measured
  0.20-0.28 before, which fails both bounds).

Prints every figure; exits 1 when any bound fails.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import exact_cache  # noqa: E402
from soft_penumbra_common import SCENE, failures, parse_args, render, run, scene_with, verdict  # noqa: E402

MIN_PIXELS = 10
WEIGHTED_MAX = 0.02


def main():
    args = parse_args()
    scene = scene_with(args.out, "terminator", None)
    for k in range(len(SCENE["lights"])):
        stem = os.path.join(args.out, "light%d" % k)
        vis, mask, _ = render(args.bin, scene, "raytrace", "samples=64", k, stem)
        r = exact_cache.run_exact(run, args.bin, "exact_terminator", scene, k, vis, mask)
        try:
            import json
            m = json.loads(r.stdout)
        except ValueError:
            failures.append("light %d: exact_terminator gave no JSON" % k)
            continue
        print("raytrace light %d terminator: %s" % (k, m), flush=True)
        if m["pixels"] < MIN_PIXELS:
            failures.append("light %d: %d terminator pixels < %d" % (k, m["pixels"], MIN_PIXELS))
            continue
        if not m["mae_weighted"] <= WEIGHTED_MAX:
            failures.append("light %d: mae against the weighted visibility %g > %g"
                            % (k, m["mae_weighted"], WEIGHTED_MAX))
        if not m["mae_weighted"] <= m["mae_unweighted"] / 3:
            failures.append("light %d: closer to the plain fraction (%g) than to the weighted (%g)"
                            % (k, m["mae_unweighted"], m["mae_weighted"]))
    return verdict("harness.rt_terminator")


if __name__ == "__main__":
    sys.exit(main())
