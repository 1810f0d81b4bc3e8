"""Render test: stencil shadow volumes (--technique volume) against the exact
answer computed here by ray casting (exact_scene.py, shadow model "all":
every caster shadows every surface, a mesh also itself).

Each case builds a scene, runs vtkshadow-render through test_planar.run_case
(the same comparison: vtkshadow-metrics --band 1 outside a one-pixel band along
every object / face / mask edge), and passes when wrong_pct <= 0.05 and
wrong_of_shadow_pct <= 1.0 (or the bounds given), the exact answer has the
shadow the case is built for, and the case's own facts hold (--stats: which
counting the pass used where that is the point of the case).

Cases (640x480 unless named):
  sphere-on-box-{directional,point,spot}-{4x3,16x9}
                      a sphere over a box on a floor: its shadow falls on the
                      box's top and the floor (640x480 and 640x360)
  box-on-sphere       a rotated box over a sphere: the shadow on a curved
                      receiver
  concave-u           a closed U-shaped solid (OBJ) whose left arm shadows the
                      slot's floor and the right arm's inner wall: shadowing
                      itself
  camera-in-shadow    the camera under a wide slab, in its shadow: z-fail
                      (the stats must show it)
  near-plane-cut      the eye just outside the slab's shadow with the near
                      plane reaching into it (checked here from the exact
                      geometry and VTK's clipping range): z-fail
  caster-behind-camera
                      a sphere behind the camera (culled from VTK's render
                      state) shadows the floor in view
  offset-1e6, scale-1e-6
                      sphere-on-box-directional-4x3 moved by 1e6 / scaled by
                      1e-6 (camera and light too)
  open-quad           a single tilted quad (an open caster) over a floor and a
                      sphere
  open-cylinder       an 8-sided tube without caps (OBJ); the light shines into
                      one end
  non-manifold        three fins sharing one edge (OBJ): every edge count
                      matters
  force-zfail         sphere-on-box-point with every volume counted by z-fail
                      (caps on the casters' own faces: the depth bias at work)
  bias-off            force-zfail with the depth bias off (depth_bias=0,
                      slope_bias=0): printed, not bounded, by hand only (not a
                      ctest test): what the bias changes. On llvmpipe 9
                      pixels differ from force-zfail, all in the band.

  test_volume.py --bin BUILD/bin --out DIR --case CASE [--light K]
      [--max-wrong-pct 0.05] [--max-wrong-of-shadow-pct 1.0]
"""
import argparse
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from exact_scene import trace_scene  # noqa: E402
from test_planar import (SPHERE_FLOOR_LIGHTS, floor, moved, rot, row_major, run_case,  # noqa: E402
                         sphere, translate, vtk_clipping_range)

S43, S169 = (640, 480), (640, 360)
CAMERA = {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
          "view_angle": 30}


def box(lo, hi, **extra):
    o = {"box": {"min": list(lo), "max": list(hi)}}
    o.update(extra)
    return o


def sphere_on_box(light, size):
    return {
        "description": f"volume test: a sphere over a box on a floor, {light} light",
        "size": list(size), "camera": dict(CAMERA),
        "lights": [SPHERE_FLOOR_LIGHTS[light]],
        "objects": [sphere([0.2, 0.1, 1.6], 0.5), box([-1, -1, 0], [1, 1, 0.8], name="box"),
                    floor(5)],
    }


def box_on_sphere(size):
    return {
        "description": "volume test: a rotated box over a sphere",
        "size": list(size), "camera": dict(CAMERA),
        "lights": [{"type": "directional", "direction": [-1, -0.5, -4]}],
        "objects": [
            box([-0.5, -0.4, -0.15], [0.5, 0.4, 0.15], name="box",
                transform=row_major(translate(0.1, 0, 2.3) @ rot("z", 25) @ rot("x", 15))),
            sphere([0, 0, 0.8], 0.8), floor(5)],
    }


def write_obj(path, verts, faces):
    with open(path, "w") as f:
        for v in verts:
            f.write("v %.17g %.17g %.17g\n" % tuple(v))
        for t in faces:
            f.write("f %d %d %d\n" % tuple(i + 1 for i in t))


def u_solid():
    """A closed U: the (x, z) cross-section extruded along y, outward faces."""
    sec = [(0, 0), (3, 0), (3, 2), (2, 2), (2, 0.6), (1, 0.6), (1, 2), (0, 2)]
    tris = [(0, 1, 4), (1, 2, 3), (1, 3, 4), (0, 4, 5), (0, 5, 6), (0, 6, 7)]
    n = len(sec)
    verts = [(x, -1.0, z) for x, z in sec] + [(x, 1.0, z) for x, z in sec]
    # Counter-clockwise in (x, z) faces -y: the y = -1 cap as is, y = +1 reversed.
    faces = [t for t in tris] + [(c + n, b + n, a + n) for a, b, c in tris]
    for i in range(n):
        j = (i + 1) % n
        faces += [(i, i + n, j + n), (i, j + n, j)]
    return np.asarray(verts, float), faces


