#!/usr/bin/env python3
"""Planar-shadow benchmark: the frame-time overhead of vtkPlanarShadowPass
("planar") against VTK's default passes ("none"), with VTK's own shadow maps
("vtk", 2048^2) for reference.

Run it with vtkshadow's Python under an X display, from the repository root:

    tests/gl-run.sh build/bin/vtkshadow-python bench/bench_planar.py

Scenes are built here with VTK (no files): a 1,000,000-triangle sphere over a
floor (1 and 3 lights), 10,000 arrow glyphs (vtkGlyph3DMapper) over a floor,
and scenes/basic/sphere-plane.json for reference. For each scene the
techniques are interleaved in rounds (the order rotates every round), each
round renders WARMUP untimed frames after the switch and then FRAMES timed
frames on a small camera orbit (+-5 deg azimuth, +-2 deg elevation, as
vtkshadow-render's --stats); a frame is window.Render() +
window.WaitForCompletion(). The table reports the median over every timed
frame of a technique. Progress goes to stderr, one line per round.

The result is written to the section "## Planar shadows: overhead against
none" of docs/performance.md (other sections are kept). --investigate adds
diagnostic variants of the 1M-triangle scene (receiver off, small caster,
fewer triangles, shadow off the receiver, 3 lights, no-op clip planes on the
main pass) to explain where the planar time goes.
"""

import argparse
import datetime
import math
import os
import platform
import re
import shlex
import statistics
import subprocess
import sys
import time

import vtkshadow
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (OpenGL factories)
import vtkmodules.vtkInteractionStyle  # noqa: F401
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkInformation, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPlane, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkGlyph3DMapper,
    vtkLight,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
)

SECTION = "## Planar shadows: overhead against none"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RECEIVER = vtkshadow.vtkPlanarShadowPass.RECEIVER()
NO_CAST = vtkshadow.vtkPlanarShadowPass.NO_CAST()


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------- scenes
def set_keys(actor, receiver=False, no_cast=False):
    keys = vtkInformation()
    keys.Set(RECEIVER, 1 if receiver else 0)
    keys.Set(NO_CAST, 1 if no_cast else 0)
    actor.SetPropertyKeys(keys)


def phong(actor, color):
    p = actor.GetProperty()
    p.SetInterpolationToPhong()
    p.SetColor(*color)
    p.SetAmbient(0.05)
    p.SetDiffuse(0.9)
    p.SetSpecular(0.1)
    p.SetSpecularPower(30.0)


def floor_actor(x0=-5.0, x1=5.0, y0=-5.0, y1=5.0):
    src = vtkPlaneSource()
    src.SetOrigin(x0, y0, 0)
    src.SetPoint1(x1, y0, 0)
    src.SetPoint2(x0, y1, 0)
    src.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(src.GetOutput())
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    phong(actor, (0.9, 0.9, 0.9))
    set_keys(actor, receiver=True)
    return actor, 2


def scene_lights(count, center=(0.0, 0.0, 0.5), direction=(-3.0, -2.0, -6.0)):
    """The lights of scenes/basic/sphere-plane.json: sun, point, spot."""
    lights = []
    sun = vtkLight()
    sun.SetLightTypeToSceneLight()
    sun.SetPositional(False)
    sun.SetFocalPoint(*center)
    sun.SetPosition(*(c - d for c, d in zip(center, direction)))
    sun.SetAttenuationValues(1, 0, 0)
    lights.append(sun)
    if count >= 3:
        point = vtkLight()
        point.SetLightTypeToSceneLight()
        point.SetPositional(True)
        point.SetPosition(3, 2, 6)
        point.SetFocalPoint(3, 2, 5)
        point.SetConeAngle(180.0)
        point.SetAttenuationValues(1, 0, 0)
        spot = vtkLight()
        spot.SetLightTypeToSceneLight()
        spot.SetPositional(True)
        spot.SetPosition(3, 2, 6)
        spot.SetFocalPoint(0, 0, 0)
        spot.SetConeAngle(30.0)
        spot.SetExponent(0.0)
        spot.SetAttenuationValues(1, 0, 0)
        lights += [point, spot]
    return lights


