"""pen_mae of every VTK row of a vtkshadow-compare run against Cycles (issue 15).

    pen_vs_cycles.py OUT [--tests vtk/volume:soft_samples=64,...] [--markdown]

OUT is a vtkshadow-compare --out folder rendered with renderers vtk,povray,
cycles (the references may come from --cache). The harness scores every row
against POV-Ray (results.json: pen_mae); this adds, for each scene, light and
VTK test, including technique variants (vtk/NAME:KEY=VALUE, docs/harness.md),
the same metric against Cycles: mean |v - v_cycles| over Cycles' penumbra
(0.02 < v < 0.98, dilated by one pixel) among the pixels valid in the test,
Cycles and POV-Ray (bench/pen_split.py's definition). Seconds per render are
the harness's (render_seconds / lights: one vtkshadow-render process per
light, start-up included). Needs python3-numpy and python3-pil.
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pen_split import mae, mask, pen_mask, vis  # noqa: E402


def scene_dir(out, scene):
    """The scene's folder: its id with '/' as '-' (SafeName in the harness)."""
    d = os.path.join(out, scene.replace("/", "-"))
    return d if os.path.isdir(d) else None


def rows(out, tests):
    """[(scene, light, test, pen_mae vs POV-Ray, pen_mae vs Cycles, pen px, s/render)]."""
    with open(os.path.join(out, "results.json")) as f:
        doc = json.load(f)
    found = []
    for sc in doc["scenes"]:
        d = scene_dir(out, sc["scene"])
        seconds = sc.get("render_seconds", {})
        for r in sc.get("results", []):
            t = r["test"]
            if not t.startswith("vtk/") or (tests and t not in tests) or d is None:
                continue
            k = r["light"]
            img = lambda who, kind: os.path.join(d, who, "light%d_%s.png" % (k, kind))
            if not os.path.exists(img("cycles", "visibility")):
                continue
            cyc = vis(img("cycles", "visibility"))
            valid = mask(img("cycles", "mask")) & mask(img(t, "mask")) & mask(img("povray", "mask"))
            pen = pen_mask(cyc, valid)
            per = seconds.get(t)
            found.append((sc["scene"], k, t, r.get("pen_mae"), mae(vis(img(t, "visibility")), cyc, pen),
                          int(pen.sum()), per / sc["lights"] if per is not None else None))
    return found


def num(v, f="%.4f"):
    return "-" if v is None or v != v else f % v


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--tests", default="", help="comma-separated tests (default: every vtk/ row)")
    ap.add_argument("--markdown", action="store_true", help="a Markdown table")
    a = ap.parse_args()
    tests = [t for t in a.tests.split(",") if t]
    found = rows(a.out, tests)
    if a.markdown:
        print("| scene | light | test | pen_mae vs Cycles | pen_mae vs POV-Ray | Cycles penumbra px | s / render |")
        print("|---|---|---|---|---|---|---|")
        for s, k, t, pov, cyc, px, sec in found:
            print("| %s | %d | %s | %s | %s | %d | %s |" % (s, k, t, num(cyc), num(pov), px, num(sec, "%.2f")))
    else:
        for s, k, t, pov, cyc, px, sec in found:
            print("%-20s %d %-34s cyc %s  pov %s  px %6d  %s s" % (s, k, t, num(cyc), num(pov), px,
                                                                  num(sec, "%.2f")))


if __name__ == "__main__":
    main()