def concave_u(size, out):
    verts, faces = u_solid()
    verts = verts * 0.6 + np.array([-0.9, 0.0, 0.0])
    path = os.path.abspath(os.path.join(out, "concave-u.obj"))
    write_obj(path, verts, faces)
    return {
        "description": "volume test: a closed U-shaped solid shadowing its own slot",
        "size": list(size),
        "camera": {"position": [1.5, -5, 5], "focal_point": [0, 0, 0.4], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [1.0, 0.3, -0.8]}],
        "objects": [{"mesh": path, "name": "U"}, floor(4)],
    }


def slab_scene(size, eye, focal):
    return {
        "description": "volume test: a wide slab overhead, the camera near or in its shadow",
        "size": list(size),
        "camera": {"position": list(eye), "focal_point": list(focal), "view_up": [0, 0, 1],
                   "view_angle": 40},
        "lights": [{"type": "directional", "direction": [-0.3, 0.2, -1]}],
        "objects": [box([-3, -3, 3], [3, 1, 3.2], name="slab"), sphere([0.5, 3, 0.6], 0.6),
                    floor(6)],
    }


def camera_in_shadow(size):
    return slab_scene(size, [0, -1.5, 1.2], [0, 3, 0])


def near_plane_eye():
    """An eye 0.3 outside the slab's shadow (the boundary plane through the
    slab's top edge y = 1, z = 3.2 along the light), looking down into it:
    VTK puts the near plane about 1.3 away here, well inside the shadow."""
    d = np.array([-0.3, 0.2, -1.0])
    edge_point = np.array([0.0, 1.0, 3.2])
    normal = np.cross(d, [1.0, 0.0, 0.0])  # the plane holds the edge (x) and d
    normal /= np.linalg.norm(normal)
    if normal[1] < 0:
        normal = -normal  # points out of the shadow (towards +y)
    # Down the boundary plane from the edge by 2 units, then just outside.
    eye = edge_point + 2.0 * d / np.linalg.norm(d) + 0.3 * normal
    return eye, eye + np.array([0.0, -2.0, -1.2])


def near_plane_cut(size):
    eye, focal = near_plane_eye()
    return slab_scene(size, eye, focal)


def caster_behind_camera(size):
    """A sphere behind the camera (outside the view, so VTK's frustum culler
    drops it from the render state) throws its shadow into the view."""
    return {
        "description": "volume test: a caster behind the camera shadowing the view",
        "size": list(size),
        "camera": {"position": [0, -4, 2], "focal_point": [0, 2, 0], "view_up": [0, 0, 1],
                   "view_angle": 40},
        "lights": [{"type": "directional", "direction": [0, 1, -0.8]}],
        "objects": [sphere([0, -5, 2.5], 0.6), sphere([1.0, 1.0, 0.5], 0.5), floor(6)],
    }


def open_quad(size):
    return {
        "description": "volume test: a single tilted quad (open) over a floor and a sphere",
        "size": list(size), "camera": dict(CAMERA),
        "lights": [{"type": "point", "position": [2, 1.5, 6]}],
        "objects": [
            {"plane": {"origin": [-0.8, -0.6, 1.6], "point1": [0.7, -0.6, 1.9],
                       "point2": [-0.8, 0.6, 1.6]}, "name": "quad"},
            sphere([-0.6, -0.4, 0.4], 0.4), floor(5)],
    }


def tube_mesh(sides=8, radius=0.5, length=2.0):
    verts, faces = [], []
    for i in range(sides):
        a = 2 * math.pi * (i + 0.5) / sides
        verts += [(radius * math.cos(a), radius * math.sin(a), -length / 2),
                  (radius * math.cos(a), radius * math.sin(a), length / 2)]
    for i in range(sides):
        j = (i + 1) % sides
        faces += [(2 * i, 2 * j, 2 * j + 1), (2 * i, 2 * j + 1, 2 * i + 1)]
    return np.asarray(verts, float), faces


def open_cylinder(size, out):
    verts, faces = tube_mesh()
    m = translate(0, 0, 1.3) @ rot("y", 70) @ rot("x", 10)
    verts = verts @ m[:3, :3].T + m[:3, 3]
    path = os.path.abspath(os.path.join(out, "open-cylinder.obj"))
    write_obj(path, verts, faces)
    return {
        "description": "volume test: an open 8-sided tube, the light shining into one end",
        "size": list(size), "camera": dict(CAMERA),
        "lights": [{"type": "point", "position": [5, 1, 3.5]}],
        "objects": [{"mesh": path, "name": "tube"}, floor(5)],
    }


