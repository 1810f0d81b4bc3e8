"""Planar mirrors (vtkPlanarReflectionPass through vtkshadow-render) against
answers computed here, not from our own output:

- geometry: a sphere over a black mirror floor (R 1) under an ambient-lit
  sphere; each pixel's expected state (reflection of the sphere or not) by
  ray casting the camera ray, reflecting it at the floor and intersecting the
  sphere analytically (one bounce, as the pass draws). Wrong pixels outside a
  one-pixel band along the expected boundary must stay <= 0.05 %.
- colour: the same kind of scene in POV-Ray (finish reflection R, diffuse
  1 - R, no fresnel), per light type; reflection_mae (mean absolute linear
  colour error over the mirror's visible pixels, computed by
  vtkshadow-metrics --reflection over the mirror pixels ray cast here)
  <= 0.02. A technique that casts no shadows (robust_techniques.py) is
  compared with POV-Ray's render without shadows. The pov-wall cases add a
  grey wall behind the sphere that takes its shadow, seen in the mirror: a
  technique whose reflection lacks that shadow scores 0.022 (directional) /
  0.049 (point), one whose mirrored draw flips the normals (volume before
  its glFrontFace fix) 0.23 / 0.21.

Every case runs with every registered technique (--technique all, the
default: the list of vtkshadow-render --list-techniques), since the mirrored
scene is drawn by the technique's own pass.
"""
import argparse
import json
import math
import os
import subprocess
import sys

import numpy as np
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy

ap = argparse.ArgumentParser()
ap.add_argument("--bin", required=True)
ap.add_argument("--out", required=True)
ap.add_argument("--case", required=True)
ap.add_argument("--povray", default="povray")
ap.add_argument("--technique", default="all",
                help="a technique name, or all (every registered technique)")
args = ap.parse_args()

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_io import write_png  # noqa: E402
from robust_techniques import profile  # noqa: E402


def techniques():
    if args.technique != "all":
        return [args.technique]
    out = subprocess.run([os.path.join(args.bin, "vtkshadow-render"), "--list-techniques"],
                         check=True, capture_output=True, text=True, timeout=120).stdout
    names = [line.split("\t")[0] for line in out.splitlines() if line.strip()]
    if not names:
        raise SystemExit("vtkshadow-render --list-techniques listed nothing")
    return names
os.makedirs(args.out, exist_ok=True)


def read_rgb(path):
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    w, h, _ = r.GetOutput().GetDimensions()
    a = vtk_to_numpy(r.GetOutput().GetPointData().GetScalars()).reshape(h, w, -1)[::-1]
    return a[:, :, :3].astype(np.float64) / 255.0


def rays(cam, w, h, offset):
    e = np.array(cam["position"], float) - offset
    f = np.array(cam["focal_point"], float) - offset - e
    f /= np.linalg.norm(f)
    r = np.cross(f, np.array(cam["view_up"], float))
    r /= np.linalg.norm(r)
    u = np.cross(r, f)
    t = math.tan(math.radians(cam["view_angle"]) / 2)
    i = (np.arange(w) + 0.5) / w * 2 - 1
    j = 1 - (np.arange(h) + 0.5) / h * 2
    d = f[None, None, :] + i[None, :, None] * t * (w / h) * r + j[:, None, None] * t * u
    return e, d / np.linalg.norm(d, axis=2, keepdims=True)


def hit_sphere(o, d, c, rad):
    oc = o - c
    b = np.sum(d * oc, axis=-1)
    disc = b * b - (np.sum(oc * oc, axis=-1) - rad * rad)
    t = -b - np.sqrt(np.maximum(disc, 0))
    return np.where((disc > 0) & (t > 1e-9), t, np.inf)


def hit_rect(o, d, origin, p1, p2):
    e1, e2 = p1 - origin, p2 - origin
    n = np.cross(e1, e2)
    n /= np.linalg.norm(n)
    dn = d @ n
    with np.errstate(divide="ignore", invalid="ignore"):
        t = ((origin - o) @ n) / dn
        x = o + t[..., None] * d - origin
        s = (x @ e1) / (e1 @ e1)
        v = (x @ e2) / (e2 @ e2)
    ok = (t > 1e-9) & (s >= 0) & (s <= 1) & (v >= 0) & (v <= 1)
    # Both faces occlude; only the one the normal points out of reflects.
    return np.where(ok, t, np.inf), n, dn < 0


