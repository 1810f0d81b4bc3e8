"""Float renders of hand-built VTK scenes, for the render tests that compare a
variant of a scene against an equivalent reference (test_robust.py).

The measurement is the one vtkShadowVisibility defines (docs/metrics.md):
white Lambertian materials (ambient 0, diffuse 1, specular 0), one light,
rendered once with shadows (I_on) and once without (I_off) into 32-bit float
colour targets (vtkFramebufferPass), v = I_on / I_off on the pixels where
I_off > EPSILON (the valid pixels), 0 elsewhere. Row 0 of every array
returned here is the TOP row of the image.
"""
import numpy as np
import vtkshadow
from vtkmodules.vtkCommonCore import VTK_FLOAT, vtkInformation
from vtkmodules.vtkRenderingCore import vtkLight, vtkRenderWindow, vtkWindowToImageFilter
from vtkmodules.vtkRenderingOpenGL2 import (vtkFramebufferPass, vtkOpenGLRenderer,
                                            vtkRenderStepsPass, vtkTextureObject)
from vtkmodules.util.numpy_support import vtk_to_numpy

EPSILON = 1e-3  # vtkShadowVisibility's default: I_off <= EPSILON is not valid


def lambertian(actor, color=(1.0, 1.0, 1.0)):
    """White (or `color`) Lambertian material: no ambient, no specular."""
    prop = actor.GetProperty()
    prop.SetColor(*color)
    prop.SetAmbient(0.0)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(0.0)
    return actor


def set_key(actor, key, value=1):
    """Set an integer property key, keeping the actor's other keys."""
    info = actor.GetPropertyKeys()
    if info is None:
        info = vtkInformation()
        actor.SetPropertyKeys(info)
    info.Set(key, value)
    return actor


def mark_receiver(actor):
    return set_key(actor, vtkshadow.vtkPlanarShadowPass.RECEIVER(), 1)


def scene_light(position, focal_point=(0.0, 0.0, 0.0), positional=False):
    """A white scene light; directional (from position towards focal_point)
    unless positional."""
    light = vtkLight()
    light.SetLightTypeToSceneLight()
    light.SetPosition(*position)
    light.SetFocalPoint(*focal_point)
    light.SetPositional(bool(positional))
    light.SetColor(1.0, 1.0, 1.0)
    light.SetIntensity(1.0)
    return light


def set_camera(renderer, position, focal_point, view_up=(0, 0, 1), view_angle=30.0,
               clipping=(0.5, 60.0)):
    camera = renderer.GetActiveCamera()
    camera.SetPosition(*position)
    camera.SetFocalPoint(*focal_point)
    camera.SetViewUp(*view_up)
    camera.SetViewAngle(view_angle)
    camera.SetClippingRange(*clipping)
    return camera


def new_window(width, height):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(width, height)
    return window


def new_renderer(window, viewport=(0.0, 0.0, 1.0, 1.0), layer=0):
    renderer = vtkOpenGLRenderer()
    renderer.SetViewport(*viewport)
    renderer.SetLayer(layer)
    renderer.SetBackground(0.0, 0.0, 0.0)
    window.AddRenderer(renderer)
    return renderer


class FloatCapture:
    """Wraps a renderer's pass in a vtkFramebufferPass with a Float32 colour
    target; read() returns the summed RGB of the last render."""

    def __init__(self, renderer, inner_pass):
        self.renderer = renderer
        self.inner = inner_pass
        self.capture = vtkFramebufferPass()
        self.capture.SetColorFormat(vtkTextureObject.Float32)
        self.capture.SetDepthFormat(vtkTextureObject.Fixed32)
        self.capture.SetDelegatePass(inner_pass)
        renderer.SetPass(self.capture)

    def read(self):
        window = self.renderer.GetRenderWindow()
        tex = self.capture.GetColorTexture()
        if tex is None or not tex.GetHandle():
            raise RuntimeError("no float colour texture to read back")
        w, h = tex.GetWidth(), tex.GetHeight()
        window.MakeCurrent()
        pbo = tex.Download()
        rgba = np.zeros((h, w, 4), np.float32)
        if not pbo.Download2D(VTK_FLOAT, rgba, [w, h], 4, [0, 0]):
            raise RuntimeError("could not download the float colour texture")
        return rgba[::-1, :, :3].astype(np.float64).sum(axis=2)

    def release(self):
        window = self.renderer.GetRenderWindow()
        self.capture.ReleaseGraphicsResources(window)
        self.renderer.SetPass(None)


