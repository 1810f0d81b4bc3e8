"""raytrace's shadows of points drawn as spheres and lines drawn as tubes
(issue 32, first part; docs/raytraced-shadows.md, "Points as spheres, lines
as tubes"). VTK draws them as screen-space impostors of a fixed width in
pixels; raytrace casts Embree spheres and round curves whose radius is half
that width at the point's depth (vsh_rt_impostor_radius):

    radius = size * d * tan(view angle / 2) / viewport height

(d: distance along the view direction). Each case against a control of
world-sized meshes with that radius, computed here from the camera
independently of the library:

(a) 20 points, RenderPointsAsSpheres, point size 18, against sphere meshes
    (vtkSphereSource, 32 x 32) of the radius at each point;
(b) a polyline of 48 points, RenderLinesAsTubes, line width 16, against a
    vtkTubeFilter (24 sides) whose radius follows the same rule point by
    point (VaryRadiusByAbsoluteScalar);
(a') (a) with a parallel camera (scale 3.5): radius = size * scale / height.

An opaque floor, a directional light straight down, an oblique camera,
400x300. The shadow area: floor pixels with visibility I_on / I_off < 0.5
(float renders, float_render.py) that neither scene's casters cover (a
pixel is covered where the unshadowed render differs from the floor
alone). Passes when the impostors' area is 0.6-1.6x the control's (the
issue's acceptance); the none technique shows no shadow at all, nor do
the casters marked NO_CAST; the pass's stats count 20 spheres and 47
segments. Measured:
points 1882 px against 1867 (1.008), tubes 2993 against 2875 (1.041),
parallel points 2085 against 2066 (1.009); before raytrace cast
impostors, 0 px in every case.

(c) The radii follow the camera: the points zoomed to a 20 degree view
    angle after a first frame cast exactly the shadow of a fresh window at
    20 degrees (raytrace 1912 px both; with the first frame's radii kept,
    4963); so do the points given size 26 after the first frame (the
    property) and the actor moved (its matrix).

Every other technique casts closed triangle proxies instead (issue 32,
second part; vtkShadowImpostorProxies): an icosphere per point and a
12-sided truncated cone per segment with an icosphere per vertex, at the
same radius. The technique is the first argument (default raytrace); the
control is rendered with the same technique, so its own errors cancel. The
stats count raytrace's impostors, and the others' proxy triangles (80 per
sphere, 44 per segment). Measured (points, tube,
parallel points; zoomed px):
csm 1872/1861 (1.006), 2978/2869 (1.038), 2089/2066 (1.011); 1865;
auto 1857/1846 (1.006), 2975/2880 (1.033), 2080/2064 (1.008); 1869;
volume 1874/1866 (1.004), 2977/2874 (1.036), 2088/2068 (1.010); 1873;
planar 1873/1867 (1.003), 2976/2873 (1.036), 2086/2067 (1.009); 1873;
before the proxies, 0 px for each of them in every case.

Usage: test_impostor_casters.py [raytrace|csm|auto|volume|planar]"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkTubeFilter  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

W, H = 400, 300
EYE, FOCAL, VIEW_ANGLE = (7.0, -7.0, 6.0), (0.0, 0.0, 0.6), 30.0
POINT_SIZE, LINE_WIDTH = 18.0, 16.0
RATIO = (0.6, 1.6)
PARALLEL_SCALE = 3.5
TECHNIQUE = sys.argv[1] if len(sys.argv) > 1 else "raytrace"


def view_distance(p):
    """p's distance from the eye along the view direction."""
    direction = np.subtract(FOCAL, EYE)
    direction /= np.linalg.norm(direction)
    return float(np.dot(np.subtract(p, EYE), direction))


def impostor_radius(p, pixels, parallel_scale=None):
    """Half the pixel width at p's depth, in world units (the rule): with a
    parallel camera the same everywhere."""
    if parallel_scale:
        return pixels * parallel_scale / H
    return pixels * view_distance(p) * math.tan(math.radians(VIEW_ANGLE) / 2) / H


def cloud():
    rng = np.random.default_rng(32)
    xy = rng.uniform(-2.6, 2.6, (20, 2))
    z = rng.uniform(0.9, 2.0, (20, 1))
    return np.hstack([xy, z])


def polyline():
    t = np.linspace(0.0, 1.0, 48)
    x = -2.8 + 5.6 * t
    y = 1.4 * np.sin(2 * math.pi * t)
    z = 1.3 + 0.4 * np.cos(3 * math.pi * t)
    return np.stack([x, y, z], axis=1)


def poly_data(points, cell):
    """Points as verts (cell 'verts') or one polyline (cell 'line')."""
    pts = vtkPoints()
    for p in points:
        pts.InsertNextPoint(*p)
    cells = vtkCellArray()
    if cell == "verts":
        for i in range(len(points)):
            cells.InsertNextCell(1)
            cells.InsertCellPoint(i)
    else:
        cells.InsertNextCell(len(points))
        for i in range(len(points)):
            cells.InsertCellPoint(i)
    data = vtkPolyData()
    data.SetPoints(pts)
    if cell == "verts":
        data.SetVerts(cells)
    else:
        data.SetLines(cells)
    return data


