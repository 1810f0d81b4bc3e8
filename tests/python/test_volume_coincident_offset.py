"""Shadow volumes on a mesh drawn with VTK's coincident-topology offset.

vedo turns vtkMapper's ResolveCoincidentTopology to PolygonOffset for every
mesh (factor 0.1, units 0.1): the mappers push each surface's depth back by
factor x its slope + units x 1.6e-5. An open caster's volume is drawn with
caps (z-pass with the caps of the faces seen from their unlit side,
unlit_caps, the default; z-fail with every cap otherwise), and the caps lie
on the surface itself; without the same offset they win the depth test against
their own pushed-back face and that face is shadowed whole (vedo's
interpolateScalar3: 1.3 % of the frame off raytrace's, the RandomHills
alone 5.4 %).

The scene is the one of that example: vtkParametricRandomHills, the camera
above it with its clipping range fitted, a directional light; visibility
(float renders, tests/render/float_render.py) of volume against raytrace:
at most MAX_PCT % of the valid pixels may disagree (|v_a - v_b| > 0.5), and
volume must have drawn caps (its stats), and the hills must
fill half the view. vedo's light (its key light: elevation 50, azimuth 10
from the camera) casts hardly any shadow here: the defect is false
shadows, 100 % of the pixels before the caps took the offset.

With --edges, the hills are a plain VTK program's instead: no global
offset, but the actor drawn with its edges (EdgeVisibilityOn, as vedo's
linewidth() also does). VTK 9.1 then draws the surface a second time for
its edges, with the line offset (factor 0, units -4: pulled towards the
camera by 4 x 1.6e-5) over every triangle, and the caps must take that too:
with the polygon offset alone (0 here) 1.9 % of a bowl's pixels and whole
facets of vedo's buildmesh were off raytrace's.

With --edges --tetra, the mesh is that of vedo's basic/buildmesh.py (three
faces of a tetrahedron, open), drawn with its edges at line width 2, seen
steeply from above under a directional light. VTK 9.1 draws a surface with
edges through a geometry shader that moves each vertex a line width's half
outwards on the screen but keeps its depth: the drawn depth is a tilted
plane, off the true one by up to half the line width times the depth's
slope per pixel. The caps must take that too: with the line offset alone,
43.2 % of the tetrahedron's pixels were shadowed by its own caps.

Usage: test_volume_coincident_offset.py [--edges [--tetra]] [KEY=VALUE]...  (volume's settings)"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))

import vtkshadow  # noqa: E402
import float_render as fr  # noqa: E402
from vtkmodules.vtkCommonComputationalGeometry import vtkParametricRandomHills  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkParametricFunctionSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkMapper, vtkPolyDataMapper  # noqa: E402

W, H = 400, 300
MAX_PCT = 0.2
FLAGS = ("--edges", "--tetra")
EDGES, TETRA = (flag in sys.argv[1:] for flag in FLAGS)
SETTINGS = {k: float(v) for k, v in (kv.split("=", 1) for kv in sys.argv[1:] if kv not in FLAGS)}
# basic/buildmesh.py's mesh: its vertices and faces.
TETRA_POINTS = [(50, 50, 50), (70, 40, 50), (50, 40, 80), (80, 70, 50)]
TETRA_FACES = [(0, 1, 2), (2, 1, 3), (1, 0, 3)]


def tetra():
    points = vtkPoints()
    for p in TETRA_POINTS:
        points.InsertNextPoint(*p)
    faces = vtkCellArray()
    for f in TETRA_FACES:
        faces.InsertNextCell(3, f)
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(faces)
    return mesh


def build(renderer):
    mapper = vtkPolyDataMapper()
    if TETRA:
        mapper.SetInputData(tetra())
    else:
        hills = vtkParametricFunctionSource()
        hills.SetParametricFunction(vtkParametricRandomHills())
        mapper.SetInputConnection(hills.GetOutputPort())
    mapper.ScalarVisibilityOff()
    if not EDGES:
        # vedo's Mesh does this (both are global to every mapper).
        mapper.SetResolveCoincidentTopologyToPolygonOffset()
        mapper.SetResolveCoincidentTopologyPolygonOffsetParameters(0.1, 0.1)
    actor = fr.lambertian(vtkActor())
    if EDGES:
        actor.GetProperty().EdgeVisibilityOn()
        actor.GetProperty().SetLineWidth(2.0 if TETRA else 1.0)
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    if TETRA:
        renderer.AddLight(fr.scene_light((80.88, 30.16, 153.18), focal_point=(62, 50, 57)))
        camera.SetPosition(81.23, -48.18, 123.27)
        camera.SetFocalPoint(62, 50, 57)
        camera.SetViewUp(0, 0, 1)
        renderer.ResetCamera()
    else:
        renderer.AddLight(fr.scene_light((0.558, 5.02, 3.545), focal_point=(0.0, 1.19, 0.38)))
        camera.SetPosition(0.0, 1.19, 7.04)
        camera.SetFocalPoint(0.0, 1.19, 0.38)
        camera.SetViewUp(0, 1, 0)
        camera.SetViewAngle(30)
    renderer.ResetCameraClippingRange()


def render(technique, options=None):
    """(float image, the pass's stats) under `technique` ("off": none)."""
    inner = None
    if technique != "off":
        t = vtkshadow.vtkShadowTechnique()
        t.SetName(technique)
        for key, value in (options or {}).items():
            t.SetOption(key, value)
        inner = t.CreatePass()
    image, stats = fr.render_technique(
        build, inner, W, H, inspect=lambda r, p: p.GetStatsJSON(r) if inner else "")
    vtkMapper.SetResolveCoincidentTopologyToDefault()
    return image, stats


off, _ = render("off")
ray, _ = render("raytrace")
vol, stats = render("volume", SETTINGS)
v_ray, v_vol = fr.visibility(ray, off), fr.visibility(vol, off)
valid = int(v_ray[1].sum())
least = W * H // 20 if TETRA else W * H // 2
what = "the tetrahedron's faces fill a twentieth" if TETRA else "the hills fill half"
check(valid > least, f"{what} of the view ({valid} of {W * H} px valid)")
caps = sum(light.get("cap_triangles", 0) for light in json.loads("{" + stats + "}")["lights"])
check(caps >= 1, f"volume drew the caster's caps ({caps} cap triangles)")
pct, n, _ = fr.compare_visibility(*v_vol, *v_ray)
check(100.0 - pct <= MAX_PCT,
      f"volume against raytrace: {100.0 - pct:.3f} % of {n} px differ (at most {MAX_PCT} %)")
finish()