CAMERA = dict(position=(0, -8, 5), focal_point=(0, 0, 0.5), view_up=(0, 0, 1), view_angle=30)


def build_sphere(renderer, args, lights=1, radius=1.0, theta=1000, phi=502,
                 floor=(-5, 5, -5, 5), direction=(-3, -2, -6), clip_planes=False):
    src = vtkSphereSource()
    src.SetCenter(0, 0, 1.2)
    src.SetRadius(radius)
    src.SetThetaResolution(theta)
    src.SetPhiResolution(phi)
    src.Update()
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(src.GetOutput())
    mapper.ScalarVisibilityOff()
    if clip_planes:
        # Two clipping planes that keep everything: the cost of gl_ClipDistance
        # in llvmpipe's vertex pipeline, measured on the main pass.
        for normal, origin in (((0, 0, 1), (0, 0, -100)), ((1, 0, 0), (-100, 0, 0))):
            plane = vtkPlane()
            plane.SetNormal(*normal)
            plane.SetOrigin(*origin)
            mapper.AddClippingPlane(plane)
    actor = vtkActor()
    actor.SetMapper(mapper)
    phong(actor, (0.9, 0.3, 0.2))
    set_keys(actor)
    renderer.AddActor(actor)
    fl, ftri = floor_actor(*floor)
    renderer.AddActor(fl)
    for light in scene_lights(lights, direction=direction):
        renderer.AddLight(light)
    return dict(triangles=src.GetOutput().GetNumberOfPolys() + ftri,
                caster_triangles=src.GetOutput().GetNumberOfPolys(), camera=CAMERA, floor=fl)


def build_investigation(renderer, args):
    """The 1M-triangle scene plus two alternative casters at the same place
    (1M triangles at radius 0.1, 250k triangles at radius 1), switched by
    visibility, and switchable no-op clipping planes and receiver key, so every
    variant is timed interleaved in one window."""
    info = build_sphere(renderer, args, lights=1)
    big = renderer.GetActors().GetLastActor()  # floor is last; find the sphere
    actors = [renderer.GetActors().GetItemAsObject(i)
              for i in range(renderer.GetActors().GetNumberOfItems())]
    big = [a for a in actors if a is not info["floor"]][0]
    extra = {}
    for key, radius, theta, phi in (("small", 0.1, 1000, 502), ("250k", 1.0, 500, 252)):
        src = vtkSphereSource()
        src.SetCenter(0, 0, 1.2)
        src.SetRadius(radius)
        src.SetThetaResolution(theta)
        src.SetPhiResolution(phi)
        src.Update()
        mapper = vtkPolyDataMapper()
        mapper.SetInputData(src.GetOutput())
        mapper.ScalarVisibilityOff()
        actor = vtkActor()
        actor.SetMapper(mapper)
        phong(actor, (0.9, 0.3, 0.2))
        set_keys(actor)
        actor.VisibilityOff()
        renderer.AddActor(actor)
        extra[key] = actor
    state = {}

    def visible(key):
        def fn(on):
            state[key] = on
            extra[key].SetVisibility(on)
            big.SetVisibility(not any(state.values()))
        return fn

    planes = []
    for normal, origin in (((0, 0, 1), (0, 0, -100)), ((1, 0, 0), (-100, 0, 0))):
        plane = vtkPlane()
        plane.SetNormal(*normal)
        plane.SetOrigin(*origin)
        planes.append(plane)

    def clip(on):
        m = big.GetMapper()
        if on and m.GetNumberOfClippingPlanes() == 0:
            for plane in planes:
                m.AddClippingPlane(plane)
        elif not on and m.GetNumberOfClippingPlanes() > 0:
            m.RemoveAllClippingPlanes()

    def norecv(on):
        set_keys(info["floor"], receiver=not on)

    info["toggles"] = {"small": visible("small"), "250k": visible("250k"), "clip": clip,
                       "norecv": norecv}
    return info


