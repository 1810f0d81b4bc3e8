"""Render test: vtkCascadedShadowMapPass (technique "csm") in the situations
real applications put it in, and every setting of it, one case per process
(--case).

Two kinds of check:
  * VARIANT vs REFERENCE: a set-up an application may use (several viewports,
    a composite or glyph mapper, a resized window, ...) against an equivalent
    scene of plain vtkPolyDataMapper actors in a single renderer, as float
    renders of white Lambertian materials with one light (float_render.py:
    v = I_on / I_off as vtkShadowVisibility defines it). Agreement: the share
    of pixels valid in either with |dv| <= 0.5 and valid in both, >= 99.9 %;
    and >= 1000 shadowed pixels in both, so that a pass drawing no shadow
    cannot pass.
  * EXACT: test_planar.py's sphere-floor scene (scene file -> vtkShadowScene,
    Populate, as vtkShadowVisibility renders it) against the ray-cast answer
    (exact_scene.trace_scene, shadows on every surface), wrong_pct as
    vtkshadow-metrics computes it with --band 1 and test_planar's exclude
    band; bound 0.5 % (the bound of the render.csm.* tests).
Every case also fails on a GL error (glGetError after each frame, read
through ctypes while the window's context is current) or a VTK error message.

Cases:
  viewports      an 800x300 window: two renderers side by side with different
                 cameras, each with its own pass, and a layer-1 overlay
                 renderer; each viewport vs a single 400x300 render (float
                 captures, and direct 8-bit renders into the window).
  translucent    an opacity-0.4 box beside the shadow: floor visibility
                 unchanged outside the box's pixels vs no box, the box still
                 renders.
  lighting-off   a caster with lighting off: no crash, visibility outside it
                 unchanged vs the lit caster (it still casts).
  pbr            the floor with SetInterpolationToPBR (metallic 0, roughness 1)
                 receives the sphere's shadow: >= 2000 shadowed px where the
                 exact answer has shadow, and the same shadow pixels as the
                 Phong floor on >= 99 % (intersection over union). VTK's PBR
                 shader gamma-encodes its output (pow(colour, 1/2.2)), so
                 I_on / I_off there is v^(1/2.2): the test takes it to the 2.2.
  composite      3 spheres through vtkCompositePolyDataMapper2 vs 3 plain
                 actors; a hidden leaf block; a hidden parent block.
  glyph          ~500 cones through vtkGlyph3DMapper vs the vtkGlyph3D
                 filter's output in a plain actor.
  resize         render at 640x480, resize the window to 800x450, render: vs a
                 fresh 800x450 render.
  big-map        SetMapResolution(16384) with 4 cascades: GetUsedResolution()
                 < 16384, a warning naming the GL limit, and the sphere-floor
                 scene within the exact bound.
  caching        still camera over a still scene: GetNumberOfMapsRendered() == 0;
                 small camera moves reuse maps (GetNumberOfMapsReused() > 0) and
                 still match a fresh render
                 from the 2nd frame on; moving a caster re-renders (and equals a
                 fresh render); changing a caster's points re-renders; moving
                 the light re-renders (and equals a fresh render); an orbiting
                 camera re-renders.
  filters        HARDWARE_2X2, PCF 3, PCF 5, POISSON: exact bound each.
  splits         UNIFORM, LOGARITHMIC, PRACTICAL, EXPLICIT (0.1, 0.3, 0.6) with
                 4 cascades: exact bound each; the cascade far depths follow
                 the explicit fractions.
  stable         Stable on and off: exact bound each.
  cascade-count  CascadeCount 1, 2, 3, 4: exact bound each, and
                 GetNumberOfCascades(0) == the count.
  debug-cascades DebugCascades on: >= 50 % of the lit floor pixels tinted (the
                 channels differ), visibility (from the brightest channel: every
                 tint of cascades 0..6 has a channel at 1.0) unchanged.
  max-texel      MaxTexelPixels 1.5: every cascade's GetCascadeTexelPixels <=
                 1.5 within the default 256 MiB budget (the figures printed).

  test_csm_robust.py --case CASE [--out DIR] [--bin DIR]
"""
import argparse
import ctypes
import json
import os
import sys

import numpy as np
import vtkshadow
from vtkmodules.vtkCommonCore import (VTK_FLOAT, vtkCommand, vtkOutputWindow,
                                      vtkStringOutputWindow)
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkGlyph3D
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCompositeDataDisplayAttributes,
                                         vtkGlyph3DMapper)
from vtkmodules.vtkRenderingOpenGL2 import (vtkCompositePolyDataMapper2, vtkOpenGLRenderer,
                                            vtkRenderStepsPass)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import float_render as fr  # noqa: E402
import test_planar as tp  # noqa: E402
import test_planar_robust as pr  # noqa: E402
from exact_scene import trace_scene  # noqa: E402

