"""Writes the scenes of scenes/primitives/ (what VTK draws without a surface
mesh: points as spheres, lines as tubes, a volume-rendered blob;
docs/scene-format.md). Deterministic: run it again and the files are the
same. Usage: python3 make_primitives.py"""
import json
import math
import os
import random

HERE = os.path.dirname(os.path.abspath(__file__))
FLOOR = {"plane": {"origin": [-4, -4, 0.0], "point1": [4, -4, 0.0], "point2": [-4, 4, 0.0]},
         "receiver": True, "color": [0.9, 0.9, 0.9]}


def r6(v):
    return [round(x, 6) for x in v]


def write(name, scene):
    with open(os.path.join(HERE, name + ".json"), "w") as f:
        f.write("{\n")
        keys = list(scene)
        for i, k in enumerate(keys):
            end = ",\n" if i + 1 < len(keys) else "\n"
            if k in ("lights", "objects"):
                f.write('  "%s": [\n' % k)
                for j, e in enumerate(scene[k]):
                    f.write("    " + json.dumps(e) + (",\n" if j + 1 < len(scene[k]) else "\n"))
                f.write("  ]" + end)
            else:
                f.write('  "%s": %s%s' % (k, json.dumps(scene[k]), end))
        f.write("}\n")


def molecule():
    """Ball and stick: atoms drawn as spheres (two point sizes), bonds as tubes."""
    heavy = [[0, 0, 1.4], [0.9, 0.3, 1.5], [-0.8, 0.5, 1.3], [0.1, -0.9, 1.6], [0.2, 0.2, 2.3]]
    light = [[1.6, -0.2, 1.2], [1.2, 1.0, 2.0], [-1.5, 0.1, 1.0], [-1.0, 1.3, 1.8],
             [0.8, -1.5, 1.4], [-0.4, -1.4, 2.2], [0.6, 0.6, 3.0], [-0.5, -0.1, 2.9]]
    bonds = [(0, 1), (0, 2), (0, 3), (0, 4)]
    hbonds = [(1, 0), (1, 1), (2, 2), (2, 3), (3, 4), (3, 5), (4, 6), (4, 7)]
    objects = [
        {"points": {"positions": heavy, "point_size": 64}, "color": [0.8, 0.3, 0.3]},
        {"points": {"positions": light, "point_size": 40}, "color": [0.9, 0.9, 0.9]},
    ]
    for a, b in bonds:
        objects.append({"polyline": {"points": [heavy[a], heavy[b]], "line_width": 16},
                        "color": [0.6, 0.6, 0.6]})
    for a, b in hbonds:
        objects.append({"polyline": {"points": [heavy[a], light[b]], "line_width": 12},
                        "color": [0.6, 0.6, 0.6]})
    objects.append(FLOOR)
    return {
        "description": "A ball-and-stick molecule: atoms drawn as spheres (RenderPointsAsSpheres), "
                       "bonds as tubes (RenderLinesAsTubes), over a floor; sun and point light",
        "size": [800, 600],
        "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 1.3], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [-1, 0.6, -3]},
                   {"type": "point", "position": [2.5, -1.5, 5]}],
        "objects": objects,
    }


def streamlines():
    """Streamlines of a swirling flow drawn as tubes."""
    objects = []
    for k in range(5):
        phase = 2 * math.pi * k / 5
        pts = []
        for i in range(48):
            t = i / 47.0
            radius = 0.5 + 1.1 * t
            a = phase + 3.2 * t
            pts.append(r6([radius * math.cos(a), radius * math.sin(a), 0.6 + 2.2 * t]))
        objects.append({"polyline": {"points": pts, "line_width": 14},
                        "color": [0.2 + 0.15 * k, 0.5, 0.9 - 0.15 * k]})
    objects.append(FLOOR)
    return {
        "description": "Five streamlines of a swirl drawn as tubes (RenderLinesAsTubes, 14 px at "
                       "800x600) over a floor; sun and spot light",
        "size": [800, 600],
        "camera": {"position": [0, -8, 5.5], "focal_point": [0, 0, 1.4], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [1, 0.5, -3]},
                   {"type": "spot", "position": [-2, -2, 6], "focal_point": [0, 0, 0],
                    "cone_angle": 40}],
        "objects": objects,
    }


def particles():
    """A particle cloud: 240 points drawn as small spheres."""
    rng = random.Random(32)
    pts = []
    while len(pts) < 240:
        p = [rng.uniform(-1, 1) for _ in range(3)]
        if sum(x * x for x in p) <= 1:
            pts.append(r6([1.3 * p[0], 1.3 * p[1], 1.9 + 0.9 * p[2]]))
    return {
        "description": "A particle cloud: 240 points drawn as spheres (RenderPointsAsSpheres, "
                       "12 px at 800x600) over a floor; sun",
        "size": [800, 600],
        "camera": {"position": [0, -8, 5], "focal_point": [0, 0, 1.2], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [-0.8, 0.4, -3]}],
        "objects": [{"points": {"positions": pts, "point_size": 12},
                     "color": [0.9, 0.6, 0.2]}, FLOOR],
    }


def blob():
    """A volume-rendered blob beside a mesh, both over a floor."""
    return {
        "description": "A volume-rendered blob (extinction 2.5 at its centre, falling to 0 at "
                       "radius 1.1) beside an opaque box, over a floor; sun and point light",
        "size": [800, 600],
        "camera": {"position": [0, -8, 4.5], "focal_point": [0, 0, 1.0], "view_up": [0, 0, 1],
                   "view_angle": 30},
        "lights": [{"type": "directional", "direction": [-1, 1.2, -3]},
                   {"type": "point", "position": [-2.5, -0.5, 4.5]}],
        "objects": [
            {"volume": {"center": [-0.6, 0.4, 1.6], "radius": 1.1, "density": 2.5},
             "color": [0.4, 0.7, 1.0]},
            {"box": {"min": [1.0, -0.4, 0.0], "max": [1.8, 0.4, 1.4]}, "color": [0.8, 0.5, 0.3]},
            FLOOR,
        ],
    }


if __name__ == "__main__":
    write("molecule-spheres", molecule())
    write("streamlines-tubes", streamlines())
    write("particle-cloud", particles())
    write("volume-blob", blob())