def hit_box(o, d, lo, hi):
    """Nearest positive hit of rays with an axis-aligned box (slab method)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        t1 = (np.asarray(lo, float) - o) / d
        t2 = (np.asarray(hi, float) - o) / d
    tn = np.nanmax(np.minimum(t1, t2), axis=-1)
    tf = np.nanmin(np.maximum(t1, t2), axis=-1)
    t = np.where(tn > 1e-9, tn, tf)
    return np.where((tf >= tn) & (t > 1e-9), t, np.inf)


def render(scene, tag, technique, extra=()):
    path = os.path.join(args.out, tag + ".json")
    with open(path, "w") as fh:
        json.dump(scene, fh)
    image = os.path.join(args.out, tag + ".png")
    cmd = [os.path.join(args.bin, "vtkshadow-render"), path, "--technique", technique,
           "--image", image, "--reflections", "on", "--quiet"] + list(extra)
    subprocess.run(cmd, check=True, timeout=600)
    return image


def band(mask):
    """Pixels within one pixel (8-neighbourhood) of a pixel of the other state."""
    b = np.zeros_like(mask)
    for dy in (-1, 0, 1):
        for dx in (-1, 0, 1):
            sh = np.roll(np.roll(mask, dy, 0), dx, 1)
            b |= sh != mask
    b[0, :] = b[-1, :] = b[:, 0] = b[:, -1] = True
    return b


def geometric(tag, cam, size, mirrors, technique, offset=0.0, extra=()):
    """Expected pixels: reflection of the sphere in a mirror, one bounce."""
    off = np.array([offset, offset, offset])
    c, rad = np.array([0.0, 0.0, 1.2]), 0.8
    objects = [{"sphere": {"center": list(c + off), "radius": rad, "resolution": 256}}]
    for m in mirrors:
        objects.append({"plane": {k: list(np.array(v, float) + off) for k, v in m.items()},
                        "mirror": 1.0, "color": [0, 0, 0]})
    scene = {"size": list(size), "camera": {k: (list(np.array(v, float) + off)
                                                if isinstance(v, list) and k != "view_up" else v)
                                            for k, v in cam.items()},
             "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 0}],
             "objects": objects}
    tag = tag + "-" + technique
    image = read_rgb(render(scene, tag, technique, extra))
    w, h = size
    e, d = rays(cam, w, h, 0.0)
    o = np.broadcast_to(e, d.shape)
    t_best = hit_sphere(o, d, c, rad)
    expected = np.zeros((h, w), bool)
    for m in mirrors:
        t, n, facing = hit_rect(o, d, *(np.array(m[k], float) for k in ("origin", "point1", "point2")))
        front = t < t_best
        p = o + np.where(np.isfinite(t), t, 0)[..., None] * d
        rd = d - 2 * (d @ n)[..., None] * n
        refl = np.isfinite(hit_sphere(p, rd, c, rad))
        expected = np.where(front, refl & facing, expected)
        t_best = np.minimum(t_best, t)
    expected |= np.isfinite(hit_sphere(o, d, c, rad)) & (hit_sphere(o, d, c, rad) <= t_best)
    got = image.max(axis=2) > 6 / 255  # ambient 0.05 lights every sphere pixel
    considered = ~band(expected)
    wrong = (got != expected) & considered
    pct = 100.0 * wrong.sum() / considered.sum()
    reflected = (got & ~band(expected)).sum()
    print(f"{tag}: {wrong.sum()} wrong of {considered.sum()} ({pct:.4f} %), "
          f"{int(expected.sum())} expected sphere/reflection pixels, {int(reflected)} drawn")
    # The camera below the mirror: nothing but the background may show.
    return pct <= 0.05 and (expected.sum() > 0 or got.sum() == 0)


FLOOR = {"origin": [-5, -5, 0], "point1": [5, -5, 0], "point2": [-5, 5, 0]}
WALL = {"origin": [-5, 3, 0], "point1": [5, 3, 0], "point2": [-5, 3, 4]}  # normal -y
# A wall behind the sphere (normal -y, towards the camera); BACK_FAR is its
# fourth corner.
BACK = {"origin": [-5, 2.5, 0], "point1": [5, 2.5, 0], "point2": [-5, 2.5, 4]}
BACK_FAR = [5, 2.5, 4]
CAM = {"position": [0, -8, 4], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1], "view_angle": 30}


def reflection_mae(ref_png, test_png, mask, tag):
    """vtkshadow-metrics --reflection over the mirror pixels `mask`."""
    mask_png = os.path.join(args.out, tag + "-mirror.png")
    write_png(mask_png, mask.astype(np.uint8) * 255, 8)
    out_json = os.path.join(args.out, tag + "-reflection.json")
    subprocess.run([os.path.join(args.bin, "vtkshadow-metrics"), "--reflection",
                    "--reference", ref_png, "--mask", mask_png, "--test", test_png,
                    "--heatmap", os.path.join(args.out, tag + "-heat.png"),
                    "--json", out_json], check=True, timeout=120, stdout=subprocess.DEVNULL)
    with open(out_json) as fh:
        m = json.load(fh)
    if m["compared_pixels"] != int(mask.sum()):
        raise SystemExit(f"{tag}: {m['compared_pixels']} pixels compared, {int(mask.sum())} set")
    return m["reflection_mae"]


# Below the mirror: a slab wholly under it and a box half under it (the
# pov-below and below-lit cases). The mirrored draw clips them away, and so
# must the depth pre-pass of the techniques' screen masks (csm's screen
# resolve, volume, raytrace): otherwise the mirrored slab's depth, on the
# eye's side of the mirror, decides the shadows of every reflected pixel
# (volume and raytrace: below-lit 0 of 727 lit pixels of the sphere's
# reflection lit, csm resolve=1 264; pov-below 0.0436 over the pixels
# reflecting the sphere or the box, 0.0050 over the mirror).
SLAB = ([-4.5, -4.5, -1.5], [4.5, 4.5, -0.3])
HALF = ([1.5, 0.5, -0.6], [2.5, 1.5, 0.7])
BELOW_LIGHT = {"type": "point", "position": [3, -2, 6]}


def below_objects():
    return [{"box": {"min": SLAB[0], "max": SLAB[1]}, "color": [0.2, 0.8, 0.3]},
            {"box": {"min": HALF[0], "max": HALF[1]}, "color": [0.2, 0.5, 0.9]}]


def pov_compare(light, technique, wall=False, below=False, size=(320, 240), extra=()):
    """reflection_mae of VTK (the technique's shadows, matte) against POV-Ray.
    With `wall`, a grey wall stands behind the sphere and takes its shadow,
    which the mirror shows: the shadows of the mirrored world itself, not
    only the sphere's shading."""
    shadows = profile(technique).casts
    R, col = 0.5, [0.9, 0.3, 0.2]
    w, h = size
    scene = {"size": [w, h], "camera": CAM, "lights": [light],
             "objects": [{"sphere": {"center": [0, 0, 1.2], "radius": 0.8, "resolution": 256},
                          "color": col},
                         {"plane": FLOOR, "mirror": R, "receiver": True, "color": [0.7, 0.7, 0.7]}]}
    if wall:
        scene["objects"].append({"plane": BACK, "receiver": True, "color": [0.7, 0.7, 0.7]})
    if below:
        scene["objects"] += below_objects()
    kind = "wall-" if wall else "below-" if below else ""
    tag = "pov-%s%s-%s%s" % (kind, light["type"], technique, "".join(extra).replace("=", ""))
    vtk_png = render(scene, tag, technique, ["--matte"] + list(extra))
    a = w / h
    t = math.tan(math.radians(30) / 2)
    angle = math.degrees(2 * math.atan(a * t))
    v = lambda p: "<%r, %r, %r>" % tuple(p)
    if light["type"] == "directional":
        dd = np.array(light["direction"], float)
        L = "light_source { %s color rgb 1 parallel point_at %s }" % (v(-1e4 * dd), v([0, 0, 0]))
    elif light["type"] == "point":
        L = "light_source { %s color rgb 1 }" % v(light["position"])
    else:
        c = light["cone_angle"]
        L = ("light_source { %s color rgb 1 spotlight point_at %s radius %r falloff %r "
             "tightness 0 }" % (v(light["position"]), v(light["focal_point"]), c, c))
    fin = "ambient 0 diffuse %r specular 0 phong 0 reflection { %r }"
    # A technique without shadows is compared with POV-Ray without them.
    ns = "" if shadows else " no_shadow"
    pov = "\n".join([
        "#version 3.7;", "global_settings { assumed_gamma 1.0 ambient_light 0 max_trace_level 2 }",
        "background { rgb 0 }",
        "camera { perspective location %s sky <0,0,1> up y right -x*%r angle %r look_at %s }"
        % (v(CAM["position"]), a, angle, v(CAM["focal_point"])),
        L,
        "sphere { <0,0,1.2>, 0.8 pigment { rgb %s } finish { ambient 0 diffuse 1 specular 0 "
        "phong 0 }%s }" % (v(col), ns),
        "mesh { triangle { <-5,-5,0>, <5,-5,0>, <5,5,0> } triangle { <-5,-5,0>, <5,5,0>, "
        "<-5,5,0> } pigment { rgb 0.7 } finish { %s }%s }" % (fin % (1 - R, R), ns),
    ] + (["mesh { triangle { %s, %s, %s } triangle { %s, %s, %s } pigment { rgb 0.7 } "
          "finish { ambient 0 diffuse 1 specular 0 phong 0 }%s }"
          % (v(BACK["origin"]), v(BACK["point1"]), v(BACK_FAR), v(BACK["origin"]), v(BACK_FAR),
             v(BACK["point2"]), ns)] if wall else [])
        + (["box { %s, %s pigment { rgb %s } finish { ambient 0 diffuse 1 specular 0 phong 0 }%s }"
            % (v(o["box"]["min"]), v(o["box"]["max"]), v(o["color"]), ns)
            for o in below_objects()] if below else []))
    stem = "pov-%s%s-%dx%d-shadows%d" % (kind, light["type"], w, h, shadows)
    pov_path = os.path.join(args.out, stem + ".pov")
    with open(pov_path, "w") as fh:
        fh.write(pov)
    out_png = stem + "-ref.png"
    subprocess.run([args.povray, "-D", "-P", "-V", "-A", "+FN8", "File_Gamma=1.0",
                    "Display_Gamma=1.0", "+W%d" % w, "+H%d" % h, "+WT2",
                    "+I" + os.path.basename(pov_path), "+O" + out_png],
                   cwd=args.out, check=True, timeout=600, capture_output=True)
    ref = read_rgb(os.path.join(args.out, out_png))
    # The mirror's visible pixels, by ray casting (not from either image).
    e, d = rays(CAM, w, h, 0.0)
    o = np.broadcast_to(e, d.shape)
    tf, _, _ = hit_rect(o, d, *(np.array(FLOOR[k], float) for k in ("origin", "point1", "point2")))
    mask = np.isfinite(tf) & (tf < hit_sphere(o, d, np.array([0, 0, 1.2]), 0.8))
    if wall:
        tw, _, _ = hit_rect(o, d, *(np.array(BACK[k], float) for k in ("origin", "point1", "point2")))
        mask &= tf < tw
    ok = True
    if below:
        mask &= tf < hit_box(o, d, *HALF)
        # Also over the mirror pixels that reflect the sphere or the box
        # (where the shadows of the mirrored world show), not diluted by the
        # mirror's empty pixels.
        p = o + np.where(np.isfinite(tf), tf, 0)[..., None] * d
        rd = d * np.array([1, 1, -1])
        seen = mask & (np.isfinite(hit_sphere(p, rd, np.array([0, 0, 1.2]), 0.8))
                       | np.isfinite(hit_box(p, rd, *HALF)))
        mae_seen = reflection_mae(os.path.join(args.out, out_png), vtk_png, seen, tag + "-seen")
        print(f"{tag}: reflection_mae {mae_seen:.4f} over the {int(seen.sum())} mirror pixels "
              "reflecting the sphere or the box")
        ok = mae_seen <= 0.02 and seen.sum() > 500
    mae = reflection_mae(os.path.join(args.out, out_png), vtk_png, mask, tag)
    refl = ref[mask].max() > 0
    print(f"{tag}: reflection_mae {mae:.4f} over {int(mask.sum())} mirror pixels")
    return ok and mae <= 0.02 and refl and mask.sum() > 1000


def below_lit(technique, extra=()):
    """The lighting of the reflection with objects below the mirror, against
    the test's own ray casting: a black mirror (R 1) under a white sphere, a
    point light, SLAB and HALF below. Each mirror pixel's expected state:
    the reflected ray hits the sphere at a point lit by the light (N.L >=
    0.15, not behind HALF: bright), one it does not light (N.L < 0 or
    behind HALF: dark), or nothing (dark: nothing below the mirror shows
    through). Pixels with 0 <= N.L < 0.15, reflections of HALF and a
    one-pixel band along every boundary are not counted."""
    w, h = 384, 216
    c, rad = np.array([0.0, 0.0, 1.2]), 0.8
    scene = {"size": [w, h], "camera": CAM, "lights": [BELOW_LIGHT],
             "objects": [{"sphere": {"center": list(c), "radius": rad, "resolution": 256},
                          "color": [1, 1, 1]},
                         {"plane": FLOOR, "mirror": 1.0, "receiver": True, "color": [0, 0, 0]}]
             + below_objects()}
    tag = "below-lit-%s%s" % (technique, "".join(extra).replace("=", ""))
    image = read_rgb(render(scene, tag, technique, ["--matte"] + list(extra)))
    e, d = rays(CAM, w, h, 0.0)
    o = np.broadcast_to(e, d.shape)
    tf, _, _ = hit_rect(o, d, *(np.array(FLOOR[k], float) for k in ("origin", "point1", "point2")))
    mirror = np.isfinite(tf) & (tf < hit_sphere(o, d, c, rad)) & (tf < hit_box(o, d, *HALF))
    p = o + np.where(np.isfinite(tf), tf, 0)[..., None] * d
    rd = d * np.array([1, 1, -1])
    ts, tb = hit_sphere(p, rd, c, rad), hit_box(p, rd, *HALF)
    on_sphere = np.isfinite(ts) & (ts < tb)
    q = p + np.where(on_sphere, ts, 0)[..., None] * rd
    to_light = np.array(BELOW_LIGHT["position"], float) - q
    dist = np.linalg.norm(to_light, axis=-1)
    ldir = to_light / dist[..., None]
    ndl = np.sum((q - c) / rad * ldir, axis=-1)
    blocked = hit_box(q, ldir, *HALF) < dist
    # 0 outside the mirror, 1 nothing reflected, 2 lit sphere, 3 dark
    # sphere, 4 not counted (HALF's reflection, the terminator).
    label = np.zeros((h, w), int)
    label[mirror & ~np.isfinite(ts) & ~np.isfinite(tb)] = 1
    label[mirror & on_sphere & (ndl >= 0.15) & ~blocked] = 2
    label[mirror & on_sphere & ((ndl < 0) | blocked)] = 3
    label[mirror & (label == 0)] = 4
    considered = (label >= 1) & (label <= 3)
    for v in range(5):
        considered &= ~band(label == v)
    bright = image.max(axis=2)
    wrong = considered & np.where(label == 2, bright < 0.05, bright > 6 / 255)
    lit = (label == 2) & considered
    pct = 100.0 * wrong.sum() / max(considered.sum(), 1)
    print(f"{tag}: {wrong.sum()} wrong of {considered.sum()} mirror pixels ({pct:.4f} %); "
          f"{int(((bright >= 0.05) & lit).sum())} of {int(lit.sum())} lit reflected-sphere "
          "pixels lit")
    return pct <= 0.05 and lit.sum() > 300 and ((label == 3) & considered).sum() > 300


def harness_mae(name, scene, technique):
    """reflection_mae of `technique` against POV-Ray through the harness
    (vtkshadow-compare: POV-Ray's colour image, shadows on, and mirror
    mask)."""
    folder = os.path.join(args.out, name + "-" + technique)
    os.makedirs(os.path.join(folder, "scenes"), exist_ok=True)
    with open(os.path.join(folder, "scenes", name + ".json"), "w") as fh:
        json.dump(scene, fh)
    subprocess.run([os.path.join(args.bin, "vtkshadow-compare"), os.path.join(folder, "scenes"),
                    "--out", os.path.join(folder, "out"), "--renderers", "vtk,povray",
                    "--techniques", technique, "--povray-binary", args.povray, "--no-report",
                    "--no-cache"], check=True, timeout=900, stdout=subprocess.DEVNULL)
    with open(os.path.join(folder, "out", "results.json")) as fh:
        rows = [r for sc in json.load(fh)["scenes"] for r in sc["results"]]
    maes = [float(r["reflection_mae"]) for r in rows
            if r.get("test") == "vtk/" + technique and r.get("reflection_mae") not in (None, "")]
    if not maes:
        raise SystemExit(f"{name}-{technique}: no reflection_mae in the harness results")
    print(f"{name}-{technique}: reflection_mae {maes[0]:.4f} (harness, against POV-Ray)")
    return maes[0]


SIDE_SCENE_OBJECTS = [
    {"sphere": {"center": [0, 0, 0.9], "radius": 0.6, "resolution": 128}, "color": [0.9, 0.3, 0.2]},
    {"sphere": {"center": [1.4, -2, 0.5], "radius": 0.4, "resolution": 96},
     "color": [0.2, 0.4, 0.9]},
    {"box": {"min": [-2, 1, 0], "max": [-1.2, 1.8, 1.4]}, "color": [0.8, 0.8, 0.3]},
    {"plane": {"origin": [-6, -8, 0], "point1": [3, -8, 0], "point2": [-6, 6, 0]},
     "receiver": True, "color": [0.7, 0.7, 0.7]},
    {"plane": {"origin": [3, -8, 0], "point1": [3, -8, 3], "point2": [3, 6, 0]},
     "receiver": True, "mirror": 0.6, "color": [0.6, 0.6, 0.6]}]


def pov_wall_mirror(technique):
    """A wall mirror (x = 3, facing -x) beside a sphere and a box on a matte
    floor, the sun behind the wall: the wall shadows the floor in front of
    it, and that shadow shows in the mirror. In the mirrored world the
    mirror still casts (it is its own reflection) but is not drawn; counted
    z-pass, which draws no caps, its volume shadow comes out inverted
    (0.161 here). reflection_mae <= 0.02; a technique
    without shadows must show the wall's missing shadow (none: 0.099)."""
    scene = {"size": [256, 144],
             "camera": {"position": [1, -14, 3], "focal_point": [0, 0, 0.6],
                        "view_up": [0, 0, 1], "view_angle": 28},
             "lights": [{"type": "directional", "direction": [-1, 2, -3]}],
             "objects": SIDE_SCENE_OBJECTS}
    mae = harness_mae("wall-mirror", scene, technique)
    return mae <= 0.02 if profile(technique).casts else mae > 0.02


def pov_two_mirrors(technique):
    """Two mirrors, the floor (R 0.5) seen at a grazing angle and the wall,
    under a sun and a point light whose N.L on the floor sum to more than
    1 / its colour. A mirror is drawn at (1 - R) of its shading with R x
    the reflection added, clamped once (it was the clamped shading mixed:
    too dark), and a mirror seen in another one shows (1 - R) of its
    shading, the bounce not drawn left out as POV-Ray's max_trace_level 2
    does (it was drawn plain: too bright). Before: planar 0.0339 (volume
    0.0518 before its z-pass fix); now 0.0015-0.0023. <= 0.01; a
    technique without shadows must exceed it (none: 0.0226)."""
    scene = {"size": [264, 120],
             "camera": {"position": [1, -14, 0.45], "focal_point": [0, 0, 0.6],
                        "view_up": [0, 0, 1], "view_angle": 28},
             "lights": [{"type": "directional", "direction": [-1, 2, -3]},
                        {"type": "point", "position": [-2, -4, 4]}],
             "objects": [dict(o) for o in SIDE_SCENE_OBJECTS]}
    scene["objects"][3]["mirror"] = 0.5
    mae = harness_mae("two-mirrors", scene, technique)
    return mae <= 0.01 if profile(technique).casts else mae > 0.01


def self_consistency(light, technique):
    """The reflection against the technique's own render of the mirrored
    world, so that a technique whose shadows differ from POV-Ray's (vtk)
    is still checked for composing with the mirror: scene A, a red sphere
    and a blue box over a black R = 1 mirror floor (the box lifted by 0.05: a face lying in the mirror's
    plane is half clipped), under `light`; scene B,
    no mirror, the sphere, the box and the light reflected through the
    floor's plane (z -> -z) and seen from the same camera, plus four tiny
    non-casting spheres at the floor's corners so that the scene's bounds,
    from which VTK's own pass fits its light cameras, are A's. Over A's
    mirror pixels (ray cast here) the two images must agree: mean absolute
    difference <= 0.002 and <= 0.1 % of the pixels off by more than 0.1."""
    w, h = 320, 240
    flip = lambda p: [p[0], p[1], -p[2]]
    objects_a = [{"sphere": {"center": [0, 0, 1.2], "radius": 0.8, "resolution": 256},
                  "color": [0.9, 0.3, 0.2]},
                 {"box": {"min": [1.5, 0.5, 0.05], "max": [2.5, 1.5, 1]},
                  "color": [0.2, 0.5, 0.9]}]
    objects_b = [{"sphere": {"center": [0, 0, -1.2], "radius": 0.8, "resolution": 256},
                  "color": [0.9, 0.3, 0.2]},
                 {"box": {"min": [1.5, 0.5, -1], "max": [2.5, 1.5, -0.05]},
                  "color": [0.2, 0.5, 0.9]}]
    objects_b += [{"sphere": {"center": [x, y, 0], "radius": 1e-3, "resolution": 8},
                   "casts": False, "color": [0, 0, 0]} for x in (-5, 5) for y in (-5, 5)]
    mirrored = dict(light)
    for key in ("direction", "position", "focal_point"):
        if key in light:
            mirrored[key] = flip(light[key])
    scene_a = {"size": [w, h], "camera": CAM, "lights": [light],
               "objects": objects_a + [{"plane": FLOOR, "mirror": 1.0, "receiver": True,
                                        "color": [0, 0, 0]}]}
    scene_b = {"size": [w, h], "camera": CAM, "lights": [mirrored], "objects": objects_b}
    tag = "self-%s-%s" % (light["type"], technique)
    a = read_rgb(render(scene_a, tag + "-mirror", technique, ["--matte"]))
    b = read_rgb(render(scene_b, tag + "-mirrored-world", technique, ["--matte"]))
    e, d = rays(CAM, w, h, 0.0)
    o = np.broadcast_to(e, d.shape)
    tf, _, _ = hit_rect(o, d, *(np.array(FLOOR[k], float) for k in ("origin", "point1", "point2")))
    mask = (np.isfinite(tf) & (tf < hit_sphere(o, d, np.array([0, 0, 1.2]), 0.8))
            & (tf < hit_box(o, d, [1.5, 0.5, 0.05], [2.5, 1.5, 1])))
    diff = np.abs(a - b).max(axis=2)[mask]
    mae = float(np.abs(a - b).mean(axis=2)[mask].mean())
    off = 100.0 * float((diff > 0.1).mean())
    lit = int((b.max(axis=2)[mask] > 0.05).sum())
    print(f"{tag}: reflection against the mirrored world's render: mean {mae:.5f}, "
          f"{off:.4f} % of {int(mask.sum())} mirror pixels off by > 0.1 ({lit} lit)")
    return mae <= 0.002 and off <= 0.1 and lit > 300


cases = {
    "basic": lambda t: geometric("geo-basic", CAM, (320, 240), [FLOOR], t),
    "grazing": lambda t: geometric("geo-grazing", {"position": [0, -30, 0.9], "focal_point": [0, 0, 0.9],
                                                    "view_up": [0, 0, 1], "view_angle": 20},
                                   (400, 200), [FLOOR], t),
    "wide": lambda t: geometric("geo-wide", CAM, (480, 160), [FLOOR], t),
    "offset-1e6": lambda t: geometric("geo-offset", CAM, (320, 240), [FLOOR], t, offset=1e6),
    "below": lambda t: geometric("geo-below", {"position": [0, -8, -3], "focal_point": [0, 0, 0.5],
                                                "view_up": [0, 0, 1], "view_angle": 30},
                                 (320, 240), [FLOOR], t),
    "two-mirrors": lambda t: geometric("geo-two", CAM, (320, 240), [FLOOR, WALL], t),
    "pov-directional": lambda t: pov_compare({"type": "directional", "direction": [-3, -2, -6]}, t),
    "pov-point": lambda t: pov_compare({"type": "point", "position": [3, -2, 6]}, t),
    "pov-spot": lambda t: pov_compare({"type": "spot", "position": [3, -2, 6],
                                       "focal_point": [0, 0, 0], "cone_angle": 40}, t),
    # The sphere's shadow falls on the wall at about x 1.7, z 0.4: seen in
    # the mirror beside the sphere's reflection.
    "pov-wall-directional": lambda t: pov_compare({"type": "directional",
                                                   "direction": [1.2, 2, -0.3]}, t, wall=True),
    "pov-wall-point": lambda t: pov_compare({"type": "point", "position": [-2, -3, 2]}, t,
                                            wall=True),
    # Objects below the mirror at 16:9; csm also with its screen resolve
    # (resolve=1), which reads the screen mask.
    "below-lit": lambda t: below_lit(t) and (t != "csm" or below_lit(t, ["--set", "resolve=1"])),
    "pov-wall-mirror": pov_wall_mirror,
    # The reflection against the technique's own render of the mirrored
    # world (what "mirrors work with every technique" can rely on for vtk).
    "self-directional": lambda t: self_consistency({"type": "directional",
                                                    "direction": [0.5, 2, -1]}, t),
    "self-point": lambda t: self_consistency({"type": "point", "position": [3, -2, 6]}, t),
    "self-spot": lambda t: self_consistency({"type": "spot", "position": [3, -2, 6],
                                             "focal_point": [0, 0, 0], "cone_angle": 40}, t),
    "pov-two-mirrors": pov_two_mirrors,
    "pov-below": lambda t: (pov_compare(BELOW_LIGHT, t, below=True, size=(384, 216)) and
                            (t != "csm" or pov_compare(BELOW_LIGHT, t, below=True, size=(384, 216),
                                                       extra=["--set", "resolve=1"]))),
}
# Known failures: (technique, case) -> why. Such a case must still fail
# (printed "xfail"); once it passes, this test fails until the entry goes.
KNOWN = {
    (t, c): "not the reflection: VTK 9.1's own shadow-map pass darkens and cuts off the far "
            "end of the floor in the main image (the same without a mirror: 0.34 against planar "
            "over that band), which is mirror pixels here (0.17 over the far part of the directional case), and "
            "skips point lights (no shadow at all in the point cases); the reflection itself "
            "differs by <= 0.0005 (the reflected sphere's lit rim, lost in the mirrored world's "
            "shadow map); see docs/reflections.md"
    # (vtk, pov-point) is not listed: since the reflection is added to the
    # mirror's (1 - R) shading instead of mixed in 8 bits, vtk's missing
    # point-light shadow alone scores 0.0197 there, under the 0.02 limit.
    for t in ("vtk",) for c in ("pov-directional", "pov-spot", "pov-wall-directional",
                                "pov-wall-point", "pov-wall-mirror", "pov-two-mirrors")
}
failed = []
for t in techniques():
    ok = cases[args.case](t)
    why = KNOWN.get((t, args.case))
    if why and ok:
        failed.append(t + " (known failure now passes: remove it from KNOWN)")
    elif why:
        print(f"xfail {t}: {why}")
    elif not ok:
        failed.append(t)
print(("FAIL %s (%s)" % (args.case, ", ".join(failed))) if failed else "PASS " + args.case)
sys.exit(1 if failed else 0)
