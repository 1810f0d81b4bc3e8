"""A vtkVolume casts a shadow under raytrace, csm and volume (issue 32;
docs/raytraced-shadows.md and docs/cascaded-shadow-maps.md, "Volumes"): the
light reaching the floor through it is the transmittance of its scalar
opacity along the light ray, with VTK's opacity correction: a step of
length ds keeps (1 - a)^(ds / u) of the light, a the transfer function's
opacity and u the property's scalar opacity unit distance. raytrace marches
every shadow ray; csm and volume multiply their screen mask by the volumes'
opacity shadow map (vtkShadowVolumeOpacityMap).

The scene is translucent_scene.py's: a directional light straight down, an
opaque floor at z = 0, the camera beside (it sees the floor patch under the
volume past it, not through it). The volume: a vtkImageData box of 20^3
points, spacing 0.1 (1.9 units a side), centred 2 above the floor, a
constant scalar, drawn by vtkSmartVolumeMapper. Visibility I_on / I_off in
float, 320x240, on the 9 x 9 patch of floor points under its centre, within
0.03 (mean, min and max), under raytrace, csm and volume:

  case                                   expected visibility
  opacity 0.06 at unit distance 0.1      (1 - 0.06)^(1.9 / 0.1) = 0.3086
  the same at unit distance 0.2          (1 - 0.06)^(1.9 / 0.2) = 0.5555
  the first, its data at the origin,     0.3086 (ignoring the matrix: 0.5555)
    turned 30 degrees about z and moved
    up 2 by the volume's matrix
  scalar 1 on the top 6 layers of        0.2943: exp(integral of ln(1 - a(h)) / u),
    points, 0 below; opacity 0.2 x      the scalar interpolated between layers,
    scalar, unit 0.1                     then classified (a wrong axis order: 1)
  the second under a translucent slab    0.25 x 0.5555 = 0.1389 (the translucent
    of opacity 0.5 (0.25)                casters' rays march the volume too)
  opacity 0 (control)                    1
  the volume VisibilityOff               1
and, the first case only:
  the `none` technique                   1
  the `auto` technique                   0.3086 (it gives the light raytrace:
                                         never "nothing casts" for a volume)

planar and vtk cast no volume shadow and say so per light (GetLightNote
"volumes cast no shadow"); csm and volume say nothing about it; auto's
reason names the volume.

The stats say what was collected ("volumes": 1) and what was skipped and
why (a volume of cell scalars casts nothing: "volumes_skipped"). A second
frame with nothing changed is still (not traced); changing the transfer
function traces again and gives its visibility. Under csm and volume the
camera orbiting 30 degrees and back computes no new opacity map (the stats'
volume_maps_computed stays 1) and the function's change computes one and
gives its visibility.

Usage: test_volume_casters.py"""
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "render"))
from checks import check, finish  # noqa: E402

import float_render as fr  # noqa: E402
import translucent_scene as ts  # noqa: E402
import vtkshadow  # noqa: E402
from vtkmodules.vtkCommonCore import vtkFloatArray  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkImageData, vtkPiecewiseFunction  # noqa: E402
from vtkmodules.vtkRenderingCore import (vtkColorTransferFunction, vtkVolume,  # noqa: E402
                                         vtkVolumeProperty)
from vtkmodules.vtkRenderingVolumeOpenGL2 import vtkSmartVolumeMapper  # noqa: E402

POINTS, SPACING = 20, 0.1
SIDE = (POINTS - 1) * SPACING  # the box's side: the vertical crossing's length
ALPHA, UNIT = 0.06, 0.1
SLAB_Z = 3.5  # above the volume, out of the camera's line to the patch


def expected(alpha, unit, length=SIDE):
    """VTK's opacity correction over the crossing: (1 - a)^(L / u)."""
    return (1.0 - alpha) ** (length / unit)