def sphere_meshes(points, parallel_scale=None):
    return sphere_meshes_of([(p, impostor_radius(p, POINT_SIZE, parallel_scale))
                             for p in points])


def sphere_meshes_of(spheres):
    """Sphere meshes (vtkSphereSource, 32 x 32) of (centre, radius) pairs."""
    append = vtkAppendPolyData()
    for p, radius in spheres:
        s = vtkSphereSource()
        s.SetCenter(*p)
        s.SetRadius(radius)
        s.SetThetaResolution(32)
        s.SetPhiResolution(32)
        s.Update()
        append.AddInputData(s.GetOutput())
    append.Update()
    return append.GetOutput()


def tube_mesh(points):
    data = poly_data(points, "line")
    radii = vtkDoubleArray()
    for p in points:
        radii.InsertNextValue(impostor_radius(p, LINE_WIDTH))
    data.GetPointData().SetScalars(radii)
    tube = vtkTubeFilter()
    tube.SetInputData(data)
    tube.SetNumberOfSides(24)
    tube.SetVaryRadiusToVaryRadiusByAbsoluteScalar()
    tube.Update()
    return tube.GetOutput()


def add(renderer, data):
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    mapper.ScalarVisibilityOff()
    actor = fr.lambertian(vtkActor())
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    return actor


def floor():
    p = vtkPlaneSource()
    p.SetOrigin(-6, -6, 0)
    p.SetPoint1(6, -6, 0)
    p.SetPoint2(-6, 6, 0)
    p.Update()
    return p.GetOutput()


def scene(caster=None, view_angle=VIEW_ANGLE, parallel_scale=None):
    """build(renderer): the floor, the light, the camera (with `view_angle`,
    or parallel with `parallel_scale`) and `caster` (renderer -> None) if
    any."""
    def build(renderer):
        add(renderer, floor())
        if caster:
            caster(renderer)
        renderer.AddLight(fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0)))
        camera = fr.set_camera(renderer, EYE, FOCAL, view_angle=view_angle,
                               clipping=(1.0, 40.0))
        if parallel_scale:
            camera.ParallelProjectionOn()
            camera.SetParallelScale(parallel_scale)
    return build


def spheres_as_points(renderer):
    actor = add(renderer, poly_data(cloud(), "verts"))
    actor.GetProperty().SetRenderPointsAsSpheres(True)
    actor.GetProperty().SetPointSize(POINT_SIZE)
    return actor


def lines_as_tubes(renderer):
    actor = add(renderer, poly_data(polyline(), "line"))
    actor.GetProperty().SetRenderLinesAsTubes(True)
    actor.GetProperty().SetLineWidth(LINE_WIDTH)
    return actor


def no_cast(caster):
    """`caster` marked NO_CAST."""
    return lambda renderer: fr.set_key(caster(renderer),
                                       vtkshadow.vtkRayTracedShadowPass.NO_CAST())


def render(build, technique):
    """The float image of `build` with technique (None: no shadow pass)."""
    return fr.render_technique(build, technique, W, H)[0]


def changed(build, technique, change):
    """The float image of `build` rendered with technique, then again after
    change(renderer) in the same window (the second frame's)."""
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    build(renderer)
    capture = fr.FloatCapture(renderer, vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique))
    window.Render()
    change(renderer)
    window.Render()
    image = capture.read()
    capture.release()
    window.Finalize()
    return image


def caster_actor(renderer):
    """The scene's caster: the actor added after the floor."""
    actors = renderer.GetActors()
    actors.InitTraversal()
    actors.GetNextActor()
    return actors.GetNextActor()


def covered(off, floor_alone):
    """Pixels a caster covers: the unshadowed render differs from the floor."""
    return np.abs(off - floor_alone) > 1e-3 * max(1e-6, float(floor_alone.max()))


def shadow_area(build, technique, mask_out, off, stats=None):
    """Shadowed floor pixels outside `mask_out`; the pass's stats go into
    `stats` (a dict) if given."""
    on, read = fr.render_technique(
        build, technique, W, H,
        lambda renderer, inner: json.loads("{" + inner.GetStatsJSON(renderer) + "}"))
    if stats is not None:
        stats.update(read)
    v, valid = fr.visibility(on, off)
    return int((valid & (v < 0.5) & ~mask_out).sum())


SPHERE_TRIANGLES, TUBE_TRIANGLES = 80, 44  # vsh_impostor_proxy.h


def proxy_triangles(spheres, segments):
    """The proxies' triangles: an icosphere per sphere, a cone per segment."""
    return spheres * SPHERE_TRIANGLES + segments * TUBE_TRIANGLES


