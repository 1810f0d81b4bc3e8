"""Corpus test: in third-party programs, raytrace's classifier (classify, on
by default) changes no pixel.

Each EXAMPLE (a vedo example, run unmodified by compare/corpus/run_example.py
with enable_shadows injected) is captured under `raytrace` and under
`raytrace:classify=0` (every pixel traced); the two frames must be equal in
every pixel, and the classifier must have built its maps in every example
(a classifier that stands aside would pass the comparison trivially, as
it would in programs drawing points as spheres or lines as tubes were the
maps not to take those as occluders).

  test_classify_identical.py --python PY --out DIR EXAMPLE...
"""
import argparse
import json
import os
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
RUN = os.path.join(HERE, "..", "..", "compare", "corpus", "run_example.py")
VEDO = "/usr/share/doc/python3-vedo-examples/examples"


def capture(args, example, technique):
    """The frame (RGB array) and stats of `example` under `technique`."""
    prefix = os.path.join(args.out, example.replace("/", ".") + "." +
                          technique.replace(":", "_").replace("=", "_"))
    subprocess.run([args.python, RUN, "--example", os.path.join(VEDO, example + ".py"),
                    "--technique", technique, "--out", prefix, "--frames", "2"], check=True)
    with open(prefix + ".json") as f:
        stats = json.load(f).get("stats") or []
    return np.load(prefix + ".npz")["rgb"], stats


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--python", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("examples", nargs="+", help="vedo example, e.g. basic/boolean")
    args = p.parse_args()
    os.makedirs(args.out, exist_ok=True)
    failures, classified = [], 0
    for example in args.examples:
        with_maps, stats = capture(args, example, "raytrace")
        traced, _ = capture(args, example, "raytrace:classify=0")
        differ = int(np.count_nonzero(np.any(with_maps != traced, axis=-1)))
        ran = any(s.get("classify_maps_built", 0) > 0 for s in stats if isinstance(s, dict))
        classified += ran
        print("%-28s %d of %d pixels differ; classifier maps built: %s" %
              (example, differ, traced.shape[0] * traced.shape[1], ran))
        if differ:
            failures.append("%s: %d pixels differ from every pixel traced" % (example, differ))
        if not ran:
            failures.append("%s: the classifier built no map" % example)
    for f in failures:
        print("FAIL: " + f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