def image(cells=False, z=ts.HEIGHT, top=None):
    """The box of constant scalar 0.5, centred at (0, 0, z); with `cells`
    the scalar is on the cells (not supported: skipped); with `top` it is 1
    on the layers of points from `top` up and 0 below."""
    data = vtkImageData()
    data.SetDimensions(POINTS, POINTS, POINTS)
    data.SetSpacing(SPACING, SPACING, SPACING)
    half = 0.5 * SIDE
    data.SetOrigin(-half, -half, z - half)
    scalars = vtkFloatArray()
    scalars.SetName("density")
    count = (POINTS - 1) ** 3 if cells else POINTS ** 3
    scalars.SetNumberOfTuples(count)
    scalars.Fill(0.5)
    if top is not None:
        # 1 on the layers of points from `top` up, 0 below (x fastest).
        for index in range(count):
            scalars.SetValue(index, 1.0 if index // (POINTS * POINTS) >= top else 0.0)
    (data.GetCellData() if cells else data.GetPointData()).SetScalars(scalars)
    return data


def volume(alpha=ALPHA, unit=UNIT, cells=False, visible=True, moved=False, top=None):
    """A vtkVolume of image() whose opacity function is `alpha` everywhere
    in [0, 1] (with `top`: from 0 at scalar 0 to `alpha` at 1), at unit
    distance `unit`; `moved`: its data centred at the
    origin, placed by the volume's matrix (turned 30 degrees about z, moved
    up by HEIGHT): the same vertical crossing."""
    opacity = vtkPiecewiseFunction()
    opacity.AddPoint(0.0, 0.0 if top is not None else alpha)
    opacity.AddPoint(1.0, alpha)
    colour = vtkColorTransferFunction()
    colour.AddRGBPoint(0.0, 0.8, 0.5, 0.2)
    colour.AddRGBPoint(1.0, 0.8, 0.5, 0.2)
    prop = vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetScalarOpacityUnitDistance(unit)
    prop.SetInterpolationTypeToLinear()
    mapper = vtkSmartVolumeMapper()
    mapper.SetInputData(image(cells, 0.0 if moved else ts.HEIGHT, top))
    v = vtkVolume()
    if moved:
        v.RotateZ(30.0)
        v.SetPosition(0.0, 0.0, ts.HEIGHT)
    v.SetMapper(mapper)
    v.SetProperty(prop)
    v.SetVisibility(visible)
    return v


def expected_top(alpha, unit, top, steps=100000):
    """The transmittance up through the volume whose scalar is 1 from layer
    `top` up: the scalar interpolated linearly between layers (0 to 1 from
    layer top - 1 to top), then classified (opacity alpha x scalar):
    exp(integral of ln(1 - a(h)) / u dh) over the box's height."""
    total = 0.0
    for k in range(steps):
        layer = (k + 0.5) / steps * (POINTS - 1)
        scalar = min(1.0, max(0.0, layer - (top - 1)))
        total += math.log(1.0 - alpha * scalar) * SIDE / steps / unit
    return math.exp(total)


def scene(slab=False, **kw):
    """The floor and light of translucent_scene.py with volume(**kw); with
    `slab`, a translucent slab (opacity 0.5, two crossings: 0.25) above the
    volume too."""
    casters = [(ts.slab(z=SLAB_Z), 0.5)] if slab else []
    return ts.caster_scene(casters, lambda renderer: renderer.AddVolume(volume(**kw)))


def stats_of(build, technique):
    """The pass's stats after one frame of `build`."""
    return fr.render_technique(
        build, technique, ts.W, ts.H,
        lambda renderer, inner: json.loads("{" + inner.GetStatsJSON(renderer) + "}"))[1]


def patch_after(window, capture, renderer, off):
    """(mean, min, max) visibility of the patch in the window's last frame,
    against the unshadowed image `off`."""
    v, valid = fr.visibility(capture.read(), off)
    rows, cols = ts.patch_pixels(renderer)
    values = v[rows, cols][valid[rows, cols]]
    return float(values.mean()), float(values.min()), float(values.max())


def still_then_changed():
    """Three frames in one window: the first traces, the second (nothing
    changed) is still, the third after the opacity function changed to
    0.12 traces again; (stats per frame, the third's patch visibility)."""
    off, _ = ts.render(scene(alpha=0.12), None)
    window = fr.new_window(ts.W, ts.H)
    renderer = fr.new_renderer(window)
    scene()(renderer)
    inner = vtkshadow.vtkShadowTechniqueRegistry.CreatePass("raytrace")
    capture = fr.FloatCapture(renderer, inner)
    frames = []
    for change in (False, False, True):
        if change:
            vol = renderer.GetVolumes().GetLastProp()
            function = vol.GetProperty().GetScalarOpacity()
            function.RemoveAllPoints()
            function.AddPoint(0.0, 0.12)
            function.AddPoint(1.0, 0.12)
        window.Render()
        frames.append(json.loads("{" + inner.GetStatsJSON(renderer) + "}"))
    visibility = patch_after(window, capture, renderer, off)
    capture.release()
    window.Finalize()
    return frames, visibility


def orbit_then_changed(technique):
    """Five frames of `technique` in one window: the first computes the
    volume's opacity map, the camera then orbits 30 degrees and back
    (frames 2 and 3: the map is reused), frame 4 is still, and frame 5
    follows a change of the opacity function to 0.12 (computed again);
    (volume_maps_computed per frame, the last frame's patch visibility)."""
    off, _ = ts.render(scene(alpha=0.12), None)
    window = fr.new_window(ts.W, ts.H)
    renderer = fr.new_renderer(window)
    scene()(renderer)
    inner = vtkshadow.vtkShadowTechniqueRegistry.CreatePass(technique)
    capture = fr.FloatCapture(renderer, inner)
    computed = []
    for step in ("first", "orbit", "back", "still", "change"):
        camera = renderer.GetActiveCamera()
        if step in ("orbit", "back"):
            camera.Azimuth(30.0 if step == "orbit" else -30.0)
        if step == "change":
            function = renderer.GetVolumes().GetLastProp().GetProperty().GetScalarOpacity()
            function.RemoveAllPoints()
            function.AddPoint(0.0, 0.12)
            function.AddPoint(1.0, 0.12)
        window.Render()
        computed.append(json.loads("{" + inner.GetStatsJSON(renderer) + "}")
                        .get("volume_maps_computed"))
    visibility = patch_after(window, capture, renderer, off)
    capture.release()
    window.Finalize()
    return computed, visibility


CASES = (
    (f"opacity {ALPHA} at unit {UNIT}", scene(), expected(ALPHA, UNIT)),
    (f"opacity {ALPHA} at unit 0.2", scene(unit=0.2), expected(ALPHA, 0.2)),
    ("placed by its matrix", scene(moved=True), expected(ALPHA, UNIT)),
    ("opacity 0.2 in the top 6 layers", scene(alpha=0.2, top=14), expected_top(0.2, UNIT, 14)),
    ("under a translucent slab (0.25) too, unit 0.2", scene(slab=True, unit=0.2),
     0.25 * expected(ALPHA, 0.2)),
    ("opacity 0 (control)", scene(alpha=0.0), 1.0),
    ("the volume VisibilityOff", scene(visible=False), 1.0))
# raytrace marches each shadow ray; csm and volume multiply the volumes'
# opacity shadow map into their screen mask.
for technique in ("raytrace", "csm", "volume"):
    for label, build, want in CASES:
        ts.check_patch(check, f"{technique}: {label}, floor under the centre", build, technique,
                       round(want, 4))
for label, build, technique, want in (
        (f"opacity {ALPHA}, technique none", scene(), "none", 1.0),
        # auto never answers "nothing casts" for a visible volume: raytrace.
        (f"opacity {ALPHA} at unit {UNIT}, technique auto", scene(), "auto",
         expected(ALPHA, UNIT))):
    ts.check_patch(check, f"{label}, floor under the centre", build, technique, round(want, 4))

# planar and vtk cast no volume shadow and say so per light; csm and volume
# cast it and say nothing.
for technique in ("csm", "planar", "volume", "vtk"):
    note = fr.render_technique(scene(), technique, ts.W, ts.H,
                               lambda renderer, inner: inner.GetLightNote(0))[1]
    print(f"{technique}: light 0's note {note!r}")
    if technique in ("csm", "volume"):
        check("volume" not in note, f"{technique} casts the volume (no note about it)")
    else:
        check("volumes cast no shadow" in note, f"{technique} says volumes cast no shadow")
reason = fr.render_technique(scene(), "auto", ts.W, ts.H,
                             lambda renderer, inner: inner.GetLightReason(0))[1]
print(f"auto: light 0 {reason!r}")
check("volume" in reason and "raytrace" in reason, "auto gives the volume's light raytrace")

stats = stats_of(scene(), "raytrace")
print(f"stats: volumes {stats.get('volumes')}, skipped {stats.get('volumes_skipped')}, "
      f"volume samples {stats.get('volume_samples')}")
check(stats.get("volumes") == 1 and stats.get("volumes_skipped") == [],
      "raytrace collects the volume (volumes 1, none skipped)")
check(stats.get("volume_samples", 0) > 0, "the shadow rays sampled it")

cells = stats_of(scene(cells=True), "raytrace")
print(f"cell scalars: volumes {cells.get('volumes')}, skipped {cells.get('volumes_skipped')}")
check(cells.get("volumes") == 0 and len(cells.get("volumes_skipped", [])) == 1
      and "point" in cells["volumes_skipped"][0],
      "a volume of cell scalars is skipped, with the reason in the stats")
ts.check_patch(check, "cell scalars (skipped), floor under the centre", scene(cells=True),
               "raytrace", 1.0)

frames, (mean, lo, hi) = still_then_changed()
print("frames: " + ", ".join(f"traced {f.get('traced')} still {f.get('still_frame')}"
                             for f in frames))
check(frames[0].get("traced") and frames[1].get("still_frame") and frames[2].get("traced"),
      "a still frame does not trace; changing the opacity function traces again")
want = expected(0.12, UNIT)
print(f"after the change: visibility {mean:.4f} (min {lo:.4f}, max {hi:.4f}); expected {want:.4f}")
check(abs(mean - want) <= ts.TOLERANCE and lo >= want - ts.TOLERANCE
      and hi <= want + ts.TOLERANCE, f"the changed function's shadow is {want:.4f} within 0.03")

for technique in ("csm", "volume"):
    computed, (mean, lo, hi) = orbit_then_changed(technique)
    print(f"{technique}: volume_maps_computed per frame {computed}; after the change "
          f"visibility {mean:.4f} (min {lo:.4f}, max {hi:.4f}); expected {want:.4f}")
    check(computed == [1, 1, 1, 1, 2],
          f"{technique}: the camera orbiting reuses the volume's map; the function's change "
          "computes it again")
    check(abs(mean - want) <= ts.TOLERANCE and lo >= want - ts.TOLERANCE
          and hi <= want + ts.TOLERANCE, f"{technique}: the changed function's shadow is "
          f"{want:.4f} within 0.03")
finish()
