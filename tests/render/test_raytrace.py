"""Render test: ray-traced shadows (--technique raytrace) against the exact
answer computed here by ray casting the analytic scene (exact_scene.py, every
caster on every surface: --reference all).

The cases are test_planar.py's (sphere over a floor for each light type at
4:3 and 16:9, a tilted plane under a rotated box, grazing lights, a 1e5-wide
floor, a 1e6 offset, a 1e-6 scale, two lights, a 200x floor, a thin plate on
the floor, ...) and the ones below, which shadow maps find hard:

  needles-{directional,point,spot}  a field of 0.02-thick boxes (needles)
                                    standing and leaning over a floor, their
                                    shadows 1-3 pixels wide
  thin-plate-point                  the thin plate under a point light
  offset-1e6-{point,spot}           sphere-floor moved by 1e6 on every axis
  scale-1e-6-{point,spot}           sphere-floor scaled by 1e-6 about the origin
  sphere-floor-{point,spot}-16x9    the other light types at 16:9
  thin-plate-long-floor             the thin plate on a floor 2e5 long in two
                                    tiles (the far one out of view): a float
                                    frame at the scene's centre puts the plate
                                    at 1e5, whose shadow-ray offset (0.05)
                                    exceeds its thickness (0.01)
  casters-behind-camera             every caster behind the camera (VTK's
                                    frustum culler drops them from the
                                    render state), a directional (--light 0)
                                    and a point light (--light 1) behind
                                    them throw their shadows into the view

and a caching check (--case caching): still frames trace nothing, moving an
actor re-commits the top level without rebuilding any mesh, changing one
actor's data rebuilds that mesh only, a camera move traces again with no
mesh work.

  test_raytrace.py --bin BUILD/bin --out DIR --case CASE [--light K]
      [--max-wrong-pct 0.05] [--max-wrong-of-shadow-pct P]
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_planar as tp  # noqa: E402
from test_planar import S43, S169, floor, moved, sphere, sphere_floor  # noqa: E402

LIGHTS = {
    "directional": {"type": "directional", "direction": [-1, 0.7, -2.2]},
    "point": {"type": "point", "position": [2.5, -1.5, 4.5]},
    "spot": {"type": "spot", "position": [2.5, -1.5, 4.5], "focal_point": [0, 0.5, 0],
             "cone_angle": 40},
}


def needle(base, height, lean_deg, azimuth_deg, width=0.02):
    """A width x width x height box standing at `base`, leaning `lean_deg`
    from vertical towards `azimuth_deg` (via the scene's "transform")."""
    box = {"box": {"min": [-width / 2, -width / 2, 0.0], "max": [width / 2, width / 2, height]}}
    lean, az = math.radians(lean_deg), math.radians(azimuth_deg)
    ca, sa, cl, sl = math.cos(az), math.sin(az), math.cos(lean), math.sin(lean)
    rz = np.array([[ca, -sa, 0], [sa, ca, 0], [0, 0, 1]])
    ry = np.array([[cl, 0, sl], [0, 1, 0], [-sl, 0, cl]])
    m = np.eye(4)
    m[:3, :3] = rz @ ry @ rz.T
    m[:3, 3] = base
    box["transform"] = [float(v) for v in m.reshape(-1)]
    box["name"] = "needle"
    return box


def needles(light, size):
    rng = np.random.default_rng(13)
    objects = []
    for k in range(14):
        x, y = rng.uniform(-2.2, 2.2), rng.uniform(-1.5, 2.0)
        objects.append(needle([x, y, 0.0], rng.uniform(0.8, 1.8), rng.uniform(0, 35),
                              rng.uniform(0, 360)))
    objects.append(floor(5))
    return {"description": f"raytrace test: 14 needles 0.02 thick over a floor, {light} light",
            "size": list(size),
            "camera": {"position": [0, -7, 4.5], "focal_point": [0, 0.3, 0.5],
                       "view_up": [0, 0, 1], "view_angle": 35},
            "lights": [LIGHTS[light]], "objects": objects}


def thin_plate_point(size):
    s = tp.thin_plate(size)
    s["lights"] = [{"type": "point", "position": [-2, 1.5, 2.5]}]
    s["description"] += " (point light)"
    return s


def thin_plate_long_floor(size):
    s = tp.thin_plate(size)
    s["objects"] = [o for o in s["objects"] if o.get("name") != "floor"]
    # Two tiles: one mesh 2e5 long would itself be stored with 0.008 float
    # steps (its offset rule then exceeds the plate: docs/raytraced-shadows.md).
    s["objects"].append(floor(5))
    s["objects"].append(dict(floor(5, y0=5, y1=2e5), name="far floor"))
    s["description"] += " (the floor 2e5 long)"
    return s


def casters_behind_camera(size):
    """Two spheres and a box behind the camera (outside the view frustum, so
    VTK's culler leaves them out of the render state's props) and a floor in
    front; the lights shine past the camera, so every shadow in view comes
    from a caster the frame does not draw."""
    return {"description": "raytrace test: casters behind the camera, shadows in view",
            "size": list(size),
            "camera": {"position": [0, -4, 2], "focal_point": [0, 2, 0],
                       "view_up": [0, 0, 1], "view_angle": 40},
            "lights": [{"type": "directional", "direction": [0.15, 1, -0.25]},
                       {"type": "point", "position": [0, -9, 3]}],
            "objects": [sphere([0, -6, 1.5], 0.6), sphere([-1.6, -5.5, 1.2], 0.4),
                        {"box": {"min": [1.0, -6.6, 0.6], "max": [1.6, -6.0, 2.0]},
                         "name": "box"},
                        floor(12)]}


EXTRA = {
    "needles-directional": (lambda: needles("directional", S43), 600),
    "needles-point": (lambda: needles("point", S43), 1500),
    "needles-spot": (lambda: needles("spot", S169), 1000),
    "thin-plate-point": (lambda: thin_plate_point(S43), 500),
    "offset-1e6-point": (lambda: moved(sphere_floor("point", S43), offset=1e6), 2000),
    "offset-1e6-spot": (lambda: moved(sphere_floor("spot", S169), offset=1e6), 1500),
    "scale-1e-6-point": (lambda: moved(sphere_floor("point", S43), scale=1e-6), 2000),
    "scale-1e-6-spot": (lambda: moved(sphere_floor("spot", S169), scale=1e-6), 1500),
    "sphere-floor-point-16x9": (lambda: sphere_floor("point", S169), 1500),
    "sphere-floor-spot-16x9": (lambda: sphere_floor("spot", S169), 1500),
    "casters-behind-camera": (lambda: casters_behind_camera(S43), 3000),
    "thin-plate-long-floor": (lambda: thin_plate_long_floor(S43), 500),
}
CASES = dict(tp.CASES, **EXTRA)


def caching(out):
    """Counters of the pass over frames: what a still frame, an actor move,
    a data change and a camera move cost."""
    import vtkshadow
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow
    from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderer
    import json
    scene = sphere_floor("directional", (320, 240))
    scene["objects"].append(sphere([1.5, 0.5, 0.6], 0.4))
    os.makedirs(out, exist_ok=True)
    path = os.path.join(out, "caching.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    sc = vtkshadow.vtkShadowScene()
    if not sc.Load(path):
        sys.exit(sc.GetErrorMessage())
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(320, 240)
    renderer = vtkOpenGLRenderer()
    window.AddRenderer(renderer)
    sc.Populate(renderer)
    # One more caster whose data we change: a sphere source.
    src = vtkSphereSource()
    src.SetCenter(-1.5, 0.5, 0.6)
    src.SetRadius(0.4)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(src.GetOutputPort())
    extra = vtkActor()
    extra.SetMapper(mapper)
    renderer.AddActor(extra)
    p = vtkshadow.vtkRayTracedShadowPass()
    renderer.SetPass(p)
    failures = []

    def frame(label):
        window.Render()
        st = (p.GetNumberOfRaysTraced(), p.GetNumberOfMeshBuilds(), p.GetNumberOfTopLevelCommits())
        print(f"{label}: rays {st[0]}  mesh builds {st[1]}  top-level commits {st[2]}")
        return st

    def expect(ok, what):
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            failures.append(what)

    rays0, builds0, commits0 = frame("first")
    meshes = renderer.GetActors().GetNumberOfItems()
    # The classifier decides most pixels without rays; some are traced.
    expect(rays0 > 1000 and builds0 == meshes and commits0 == 1,
           f"first frame traces and builds each of the {meshes} meshes once")
    for k in range(3):
        rays, builds, commits = frame(f"still {k}")
        expect(rays == 0 and builds == builds0 and commits == commits0,
               "a still frame traces nothing and builds nothing")
    extra.SetPosition(0.3, -0.2, 0.0)
    rays, builds, commits = frame("actor moved")
    expect(rays > 0 and builds == builds0 and commits == commits0 + 1,
           "moving an actor traces, re-commits the top level once, rebuilds no mesh")
    rays, builds2, commits2 = frame("still after the move")
    expect(rays == 0 and builds2 == builds0, "still again after the move")
    src.SetRadius(0.5)
    rays, builds, commits = frame("data changed")
    expect(rays > 0 and builds == builds0 + 1 and commits == commits2 + 1,
           "changing one actor's data rebuilds that mesh only")
    renderer.GetActiveCamera().Azimuth(5)
    rays, builds3, commits3 = frame("camera moved")
    expect(rays > 0 and builds3 == builds and commits3 == commits,
           "a camera move traces again with no mesh or top-level work")
    rays, _, _ = frame("still after the camera move")
    expect(rays == 0, "still after the camera move")
    stats = p.GetStatsJSON(renderer)
    json.loads("{" + stats + "}")
    expect('"still_frame": true' in stats, "--stats says the frame was still: " + stats[:80])
    window.Finalize()
    return failures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--case", required=True, choices=sorted(CASES) + ["caching"])
    ap.add_argument("--light", type=int, default=0)
    ap.add_argument("--max-wrong-pct", type=float, default=0.05)
    ap.add_argument("--max-wrong-of-shadow-pct", type=float)
    ap.add_argument("--min-mask-agreement", type=float, default=99.9)
    ap.add_argument("--known-failure", metavar="REASON")
    args = ap.parse_args()
    if args.case == "caching":
        failures = caching(args.out)
        sys.exit(1 if failures else 0)
    builder, fact = CASES[args.case]
    failed, _, _ = tp.run_case(args.bin, args.out, args.case, builder(), args.light, "raytrace",
                               "all", args.max_wrong_pct, args.min_mask_agreement, fact,
                               args.max_wrong_of_shadow_pct, args.known_failure)
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