CSM = vtkshadow.vtkCascadedShadowMapPass
MIN_AGREEMENT = 99.9     # percent of compared pixels with |dv| <= 0.5
MIN_SHADOWED = 1000
MAX_WRONG_PCT = 0.5      # exact comparisons, as render.csm.*
W, H = pr.W, pr.H

# ---------------------------------------------------------------------------
# GL errors and VTK messages
_libgl = ctypes.CDLL("libGL.so.1")
_libgl.glGetError.restype = ctypes.c_uint


class Messages:
    """Every VTK error/warning text goes to a string window; take() returns
    what arrived since the last call (and echoes it)."""

    def __init__(self):
        self.window = vtkStringOutputWindow()
        vtkOutputWindow.SetInstance(self.window)
        self.seen = 0

    def take(self):
        text = self.window.GetOutput() or ""
        new = text[self.seen:]
        self.seen = len(text)
        if new.strip():
            sys.stdout.write("[vtk] " + new.strip().replace("\n", "\n[vtk] ") + "\n")
        return new


MESSAGES = None
GL_ERRORS = []


def gl_errors(window, label=""):
    """Drain glGetError in the window's context; remember any error."""
    window.MakeCurrent()
    errors = []
    for _ in range(32):
        e = _libgl.glGetError()
        if e == 0:
            break
        errors.append(hex(e))
    if errors:
        GL_ERRORS.append(f"{label}: {errors}")
    return errors


def render(window, label=""):
    window.Render()
    gl_errors(window, label)


# ---------------------------------------------------------------------------
class Checks(pr.Checks):
    def agreement(self, label, a, b, exclude=None, min_shadowed=MIN_SHADOWED,
                  min_agreement=MIN_AGREEMENT):
        pct, n, missed = fr.compare_visibility(a[0], a[1], b[0], b[1], exclude)
        sa, sb = fr.shadowed(*a), fr.shadowed(*b)
        if exclude is not None:
            sa, sb = sa & ~exclude, sb & ~exclude
        na, nb = int(sa.sum()), int(sb.sum())
        self.check(pct >= min_agreement and n > 0,
                   f"{label}: visibility agrees on {pct:.4f} % of {n} px ({missed} differ; "
                   f"need >= {min_agreement} %)")
        if min_shadowed:
            self.check(na >= min_shadowed and nb >= min_shadowed,
                       f"{label}: shadowed px variant {na}, reference {nb} (need >= {min_shadowed})")
        return pct

    def finish(self):
        text = MESSAGES.take() if MESSAGES else ""
        bad = [line for line in text.splitlines() if "ERROR" in line.upper()]
        self.check(not bad, f"no VTK error messages ({len(bad)})")
        self.check(not GL_ERRORS, "no GL errors" + (f": {GL_ERRORS}" if GL_ERRORS else ""))
        super().finish()


def stats(p):
    return {"cascades": p.GetNumberOfCascades(0), "used": p.GetUsedResolution(),
            "maps": p.GetNumberOfMapsRendered(), "total": p.GetTotalMapsRendered(),
            "bytes": p.GetMemoryBytes(),
            "far": [p.GetCascadeFar(0, k) for k in range(p.GetNumberOfCascades(0))],
            "texel_px": [p.GetCascadeTexelPixels(0, k) for k in range(p.GetNumberOfCascades(0))]}


def new_csm(configure=None):
    p = CSM()
    if configure:
        configure(p)
    return p


def render_once(build, width, height, shadows, frames=1, configure=None):
    """float_render.render_once with vtkCascadedShadowMapPass: returns
    (float image, stats of the pass or {})."""
    window = fr.new_window(width, height)
    renderer = fr.new_renderer(window)
    build(renderer)
    inner = new_csm(configure) if shadows else vtkRenderStepsPass()
    capture = fr.FloatCapture(renderer, inner)
    for k in range(frames):
        render(window, f"render {width}x{height} frame {k}")
    image = capture.read()
    st = stats(inner) if shadows else {}
    capture.release()
    window.Finalize()
    return image, st


def vis(build, w=W, h=H, frames=1, configure=None):
    """((v, valid), I_on, I_off, stats) of a hand-built scene under csm."""
    on, st = render_once(build, w, h, True, frames, configure)
    off, _ = render_once(build, w, h, False, frames)
    v, valid = fr.visibility(on, off)
    return (v, valid), on, off, st


# ---------------------------------------------------------------------------
# Scene files (test_planar's builders) against the exact answer
def populate(renderer, scene, out):
    path = os.path.join(out, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f, indent=1)
    sc = vtkshadow.vtkShadowScene()
    if not sc.Load(path):
        sys.exit(sc.GetErrorMessage())
    sc.Populate(renderer, True, 0)   # lambertian, light 0 only (vtkShadowVisibility)
    return sc