def compare(name, impostors, control_data, count, parallel_scale=None, triangles=0):
    """Case `name`: the impostors against their control, none and NO_CAST."""
    floor_alone = render(scene(parallel_scale=parallel_scale), None)
    control = scene(lambda renderer: add(renderer, control_data()),
                    parallel_scale=parallel_scale)
    tested = scene(impostors, parallel_scale=parallel_scale)
    off_tested, off_control = render(tested, None), render(control, None)
    mask = covered(off_tested, floor_alone) | covered(off_control, floor_alone)
    stats = {}
    area = shadow_area(tested, TECHNIQUE, mask, off_tested, stats)
    reference = shadow_area(control, TECHNIQUE, mask, off_control)
    none = shadow_area(tested, "none", mask, off_tested)
    unmarked = shadow_area(scene(no_cast(impostors), parallel_scale=parallel_scale),
                           TECHNIQUE, mask, off_tested)
    # What the technique shows with no caster but the floor: volume's open
    # floor marks 2 px of its own far edge with the parallel camera.
    own = shadow_area(scene(parallel_scale=parallel_scale), TECHNIQUE, mask, floor_alone)
    ratio = area / reference if reference else float("nan")
    print(f"{name}: {TECHNIQUE} shadow area {area} px, control (meshes) {reference} px, "
          f"ratio {ratio:.3f}; none {none} px; NO_CAST {unmarked} px; floor alone {own} px; "
          f"casters cover {int(mask.sum())} px")
    check(reference > 500, f"{name}: the control casts a shadow ({reference} px > 500)")
    check(RATIO[0] <= ratio <= RATIO[1],
          f"{name}: impostor shadow area / control's = {ratio:.3f} in {RATIO}")
    check(none == 0, f"{name}: the none technique shows no shadow ({none} px)")
    check(unmarked <= own,
          f"{name}: marked NO_CAST, they cast nothing ({unmarked} px, the floor alone {own})")
    # auto traces them where it picks raytrace (its raytrace pass's stats).
    traced = stats if TECHNIQUE == "raytrace" else stats.get("raytrace", {})
    if TECHNIQUE == "raytrace" or "raytrace" in stats.get("light_choices", []):
        check(traced.get("impostors") == count,
              f"{name}: {TECHNIQUE} traces {traced.get('impostors')} spheres / segments ({count})")
    else:
        held = stats.get("impostor_proxies", {}).get("triangles")
        check(held == triangles, f"{name}: {TECHNIQUE} holds {held} proxy triangles ({triangles})")


ZOOM = 20.0


def follows(name, fresh_build, change):
    """Case `name`: the spheres after change(renderer) following a first
    frame cast exactly the shadow of a fresh window built by fresh_build."""
    off = render(fresh_build, None)
    mask = covered(off, render(scene(view_angle=ZOOM), None))
    fresh = shadow_area(fresh_build, TECHNIQUE, mask, off)
    v, valid = fr.visibility(changed(scene(spheres_as_points), TECHNIQUE, change), off)
    after = int((valid & (v < 0.5) & ~mask).sum())
    print(f"points as spheres, {name}: shadow area {after} px after the change, "
          f"{fresh} px in a fresh window")
    check(fresh > 500 and after == fresh,
          f"{name}: the spheres cast the fresh window's shadow ({after} == {fresh} px)")


def sized(size, position=(0.0, 0.0, 0.0)):
    """spheres_as_points with point size `size`, the actor at `position`."""
    def build(renderer):
        actor = spheres_as_points(renderer)
        actor.GetProperty().SetPointSize(size)
        actor.SetPosition(*position)
    return build


def main():
    compare("points as spheres (size 18)", spheres_as_points, lambda: sphere_meshes(cloud()),
            len(cloud()), triangles=proxy_triangles(len(cloud()), 0))
    compare("lines as tubes (width 16)", lines_as_tubes, lambda: tube_mesh(polyline()),
            len(polyline()) - 1, triangles=proxy_triangles(len(polyline()), len(polyline()) - 1))
    compare(f"points as spheres, parallel (scale {PARALLEL_SCALE})", spheres_as_points,
            lambda: sphere_meshes(cloud(), PARALLEL_SCALE), len(cloud()), PARALLEL_SCALE,
            proxy_triangles(len(cloud()), 0))
    # The radii follow the camera: zoomed in after a first frame (the eye stays,
    # so the top levels' origin does too), the spheres' shadow is the one a
    # fresh window with the new view angle traces (the first frame's radii are
    # tan(15) / tan(10) = 1.52 times as large). Likewise a new point size (the
    # property) and a moved actor (its matrix) after the first frame.
    follows(f"zoomed to a {ZOOM} degree view angle", scene(spheres_as_points, ZOOM),
            lambda renderer: renderer.GetActiveCamera().SetViewAngle(ZOOM))
    follows("point size 18 -> 26", scene(sized(26.0), ZOOM),
            lambda renderer: (renderer.GetActiveCamera().SetViewAngle(ZOOM),
                              caster_actor(renderer).GetProperty().SetPointSize(26.0)))
    follows("moved by (0.4, -0.3, 0.2)", scene(sized(POINT_SIZE, (0.4, -0.3, 0.2)), ZOOM),
            lambda renderer: (renderer.GetActiveCamera().SetViewAngle(ZOOM),
                              caster_actor(renderer).SetPosition(0.4, -0.3, 0.2)))
    finish()


if __name__ == "__main__":
    main()
