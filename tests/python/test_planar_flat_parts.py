"""planar on the flat parts of meshes that are not flat as a whole (issue
29, defect 6): vedo's floors are thin boxes, scientific scenes put objects
on pedestals. Each scene is rendered with planar and with raytrace (the
exact reference), visibility I_on / I_off in float against the same scene
without shadows, 320x240:

- slab: a sphere over a 8 x 8 x 0.1 box used as the floor (no flat actor);
- pedestal: a sphere over a 2 x 2 x 1 box standing on a flat floor, the
  sphere's shadow falling on the box's top and beyond it on the floor;
- cylinder: a sphere over a standing cylinder (its top cap) on a floor;
- opted out: the slab with RECEIVER() = 0 receives nothing (the control).

planar must agree with raytrace on at least 99.5 % of the valid pixels
(|v_planar - v_raytrace| <= 0.5) and find at least 95 % of raytrace's
shadowed pixels; the stats count the parts (detected_flat_parts). Before
the fix planar drew no shadow on any box (0 % of raytrace's shadow found on
the slab).

Usage: test_planar_flat_parts.py"""
import json
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import float_render as fr  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkFiltersSources import (vtkCubeSource, vtkCylinderSource,  # noqa: E402
                                          vtkPlaneSource, vtkSphereSource)
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper  # noqa: E402

W, H = 320, 240


def add(renderer, source, position=(0, 0, 0), orientation=(0, 0, 0)):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = fr.lambertian(vtkActor())
    actor.SetMapper(mapper)
    actor.SetPosition(*position)
    actor.SetOrientation(*orientation)
    renderer.AddActor(actor)
    return actor


def sphere(center, radius=0.6):
    s = vtkSphereSource()
    s.SetCenter(*center)
    s.SetRadius(radius)
    s.SetThetaResolution(48)
    s.SetPhiResolution(48)
    return s


def box(lengths, center):
    c = vtkCubeSource()
    c.SetXLength(lengths[0])
    c.SetYLength(lengths[1])
    c.SetZLength(lengths[2])
    c.SetCenter(*center)
    return c


def floor():
    p = vtkPlaneSource()
    p.SetOrigin(-5, -5, 0)
    p.SetPoint1(5, -5, 0)
    p.SetPoint2(-5, 5, 0)
    return p


def common(renderer):
    renderer.AddLight(fr.scene_light((1.5, -1.0, 4.0)))
    fr.set_camera(renderer, (5, -9, 7), (0, 0, 0.5))


def slab(renderer, opted_out=False):
    floor_box = add(renderer, box((8, 8, 0.1), (0, 0, -0.05)))
    if opted_out:
        fr.set_key(floor_box, vtkshadow.vtkPlanarShadowPass.RECEIVER(), 0)
    add(renderer, sphere((0, 0, 1.5)))
    common(renderer)


def pedestal(renderer):
    add(renderer, floor())
    add(renderer, box((2, 2, 1), (0, 0, 0.5)))
    add(renderer, sphere((0.4, -0.2, 2.3)))
    common(renderer)


def cylinder(renderer):
    add(renderer, floor())
    c = vtkCylinderSource()
    c.SetRadius(1.2)
    c.SetHeight(1.0)
    c.SetResolution(64)
    # The cylinder's axis is y: stood up, its top cap at z = 1.
    add(renderer, c, position=(0, 0, 0.5), orientation=(90, 0, 0))
    add(renderer, sphere((0.2, 0, 2.2), 0.5))
    common(renderer)


def render(build, technique):
    """(float image, stats) of `build` with technique (None: no shadows)."""
    return fr.render_technique(
        build, W, H, technique,
        lambda renderer, inner:
        json.loads("{" + inner.GetStatsJSON(renderer) + "}") if technique else {})


def compare(name, build, expect_parts):
    off, _ = render(build, None)
    planar, stats = render(build, "planar")
    exact, _ = render(build, "raytrace")
    v_planar, valid_planar = fr.visibility(planar, off)
    v_exact, valid_exact = fr.visibility(exact, off)
    agree, n, missed = fr.compare_visibility(v_planar, valid_planar, v_exact, valid_exact)
    shadow_exact = fr.shadowed(v_exact, valid_exact)
    found = int((shadow_exact & fr.shadowed(v_planar, valid_planar)).sum())
    share = 100.0 * found / max(int(shadow_exact.sum()), 1)
    parts = stats.get("detected_flat_parts")
    print(f"{name}: planar agrees with raytrace on {agree:.3f} % of {n} px ({missed} differ); "
          f"finds {found} of raytrace's {int(shadow_exact.sum())} shadowed px ({share:.1f} %); "
          f"detected_flat_parts {parts}")
    return agree, share, int(shadow_exact.sum()), parts


for name, build, parts_wanted in (("slab", slab, 1), ("pedestal", pedestal, 1),
                                  ("cylinder", cylinder, 1)):
    agree, share, shadow, parts = compare(name, build, parts_wanted)
    check(shadow > 500, f"{name}: raytrace has a shadow to compare ({shadow} px > 500)")
    check(agree >= 99.5, f"{name}: planar agrees with raytrace on {agree:.3f} % >= 99.5 %")
    check(share >= 95.0, f"{name}: planar finds {share:.1f} % >= 95 % of raytrace's shadow")
    check(parts is not None and parts >= parts_wanted,
          f"{name}: the stats count the flat parts ({parts} >= {parts_wanted})")

agree, share, shadow, parts = compare("slab, RECEIVER() = 0", lambda r: slab(r, True), 0)
check(share < 5.0 and parts == 0,
      f"slab opted out with RECEIVER() = 0: no planar shadow ({share:.1f} % of raytrace's), "
      f"{parts} parts")
finish()
