"""Penumbra error split by where the pixels are (issue 15; docs/harness.md,
"Where the references differ").

    pen_split.py --out DIR --casters CDIR SCENE... [--seed1 DIR1] [--techniques raytrace,planar]

DIR is a vtkshadow-compare --out directory (renderers vtk,povray,cycles),
DIR1 the same scenes rendered with --seed 1 (povray,cycles). CDIR holds,
per scene and light, NAME-lK.png: vtkshadow-render --technique none of the
scene with its receivers removed (any pixel that is not the background
there shows a caster). For each scene, light and comparison (POV-Ray vs
Cycles, each technique vs POV-Ray and vs Cycles) it prints pen_mae over the
reference's penumbra (0.02 < v_ref < 0.98 dilated by one pixel, pixels
valid in every image: the harness's definition) and split into receiver and
caster pixels, and with DIR1 each reference's own noise sigma =
std(V_seed0 - V_seed1) / sqrt 2 over the same split (docs/harness.md).
Needs python3-numpy and python3-pil.
"""
import argparse
import os

import numpy as np
from PIL import Image


def vis(path):
    return np.asarray(Image.open(path), dtype=np.float64) / 65535.0


def mask(path):
    return np.asarray(Image.open(path)) > 127


def pen_mask(ref, valid):
    """vshm_penumbra_mask: valid pixels with a valid penumbra pixel in their 3x3."""
    core = valid & (ref > 0.02) & (ref < 0.98)
    h, w = ref.shape
    pad = np.zeros((h + 2, w + 2), bool)
    pad[1:-1, 1:-1] = core
    grown = np.zeros_like(core)
    for dy in range(3):
        for dx in range(3):
            grown |= pad[dy:dy + h, dx:dx + w]
    return grown & valid


def casters(path):
    img = np.asarray(Image.open(path).convert("RGB"), dtype=np.int32)
    bg = img[0, 0]
    return np.any(img != bg, axis=2)


def mae(a, b, m):
    return float(np.abs(a - b)[m].mean()) if m.any() else float("nan")


def split(a, b, pen, cast):
    return (mae(a, b, pen), mae(a, b, pen & ~cast), mae(a, b, pen & cast),
            int(pen.sum()), int((pen & cast).sum()))


def fmt(t):
    return "%.4f (recv %.4f / cast %.4f; %d px, %d on casters)" % t


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--out", required=True)
    ap.add_argument("--seed1")
    ap.add_argument("--casters", required=True)
    ap.add_argument("--techniques", default="raytrace,planar,csm,auto")
    ap.add_argument("scenes", nargs="+")
    a = ap.parse_args()
    for name in a.scenes:
        d = os.path.join(a.out, name)
        k = 0
        while os.path.exists(os.path.join(d, "povray", "light%d_visibility.png" % k)):
            img = lambda r, kind: os.path.join(d, r, "light%d_%s.png" % (k, kind))
            pov, cyc = vis(img("povray", "visibility")), vis(img("cycles", "visibility"))
            valid = mask(img("povray", "mask")) & mask(img("cycles", "mask"))
            techs = {}
            for t in a.techniques.split(","):
                if os.path.exists(img("vtk/" + t, "visibility")):
                    techs[t] = vis(img("vtk/" + t, "visibility"))
                    valid &= mask(img("vtk/" + t, "mask"))
            cast = casters(os.path.join(a.casters, "%s-l%d.png" % (name.replace("soft-", ""), k)))
            pp, pc = pen_mask(pov, valid), pen_mask(cyc, valid)
            print("%s light %d" % (name, k))
            print("  POV vs Cycles (Cycles' penumbra): " + fmt(split(pov, cyc, pc, cast)))
            print("  POV vs Cycles (POV's penumbra):   " + fmt(split(pov, cyc, pp, cast)))
            for t, v in techs.items():
                print("  %-8s vs POV %s" % (t, fmt(split(v, pov, pp, cast))))
                print("  %-8s vs Cyc %s" % (t, fmt(split(v, cyc, pc, cast))))
            if a.seed1:
                d1 = os.path.join(a.seed1, name)
                for r, v0, pm in (("povray", pov, pp), ("cycles", cyc, pc)):
                    p1 = os.path.join(d1, r, "light%d_visibility.png" % k)
                    if not os.path.exists(p1):
                        continue
                    diff = v0 - vis(p1)
                    s = lambda m: float(diff[m].std() / np.sqrt(2)) if m.any() else float("nan")
                    print("  %s noise sigma %.4f (recv %.4f / cast %.4f); seed0 vs seed1 mae %s" % (
                        r, s(pm), s(pm & ~cast), s(pm & cast), fmt(split(v0, vis(p1), pm, cast))))
                if os.path.exists(os.path.join(d1, "cycles", "light%d_visibility.png" % k)):
                    c1 = vis(os.path.join(d1, "cycles", "light%d_visibility.png" % k))
                    cm = 0.5 * (cyc + c1)
                    print("  POV vs mean of 2 Cycles seeds: " + fmt(split(pov, cm, pen_mask(cm, valid), cast)))
                    for t, v in techs.items():
                        print("  %-8s vs mean of 2 Cycles seeds: %s" % (t, fmt(split(v, cm, pen_mask(cm, valid), cast))))
            k += 1


if __name__ == "__main__":
    main()
