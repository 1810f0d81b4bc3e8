"""raytrace lands a pixel of a ball-and-stick joint on the solid the camera
sees (docs/raytraced-shadows.md, "Points as spheres, lines as tubes").

A bond drawn as a tube (RenderLinesAsTubes) ends at its atom's centre, so
its first part lies inside the atom's sphere (RenderPointsAsSpheres).
VTK's impostor depth is only near the sphere's surface: a refinement ray
that starts inside the sphere meets the tube inside it first, and a pixel
landed there is in the sphere's own shadow. The right surface is the
front-most solid near the depth point.

The scene: an atom (point size 90) at the origin, a bond (width 24) from
its centre straight up; a directional light
straight down the bond; an oblique camera from above; 400x300; no floor.
Geometrically nothing shadows the big atom's upper half: the bond is
vertical and thinner than the atom, so the only points below it are
inside the bond. Checked: among the big atom's pixels that face the light
(the unshadowed render at least 0.3 of its brightest) and that no bond pixel
touches (the bond rendered alone, dilated
by 2 pixels), none has visibility below 0.5 (I_on / I_off, float
renders): 0 of 2366. Landing on the hit instance's own solid only (the
tube inside the sphere), 154 were dark. A control: with the light tilted
35 degrees the bond does shadow the atom's upper half, and raytrace shows
it (61 dark pixels; at least 25 required).

Usage: test_impostor_joints.py"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import float_render as fr  # noqa: E402
from test_impostor_casters import poly_data  # noqa: E402
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

W, H = 400, 300
EYE, FOCAL = (3.2, -4.0, 3.6), (0.0, 0.0, 0.5)
ATOM_SIZE, BOND_WIDTH = 90.0, 24.0
TOP = (0.0, 0.0, 1.6)


def add(renderer, data, points_size=None, line_width=None, flat=False):
    """An actor of `data`, Lambertian, or with `flat` the same brightness
    wherever it is drawn (ambient only: its coverage)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(data)
    mapper.ScalarVisibilityOff()
    actor = fr.lambertian(vtkActor())
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    if flat:
        prop.SetAmbient(1.0)
        prop.SetDiffuse(0.0)
    if points_size:
        prop.SetRenderPointsAsSpheres(True)
        prop.SetPointSize(points_size)
    if line_width:
        prop.SetRenderLinesAsTubes(True)
        prop.SetLineWidth(line_width)
    renderer.AddActor(actor)


def scene(atom=True, bond=True, light_from=(0.0, 0.0, 10.0), flat=False):
    def build(renderer):
        if atom:
            add(renderer, poly_data([(0.0, 0.0, 0.0)], "verts"), points_size=ATOM_SIZE, flat=flat)
        if bond:
            add(renderer, poly_data([(0.0, 0.0, 0.0), TOP], "line"), line_width=BOND_WIDTH,
                flat=flat)
        renderer.AddLight(fr.scene_light(light_from, (0.0, 0.0, 0.0)))
        fr.set_camera(renderer, EYE, FOCAL, clipping=(1.0, 30.0))
    return build


def render(build, technique):
    return fr.render_technique(build, technique, W, H)[0]


def dilate(mask, k):
    out = mask.copy()
    for dy in range(-k, k + 1):
        for dx in range(-k, k + 1):
            out |= np.roll(np.roll(mask, dy, axis=0), dx, axis=1)
    return out


def dark_atom_pixels(light_from):
    """The atom's light-facing pixels clear of the bond, and how many of
    them raytrace shows below half visibility."""
    off = render(scene(light_from=light_from), None)
    on = render(scene(light_from=light_from), "raytrace")
    atom_alone = render(scene(bond=False, light_from=light_from), None)
    bond_alone = render(scene(atom=False, light_from=light_from, flat=True), None)
    bond_pixels = dilate(bond_alone > 0.5 * float(bond_alone.max()), 2)
    facing = atom_alone >= 0.3 * float(atom_alone.max())
    region = facing & ~bond_pixels
    v, valid = fr.visibility(on, off)
    return int(region.sum()), int((region & valid & (v < 0.5)).sum())


region, dark = dark_atom_pixels((0.0, 0.0, 10.0))
print(f"light down the bond: {region} atom pixels facing the light, {dark} dark")
check(region > 2000, f"the atom shows at least 2000 light-facing pixels clear of the bond ({region})")
check(dark == 0, f"no atom pixel is dark under a light straight down the bond ({dark})")
region, dark = dark_atom_pixels((5.7, 0.0, 8.2))
print(f"light tilted 35 degrees: {region} atom pixels facing the light, {dark} dark")
check(dark >= 25, f"tilted, the bond's shadow on the atom shows ({dark} dark pixels)")
finish()
