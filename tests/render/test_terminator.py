"""Render test: the terminator of a smooth-shaded closed mesh.

Case "sphere": a coarse closed sphere (a UV sphere of 10 x 6 facets, OBJ with
one radial normal per vertex) over a floor, lit from the side so that its
terminator faces the camera. Case "grazing-facet": a closed 48-sided prism
(radial normals on the side, flat caps with their own vertices at the same
positions, as the scene format's cylinders are made) in the place, camera
and light 0 of cad/table-parts' tall cylinder (the camera zoomed in), where one side facet faces
away from the light by 5.4e-4 (0.03 degrees): that whole facet is dark on
the triangles though the interpolated normals light half of it. VTK lights a facet by its interpolated normals, so facets
that face away from the light by up to half a facet angle are still lit in
the unshadowed image; on the triangles themselves those points are dark: a
ray from them towards the light enters the solid. The exact answer here is
ray cast against the same triangles (exact_scene.py, model "all"): such
pixels get visibility 0. They are compared where VTK's own mask (its
unshadowed intensity, from the smooth normals) says the light reaches,
outside a one-pixel band along every triangle edge, object edge, mask edge
and shadow boundary.

    test_terminator.py --bin BUILD/bin --out DIR --technique volume|raytrace
        [--case sphere|grazing-facet] [--set KEY=VALUE]... [--expect-fail]

Passes when wrong_pct <= 0.05 and at least MIN_TERMINATOR_PX compared pixels
lie on facets facing away from the light (so the case cannot pass without
testing them). --expect-fail inverts the bound (used with volume's
facing_test=0: the volumes alone leave the strip lit, which the test must
see).
"""
import argparse
import math
import os
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_scene import edge_band, trace_scene  # noqa: E402
from png_io import read_png  # noqa: E402

MAX_WRONG_PCT = 0.05
MIN_TERMINATOR_PX = 200
MIN_GRAZING_PX = 20
PRISM_SIDES = 48
GRAZING_FACET = 31


def uv_sphere(center, radius, around=10, rings=6):
    """Vertices, per-vertex unit normals and outward triangles of a closed
    UV sphere (poles shared, so every edge has two faces)."""
    verts = [(0.0, 0.0, 1.0)]
    for r in range(1, rings):
        polar = math.pi * r / rings
        for a in range(around):
            az = 2 * math.pi * a / around
            verts.append((math.sin(polar) * math.cos(az), math.sin(polar) * math.sin(az),
                          math.cos(polar)))
    verts.append((0.0, 0.0, -1.0))
    bottom = len(verts) - 1

    def ring(r, a):
        return 1 + (r - 1) * around + a % around
    faces = []
    for a in range(around):
        faces.append((0, ring(1, a), ring(1, a + 1)))
        faces.append((bottom, ring(rings - 1, a + 1), ring(rings - 1, a)))
    for r in range(1, rings - 1):
        for a in range(around):
            p, q = ring(r, a), ring(r, a + 1)
            s, t = ring(r + 1, a), ring(r + 1, a + 1)
            faces += [(p, s, t), (p, t, q)]
    unit = np.asarray(verts, float)
    return unit * radius + np.asarray(center, float), unit, faces


def write_obj(path, verts, normals, faces):
    with open(path, "w") as f:
        for v in verts:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for n in normals:
            f.write("vn %.17g %.17g %.17g\n" % tuple(n))
        for t in faces:
            f.write("f %s\n" % " ".join("%d//%d" % (i + 1, i + 1) for i in t))


def prism(center, radius, height, sides=PRISM_SIDES):
    """Vertices, normals and outward triangles of a closed vertical prism:
    side vertices with radial normals, cap vertices (same positions) with
    axial ones, as vsh_tessellate makes a cylinder."""
    verts, normals, faces = [], [], []
    c = np.asarray(center, float)
    for z, nz in ((0.0, -1.0), (height, 1.0)):
        for j in range(sides):
            a = 2 * math.pi * j / sides
            verts.append(c + (radius * math.cos(a), radius * math.sin(a), z))
            normals.append((math.cos(a), math.sin(a), 0.0))
    for z, nz in ((0.0, -1.0), (height, 1.0)):
        for j in range(sides):
            verts.append(verts[j + (sides if z else 0)])
            normals.append((0.0, 0.0, nz))
    for j in range(sides):
        k = (j + 1) % sides
        faces += [(j, k, sides + k), (j, sides + k, sides + j)]
    bottom, top = 2 * sides, 3 * sides
    for j in range(1, sides - 1):
        faces.append((bottom, bottom + j + 1, bottom + j))
        faces.append((top, top + j, top + j + 1))
    return verts, normals, faces