def build_glyphs(renderer, args, lights=1, n=100):
    points = vtkPoints()
    scale = vtkFloatArray()
    scale.SetName("scale")
    orient = vtkFloatArray()
    orient.SetName("orient")
    orient.SetNumberOfComponents(3)
    for j in range(n):
        for i in range(n):
            x = -4.5 + 9.0 * i / (n - 1)
            y = -4.5 + 9.0 * j / (n - 1)
            points.InsertNextPoint(x, y, 0.25 + 0.1 * math.sin(0.7 * x) * math.cos(0.5 * y))
            a = 0.3 * x + 0.2 * y
            orient.InsertNextTuple3(math.cos(a), math.sin(a), 0.4 + 0.3 * math.sin(x * y))
            scale.InsertNextValue(0.6 + 0.4 * (0.5 + 0.5 * math.sin(0.9 * x + 1.3 * y)))
    poly = vtkPolyData()
    poly.SetPoints(points)
    poly.GetPointData().AddArray(scale)
    poly.GetPointData().AddArray(orient)
    arrow = vtkArrowSource()
    tri = vtkTriangleFilter()
    tri.SetInputConnection(arrow.GetOutputPort())
    tri.Update()
    mapper = vtkGlyph3DMapper()
    mapper.SetInputData(poly)
    mapper.SetSourceData(tri.GetOutput())
    mapper.SetScaleArray("scale")
    mapper.SetScaleModeToScaleByMagnitude()
    mapper.SetScaleFactor(0.12)
    mapper.SetOrientationArray("orient")
    mapper.SetOrientationModeToDirection()
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    phong(actor, (0.3, 0.5, 0.9))
    set_keys(actor)
    renderer.AddActor(actor)
    fl, ftri = floor_actor()
    renderer.AddActor(fl)
    for light in scene_lights(lights):
        renderer.AddLight(light)
    per = tri.GetOutput().GetNumberOfPolys()
    return dict(triangles=n * n * per + ftri, caster_triangles=n * n * per, camera=CAMERA,
                floor=fl, note="%d arrows x %d triangles" % (n * n, per))


def build_json(renderer, args, path="scenes/basic/sphere-plane.json"):
    scene = vtkshadow.vtkShadowScene()
    if not scene.Load(os.path.join(REPO, path)):
        raise SystemExit(scene.GetErrorMessage())
    scene.Populate(renderer)
    tris = 0
    floor = None
    for i in range(scene.GetNumberOfObjects()):
        tf = vtkTriangleFilter()
        tf.SetInputData(scene.GetObjectPolyData(i))
        tf.Update()
        tris += tf.GetOutput().GetNumberOfPolys()
    cam = renderer.GetActiveCamera()
    camera = dict(position=cam.GetPosition(), focal_point=cam.GetFocalPoint(),
                  view_up=cam.GetViewUp(), view_angle=cam.GetViewAngle())
    return dict(triangles=tris, camera=camera, floor=floor, scene=scene)


# ----------------------------------------------------------------------------- timing
def place_camera(renderer, camera, i, frames):
    cam = renderer.GetActiveCamera()
    cam.SetPosition(*camera["position"])
    cam.SetFocalPoint(*camera["focal_point"])
    cam.SetViewUp(*camera["view_up"])
    cam.SetViewAngle(camera["view_angle"])
    phase = 2.0 * math.pi * i / max(frames, 2)
    cam.Azimuth(5.0 * math.sin(phase))
    cam.Elevation(2.0 * math.cos(phase) - 2.0)
    cam.OrthogonalizeViewUp()
    renderer.ResetCameraClippingRange()


def make_pass(name):
    t = vtkshadow.vtkShadowTechnique()
    t.SetName(name)
    if name == "vtk":
        t.SetMapResolution(2048)
    p = t.CreatePass()  # what Install() sets; kept so switching does not rebuild
    return t, p