def scene_render(scene, out, configure=None, frames=1, shadows=True, after_populate=None,
                 channels=False):
    """Render a scene dict as vtkShadowVisibility does: (image, stats)."""
    width, height = scene["size"]
    window = fr.new_window(width, height)
    renderer = vtkOpenGLRenderer()
    window.AddRenderer(renderer)
    populate(renderer, scene, out)
    if after_populate:
        after_populate(renderer)
    inner = new_csm(configure) if shadows else vtkRenderStepsPass()
    capture = fr.FloatCapture(renderer, inner)
    for k in range(frames):
        render(window, f"scene frame {k}")
    image = read_rgb(capture) if channels else capture.read()
    st = stats(inner) if shadows else {}
    capture.release()
    window.Finalize()
    return image, st


def read_rgb(capture):
    """The float capture's (H, W, 3) RGB, row 0 on top."""
    tex = capture.capture.GetColorTexture()
    w, h = tex.GetWidth(), tex.GetHeight()
    capture.renderer.GetRenderWindow().MakeCurrent()
    pbo = tex.Download()
    rgba = np.zeros((h, w, 4), np.float32)
    if not pbo.Download2D(VTK_FLOAT, rgba, [w, h], 4, [0, 0]):
        raise RuntimeError("could not download the float colour texture")
    return rgba[::-1, :, :3].astype(np.float64)


def band(ref, valid, n=1):
    """vtkshadow-metrics --band n: valid pixels with a valid pixel of the
    opposite reference state within Chebyshev distance n."""
    lit = valid & (ref >= 0.5)
    dark = valid & (ref < 0.5)
    near_lit, near_dark = pr.dilate(lit, n), pr.dilate(dark, n)
    return valid & ((lit & near_dark) | (dark & near_lit))


def exact_metrics(scene, v, trace=None):
    """wrong_pct etc. as vtkshadow-metrics --band 1 with test_planar's
    exclude band. v: the test's visibility (0 outside its own mask)."""
    width, height = scene["size"]
    if trace is None:
        trace = trace_scene(scene, 0, width, height, "all")
    ref, valid = trace["visibility"], trace["valid"]
    compared = valid & ~tp.exclude_band(trace) & ~band(ref, valid)
    n = int(compared.sum())
    d = v[compared] - ref[compared]
    wrong = np.abs(d) > 0.5
    return {"wrong_pct": 100.0 * wrong.mean() if n else 0.0,
            "false_shadow_pct": 100.0 * np.mean((ref[compared] > 0.9) & (v[compared] < 0.5)),
            "false_light_pct": 100.0 * np.mean((ref[compared] < 0.1) & (v[compared] > 0.5)),
            "vis_mae": float(np.abs(d).mean()) if n else 0.0, "compared": n,
            "exact_shadow_px": int(np.sum(compared & (ref < 0.5)))}, trace


SPHERE_FLOOR = tp.sphere_floor("directional", tp.S43)


def exact_case(c, out, label, configure, scene=SPHERE_FLOOR, trace=None, off=None):
    """One configuration on a scene vs the exact answer. Returns (metrics,
    stats, trace, I_off)."""
    if off is None:
        off, _ = scene_render(scene, out, shadows=False)
    on, st = scene_render(scene, out, configure)
    v, _ = fr.visibility(on, off)
    m, trace = exact_metrics(scene, v, trace)
    c.check(m["wrong_pct"] <= MAX_WRONG_PCT and m["exact_shadow_px"] >= 2000,
            f"{label}: wrong_pct {m['wrong_pct']:.4f} (<= {MAX_WRONG_PCT})  false_shadow "
            f"{m['false_shadow_pct']:.4f}  false_light {m['false_light_pct']:.4f}  vis_mae "
            f"{m['vis_mae']:.5f}  compared {m['compared']}  exact shadow px "
            f"{m['exact_shadow_px']}  cascades {st['cascades']}  res {st['used']}  far "
            f"{[round(f, 3) for f in st['far']]}  texel px "
            f"{[round(t, 3) for t in st['texel_px']]}")
    return m, st, trace, off


