"""enable_shadows on a renderer that already has passes or post-processing
(issue 29, defect 5): composed with them, or refused naming them; never
replaced silently.

A sphere over a floor, one directional scene light, frames at 240x160:
- vtkSSAOPass over a vtkRenderStepsPass (vedo's and VTK's SSAO setup): with
  csm the top pass is still the SSAO pass, the frame differs from csm
  without SSAO (the occlusion is drawn) and from SSAO without shadows (the
  shadow is drawn); switching to volume keeps SSAO on top;
- the renderer's UseFXAA and UseDepthPeeling (ignored by a renderer with a
  pass): technique none with FXAA, with depth peeling, and with neither on
  a translucent sphere equals the renderer without any pass; shadows with
  FXAA differ from shadows without it;
- a vtkCameraPass over VTK's standard steps becomes the scene the shadows
  are drawn through;
- VTK's own shadow passes (vtkCameraPass > vtkSequencePass(vtkShadowMapBakerPass,
  vtkShadowMapPass), as vedo's add_shadows sets them) are replaced and
  GetPassMessage() says so;
- vedo's add_ambient_occlusion arrangement (SSAO inside a camera pass and
  a sequence with dual depth peeling) is drawn through: occlusion and
  shadow both drawn;
- a pass that does not shade with VTK's mappers (vtkValuePass) raises
  ValueError naming it, and the renderer keeps that pass.

What it catches: a technique that replaces the renderer's pass instead of
composing with it, so that csm under SSAO draws no occlusion, FXAA and
depth peeling are dropped, and translucent geometry is blended unsorted
where VTK uses order-independent transparency.

Usage: test_enable_composes.py"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, finish  # noqa: E402

import numpy as np  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkPolyDataMapper,  # noqa: E402
                                         vtkRenderWindow, vtkWindowToImageFilter)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCameraPass, vtkLightsPass,  # noqa: E402
                                            vtkOpaquePass, vtkOpenGLRenderer,
                                            vtkRenderPassCollection, vtkRenderStepsPass,
                                            vtkSequencePass, vtkShadowMapBakerPass,
                                            vtkShadowMapPass, vtkSSAOPass,
                                            vtkTranslucentPass, vtkOverlayPass,
                                            vtkDualDepthPeelingPass, vtkValuePass,
                                            vtkVolumetricPass)

W, H = 240, 160
windows = []  # every window stays open until the end (renderers keep using them)


def scene(sphere_opacity=1.0):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(W, H)
    renderer = vtkOpenGLRenderer()
    window.AddRenderer(renderer)
    windows.append(window)
    for source, color, opacity in ((sphere(), (1, .5, .3), sphere_opacity),
                                   (floor(), (.9, .9, .9), 1.0)):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*color)
        actor.GetProperty().SetOpacity(opacity)
        renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(4, -6, 5)
    camera.SetFocalPoint(0, 0, 0.5)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCameraClippingRange()
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPositional(False)
    light.SetPosition(2, -1, 6)
    light.SetFocalPoint(0, 0, 0)
    renderer.AddLight(light)
    renderer.SetAmbient(0.3, 0.3, 0.3)
    return window, renderer


def sphere():
    s = vtkSphereSource()
    s.SetCenter(0, 0, 1.2)
    s.SetThetaResolution(32)
    s.SetPhiResolution(32)
    return s


def floor():
    p = vtkPlaneSource()
    p.SetOrigin(-3, -3, 0)
    p.SetPoint1(3, -3, 0)
    p.SetPoint2(-3, 3, 0)
    return p


def frame(window):
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    return pixels.reshape(H, W, -1)[..., :3].astype(float)


def ssao_on(renderer):
    ssao = vtkSSAOPass()
    ssao.SetRadius(0.5)
    ssao.SetKernelSize(64)
    ssao.SetDelegatePass(vtkRenderStepsPass())
    renderer.SetPass(ssao)
    return ssao


def render(technique, setup=None, opacity=1.0):
    """The frame of `technique` (None: no vtkshadow at all) after `setup`."""
    window, renderer = scene(opacity)
    if setup:
        setup(renderer)
    made = vtkshadow.enable_shadows(renderer, technique=technique) if technique else None
    return frame(window), renderer, made


def changed(a, b, level=8):
    """Pixels whose colour differs by more than `level` of 255."""
    return int((np.abs(a - b).max(axis=2) > level).sum())


# SSAO kept on top, shadows under it.
csm_ssao, renderer, made = render("csm", ssao_on)
csm_plain, _, _ = render("csm")
none_ssao, _, _ = render("none", ssao_on)
none_plain, _, _ = render("none")
shadow_px = changed(csm_plain, none_plain)
check(renderer.GetPass().GetClassName() == "vtkSSAOPass",
      f"csm under SSAO: the renderer's pass is still vtkSSAOPass "
      f"({renderer.GetPass().GetClassName()})")
check("vtkSSAOPass" in made.GetPassMessage(),
      f"GetPassMessage names the SSAO pass: {made.GetPassMessage()!r}")
check(changed(csm_ssao, csm_plain) > 200,
      f"csm under SSAO draws the occlusion: {changed(csm_ssao, csm_plain)} px differ from "
      "csm alone (> 200)")
check(shadow_px > 300 and changed(csm_ssao, none_ssao) > 0.7 * shadow_px,
      f"csm under SSAO draws the shadow: {changed(csm_ssao, none_ssao)} px differ from "
      f"SSAO alone (> 0.7 x the {shadow_px} px the shadow changes without SSAO)")
again = vtkshadow.enable_shadows(renderer, technique="volume")
renderer.GetRenderWindow().Render()
check(renderer.GetPass().GetClassName() == "vtkSSAOPass"
      and renderer.GetPass().GetDelegatePass().GetClassName() == "vtkShadowVolumePass",
      "switching to volume keeps SSAO on top with the volume pass under it")
check(again.GetShadowMapMemory(renderer) > 0,
      "the technique's pass is found under the SSAO pass (GetShadowMapMemory > 0)")


# The renderer's own FXAA, depth peeling and translucency, as without a pass.
def fxaa(renderer):
    renderer.UseFXAAOn()


def peeling(renderer):
    renderer.UseDepthPeelingOn()
    renderer.SetMaximumNumberOfPeels(8)
    renderer.SetOcclusionRatio(0.0)


for name, setup, opacity in (("FXAA", fxaa, 1.0), ("depth peeling", peeling, 0.5),
                             ("order-independent transparency", None, 0.5)):
    with_vtk, _, _ = render(None, setup, opacity)
    with_none, _, _ = render("none", setup, opacity)
    check(changed(with_none, with_vtk, 2) <= 10,
          f"{name}: none draws as the renderer without a pass "
          f"({changed(with_none, with_vtk, 2)} px differ by > 2/255, at most 10)")
fxaa_csm, _, _ = render("csm", fxaa)
check(changed(fxaa_csm, csm_plain, 2) > 100,
      f"FXAA on with csm: {changed(fxaa_csm, csm_plain, 2)} px smoothed (> 100)")


def camera_over(*steps):
    """A vtkCameraPass over a vtkSequencePass of `steps`, as VTK's examples
    and vedo build their pass arrangements."""
    passes = vtkRenderPassCollection()
    for p in steps:
        passes.AddItem(p)
    sequence = vtkSequencePass()
    sequence.SetPasses(passes)
    camera = vtkCameraPass()
    camera.SetDelegatePass(sequence)
    return camera


# A camera pass over VTK's standard steps: drawn through.
def camera_steps(renderer):
    renderer.SetPass(camera_over(vtkLightsPass(), vtkOpaquePass(), vtkTranslucentPass(),
                                 vtkOverlayPass()))


steps_csm, renderer, made = render("csm", camera_steps)
check(renderer.GetPass().GetDelegatePass().GetClassName() == "vtkCameraPass",
      "a vtkCameraPass over standard steps becomes the shadows' scene delegate")
check(changed(steps_csm, csm_plain, 8) <= 10,
      f"... and draws as csm alone ({changed(steps_csm, csm_plain, 8)} px differ, at most 10)")


# VTK's own shadow passes: replaced, and said.
def vtk_shadows(renderer):
    baker = vtkShadowMapBakerPass()
    shadows = vtkShadowMapPass()
    shadows.SetShadowMapBakerPass(baker)
    renderer.SetPass(camera_over(baker, shadows))


_, renderer, made = render("csm", vtk_shadows)
check(renderer.GetPass().GetClassName() == "vtkCascadedShadowMapPass"
      and "vtkShadowMapPass" in made.GetPassMessage()
      and "replaced" in made.GetPassMessage(),
      f"VTK's shadow passes are replaced and said so: {made.GetPassMessage()!r}")


# vedo's add_ambient_occlusion: SSAO inside a camera pass and a sequence
# (lights, SSAO over a camera pass over the opaque pass, dual depth peeling,
# overlays): drawn through, occlusion and shadow both drawn.
def vedo_ssao(renderer):
    opaque_camera = vtkCameraPass()
    opaque_camera.SetDelegatePass(vtkOpaquePass())
    ssao = vtkSSAOPass()
    ssao.SetRadius(0.5)
    ssao.SetKernelSize(64)
    ssao.SetDelegatePass(opaque_camera)
    peeling = vtkDualDepthPeelingPass()
    peeling.SetTranslucentPass(vtkTranslucentPass())
    peeling.SetVolumetricPass(vtkVolumetricPass())
    renderer.SetPass(camera_over(vtkLightsPass(), ssao, peeling, vtkOverlayPass()))


vedo_csm, renderer, made = render("csm", vedo_ssao)
vedo_none, _, _ = render("none", vedo_ssao)
check(renderer.GetPass().GetClassName() == "vtkCascadedShadowMapPass"
      and renderer.GetPass().GetDelegatePass().GetClassName() == "vtkCameraPass"
      and "drawn through" in made.GetPassMessage(),
      f"vedo's SSAO arrangement is drawn through: {made.GetPassMessage()!r}")
check(changed(vedo_csm, csm_plain) > 200,
      f"... with its occlusion: {changed(vedo_csm, csm_plain)} px differ from csm alone (> 200)")
check(changed(vedo_csm, vedo_none) > 0.7 * shadow_px,
      f"... and the shadow: {changed(vedo_csm, vedo_none)} px differ from the arrangement "
      f"without shadows (> 0.7 x {shadow_px})")


# A pass that does not shade with VTK's mappers: refused, naming it,
# nothing changed.
window, renderer = scene()
camera = camera_over(vtkLightsPass(), vtkValuePass())
renderer.SetPass(camera)
try:
    vtkshadow.enable_shadows(renderer, technique="csm")
    raised = None
except ValueError as error:
    raised = error
check(raised is not None and "vtkValuePass" in str(raised)
      and "SetPass(None)" in str(raised),
      f"a value pass: ValueError naming it and what to do: {raised}")
check(renderer.GetPass() is camera, "... and the renderer keeps its pass")
finish()
