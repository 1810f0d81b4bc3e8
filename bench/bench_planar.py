#!/usr/bin/env python3
"""Planar-shadow benchmark: the frame-time overhead of vtkPlanarShadowPass
("planar") against VTK's default passes ("none"), with VTK's own shadow maps
("vtk", 2048^2) for reference.

Run it with vtkshadow's Python under an X display, from the repository root:

    tests/gl-run.sh build/bin/vtkshadow-python bench/bench_planar.py

Scenes are written as vtkshadow scene files into --out (default: a
temporary folder): a 1,000,000-triangle sphere over a floor (1 and 3
lights, and 1 light at 1280x720), 10,000 arrow glyphs over a floor (one
.vtp mesh of the glyphed arrows), and scenes/basic/sphere-plane.json for
reference. Timing is the project's one method (docs/performance.md, "How
frames are timed"): per scene one vtkshadow-render --stats process times
planar, vtk (--time-also), none and none#2 interleaved in one window
(bench/vtkshadow_bench.py run_timing), --warmup frames each, then --rounds
rounds of one block of --frames frames per technique on vtkshadow-render's
camera orbit, the order changed every round. Reported per scene: the
median over rounds of the block medians (ms) with their spread, the ratio
to none of the same round, and none#2 / none, the noise floor (TOO NOISY
outside 1 +- --noise-tolerance). The goal of issue 14 (planar at most 1.15x
none on scenes with one receiver and one light) gets a verdict per
one-light scene (bench/bench_goals.py: met, missed by how much, or too
noisy).

The result is written to the section "## Planar shadows: overhead against
none" of docs/performance.md (other sections and the hand-written
interpretation inside it are kept). --investigate adds diagnostic variants
of the 1M-triangle scene, each timed against its own none (receiver off,
small caster, fewer triangles). To profile, write the scenes with
--scenes-only and run vtkshadow-render on one under perf, e.g.
    perf record -g build/bin/vtkshadow-render OUT/sphere1m.json \\
        --technique planar --image /tmp/p.png --stats /tmp/p.json --rounds 8
(its none blocks are in the profile too; compare with --technique none).
"""

import argparse
import datetime
import json
import math
import os
import platform
import re
import shlex
import sys
import tempfile

import vtkshadow
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersCore import vtkGlyph3D, vtkTriangleFilter
from vtkmodules.vtkFiltersSources import vtkArrowSource
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bench_goals import verdict  # noqa: E402
from vtkshadow_bench import check_ranges, run_timing, timing_checks  # noqa: E402

SECTION = "## Planar shadows: overhead against none"
REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
VTK = "vtk:map_resolution=2048"
GOAL = 1.15  # issue 14: planar / none on scenes with one receiver and one light


def log(msg):
    print(msg, file=sys.stderr, flush=True)


# ----------------------------------------------------------------------------- scenes
CAMERA = {"position": [0, -8, 5], "focal_point": [0, 0, 0.5], "view_up": [0, 0, 1],
          "view_angle": 30}
# The lights of scenes/basic/sphere-plane.json: sun, point, spot.
LIGHTS = [{"type": "directional", "direction": [-3, -2, -6]},
          {"type": "point", "position": [3, 2, 6]},
          {"type": "spot", "position": [3, 2, 6], "focal_point": [0, 0, 0], "cone_angle": 30}]


def floor(receiver=True):
    return {"plane": {"origin": [-5, -5, 0], "point1": [5, -5, 0], "point2": [-5, 5, 0]},
            "receiver": receiver, "color": [0.9, 0.9, 0.9]}


def scene_doc(objects, lights, size=(800, 600)):
    return {"description": "bench_planar", "size": list(size), "camera": CAMERA,
            "background": [0.1, 0.1, 0.12], "lights": LIGHTS[:lights], "objects": objects}


def sphere(radius=1.0, resolution=1000):
    """resolution 1000: 2 * 1000 * 499 = 998,000 triangles (the UV sphere of
    docs/scene-format.md), the old bench's 1M-triangle sphere."""
    return {"sphere": {"center": [0, 0, 1.2], "radius": radius, "resolution": resolution},
            "color": [0.9, 0.3, 0.2]}