# ---------------------------------------------------------------------------
def case_viewports(c, out):
    ww, wh = 800, 300

    def multi(shadows, capture):
        window = fr.new_window(ww, wh)
        window.SetNumberOfLayers(2)
        captures, passes = [], []
        for k, vp in enumerate([(0.0, 0.0, 0.5, 1.0), (0.5, 0.0, 1.0, 1.0)]):
            r = fr.new_renderer(window, viewport=vp)
            pr.populate_spheres(r, pr.VIEWPORT_CAMERAS[k])
            p = CSM() if shadows else vtkRenderStepsPass()
            passes.append(p)
            if capture:
                captures.append(fr.FloatCapture(r, p))
            else:
                r.SetPass(p)
        pr.overlay_renderer(window)
        render(window, "multi")
        if capture:
            images = [cap.read() for cap in captures]
        else:
            full = fr.read_window_rgb(window)
            images = [full[:, :ww // 2], full[:, ww // 2:]]
        cascades = [p.GetNumberOfCascades(0) if shadows else 0 for p in passes]
        for cap in captures:
            cap.release()
        window.Finalize()
        return images, cascades

    def single(k, shadows, capture):
        window = fr.new_window(ww // 2, wh)
        r = fr.new_renderer(window)
        pr.populate_spheres(r, pr.VIEWPORT_CAMERAS[k])
        p = CSM() if shadows else vtkRenderStepsPass()
        cap = fr.FloatCapture(r, p) if capture else None
        if not capture:
            r.SetPass(p)
        render(window, "single")
        image = cap.read() if capture else fr.read_window_rgb(window)
        if cap:
            cap.release()
        window.Finalize()
        return image

    window = fr.new_window(ww, wh)
    over = pr.overlay_renderer(window)
    over.SetLayer(0)
    render(window, "overlay")
    overlay = fr.read_window_rgb(window) > 0
    window.Finalize()
    c.check(overlay.sum() > 100, f"overlay covers {int(overlay.sum())} px of the window")

    for capture, label, eps in ((True, "float", fr.EPSILON), (False, "direct 8-bit", 3.0)):
        on, cascades = multi(True, capture)
        off, _ = multi(False, capture)
        c.check(all(n >= 1 for n in cascades), f"{label}: cascades per viewport {cascades}")
        for k in range(2):
            a = fr.visibility(on[k], off[k], eps)
            b = fr.visibility(single(k, True, capture), single(k, False, capture), eps)
            exclude = None
            if not capture:
                exclude = pr.dilate(overlay[:, :ww // 2] if k == 0 else overlay[:, ww // 2:])
            c.agreement(f"{label} viewport {k} vs a single 400x300 renderer", a, b, exclude)


def case_translucent(c, out):
    def with_box(renderer):
        pr.sphere_floor(renderer)
        renderer.AddActor(pr.translucent_box())

    def box_only(renderer):
        pr.base(renderer)
        renderer.AddActor(pr.translucent_box())

    covered = pr.coverage(box_only)
    box_px = pr.dilate(covered, 2)
    c.check(box_px.sum() > 2000, f"the box covers {int(box_px.sum())} px")
    a, on_a, _, _ = vis(with_box)
    b, on_b, _, _ = vis(pr.sphere_floor)
    c.agreement("floor with a translucent box vs without (outside the box)", a, b, box_px)
    inner = covered & ~pr.dilate(~covered, 2)
    changed = np.mean(np.abs(on_a[inner] - on_b[inner]) > 1e-3) * 100 if inner.any() else 0
    c.check(changed >= 90.0, f"the translucent box renders: {changed:.2f} % of its "
                             f"{int(inner.sum())} inner px differ from the scene without it")


def case_lighting_off(c, out):
    def scene(lit):
        def build(renderer):
            pr.sphere_floor(renderer)
            renderer.AddActor(pr.unlit_cube(lit))
        return build

    def cube_only(renderer):
        pr.base(renderer)
        renderer.AddActor(pr.unlit_cube(True))

    cube_px = pr.dilate(pr.coverage(cube_only), 2)
    a, on_a, _, _ = vis(scene(False))
    b, _, _, _ = vis(scene(True))
    c.agreement("caster with lighting off vs lit (outside the cube)", a, b, cube_px)
    # The unlit cube is drawn (flat colour): its pixels are bright in I_on.
    inner = pr.coverage(cube_only) & ~pr.dilate(~pr.coverage(cube_only), 2)
    bright = 100.0 * np.mean(on_a[inner] > 0.5) if inner.any() else 0.0
    c.check(bright >= 90.0, f"the unlit cube renders: {bright:.2f} % of its {int(inner.sum())} "
                            f"inner px bright")


def case_pbr(c, out):
    scene = SPHERE_FLOOR

    def floor_actor(renderer):
        actors = renderer.GetActors()
        actors.InitTraversal()
        for _ in range(actors.GetNumberOfItems()):
            a = actors.GetNextActor()
            b = a.GetBounds()
            if b[5] - b[4] < 1e-9:
                return a
        raise RuntimeError("no floor actor")

    def make_pbr(renderer):
        prop = floor_actor(renderer).GetProperty()
        prop.SetInterpolationToPBR()
        prop.SetMetallic(0.0)
        prop.SetRoughness(1.0)
        prop.SetAmbient(0.0)

    trace = trace_scene(scene, 0, *scene["size"], "all")
    exact_shadow = trace["valid"] & (trace["visibility"] < 0.5) & ~tp.exclude_band(trace)
    floor_mask = trace["object"] == 1   # objects: [sphere, floor]
    results = {}
    for label, hook in (("phong", None), ("pbr", make_pbr)):
        off, _ = scene_render(scene, out, shadows=False, after_populate=hook)
        on, st = scene_render(scene, out, after_populate=hook)
        v, valid = fr.visibility(on, off)
        if label == "pbr":
            # VTK's PBR shader writes gamma-encoded colour (pow(c, 1/2.2)):
            # the ratio of two such values is v^(1/2.2); back to linear.
            v = v ** 2.2
        results[label] = (v, valid)
        shadow = fr.shadowed(v, valid) & floor_mask
        hit = int(np.sum(shadow & exact_shadow))
        c.check(hit >= 2000, f"{label} floor: {hit} shadowed px where the exact answer has "
                             f"shadow ({int(np.sum(exact_shadow & floor_mask))} exact, "
                             f"{int(shadow.sum())} measured; need >= 2000)")
        m, _ = exact_metrics(scene, v, trace)
        print(f"pbr: {label}: wrong_pct {m['wrong_pct']:.4f}  false_light {m['false_light_pct']:.4f}"
              f"  false_shadow {m['false_shadow_pct']:.4f}")
    sa = fr.shadowed(*results["pbr"]) & floor_mask
    sb = fr.shadowed(*results["phong"]) & floor_mask
    union = int((sa | sb).sum())
    iou = 100.0 * int((sa & sb).sum()) / union if union else 0.0
    c.check(iou >= 99.0, f"PBR vs Phong floor: same shadow pixels on {iou:.3f} % of {union} "
                         f"(intersection / union; need >= 99 %)")


def case_composite(c, out):
    polys = [pr.sphere_poly(center, r) for center, r in pr.SPHERES]

    def composite(hidden=None, nested=False):
        def build(renderer):
            pr.base(renderer)
            pr.add_floor(renderer)
            mb = vtkMultiBlockDataSet()
            if nested:
                inner = vtkMultiBlockDataSet()
                inner.SetNumberOfBlocks(2)
                inner.SetBlock(0, polys[1])
                inner.SetBlock(1, polys[2])
                mb.SetNumberOfBlocks(2)
                mb.SetBlock(0, polys[0])
                mb.SetBlock(1, inner)
            else:
                mb.SetNumberOfBlocks(len(polys))
                for i, p in enumerate(polys):
                    mb.SetBlock(i, p)
            mapper = vtkCompositePolyDataMapper2()
            mapper.SetInputDataObject(mb)
            mapper.SetCompositeDataDisplayAttributes(vtkCompositeDataDisplayAttributes())
            if hidden is not None:
                mapper.SetBlockVisibility(hidden, False)   # flat index, root 0
            actor = vtkActor()
            actor.SetMapper(mapper)
            renderer.AddActor(fr.lambertian(actor))
        return build

    def plain(keep):
        def build(renderer):
            pr.base(renderer)
            pr.add_floor(renderer)
            for i in keep:
                renderer.AddActor(pr.poly_actor(polys[i]))
        return build

    for label, variant, keep in (
            ("3 blocks vs 3 plain actors", composite(), [0, 1, 2]),
            ("leaf block 1 hidden vs 2 plain actors", composite(hidden=2), [0, 2]),
            ("hidden parent block (2 spheres) vs 1 plain actor", composite(hidden=2, nested=True),
             [0])):
        a, _, _, _ = vis(variant)
        b, _, _, _ = vis(plain(keep))
        c.agreement(label, a, b)


def case_glyph(c, out):
    points = pr.glyph_input()
    cone = pr.cone_source()

    def mapper_build(renderer):
        pr.base(renderer)
        pr.add_floor(renderer)
        mapper = vtkGlyph3DMapper()
        mapper.SetInputData(points)
        mapper.SetSourceConnection(cone.GetOutputPort())
        mapper.SetScaleArray("mag")
        mapper.SetScaleModeToScaleByMagnitude()
        mapper.ScalingOn()
        mapper.ClampingOn()
        mapper.SetRange(*pr.GLYPH_RANGE)
        mapper.SetScaleFactor(pr.GLYPH_SCALE)
        mapper.SetOrientationArray("dir")
        mapper.SetOrientationModeToDirection()
        mapper.OrientOn()
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer.AddActor(fr.lambertian(actor))

    glyph = vtkGlyph3D()
    glyph.SetInputData(points)
    glyph.SetSourceConnection(cone.GetOutputPort())
    glyph.SetInputArrayToProcess(0, 0, 0, 0, "mag")
    glyph.SetInputArrayToProcess(1, 0, 0, 0, "dir")
    glyph.SetScaleModeToScaleByScalar()
    glyph.ScalingOn()
    glyph.ClampingOn()
    glyph.SetRange(*pr.GLYPH_RANGE)
    glyph.SetScaleFactor(pr.GLYPH_SCALE)
    glyph.SetVectorModeToUseVector()
    glyph.OrientOn()
    glyph.Update()
    cpu = vtkPolyData()
    cpu.ShallowCopy(glyph.GetOutput())
    cpu.GetPointData().SetScalars(None)

    def filter_build(renderer):
        pr.base(renderer)
        pr.add_floor(renderer)
        actor = pr.poly_actor(cpu)
        actor.GetMapper().ScalarVisibilityOff()
        renderer.AddActor(actor)

    a, _, off_a, _ = vis(mapper_build)
    b, _, off_b, _ = vis(filter_build)
    print(f"glyph: {points.GetNumberOfPoints()} glyphs, filter output {cpu.GetNumberOfPolys()} "
          f"polys")
    # Same geometry: the unshadowed renders agree (as test_planar_robust's glyph case).
    both = (off_a > fr.EPSILON) | (off_b > fr.EPSILON)
    rel = np.abs(off_a - off_b) / np.maximum(np.maximum(off_a, off_b), 1e-6)
    same = 100.0 * np.mean(rel[both] <= 0.01)
    c.check(same >= 99.5, f"unshadowed renders agree (1 %) on {same:.4f} % of {int(both.sum())} px "
                          f"(need >= 99.5 %: glyph edges rasterize from float vs double)")
    c.agreement("vtkGlyph3DMapper vs the vtkGlyph3D filter", a, b)


def case_resize(c, out):
    window = fr.new_window(640, 480)
    renderer = fr.new_renderer(window)
    pr.populate_spheres(renderer, pr.VIEWPORT_CAMERAS[0])
    p = CSM()
    cap = fr.FloatCapture(renderer, p)
    render(window, "640x480")
    first = cap.read()
    c.check(first.shape == (480, 640), f"first frame {first.shape[1]}x{first.shape[0]}")
    window.SetSize(800, 450)
    render(window, "800x450 after resize")
    resized = cap.read()
    cap.release()
    window.Finalize()
    c.check(resized.shape == (450, 800), f"after resize {resized.shape[1]}x{resized.shape[0]}")

    def build(r):
        pr.populate_spheres(r, pr.VIEWPORT_CAMERAS[0])
    fresh, _ = render_once(build, 800, 450, True)
    off, _ = render_once(build, 800, 450, False)
    c.agreement("resized 640x480 -> 800x450 vs a fresh 800x450 render",
                fr.visibility(resized, off), fr.visibility(fresh, off))


def case_big_map(c, out):
    got = []

    def configure(p):
        p.SetMapResolution(16384)
        p.SetCascadeCount(4)
        got.append(p)

    MESSAGES.take()
    m, st, _, _ = exact_case(c, out, "MapResolution 16384, 4 cascades", configure)
    text = MESSAGES.take()
    c.check(st["used"] < 16384 and st["used"] >= 1024,
            f"GetUsedResolution() {st['used']} (< 16384), atlas {st['bytes'] / 2**20:.0f} MiB, "
            f"{st['cascades']} cascades")
    c.check("GL limit" in text or "exceeds" in text,
            "a warning about the GL limit: " + (text.strip().splitlines()[0][:160]
                                                if text.strip() else "none"))


def case_caching(c, out):
    window = fr.new_window(W, H)
    renderer = fr.new_renderer(window)
    light = fr.scene_light(pr.LIGHT)
    renderer.AddLight(light)
    fr.set_camera(renderer, **pr.CAMERA)
    pr.add_floor(renderer)
    actors = []
    for center, r in pr.SPHERES:
        a = pr.poly_actor(pr.sphere_poly(center, r))
        renderer.AddActor(a)
        actors.append(a)
    p = CSM()
    cap = fr.FloatCapture(renderer, p)
    state = {"light": pr.LIGHT, "shift": (0.0, 0.0, 0.0), "camera": dict(pr.CAMERA),
             "scale": 1.0}

    def fresh_build(r):
        pr.base(r, light=state["light"], camera=state["camera"])
        pr.add_floor(r)
        for k, (center, rad) in enumerate(pr.SPHERES):
            a = pr.poly_actor(pr.sphere_poly(center, rad))
            if k == 0:
                a.SetPosition(*state["shift"])
            if k == 1:
                a.SetScale(state["scale"])
                a.SetOrigin(*center)
            r.AddActor(a)

    def frame_vs_fresh(label):
        ref, _, off, _ = vis(fresh_build)
        cur = fr.visibility(cap.read(), off)
        c.agreement(label, cur, ref)
        return cur

    maps = []
    for k in range(5):
        render(window, f"still {k}")
        maps.append(p.GetNumberOfMapsRendered())
    c.check(maps[0] >= 1 and all(m == 0 for m in maps[1:]),
            f"still camera, still scene: maps rendered per frame {maps} (0 from frame 2)")
    before = frame_vs_fresh("still frame 5 vs a fresh render")

    actors[0].SetPosition(0.6, -0.4, 0.0)
    state["shift"] = (0.6, -0.4, 0.0)
    render(window, "caster moved")
    moved = p.GetNumberOfMapsRendered()
    render(window, "after caster moved")
    again = p.GetNumberOfMapsRendered()
    c.check(moved >= 1 and again == 0, f"caster moved: {moved} maps rendered, next still "
                                       f"frame {again}")
    after = frame_vs_fresh("frame after moving a caster vs a fresh render")
    changed = int((fr.shadowed(*before) ^ fr.shadowed(*after)).sum())
    c.check(changed >= 300, f"the caster's shadow moved: {changed} px changed state")

    # The data (not the actor) changes: scale sphere 1 through its points.
    poly = actors[1].GetMapper().GetInput()
    pts = poly.GetPoints()
    cx, cy, cz = pr.SPHERES[1][0]
    for i in range(pts.GetNumberOfPoints()):
        x, y, z = pts.GetPoint(i)
        pts.SetPoint(i, cx + 1.3 * (x - cx), cy + 1.3 * (y - cy), cz + 1.3 * (z - cz))
    pts.Modified()
    state["scale"] = 1.3
    render(window, "points modified")
    data = p.GetNumberOfMapsRendered()
    c.check(data >= 1, f"a caster's points modified: {data} maps rendered")
    old = frame_vs_fresh("frame after modifying a caster's points vs a fresh render")

    light.SetPosition(-2.0, 3.0, 5.0)
    state["light"] = (-2.0, 3.0, 5.0)
    render(window, "light moved")
    lm = p.GetNumberOfMapsRendered()
    render(window, "after light moved")
    lm2 = p.GetNumberOfMapsRendered()
    c.check(lm >= 1 and lm2 == 0, f"light moved: {lm} maps rendered, next still frame {lm2}")
    new = frame_vs_fresh("frame after moving the light vs a fresh render")
    changed = int((fr.shadowed(*old) ^ fr.shadowed(*new)).sum())
    c.check(changed >= MIN_SHADOWED, f"the shadow moved with the light: {changed} px changed")

    camera = renderer.GetActiveCamera()

    def orbit(step, frames, label):
        rendered, reused = [], []
        for _ in range(frames):
            camera.Azimuth(step)
            render(window, label)
            rendered.append(p.GetNumberOfMapsRendered())
            reused.append(p.GetNumberOfMapsReused())
        state["camera"] = dict(position=camera.GetPosition(), focal_point=camera.GetFocalPoint(),
                               view_up=camera.GetViewUp())
        return rendered, reused

    # Large steps eventually leave the maps' squares: some frames render.
    rendered, reused = orbit(5.0, 4, "orbit 5 deg")
    c.check(sum(rendered) >= 1, f"orbit by 5 deg a frame: maps rendered per frame "
                                f"{rendered} (reused {reused})")
    frame_vs_fresh("last 5-deg orbit frame vs a fresh render")
    # Small steps stay inside the stable cascades' squares: earlier maps are
    # reused, and the frame must still equal a fresh render (which renders
    # every map for exactly this camera).
    rendered, reused = orbit(0.25, 6, "orbit 0.25 deg")
    c.check(sum(reused) >= 1, f"orbit by 0.25 deg a frame: maps reused per frame {reused} "
                              f"(rendered {rendered})")
    frame_vs_fresh("last 0.25-deg orbit frame (reused maps) vs a fresh render")
    print(f"caching: total maps rendered {p.GetTotalMapsRendered()}")
    cap.release()
    window.Finalize()


def settings_case(c, out, configs):
    off, _ = scene_render(SPHERE_FLOOR, out, shadows=False)
    trace = None
    results = []
    for label, configure in configs:
        m, st, trace, _ = exact_case(c, out, label, configure, trace=trace, off=off)
        results.append((label, m, st))
    return results


def case_filters(c, out):
    def f(kind, size=3):
        def configure(p):
            p.SetFilter(kind)
            p.SetPCFSize(size)
        return configure
    settings_case(c, out, [("HARDWARE_2X2", f(CSM.HARDWARE_2X2)), ("PCF 3", f(CSM.PCF, 3)),
                           ("PCF 5", f(CSM.PCF, 5)), ("POISSON", f(CSM.POISSON))])


def case_splits(c, out):
    fractions = (0.1, 0.3, 0.6)

    def s(scheme):
        def configure(p):
            p.SetCascadeCount(4)
            p.SetSplitScheme(scheme)
            for i, fr_ in enumerate(fractions):
                p.SetSplitFraction(i, fr_)
        return configure
    results = settings_case(c, out, [(name, s(getattr(CSM, name))) for name in
                                     ("UNIFORM", "LOGARITHMIC", "PRACTICAL", "EXPLICIT")])
    fars = {label: st["far"] for label, _, st in results}
    c.check(len({tuple(round(x, 6) for x in f) for f in fars.values()}) == 4,
            "the four schemes give four different split sets")
    ex = fars["EXPLICIT"]
    # Split i ends at near + fraction_i * (far - near) of the visible range.
    near_guess = None
    if len(ex) == 4:
        far = ex[3]
        # near from the first split: ex0 = near + 0.1 (far - near)
        near_guess = (ex[0] - fractions[0] * far) / (1.0 - fractions[0])
        want = [near_guess + f_ * (far - near_guess) for f_ in fractions]
        ok = all(abs(a - b) <= 1e-6 * far for a, b in zip(ex[1:3], want[1:]))
    else:
        ok = False
    c.check(ok, f"EXPLICIT far depths {[round(x, 4) for x in ex]} follow the fractions "
                f"{fractions} of the visible range (near {near_guess})")


def case_stable(c, out):
    settings_case(c, out, [("Stable on", lambda p: p.SetStable(True)),
                           ("Stable off", lambda p: p.SetStable(False))])


def case_cascade_count(c, out):
    def n(count):
        return lambda p: p.SetCascadeCount(count)
    results = settings_case(c, out, [(f"CascadeCount {k}", n(k)) for k in (1, 2, 3, 4)])
    got = [st["cascades"] for _, _, st in results]
    c.check(got == [1, 2, 3, 4], f"GetNumberOfCascades(0) {got} (want [1, 2, 3, 4])")


def case_debug_cascades(c, out):
    off, _ = scene_render(SPHERE_FLOOR, out, shadows=False)
    plain, st_plain = scene_render(SPHERE_FLOOR, out, lambda p: p.SetCascadeCount(4),
                                   channels=True)
    debug, st = scene_render(SPHERE_FLOOR, out,
                             lambda p: (p.SetCascadeCount(4), p.SetDebugCascades(True)),
                             channels=True)
    valid = off > fr.EPSILON
    lit = valid & (plain.sum(axis=2) > 0.5 * off)
    spread = debug.max(axis=2) - debug.min(axis=2)
    tinted = 100.0 * np.mean(spread[lit] > 0.05 * debug.max(axis=2)[lit])
    c.check(tinted >= 50.0, f"debug view: {tinted:.2f} % of {int(lit.sum())} lit px tinted "
                            f"(channels differ by > 5 %; need >= 50 %)")
    plain_spread = plain.max(axis=2) - plain.min(axis=2)
    c.check(float(plain_spread[valid].max()) < 1e-4,
            f"without the debug view the white scene is grey (max channel spread "
            f"{float(plain_spread[valid].max()):.2e})")
    # Visibility from the brightest channel (each tint of cascades 0..6 has a 1.0).
    v_plain, _ = fr.visibility(plain.sum(axis=2), off)
    v_debug, _ = fr.visibility(3.0 * debug.max(axis=2), off)
    c.agreement("visibility with the debug view vs without", (v_debug, valid), (v_plain, valid),
                min_agreement=99.99)
    c.check(st["cascades"] == 4, f"{st['cascades']} cascades shown")


def case_max_texel(c, out):
    def configure(p):
        p.SetMaxTexelPixels(1.5)
    m, st, _, _ = exact_case(c, out, "MaxTexelPixels 1.5", configure)
    worst = max(st["texel_px"]) if st["texel_px"] else float("inf")
    c.check(worst <= 1.5, f"GetCascadeTexelPixels per cascade {[round(t, 3) for t in st['texel_px']]}"
                          f" (max {worst:.3f}, need <= 1.5): {st['cascades']} cascades at "
                          f"{st['used']}^2, atlas {st['bytes'] / 2**20:.0f} MiB (budget 256 MiB)")


CASES = {
    "viewports": case_viewports,
    "translucent": case_translucent,
    "lighting-off": case_lighting_off,
    "pbr": case_pbr,
    "composite": case_composite,
    "glyph": case_glyph,
    "resize": case_resize,
    "big-map": case_big_map,
    "caching": case_caching,
    "filters": case_filters,
    "splits": case_splits,
    "stable": case_stable,
    "cascade-count": case_cascade_count,
    "debug-cascades": case_debug_cascades,
    "max-texel": case_max_texel,
}


def main():
    global MESSAGES
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", required=True, choices=sorted(CASES))
    ap.add_argument("--out", default=os.path.join(os.getcwd(), "csm_robust"))
    ap.add_argument("--bin", help="unused; accepted for symmetry with the other render tests")
    args = ap.parse_args()
    out = os.path.join(args.out, args.case)
    os.makedirs(out, exist_ok=True)
    MESSAGES = Messages()
    checks = Checks(args.case)
    CASES[args.case](checks, out)
    checks.finish()


if __name__ == "__main__":
    main()
