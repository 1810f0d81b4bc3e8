"""A shaded vtkVolume receives the shadows of opaque surfaces under raytrace,
csm, volume and auto (issue 32; docs/raytraced-shadows.md, "Volumes":
vtkShadowVolumeReceiver, a light-space depth map of the opaque casters that
the volume's ray-cast shader tests every sample against).

The scene: a directional light straight down; a vtkImageData box of 20^3
points, spacing 0.1, centred at (0, 0, 2), its scalar rising with z from 0
to 1 (the gradient, so the shading normal, is vertical: n.l = 1 with VTK's
two-sided lighting), a constant opacity 0.3 at unit distance 0.1 and a
constant colour c = (0.8, 0.5, 0.2), ShadeOn with ambient 0.3, diffuse 0.7,
specular 0; the light's ambient colour white. An opaque slab at z = 3.5
covers x < 0 above the volume. The camera looks along +y at height 2: every
view ray stays in one half of the volume, and no background surface shows
through it (black background).

Each sample of the lit half is 0.3 + 0.7 c; of the shadowed half, whose
diffuse term the shadow removes, 0.3. The volume's pixel is the sample
colour times its coverage (1 - T along the view ray), so on the summed RGB
the shadowed half keeps (3 x 0.3) / (3 x 0.3 + 0.7 (0.8 + 0.5 + 0.2)) =
0.9 / 1.95 = 0.4615 of the `none` image, within 0.02 (mean, min and max
over a 7 x 7 grid of pixels at x in [-0.8, -0.2], z in [1.4, 2.6]); the lit
half (x in [0.2, 0.8]) equals `none` within 1/255 per channel; with the
slab moved beside the volume (x in [3, 5], nothing above it) every pixel of
the image equals `none` exactly; an unshaded volume (ShadeOff) under the
slab equals `none` exactly too. Under csm the camera orbiting and coming
back computes no new receiver map (volume_receiver_maps_computed stays 1)
and moving the slab computes one (raytrace, csm and volume). planar says
per light that shaded volumes receive no shadow; csm does not.

Usage: test_volume_receivers.py"""
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import float_render as fr  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkCubeSource  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction,  # noqa: E402
                                         vtkPolyDataMapper, vtkVolume, vtkVolumeProperty)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper  # noqa: E402

W, H = 320, 240
POINTS, SPACING, HEIGHT = 20, 0.1, 2.0
COLOUR = (0.8, 0.5, 0.2)
AMBIENT, DIFFUSE = 0.3, 0.7
EXPECTED = 3 * AMBIENT / (3 * AMBIENT + DIFFUSE * sum(COLOUR))  # 0.4615
TOLERANCE = 0.02
TECHNIQUES = ("raytrace", "csm", "volume", "auto")


def volume(shade=True):
    side = (POINTS - 1) * SPACING
    data = vtkImageData()
    data.SetDimensions(POINTS, POINTS, POINTS)
    data.SetSpacing(SPACING, SPACING, SPACING)
    data.SetOrigin(-side / 2, -side / 2, HEIGHT - side / 2)
    scalars = vtkFloatArray()
    scalars.SetNumberOfTuples(POINTS ** 3)
    for index in range(POINTS ** 3):
        scalars.SetValue(index, (index // (POINTS * POINTS)) / (POINTS - 1.0))
    data.GetPointData().SetScalars(scalars)
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.3)
    opacity.AddPoint(1.0, 0.3)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, *COLOUR)
    colour.AddRGBPoint(1.0, *COLOUR)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(0.1)
    prop.SetInterpolationTypeToLinear()
    prop.SetShade(shade)
    prop.SetAmbient(AMBIENT)
    prop.SetDiffuse(DIFFUSE)
    prop.SetSpecular(0.0)
    mapper = vtkSmartVolumeMapper()
    mapper.SetInputData(data)
    v = vtkVolume()
    v.SetMapper(mapper)
    v.SetProperty(prop)
    return v


def slab(x0, x1):
    cube = vtkCubeSource()
    cube.SetBounds(x0, x1, -3.0, 3.0, 3.45, 3.55)
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(cube.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def scene(slab_x=(-3.0, 0.0), shade=True, positional=False):
    def build(renderer):
        renderer.AddActor(slab(*slab_x))
        renderer.AddVolume(volume(shade))
        light = fr.scene_light((0.0, 0.0, 10.0), (0.0, 0.0, 0.0), positional)
        light.SetAmbientColor(1.0, 1.0, 1.0)
        renderer.AddLight(light)
        fr.set_camera(renderer, (0.0, -10.0, HEIGHT), (0.0, 0.0, HEIGHT), clipping=(1.0, 30.0))
    return build


def pixels(renderer, x0, x1):
    """(rows, cols) of a 7 x 7 grid at y = 0 over x in [x0, x1], z in
    [1.4, 2.6] (the volume's middle plane)."""
    rows, cols = [], []
    for x in np.linspace(x0, x1, 7):
        for z in np.linspace(HEIGHT - 0.6, HEIGHT + 0.6, 7):
            renderer.SetWorldPoint(x, 0.0, z, 1.0)
            renderer.WorldToDisplay()
            dx, dy, _ = renderer.GetDisplayPoint()
            rows.append(H - 1 - int(round(dy)))
            cols.append(int(round(dx)))
    return np.array(rows), np.array(cols)


def render(build, technique):
    """(float RGB image, shadowed-half pixels, lit-half pixels, stats)."""
    def inspect(renderer, inner):
        stats = {}
        if isinstance(technique, str) and technique != "none":
            stats = json.loads("{" + inner.GetStatsJSON(renderer) + "}")
        return pixels(renderer, -0.8, -0.2), pixels(renderer, 0.2, 0.8), stats
    image, (dark, lit, stats) = fr.render_technique(build, technique, W, H, inspect, rgb=True)
    return image, dark, lit, stats


def orbit(technique):
    """volume_receiver_maps_computed after each of: a frame, the camera
    orbited 30 degrees, orbited back, the slab moved 0.5 in -x."""
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    scene()(renderer)
    inner = vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique)
    capture = fr.FloatCapture(renderer, inner)
    counts = []
    for step in ("first", "orbit", "back", "moved"):
        camera = renderer.GetActiveCamera()
        if step == "orbit":
            camera.Azimuth(30.0)
        elif step == "back":
            camera.Azimuth(-30.0)
        elif step == "moved":
            renderer.GetActors().GetLastActor().AddPosition(-0.5, 0.0, 0.0)
        window.Render()
        stats = json.loads("{" + inner.GetStatsJSON(renderer) + "}")
        counts.append(stats.get("volume_receiver_maps_computed", -1))
    capture.release()
    window.Finalize()
    return counts