def grazing_scene_of(obj_path):
    """The tall cylinder of cad/table-parts alone, seen from that scene's
    camera position (zoomed in on it) under its light 0: its facet GRAZING_FACET faces away from the light by
    5.4e-4 (the light direction's horizontal part is at -33.69 degrees, the
    facet's normal at 236.25)."""
    return {
        "description": "terminator test: a light grazing one facet of a closed prism",
        "size": [320, 240],
        "camera": {"position": [2, -8, 6], "focal_point": [0, 0, 1], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [-1.5, 1, -3]}],
        "objects": [
            {"mesh": obj_path, "name": "48-sided prism"},
            {"plane": {"origin": [-3, -2, 1], "point1": [3, -2, 1], "point2": [-3, 2, 1]},
             "receiver": True},
            {"plane": {"origin": [-6, -6, 0], "point1": [6, -6, 0], "point2": [-6, 6, 0]},
             "receiver": True},
        ],
    }


def scene_of(obj_path):
    return {
        "description": "terminator test: a coarse smooth-shaded closed sphere lit from the side",
        "size": [640, 480],
        "camera": {"position": [0, -6, 2.5], "focal_point": [0, 0, 1.1], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "point", "position": [6, 1.5, 2.2]}],
        "objects": [
            {"mesh": obj_path, "name": "coarse sphere"},
            {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0], "point2": [-5, 5, 0]},
             "receiver": True},
        ],
    }


def render(args, scene_path, name):
    vis, mask = (os.path.join(args.out, f"{name}-{k}.png") for k in ("visibility", "mask"))
    cmd = [os.path.join(args.bin, "vtkshadow-render"), scene_path, "--technique", args.technique,
           "--image", os.path.join(args.out, name + "-image.png"), "--visibility", vis,
           "--mask", mask, "--quiet"] + [a for kv in args.set for a in ("--set", kv)]
    run = subprocess.run(cmd, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"{name}: vtkshadow-render failed ({run.returncode}): {run.stderr}")
    return read_png(vis) / 65535.0, read_png(mask) > 127


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--technique", required=True)
    ap.add_argument("--case", choices=("sphere", "grazing-facet"), default="sphere")
    ap.add_argument("--set", action="append", default=[])
    ap.add_argument("--expect-fail", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    name = "-".join(["terminator", args.case, args.technique] +
                    [kv.replace("=", "") for kv in args.set])
    if args.case == "sphere":
        verts, normals, faces = uv_sphere([0, 0, 1.2], 1.0)
    else:
        verts, normals, faces = prism([1.8, -0.8, 1.0], 0.3, 1.2)
    obj_path = os.path.abspath(os.path.join(args.out, args.case + ".obj"))
    write_obj(obj_path, verts, normals, faces)
    scene = (scene_of if args.case == "sphere" else grazing_scene_of)(obj_path)
    scene_path = os.path.join(args.out, name + ".json")
    import json
    with open(scene_path, "w") as f:
        json.dump(scene, f, indent=1)

    vis, vtk_mask = render(args, scene_path, name)
    width, height = scene["size"]
    exact = trace_scene(scene, 0, width, height, "all")
    hit = exact["object"] >= 0
    if args.case == "sphere":
        exclude = (edge_band(exact["object"] * 100000 + exact["face"]) |
                   edge_band(exact["valid"].astype(int)) | edge_band(vtk_mask.astype(int)) |
                   edge_band((exact["visibility"] > 0.5).astype(int)))
    else:
        # The grazing facet is a pixel and a half wide at the scene's own
        # size, its lit half (by the smooth normals) under one: only the
        # objects' outlines are left out.
        exclude = edge_band(exact["object"])
    compared = vtk_mask & hit & ~exclude
    # Facets facing away from the light that VTK's smooth normals light:
    # the exact answer is dark there (not "valid" for the flat facet).
    terminator = compared & ~exact["valid"] & (exact["object"] == 0)
    wrong = compared & (np.abs(vis - exact["visibility"]) > 0.5)
    wrong_pct = 100.0 * wrong.sum() / max(compared.sum(), 1)
    wrong_terminator = int((wrong & terminator).sum())
    print(f"{name}: wrong_pct {wrong_pct:.4f} ({int(wrong.sum())} of {int(compared.sum())} px), "
          f"terminator px compared {int(terminator.sum())}, wrong there {wrong_terminator}")
    failed = False
    min_terminator = MIN_TERMINATOR_PX if args.case == "sphere" else MIN_GRAZING_PX
    if terminator.sum() < min_terminator:
        print(f"FAIL: only {int(terminator.sum())} terminator pixels compared "
              f"(the case needs >= {min_terminator})")
        failed = True
    if args.expect_fail:
        if wrong_pct <= MAX_WRONG_PCT:
            print(f"FAIL: expected more than {MAX_WRONG_PCT}% wrong with {args.set}")
            failed = True
    elif wrong_pct > MAX_WRONG_PCT:
        print(f"FAIL: wrong_pct {wrong_pct:.4f} > {MAX_WRONG_PCT}")
        failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
