"""Actors drawn through prop paths (vtkAssembly, vtkPropAssembly, nested)
cast and receive exactly as the same actors added as plain actors with the
composed matrix, with every registered technique (issue 29).

Each variant's render is compared with the render of its reference scene
(plain actors placed by the matrices VTK composes along the paths) under the
same technique: at most max(8, 1 %) of the reference's shadowed pixels may
differ by more than 12 levels of summed RGB. The reference itself must show a shadow on the
floor for techniques that cast. Variants: a sphere in a transformed
vtkAssembly; a vtkPropAssembly holding a plain actor and a transformed
assembly of a transformed assembly; the floor and the sphere in one
assembly (the floor receives through the path: planar detects it); the
assembly moved after a first frame; NO_CAST on the assembly (as on the plain
actor). auto must not say "nothing casts shadows" for an assembly.

Usage: test_assembly_casters.py [--technique NAME]"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "render"))

import vtkshadow  # noqa: E402
import float_render as fr  # noqa: E402
import robust_techniques  # noqa: E402
from vtkmodules.vtkCommonCore import vtkInformation  # noqa: E402
from vtkmodules.vtkCommonMath import vtkMatrix4x4  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkAssembly,  # noqa: E402
                                         vtkPolyDataMapper, vtkPropAssembly)

W, H = 320, 240


def actor_of(source):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def floor_actor():
    plane = vtkPlaneSource()
    plane.SetOrigin(-4, -4, 0)
    plane.SetPoint1(4, -4, 0)
    plane.SetPoint2(-4, 4, 0)
    return actor_of(plane)


def sphere_actor(position=(0.3, 0.0, 0.5), radius=0.6):
    sphere = vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(32)
    sphere.SetPhiResolution(32)
    actor = actor_of(sphere)
    actor.SetPosition(*position)
    actor.SetOrientation(10, 20, 0)
    return actor


def composed(*props):
    """The product of the props' matrices, outermost first: what VTK's
    assembly paths give the last one."""
    m = vtkMatrix4x4()
    for prop in props:
        vtkMatrix4x4.Multiply4x4(m, prop.GetMatrix(), m)
    return m


def placed(actor, matrix):
    """The actor, now placed by `matrix` alone (a plain actor's reference)."""
    actor.SetPosition(0, 0, 0)
    actor.SetOrientation(0, 0, 0)
    actor.SetScale(1, 1, 1)
    actor.SetUserMatrix(matrix)
    return actor


def transformed_assembly(position, rotate_z, scale, *parts):
    assembly = vtkAssembly()
    for part in parts:
        assembly.AddPart(part)
    assembly.SetPosition(*position)
    assembly.RotateZ(rotate_z)
    assembly.SetScale(scale)
    return assembly


def no_cast(prop):
    keys = prop.GetPropertyKeys() or vtkInformation()
    keys.Set(vtkshadow.vtkShadowPassBase.NO_CAST(), 1)
    prop.SetPropertyKeys(keys)
    prop.Modified()


# Each builder adds to a renderer the variant (reference=False) or its plain
# reference (True) and returns a function to call after the first frame
# (or None).
def single(renderer, reference, mark=False):
    sphere = sphere_actor()
    assembly = transformed_assembly((0.5, 0.2, 1.0), 30, 1.2, sphere)
    renderer.AddActor(floor_actor())
    top = placed(sphere, composed(assembly, sphere)) if reference else assembly
    if mark:
        no_cast(top)
    renderer.AddViewProp(top)


def nested(renderer, reference):
    near, far = sphere_actor((-1.5, 1.0, 0.8), 0.5), sphere_actor()
    inner = transformed_assembly((0.0, 0.3, 0.2), -20, 0.9, far)
    outer = transformed_assembly((0.8, -0.2, 0.6), 40, 1.1, inner)
    renderer.AddActor(floor_actor())
    if reference:
        renderer.AddActor(placed(far, composed(outer, inner, far)))
        renderer.AddActor(near)
        return
    props = vtkPropAssembly()
    props.AddPart(near)
    props.AddPart(outer)
    renderer.AddViewProp(props)


def with_floor(renderer, reference):
    floor, sphere = floor_actor(), sphere_actor()
    assembly = transformed_assembly((0.2, -0.3, -0.4), 15, 1.0, floor, sphere)
    if reference:
        renderer.AddActor(placed(floor, composed(assembly, floor)))
        renderer.AddActor(placed(sphere, composed(assembly, sphere)))
    else:
        renderer.AddViewProp(assembly)


def moved(renderer, reference):
    sphere = sphere_actor()
    assembly = transformed_assembly((0.5, 0.2, 1.0), 30, 1.2, sphere)
    renderer.AddActor(floor_actor())
    if reference:
        assembly.SetPosition(-0.6, 0.4, 0.9)
        renderer.AddActor(placed(sphere, composed(assembly, sphere)))
        return None
    renderer.AddViewProp(assembly)
    return lambda: assembly.SetPosition(-0.6, 0.4, 0.9)


def render(build, technique):
    """(summed RGB image, the technique's stats) of `build` rendered with
    `technique`."""
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    after_first = build(renderer)
    renderer.AddLight(fr.scene_light((1.0, 0.5, 3.0)))
    fr.set_camera(renderer, (0, -9, 7), (0, 0, 0.5))
    renderer.ResetCameraClippingRange()
    t = vtkshadow.enable_shadows(renderer, technique)
    window.Render()
    if after_first:
        after_first()
    window.Render()
    image = fr.read_window_rgb(window)
    stats = t.GetStatsJSON(renderer)
    window.Finalize()
    return image, stats


def differs(a, b, levels=12.0):
    return np.abs(a - b) > levels


VARIANTS = (("vtkAssembly", single), ("vtkPropAssembly of nested assemblies", nested),
            ("floor and sphere in one assembly", with_floor), ("assembly moved", moved),
            ("NO_CAST on the assembly", lambda r, ref: single(r, ref, mark=True)))

registry = vtkshadow.vtkShadowTechniqueRegistry
names = [registry.GetName(i) for i in range(registry.GetNumberOfTechniques())]
if "--technique" in sys.argv:
    names = [sys.argv[sys.argv.index("--technique") + 1]]
for name in names:
    casts = robust_techniques.profile(name).casts
    for label, build in VARIANTS:
        reference, _ = render(lambda r, b=build: b(r, True), name)
        unshadowed, _ = render(lambda r, b=build: b(r, True), "none")
        variant, stats = render(lambda r, b=build: b(r, False), name)
        shadow = int(differs(reference, unshadowed, 30.0).sum())
        bad = int(differs(variant, reference).sum())
        if casts and "NO_CAST" not in label:
            check(shadow >= 300, f"{name}, {label}: the reference shows a shadow ({shadow} px)")
        check(bad <= max(8, shadow // 100),
              f"{name}, {label}: {bad} px differ from the plain actors "
              f"(reference shadow {shadow} px)")
        if name == "auto" and "NO_CAST" not in label:
            check("nothing casts" not in stats, f"auto, {label}: {stats[:160]}")

finish()