def main():
    off, dark, lit, _ = render(scene(), "none")
    off_sum = off.sum(axis=2)
    print("none: shadowed half %.4f, lit half %.4f (summed RGB)"
          % (off_sum[dark].mean(), off_sum[lit].mean()))
    check(off_sum[dark].min() > 0.1, "the volume covers the measured pixels under none")
    beside_off = render(scene(slab_x=(3.0, 5.0)), "none")[0]
    flat_off = render(scene(shade=False), "none")[0]
    for technique in TECHNIQUES:
        on, _, _, stats = render(scene(), technique)
        ratio = on.sum(axis=2)[dark] / off_sum[dark]
        maps = stats.get("volume_receiver_maps",
                         stats.get("raytrace", {}).get("volume_receiver_maps"))
        print("%s: shadowed half / none = %.4f mean, %.4f min, %.4f max (expected %.4f); "
              "receiver maps %s" % (technique, ratio.mean(), ratio.min(), ratio.max(), EXPECTED,
                                    maps))
        check(all(abs(r - EXPECTED) <= TOLERANCE for r in (ratio.mean(), ratio.min(), ratio.max())),
              "%s: the half under the slab keeps %.4f of its light (%.4f .. %.4f)"
              % (technique, EXPECTED, ratio.min(), ratio.max()))
        worst = np.abs(on[lit] - off[lit]).max()
        print("%s: lit half max |on - none| = %.6f" % (technique, worst))
        check(worst <= 1.0 / 255, "%s: the lit half is unchanged (%.6f)" % (technique, worst))
        beside = np.abs(render(scene(slab_x=(3.0, 5.0)), technique)[0] - beside_off).max()
        print("%s: nothing above, max |on - none| = %g" % (technique, beside))
        check(beside == 0.0, "%s: nothing above the volume renders as none (%g)"
              % (technique, beside))
        flat = np.abs(render(scene(shade=False), technique)[0] - flat_off).max()
        print("%s: ShadeOff under the slab, max |on - none| = %g" % (technique, flat))
        check(flat == 0.0, "%s: an unshaded volume renders as none (%g)" % (technique, flat))
        point_check(technique)
    for technique in ("planar", "csm"):
        note = fr.render_technique(scene(), technique, W, H,
                                   lambda renderer, inner: inner.GetLightNote(0))[1] or ""
        print("%s: light 0's note: %r" % (technique, note))
        says = "shaded volumes receive no shadow" in note
        check(says == (technique == "planar"), "%s %s that shaded volumes receive no shadow"
              % (technique, "says" if technique == "planar" else "does not say"))
    for technique in ("raytrace", "csm", "volume"):
        counts = orbit(technique)
        print("%s: volume_receiver_maps_computed per frame (first, orbit, back, slab moved): %s"
              % (technique, counts))
        check(counts == [1, 1, 1, 2], "%s: the orbit reuses the receiver map, the slab's move "
              "computes one (%s)" % (technique, counts))
    finish()


def point_check(technique):
    """The same under a positional light (a spot at (0, 0, 10), cone 30
    degrees: its perspective map): n.l and the cone's attenuation are
    within 1.2% of 1 over the measured pixels, so the same ratio holds."""
    off, dark, lit, _ = render(scene(positional=True), "none")
    on = render(scene(positional=True), technique)[0]
    ratio = on.sum(axis=2)[dark] / off.sum(axis=2)[dark]
    worst = np.abs(on[lit] - off[lit]).max()
    print("%s, point light: shadowed half / none = %.4f mean, %.4f min, %.4f max; lit half "
          "max |on - none| = %.6f" % (technique, ratio.mean(), ratio.min(), ratio.max(), worst))
    check(all(abs(r - EXPECTED) <= TOLERANCE for r in (ratio.mean(), ratio.min(), ratio.max())),
          "%s, point light: the half under the slab keeps %.4f (%.4f .. %.4f)"
          % (technique, EXPECTED, ratio.min(), ratio.max()))
    check(worst <= 1.0 / 255, "%s, point light: the lit half is unchanged (%.6f)"
          % (technique, worst))


if __name__ == "__main__":
    main()