def run_config(cfg, args):
    """Time cfg's techniques interleaved; returns {technique: stats}."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    window.AddRenderer(renderer)
    window.SetSize(*cfg["size"])
    info = cfg["build"](renderer, args)
    renderer.SetBackground(0.1, 0.1, 0.12)
    camera = info["camera"]
    techniques = cfg.get("techniques", ["none", "planar", "vtk"])
    # This bench measures planar against none (vtk for reference): its lists
    # are its question, not the set of techniques; they must name registered
    # ones (vtkShadowTechnique.GetKnownTechniques()).
    known = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
    unknown = sorted({n.split(":")[0] for n in techniques} - set(known))
    if unknown:
        sys.exit("bench_planar: technique(s) %s not in the registry (%s)" % (
            ", ".join(unknown), " ".join(known)))
    passes = {}
    toggles = info.get("toggles", {})

    def apply_variant(name):
        flags = name.split(":")[1:]
        for flag, fn in toggles.items():
            fn(flag in flags)

    for name in techniques:
        base = name.split(":")[0]
        passes[name] = make_pass(base)
    # A first frame with each technique (shader compilation, geometry builds).
    place_camera(renderer, camera, 0, args.frames)
    for name in techniques:
        apply_variant(name)
        renderer.SetPass(passes[name][1])
        window.Render()
        window.WaitForCompletion()
    times = {name: [] for name in techniques}
    cpu = {name: [] for name in techniques}
    rounds = {name: [] for name in techniques}
    counters = {}
    builds_seen = set()
    for rnd in range(args.rounds):
        order = techniques[rnd % len(techniques):] + techniques[:rnd % len(techniques)]
        line = []
        for name in order:
            tech, pss = passes[name]
            apply_variant(name)
            renderer.SetPass(pss)
            for i in range(args.warmup):
                place_camera(renderer, camera, i, args.frames)
                window.Render()
                window.WaitForCompletion()
            planar = pss if isinstance(pss, vtkshadow.vtkPlanarShadowPass) else None
            if planar:
                b0 = planar.GetNumberOfGeometryBuilds()
            ms = []
            for i in range(args.frames):
                place_camera(renderer, camera, i, args.frames)
                c0 = time.process_time()
                t0 = time.perf_counter()
                window.Render()
                window.WaitForCompletion()
                ms.append(1000.0 * (time.perf_counter() - t0))
                cpu[name].append(1000.0 * (time.process_time() - c0))
                if planar:
                    c = counters.setdefault(name, dict(mask=set(), pairs=set()))
                    c["mask"].add(planar.GetNumberOfMaskTriangles())
                    c["pairs"].add(planar.GetNumberOfShadowPairs())
            if planar:
                b1 = planar.GetNumberOfGeometryBuilds()
                c = counters[name]
                c["builds_during_motion"] = c.get("builds_during_motion", 0) + (b1 - b0)
                c["builds"] = b1
                c["memory"] = planar.GetMemoryBytes()
            if tech.GetName() == "vtk":
                counters[name] = dict(memory=tech.GetShadowMapMemory(renderer))
            times[name] += ms
            rounds[name].append(statistics.median(ms))
            line.append("%s %.1f" % (name, statistics.median(ms)))
        log("  [%s] round %d/%d: %s (median ms/frame)" % (cfg["label"], rnd + 1, args.rounds,
                                                       ", ".join(line)))
    result = {}
    for name in techniques:
        result[name] = dict(median=statistics.median(times[name]), min=min(times[name]),
                            max=max(times[name]), n=len(times[name]),
                            cpu=statistics.median(cpu[name]), rounds=rounds[name])
    for name, c in counters.items():
        result[name].update(c)
    # Release GL resources of every pass while the context lives.
    for name in techniques:
        passes[name][1].ReleaseGraphicsResources(window)
    renderer.SetPass(None)
    window.Finalize()
    return info, result


# ----------------------------------------------------------------------------- report
def fmt_ms(v):
    return "%.1f" % v


def paired(res, a, b):
    return statistics.median(x / y for x, y in zip(res[a]["rounds"], res[b]["rounds"]))


def write_section(path, text):
    if os.path.exists(path):
        with open(path) as f:
            doc = f.read()
    else:
        doc = ("# vtkshadow results\n\n"
               "Every section names the command that produced it; re-running that command "
               "replaces only its own section.\n")
    # Our section runs from its heading to the next "## " heading (or the end).
    pattern = re.compile(r"^" + re.escape(SECTION) + r"\n.*?(?=^## |\Z)", re.S | re.M)
    if pattern.search(doc):
        doc = pattern.sub(lambda m: text.rstrip("\n") + "\n\n", doc, count=1)
    else:
        doc = doc.rstrip("\n") + "\n\n" + text.rstrip("\n") + "\n"
    with open(path, "w") as f:
        f.write(doc.rstrip("\n") + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--frames", type=int, default=30)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--no-720p", action="store_true", help="skip the 1280x720 run of the 1M scene")
    ap.add_argument("--investigate", action="store_true",
                    help="add diagnostic variants of the 1M-triangle scene")
    ap.add_argument("--only", default="", help="comma-separated config keys to run (debugging)")
    ap.add_argument("--output", default=os.path.join(REPO, "docs", "performance.md"))
    ap.add_argument("--no-write", action="store_true")
    ap.add_argument("--profile", metavar="TECHNIQUE",
                    help="render only the 1M-triangle scene with TECHNIQUE for --frames frames "
                         "and exit (run under perf record)")
    args = ap.parse_args()
    if args.profile:
        return profile(args)

    S = (800, 600)
    configs = [
        dict(key="sphere1m", label="1M-triangle sphere, 1 light", size=S,
             build=lambda r, a: build_sphere(r, a, lights=1)),
        dict(key="sphere1m-3l", label="1M-triangle sphere, 3 lights", size=S,
             build=lambda r, a: build_sphere(r, a, lights=3)),
        dict(key="glyphs", label="10,000 arrow glyphs, 1 light", size=S,
             build=lambda r, a: build_glyphs(r, a, lights=1)),
        dict(key="json", label="sphere-plane.json (3 lights)", size=S,
             build=lambda r, a: build_json(r, a)),
    ]
    if not args.no_720p:
        configs.append(dict(key="sphere1m-720", label="1M-triangle sphere, 1 light, 1280x720",
                            size=(1280, 720), build=lambda r, a: build_sphere(r, a, lights=1)))
    investigations = []
    if args.investigate:
        def no_receiver(r, a):
            info = build_sphere(r, a, lights=1)
            set_keys(info["floor"], receiver=False)
            return info
        investigations = [
            dict(key="inv", label="1M-triangle sphere, 1 light: diagnostic variants", size=S,
                 build=build_investigation,
                 techniques=["none", "planar", "planar:norecv", "none:clip", "planar:clip",
                             "none:small", "planar:small", "none:250k", "planar:250k"]),
        ]
        old_investigations = [
            dict(key="inv-norecv", label="1M sphere, floor NOT a receiver (0 pairs)", size=S,
                 build=no_receiver, techniques=["none", "planar"]),
            dict(key="inv-small", label="1M sphere, radius 0.1 (same triangles, ~1% pixels)",
                 size=S, build=lambda r, a: build_sphere(r, a, radius=0.1),
                 techniques=["none", "planar"]),
            dict(key="inv-250k", label="250k-triangle sphere, radius 1", size=S,
                 build=lambda r, a: build_sphere(r, a, theta=500, phi=252),
                 techniques=["none", "planar"]),
            dict(key="inv-offrecv", label="1M sphere, shadow falls beside a small floor patch",
                 size=S, build=lambda r, a: build_sphere(r, a, floor=(-5, -2.5, -5, 5),
                                                         direction=(-1, 0, -1)),
                 techniques=["none", "planar"]),
            dict(key="inv-clip", label="1M sphere, 2 no-op clipping planes on its mapper", size=S,
                 build=lambda r, a: build_sphere(r, a, clip_planes=True),
                 techniques=["none", "planar"]),
        ]
    allc = configs + investigations
    if args.only:
        keep = set(args.only.split(","))
        allc = [c for c in allc if c["key"] in keep]

    started = datetime.datetime.now()
    rows = []
    for cfg in allc:
        log("%s, %dx%d: %d rounds x %d frames (+%d warm-up) per technique" % (
            cfg["label"], cfg["size"][0], cfg["size"][1], args.rounds, args.frames, args.warmup))
        info, res = run_config(cfg, args)
        rows.append((cfg, info, res))
        n = res["none"]["median"]
        p = res["planar"]["median"]
        log("  => per-round medians: %s" % "; ".join(
            "%s %s" % (k, " ".join("%.0f" % x for x in v["rounds"])) for k, v in res.items()))
        log("  => none %.1f, planar %.1f ms (+%.1f%%)%s" % (
            n, p, 100 * (p - n) / n,
            ", vtk %.1f ms" % res["vtk"]["median"] if "vtk" in res else ""))

    cmd = " ".join(shlex.quote(a) for a in
                   ["tests/gl-run.sh", "build/bin/vtkshadow-python", "bench/bench_planar.py"]
                   + sys.argv[1:])
    out = []
    out.append(SECTION)
    out.append("")
    out.append("Produced by (from the repository root):")
    out.append("")
    out.append("    " + cmd)
    out.append("")
    try:
        cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")][0]
    except Exception:
        cpu = platform.processor()
    out.append("Run %s. Machine: %d cores (%s), no GPU: Mesa llvmpipe under Xvfb, offscreen "
               "window; the machine is shared with other builds and tests, so absolute times "
               "are noisy. Techniques are interleaved in %d rounds (order rotated each round), "
               "%d warm-up + %d timed frames per round on the vtkshadow-render camera orbit "
               "(+-5 deg azimuth, +-2 deg elevation); a frame is Render() + WaitForCompletion(); "
               "medians over all %d timed frames per technique. Overhead = planar - none."
               % (started.strftime("%Y-%m-%d %H:%M"), os.cpu_count(), cpu, args.rounds,
                  args.warmup, args.frames, args.rounds * args.frames))
    out.append("")
    out.append("Columns: wall-clock medians; *paired* = median over the rounds of "
               "(planar round median / none round median), the figure least disturbed by the "
               "load of other jobs, which drifts between rounds; *CPU* = median process CPU "
               "time per frame (all llvmpipe threads) planar / none.")
    out.append("")
    out.append("| scene | window | triangles | none ms | planar ms | overhead ms | overhead % "
               "| planar/none paired | planar/none CPU | vtk ms | vtk overhead % (paired) |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    target = None
    for cfg, info, res in rows:
        if cfg["key"].startswith("inv"):
            continue
        n, p = res["none"]["median"], res["planar"]["median"]
        v = res.get("vtk", {}).get("median")
        label = cfg["label"] + (" (%s)" % info["note"] if info.get("note") else "")
        pr = paired(res, "planar", "none")
        out.append("| %s | %dx%d | %s | %s | %s | %s | %.0f%% | %.2f | %.2f | %s | %s |" % (
            label, cfg["size"][0], cfg["size"][1], "{:,}".format(info["triangles"]),
            fmt_ms(n), fmt_ms(p), fmt_ms(p - n), 100 * (p - n) / n, pr,
            res["planar"]["cpu"] / res["none"]["cpu"],
            fmt_ms(v) if v else "-",
            ("%.0f%% (%.0f%%)" % (100 * (v - n) / n, 100 * (paired(res, "vtk", "none") - 1)))
            if v else "-"))
        if cfg["key"] == "sphere1m":
            target = (100 * (p - n) / n, 100 * (pr - 1),
                      100 * (res["planar"]["cpu"] / res["none"]["cpu"] - 1))
    out.append("")
    out.append("Planar pass counters (per frame, constant over the camera orbit; builds = "
               "vtkPlanarShadowPass::GetNumberOfGeometryBuilds after the run, \"during motion\" "
               "= builds while the camera moved, must be 0):")
    out.append("")
    out.append("| scene | window | shadow pairs | mask triangles/frame | geometry builds "
               "| builds during motion | planar memory | vtk shadow-map memory |")
    out.append("|---|---|---:|---:|---:|---:|---:|---:|")
    for cfg, info, res in rows:
        c = res["planar"]
        vm = res.get("vtk", {}).get("memory")
        out.append("| %s | %dx%d | %s | %s | %d | %d | %.1f MiB | %s |" % (
            cfg["label"], cfg["size"][0], cfg["size"][1],
            "/".join(str(x) for x in sorted(c["pairs"])),
            "/".join("{:,}".format(x) for x in sorted(c["mask"])), c["builds"],
            c["builds_during_motion"], c["memory"] / 2**20,
            ("%.0f MiB" % (vm / 2**20)) if vm else "-"))
    out.append("")
    if target is not None:
        worst = min(target)
        verdict = "met" if max(target) <= 15.0 else ("missed" if worst > 15.0 else "unclear")
        out.append("**Target (planar overhead <= 15%% of the unshadowed frame on the "
                   "1M-triangle scene, 800x600, 1 light): %s** - overhead %.0f%% (pooled "
                   "medians), %.0f%% (paired rounds), %.0f%% (CPU time)%s." % (
                       verdict, target[0], target[1], target[2],
                       "; even the smallest of the three is %.1fx the target" % (worst / 15.0)
                       if verdict == "missed" else ""))
        out.append("")
    for cfg, info, res in rows:
        if not cfg["key"].startswith("inv"):
            continue
        out.append("Diagnostic variants of the 1M-triangle scene (800x600, 1 light, all in one "
                   "window, interleaved like the techniques; overhead against the `none` of the "
                   "same caster, paired by round):")
        out.append("")
        out.append("| variant | none ms | planar ms | overhead ms | overhead % paired "
                   "| CPU ms none / planar | mask triangles/frame |")
        out.append("|---|---:|---:|---:|---:|---:|---:|")
        desc = {"": "1M triangles, radius 1 (the benchmark scene)",
                "norecv": "floor not a receiver: 0 pairs, mask cleared only",
                "clip": "2 no-op clipping planes on the sphere's mapper",
                "small": "1M triangles, radius 0.1 (~1% of the pixels)",
                "250k": "250,000 triangles, radius 1"}
        for flag in ("", "norecv", "clip", "small", "250k"):
            pn = "planar" + (":" + flag if flag else "")
            nn = "none" + (":" + flag if flag and flag != "norecv" else "")
            if pn not in res:
                continue
            n, p = res[nn]["median"], res[pn]["median"]
            out.append("| %s | %s | %s | %s | %.0f%% | %.1f / %.1f | %s |" % (
                desc[flag], fmt_ms(n), fmt_ms(p), fmt_ms(p - n),
                100 * (paired(res, pn, nn) - 1), res[nn]["cpu"], res[pn]["cpu"],
                "/".join("{:,}".format(x) for x in sorted(res[pn]["mask"]))))
        out.append("")
    out.append("<!-- interpretation -->")
    text = "\n".join(out) + "\n"
    print(text)
    if not args.no_write:
        interp = interpretation_from(args.output)
        write_section(args.output, text.replace("<!-- interpretation -->", interp))
        log("wrote %s" % args.output)


def profile(args):
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)  # as in run_config
    renderer = vtkRenderer()
    renderer.AutomaticLightCreationOff()
    window.AddRenderer(renderer)
    window.SetSize(800, 600)
    info = build_sphere(renderer, args)
    tech, pss = make_pass(args.profile)
    renderer.SetPass(pss)
    for i in range(args.warmup):
        place_camera(renderer, info["camera"], i, args.frames)
        window.Render()
        window.WaitForCompletion()
    log("profile: start")  # perf can be told to skip the set-up with --delay
    t0 = time.perf_counter()
    for i in range(args.frames):
        place_camera(renderer, info["camera"], i, args.frames)
        window.Render()
        window.WaitForCompletion()
    log("profile: %s %.1f ms/frame (mean)" % (args.profile,
                                             1000 * (time.perf_counter() - t0) / args.frames))
    pss.ReleaseGraphicsResources(window)


def interpretation_from(path):
    """The hand-written analysis kept from the previous run of this section
    (between the interpretation markers), so re-running refreshes the numbers
    without deleting it."""
    if not os.path.exists(path):
        return "<!-- interpretation -->"
    doc = open(path).read()
    m = re.search(r"<!-- interpretation -->.*?<!-- /interpretation -->", doc, re.S)
    return m.group(0) if m else "<!-- interpretation -->"


if __name__ == "__main__":
    main()
