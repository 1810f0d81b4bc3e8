"""Frame time of the soft-shadow settings on scenes with lights with a size
(issue 15, docs/soft-shadows.md): planar with soft_samples 1 (hard), 4, 16
and 64, interleaved in one vtkshadow-render process per scene (the same
schedule as bench_techniques.py), printed as a markdown table.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_soft.py \
      [--frames 15] [--rounds 4] [--warmup 5] [--size 640x480] [SCENE...]

Default scenes: scenes/soft/*.json. Penumbra errors are not measured here:
tests/harness/test_soft_planar.py measures them against the exact penumbra.
"""
import argparse
import glob
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtkshadow_bench import run_timing  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CONFIGS = ["planar:soft_samples=1", "planar:soft_samples=4", "planar:soft_samples=16",
           "planar:soft_samples=64"]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="*")
    ap.add_argument("--frames", type=int, default=15)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=5)
    ap.add_argument("--size", default="640x480")
    args = ap.parse_args()
    try:
        size = tuple(int(v) for v in args.size.split("x"))
        assert len(size) == 2 and min(size) >= 1
    except (ValueError, AssertionError):
        ap.error(f"--size: expected WxH (got {args.size!r})")
    if not (1 <= args.frames and 1 <= args.rounds and 0 <= args.warmup):
        ap.error("expected frames >= 1, rounds >= 1, warmup >= 0")
    scenes = args.scenes or sorted(glob.glob(os.path.join(REPO, "scenes", "soft", "*.json")))
    print("| scene | setting | median ms | x none | soft pairs |")
    print("|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as out:
        for scene in scenes:
            st = run_timing(scene, CONFIGS, size, out, (args.frames, args.rounds, args.warmup, 0.03))
            if st is None:
                sys.exit(f"bench_soft: {scene}: vtkshadow-render failed")
            entries = {e["label"]: e for e in st["timing"]["entries"]}
            name = os.path.relpath(scene, REPO)
            for label in ["none"] + CONFIGS:
                e = entries[label]
                tech = e.get("technique_stats") or {}
                print("| %s | %s | %.1f | %.2f | %s |" % (
                    name, label, e["ms"]["median"], e["ratio_to_none"]["median"],
                    tech.get("soft_pairs", "")))
            print("| %s | noise floor none#2 / none | | %.3f | |" % (name, st["noise_floor"]["ratio"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