def read_window_rgb(window):
    """The window's back buffer as summed 8-bit RGB (H, W) floats, row 0 on top."""
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.ShouldRerenderOff()
    grab.Update()
    image = grab.GetOutput()
    w, h, _ = image.GetDimensions()
    rgb = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(h, w, 3)
    return rgb[::-1].astype(np.float64).sum(axis=2)


def render_once(build, width, height, shadows, frames=1, configure=None):
    """A fresh window with one renderer populated by build(renderer) (which
    may return a dict; its optional 'configure'(pass) is called on the planar
    pass), rendered `frames` times with vtkPlanarShadowPass (shadows) or a
    plain vtkRenderStepsPass. Returns (float image, stats dict)."""
    window = new_window(width, height)
    renderer = new_renderer(window)
    extra = build(renderer) or {}
    if shadows:
        inner = vtkshadow.vtkPlanarShadowPass()
        if extra.get("configure"):
            extra["configure"](inner)
        if configure:
            configure(inner)
    else:
        inner = vtkRenderStepsPass()
    capture = FloatCapture(renderer, inner)
    for _ in range(frames):
        window.Render()
    image = capture.read()
    stats = {}
    if shadows:
        stats = {"pairs": inner.GetNumberOfShadowPairs(),
                 "triangles": inner.GetNumberOfMaskTriangles(),
                 "builds": inner.GetNumberOfGeometryBuilds()}
    capture.release()
    window.Finalize()
    return image, stats


def render_technique(build, width, height, technique, after=None):
    """A fresh window with one renderer populated by build(renderer),
    rendered once through the registry's `technique` (None: a plain
    vtkRenderStepsPass, no shadows). Returns the float image, or (image,
    after(renderer, pass)) when `after` is given (read before the window
    goes)."""
    window = new_window(width, height)
    renderer = new_renderer(window)
    build(renderer)
    inner = (vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique) if technique
             else vtkRenderStepsPass())
    capture = FloatCapture(renderer, inner)
    window.Render()
    image = capture.read()
    extra = after(renderer, inner) if after else None
    capture.release()
    window.Finalize()
    return (image, extra) if after else image


def visibility(i_on, i_off, eps=EPSILON):
    """(v, valid): v = I_on / I_off clamped to [0, 1] where I_off > eps."""
    valid = i_off > eps
    v = np.zeros_like(i_off)
    v[valid] = np.clip(i_on[valid] / i_off[valid], 0.0, 1.0)
    return v, valid


def render_visibility(build, width, height, frames=1, configure=None):
    """Visibility of a scene under vtkPlanarShadowPass: (v, valid, I_on,
    I_off, stats)."""
    i_on, stats = render_once(build, width, height, True, frames, configure)
    i_off, _ = render_once(build, width, height, False, frames)
    v, valid = visibility(i_on, i_off)
    return v, valid, i_on, i_off, stats


def compare_visibility(v_a, valid_a, v_b, valid_b, exclude=None, tolerance=0.5):
    """Agreement of two visibility images: the share (percent) of the pixels
    valid in either (outside `exclude`) that are valid in both with
    |v_a - v_b| <= tolerance. Returns (percent, compared pixels, missed)."""
    region = valid_a | valid_b
    if exclude is not None:
        region &= ~exclude
    n = int(region.sum())
    agree = region & valid_a & valid_b & (np.abs(v_a - v_b) <= tolerance)
    missed = n - int(agree.sum())
    return (100.0 * (n - missed) / n if n else 0.0), n, missed


def shadowed(v, valid):
    """Valid pixels in shadow (v < 0.5)."""
    return valid & (v < 0.5)