def glyph_mesh(path, n=100):
    """10,000 arrows (n x n) on a wavy sheet, glyphed into one triangle mesh
    (the old bench drew them with vtkGlyph3DMapper; a scene file holds
    meshes, so the glyphs are baked: same triangles, one mapper)."""
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
    source = vtkArrowSource()  # kept referenced: the pipeline does not own it
    arrow = vtkTriangleFilter()
    arrow.SetInputConnection(source.GetOutputPort())
    glyph = vtkGlyph3D()
    glyph.SetInputData(poly)
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetInputArrayToProcess(0, 0, 0, 0, "scale")
    glyph.SetInputArrayToProcess(1, 0, 0, 0, "orient")
    glyph.SetScaleModeToScaleByScalar()
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleFactor(0.12)
    glyph.Update()
    # Geometry only: a scalar array left on the mesh would colour it.
    mesh = vtkPolyData()
    mesh.SetPoints(glyph.GetOutput().GetPoints())
    mesh.SetPolys(glyph.GetOutput().GetPolys())
    writer = vtkXMLPolyDataWriter()
    writer.SetFileName(path)
    writer.SetInputData(mesh)
    if not writer.Write():
        sys.exit(f"bench_planar: cannot write {path}")
    return {"mesh": os.path.basename(path), "color": [0.3, 0.5, 0.9]}


def write(out, name, doc):
    path = os.path.join(out, name + ".json")
    with open(path, "w") as f:
        json.dump(doc, f, indent=1)
    return path


def configs(out, investigate):
    """[(key, label, scene path, window size, --time-also list, goal applies)]."""
    s1 = write(out, "sphere1m", scene_doc([sphere(), floor()], 1))
    rows = [
        ("sphere1m", "1M-triangle sphere, 1 light", s1, (800, 600), ["planar", VTK], True),
        ("sphere1m-3l", "1M-triangle sphere, 3 lights",
         write(out, "sphere1m-3l", scene_doc([sphere(), floor()], 3)), (800, 600),
         ["planar", VTK], False),
        ("glyphs", "10,000 arrow glyphs, 1 light",
         write(out, "glyphs", scene_doc([glyph_mesh(os.path.join(out, "glyphs.vtp")), floor()],
                                        1)), (800, 600), ["planar", VTK], True),
        ("json", "sphere-plane.json (3 lights)",
         os.path.join(REPO, "scenes", "basic", "sphere-plane.json"), (800, 600),
         ["planar", VTK], False),
        ("sphere1m-720", "1M-triangle sphere, 1 light, 1280x720", s1, (1280, 720),
         ["planar", VTK], True),
    ]
    if investigate:
        rows += [
            ("inv-norecv", "floor not a receiver: 0 pairs, mask cleared only",
             write(out, "inv-norecv", scene_doc([sphere(), floor(receiver=False)], 1)),
             (800, 600), ["planar"], False),
            ("inv-small", "1M triangles, radius 0.1 (~1% of the pixels)",
             write(out, "inv-small", scene_doc([sphere(radius=0.1), floor()], 1)), (800, 600),
             ["planar"], False),
            ("inv-250k", "249,000 triangles, radius 1",
             write(out, "inv-250k", scene_doc([sphere(resolution=500), floor()], 1)),
             (800, 600), ["planar"], False),
        ]
    return rows


def triangles(path):
    s = vtkshadow.vtkShadowScene()
    if not s.Load(path):
        sys.exit(f"bench_planar: {path}: {s.GetErrorMessage()}")
    return sum(s.GetObjectPolyData(i).GetNumberOfPolys() for i in range(s.GetNumberOfObjects()))


# ----------------------------------------------------------------------------- timing
def measure(cfg, args, out):
    """One vtkshadow-render --stats process for a configuration: its
    entries by label, the noise floor, and the scene's triangle count."""
    key, label, path, size, also = cfg[:5]
    log("%s, %dx%d: %d rounds x %d frames (+%d warm-up) per technique, interleaved" % (
        label, size[0], size[1], args.rounds, args.frames, args.warmup))
    st = run_timing(path, also, size, os.path.join(out, "runs", key),
                    (args.frames, args.rounds, args.warmup, args.noise_tolerance))
    if st is None:
        sys.exit(f"bench_planar: {label}: vtkshadow-render failed (see {out}/runs/{key})")
    entries = {e["label"]: e for e in st["timing"]["entries"]}
    return dict(entries=entries, noise=st["noise_floor"], triangles=triangles(path))


# ----------------------------------------------------------------------------- report
def ms(e):
    m = e["ms"]
    return "%.1f [%.1f-%.1f]" % (m["median"], m["min"], m["max"])


def ratio(e):
    r = e["ratio_to_none"]
    return "%.2f [%.2f-%.2f]" % (r["median"], r["min"], r["max"])