def non_manifold(size, out):
    verts = [(0, 0, 0.8), (0, 0, 1.8)]
    faces = []
    for k in range(3):
        a = 2 * math.pi * k / 3 + 0.3
        c = (0.8 * math.cos(a), 0.8 * math.sin(a))
        verts += [(c[0], c[1], 1.8), (c[0], c[1], 0.8)]
        faces += [(0, 2 + 2 * k + 1, 2 + 2 * k), (0, 2 + 2 * k, 1)]
    path = os.path.abspath(os.path.join(out, "fins.obj"))
    write_obj(path, verts, faces)
    return {
        "description": "volume test: three fins sharing one edge (non-manifold)",
        "size": list(size), "camera": dict(CAMERA),
        "lights": [{"type": "directional", "direction": [-1, -0.6, -1.5]}],
        "objects": [{"mesh": path, "name": "fins"}, floor(5)],
    }


# case -> (builder(out), shadow pixels the exact answer must have, vtkshadow-render
# --set options, checks of --stats)
def zfail_used(stats):
    light = stats["technique_stats"]["lights"][0] if "technique_stats" in stats else None
    return light is not None and light["zfail"] > 0


CASES = {
    "box-on-sphere": (lambda out: box_on_sphere(S43), 1500, [], None),
    "concave-u": (lambda out: concave_u(S43, out), 1500, [], None),
    "camera-in-shadow": (lambda out: camera_in_shadow(S43), 3000, [], zfail_used),
    "near-plane-cut": (lambda out: near_plane_cut(S43), 3000, [], zfail_used),
    "offset-1e6": (lambda out: moved(sphere_on_box("directional", S43), offset=1e6), 2000, [],
                   None),
    "scale-1e-6": (lambda out: moved(sphere_on_box("directional", S43), scale=1e-6), 2000, [],
                   None),
    "open-quad": (lambda out: open_quad(S43), 1500, [], None),
    "caster-behind-camera": (lambda out: caster_behind_camera(S43), 1500, [], None),
    "open-cylinder": (lambda out: open_cylinder(S43, out), 1500, [], None),
    "non-manifold": (lambda out: non_manifold(S43, out), 1500, [], None),
    "force-zfail": (lambda out: sphere_on_box("point", S43), 2000,
                    ["--set", "force_zfail=1"], zfail_used),
    "bias-off": (lambda out: sphere_on_box("point", S43), 2000,
                 ["--set", "force_zfail=1", "--set", "depth_bias=0", "--set", "slope_bias=0"],
                 None),
}
for _light in ("directional", "point", "spot"):
    for _tag, _size in (("4x3", S43), ("16x9", S169)):
        CASES[f"sphere-on-box-{_light}-{_tag}"] = (
            lambda out, l=_light, s=_size: sphere_on_box(l, s), 1500, [], None)


def near_plane_facts(scene, out):
    """The eye is outside the exact shadow and the near plane's centre inside."""
    path = os.path.join(out, "near-plane-cut.json")
    near, far, _ = vtk_clipping_range(path)
    eye = np.asarray(scene["camera"]["position"], float)
    view = np.asarray(scene["camera"]["focal_point"], float) - eye
    centre = eye + near * view / np.linalg.norm(view)
    d = -np.asarray(scene["lights"][0]["direction"], float)

    def in_shadow(p):  # the ray towards the light meets the slab's box
        lo, hi = np.array([-3, -3, 3.0]), np.array([3, 1, 3.2])
        with np.errstate(divide="ignore"):
            t0, t1 = (lo - p) / d, (hi - p) / d
        tmin = np.max(np.minimum(t0, t1))
        tmax = np.min(np.maximum(t0, t1))
        return tmax >= max(tmin, 0.0)
    print(f"near-plane-cut: near {near:.4g}, eye in shadow {in_shadow(eye)}, "
          f"near-plane centre in shadow {in_shadow(centre)}")
    return not in_shadow(eye) and in_shadow(centre)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--light", type=int, default=0)
    ap.add_argument("--max-wrong-pct", type=float, default=0.05)
    ap.add_argument("--max-wrong-of-shadow-pct", type=float, default=1.0)
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    builder, fact, options, check = CASES[args.case]
    scene = builder(args.out)
    stats_path = os.path.join(args.out, f"{args.case}-stats.json")
    bounded = args.case != "bias-off"
    failed, _, metrics = run_case(
        args.bin, args.out, args.case, scene, args.light, "volume", "all",
        args.max_wrong_pct if bounded else 100.0, 99.9, fact,
        args.max_wrong_of_shadow_pct if bounded else 100.0,
        render_args=options + ["--stats", stats_path])
    with open(stats_path) as f:
        stats = json.load(f)
    print("stats:", json.dumps(stats.get("technique_stats", stats))[:400])
    if check is not None and not check(stats):
        print("FAIL: the stats do not show z-fail counting for this case")
        failed = True
    if args.case == "near-plane-cut" and not near_plane_facts(scene, args.out):
        print("FAIL: the scene does not put the near plane across the shadow boundary")
        failed = True
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