def floor_text(noise):
    return "%.3f%s" % (noise["ratio"], " TOO NOISY" if noise["too_noisy"] else "")


def goal_text(res):
    p = res["entries"]["planar"]["ratio_to_none"]["median"]
    return verdict(p, GOAL, res["noise"]["ratio"], res["noise"]["too_noisy"])


def main_table(rows):
    out = ["| scene | window | triangles | none ms [rounds] | planar ms [rounds] | overhead ms "
           "| planar / none [rounds] | vtk / none [rounds] | noise floor none#2 / none "
           "| goal planar <= %.2fx none |" % GOAL,
           "|---|---|---:|---:|---:|---:|---:|---:|---:|---|"]
    for cfg, res in rows:
        e = res["entries"]
        size = cfg[3]
        out.append("| %s | %dx%d | %s | %s | %s | %.1f | %s | %s | %s | %s |" % (
            cfg[1], size[0], size[1], "{:,}".format(res["triangles"]), ms(e["none"]),
            ms(e["planar"]), e["planar"]["ms"]["median"] - e["none"]["ms"]["median"],
            ratio(e["planar"]), ratio(e[VTK]) if VTK in e else "-", floor_text(res["noise"]),
            goal_text(res)[1] if cfg[5] else "n/a (not one light)"))
    return out


def counter_table(rows):
    out = ["| scene | shadow pairs | mask triangles/frame | geometry builds (whole run) "
           "| planar memory | vtk shadow-map memory | planar pixels changed after timing |",
           "|---|---:|---:|---:|---:|---:|---:|"]
    for cfg, res in rows:
        e = res["entries"]
        ts = e["planar"].get("technique_stats") or {}
        vm = e[VTK]["shadow_map_bytes"] if VTK in e else None
        out.append("| %s | %s | %s | %s | %.1f MiB | %s | %s |" % (
            cfg[1], ts.get("shadow_pairs", "-"), "{:,}".format(ts["mask_triangles"])
            if "mask_triangles" in ts else "-", ts.get("geometry_builds", "-"),
            e["planar"]["shadow_map_bytes"] / 2**20, "%.0f MiB" % (vm / 2**20) if vm else "-",
            e["planar"]["pixels_changed_after_timing"]))
    return out


def report(rows, args, started):
    cmd = " ".join(shlex.quote(a) for a in
                   ["tests/gl-run.sh", "build/bin/vtkshadow-python", "bench/bench_planar.py"]
                   + sys.argv[1:])
    try:
        cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo")
               if l.startswith("model name")][0]
    except (OSError, IndexError):
        cpu = platform.processor() or "?"
    main = [r for r in rows if not r[0][0].startswith("inv")]
    inv = [r for r in rows if r[0][0].startswith("inv")]
    noisy = sum(1 for _, res in rows if res["noise"]["too_noisy"])
    out = [SECTION, "", "Produced by (from the repository root):", "", "    " + cmd, "",
           "Run %s. Machine: %d cores (%s), no GPU: Mesa llvmpipe under Xvfb, offscreen window; "
           "the machine is shared with other builds and tests. Timing as everywhere in this "
           "project ([How frames are timed](#how-frames-are-timed)): per scene one "
           "vtkshadow-render --stats process times planar, vtk (map 2048), none and none#2 "
           "interleaved in one window, %d warm-up frames each, then %d rounds of one %d-frame "
           "block per technique on the camera orbit, the order changed every round. ms = median "
           "over rounds of the block medians [their min-max]; x none = median over rounds of "
           "(technique / none of the same round) [min-max]; overhead = planar ms - none ms. "
           "The noise floor is none#2 / none, TOO NOISY outside 1.00 +- %.2f (%d of %d runs). "
           "The glyph scene is one baked mesh of the glyphed arrows (before this method it was "
           "drawn by vtkGlyph3DMapper, so its row is not comparable with older runs)." % (
               started.strftime("%Y-%m-%d %H:%M"), os.cpu_count(), cpu, args.warmup,
               args.rounds, args.frames, args.noise_tolerance, noisy, len(rows)), ""]
    out += main_table(main) + [""]
    out += ["Planar pass counters (vtkPlanarShadowPass stats after the run; the geometry is "
            "built once per light and caster placement, so builds stay at their first-frame "
            "count through the camera orbit; pixels changed: the scene-camera image after the "
            "rounds against the one before, 0 when no state leaked between passes):", ""]
    out += counter_table(main) + [""]
    goal = [(cfg, res) for cfg, res in main if cfg[5]]
    if goal:
        out.append("**Goal (issue 14: planar at most %.2fx none on scenes with one receiver and "
                   "one light, 800x600):** %s." % (GOAL, "; ".join(
                       "%s: %s" % (cfg[1], goal_text(res)[1]) for cfg, res in goal)))
        out.append("")
    if inv:
        out += ["Diagnostic variants of the 1M-triangle scene (800x600, 1 light), each its own "
                "process with its own none; no-op clipping planes are no longer a variant (a "
                "scene file has no clipping planes):", "",
                "| variant | none ms | planar ms | overhead ms | planar / none [rounds] "
                "| noise floor | mask triangles/frame |", "|---|---:|---:|---:|---:|---:|---:|"]
        for cfg, res in inv:
            e = res["entries"]
            ts = e["planar"].get("technique_stats") or {}
            out.append("| %s | %s | %s | %.1f | %s | %s | %s |" % (
                cfg[1], ms(e["none"]), ms(e["planar"]),
                e["planar"]["ms"]["median"] - e["none"]["ms"]["median"], ratio(e["planar"]),
                floor_text(res["noise"]), "{:,}".format(ts.get("mask_triangles", 0))))
        out.append("")
    out.append("<!-- interpretation -->")
    return "\n".join(out) + "\n"


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


def interpretation_from(path):
    """The hand-written analysis kept from the previous run of this section
    (between the interpretation markers), so re-running refreshes the numbers
    without deleting it."""
    if not os.path.exists(path):
        return "<!-- interpretation -->"
    doc = open(path).read()
    m = re.search(r"<!-- interpretation -->.*?<!-- /interpretation -->", doc, re.S)
    return m.group(0) if m else "<!-- interpretation -->"


def options():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--frames", type=int, default=15, help="timed frames per block")
    ap.add_argument("--warmup", type=int, default=5, help="untimed frames per technique first")
    ap.add_argument("--noise-tolerance", type=float, default=0.03)
    ap.add_argument("--no-720p", action="store_true", help="skip the 1280x720 run of the 1M scene")
    ap.add_argument("--investigate", action="store_true",
                    help="add diagnostic variants of the 1M-triangle scene")
    ap.add_argument("--only", default="", help="comma-separated config keys to run (debugging)")
    ap.add_argument("--out", default=None,
                    help="folder for the scene files and the runs (default: a temporary one)")
    ap.add_argument("--scenes-only", action="store_true",
                    help="write the scene files into --out and exit (for profiling)")
    ap.add_argument("--output", default=os.path.join(REPO, "docs", "performance.md"))
    ap.add_argument("--no-write", action="store_true")
    a = ap.parse_args()
    check_ranges(ap, timing_checks(a))
    if a.scenes_only and not a.out:
        ap.error("--scenes-only: needs --out DIR")
    known = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
    missing = [t for t in ("none", "planar", "vtk") if t not in known]
    if missing:
        ap.error("technique(s) %s not in the registry (%s)" % (", ".join(missing),
                                                               " ".join(known)))
    return a


def main():
    args = options()
    tmp = None if args.out else tempfile.TemporaryDirectory(prefix="bench_planar.")
    out = args.out or tmp.name
    os.makedirs(out, exist_ok=True)
    cfgs = configs(out, args.investigate)
    if args.scenes_only:
        print("\n".join(sorted({c[2] for c in cfgs})))
        return
    if args.no_720p:
        cfgs = [c for c in cfgs if c[0] != "sphere1m-720"]
    if args.only:
        keep = set(args.only.split(","))
        cfgs = [c for c in cfgs if c[0] in keep]
    started = datetime.datetime.now()
    rows = []
    for cfg in cfgs:
        res = measure(cfg, args, out)
        e = res["entries"]
        log("  => %s: none %.1f ms, planar %.1f ms, planar / none %.3f, noise floor %s" % (
            cfg[0], e["none"]["ms"]["median"], e["planar"]["ms"]["median"],
            e["planar"]["ratio_to_none"]["median"], floor_text(res["noise"])))
        rows.append((cfg, res))
    text = report(rows, args, started)
    print(text)
    if not args.no_write:
        write_section(args.output, text.replace("<!-- interpretation -->",
                                                interpretation_from(args.output)))
        log("wrote %s" % args.output)
    if tmp:
        tmp.cleanup()


if __name__ == "__main__":
    main()
