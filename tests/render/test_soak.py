"""Soak: FRAMES frames per technique with the camera moving, actors added and
removed and a light switched on and off, checking that process memory and GL
objects stay flat.

Every technique of vtkShadowTechnique.GetKnownTechniques() runs in its own
process (so each RSS is its own) in a 160x120 window. The scene: a floor (a
planar receiver), three spheres, a directional, a spot and a point light.
Each frame the camera moves along a closed path (period 300 frames); every
20 frames a new actor (new polydata, new mapper, so new GL buffers) is added
and 10 frames later the oldest extra one is removed once three are present;
every 50 frames the point light is switched off or on. The state repeats
every 300 frames, so checkpoints at multiples of 300 see the same scene.

Flat means, for the last 2/3 of the frames (frame F/3 to F):
- RSS (VmRSS of /proc/self/status, sampled every 100 frames) does not
  climb steadily: the samples are cut into three windows, each window's
  floor (its least sample) taken, and the rise of the floor from window to
  window, per frame, must stay under LEAK_BOUND_KIB in at least one of the
  two steps. A leak raises every floor (1 KiB a frame fails); what the
  allocator and llvmpipe do (a shadow map's 9 MiB, llvmpipe's thread
  arenas under a loaded machine) is a step up or down once, which at most
  one of the two steps sees. Children run with a fixed glibc mmap
  threshold so freed big blocks go back to the OS;
- live GL textures, buffers, framebuffers, renderbuffers and vertex arrays
  (counted with glIsTexture etc. over every name up to the highest one the
  driver has handed out) are the same at every checkpoint with the same
  scene (multiples of 300 frames from F/3 on);
- the technique's GetShadowMapMemory is the same at those checkpoints.

  test_soak.py --bin BUILD/bin [--frames 3000] [--json OUT.json]
              [--techniques "none csm"] [--leak-kib K --expect-leak]
  test_soak.py --child TECHNIQUE --frames N [--leak-kib K]  (prints JSON)

--leak-kib K makes each child keep K KiB more every frame (a leak put there
on purpose); with --expect-leak the run passes only if every technique is
reported as leaking, which shows the RSS check can fail.
"""
import argparse
import ctypes
import json
import math
import os
import subprocess
import sys
import time

LEAK_BOUND_KIB = 1.0
PERIOD = 300


def rss_kib():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS in /proc/self/status")


class GLCounter:
    """Counts live GL objects of each kind in the current context."""
    KINDS = {"textures": ("glIsTexture", "glGenTextures", "glDeleteTextures"),
             "buffers": ("glIsBuffer", "glGenBuffers", "glDeleteBuffers"),
             "framebuffers": ("glIsFramebuffer", "glGenFramebuffers", "glDeleteFramebuffers"),
             "renderbuffers": ("glIsRenderbuffer", "glGenRenderbuffers",
                               "glDeleteRenderbuffers"),
             "vertex_arrays": ("glIsVertexArray", "glGenVertexArrays",
                               "glDeleteVertexArrays")}

    def __init__(self):
        gl = ctypes.CDLL("libGL.so.1")
        get = gl.glXGetProcAddressARB
        get.restype = ctypes.c_void_p
        get.argtypes = [ctypes.c_char_p]
        self.fns = {}
        for kind, names in self.KINDS.items():
            addr = [get(n.encode()) for n in names]
            if not all(addr):
                raise RuntimeError(f"no GL entry point for {kind}")
            is_ = ctypes.CFUNCTYPE(ctypes.c_ubyte, ctypes.c_uint)(addr[0])
            gen = ctypes.CFUNCTYPE(None, ctypes.c_int, ctypes.POINTER(ctypes.c_uint))(addr[1])
            dele = ctypes.CFUNCTYPE(None, ctypes.c_int, ctypes.POINTER(ctypes.c_uint))(addr[2])
            self.fns[kind] = (is_, gen, dele)

    def count(self):
        out = {}
        for kind, (is_, gen, dele) in self.fns.items():
            # The highest name in use is below a fresh one (or the driver
            # reuses freed names, and a generous margin covers them).
            name = ctypes.c_uint(0)
            gen(1, ctypes.byref(name))
            dele(1, ctypes.byref(name))
            top = max(4096, 2 * name.value)
            out[kind] = sum(1 for n in range(1, top + 1) if is_(n))
        return out


def build_scene(renderer):
    import vtkshadow
    from vtkmodules.vtkCommonCore import vtkInformation
    from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
    from vtkmodules.vtkRenderingCore import vtkActor, vtkLight, vtkPolyDataMapper

    def actor_of(source):
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(source.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor._source = source  # keep the pipeline alive with the actor
        return actor

    floor = vtkPlaneSource()
    floor.SetOrigin(-6, -6, 0)
    floor.SetPoint1(6, -6, 0)
    floor.SetPoint2(-6, 6, 0)
    floor_actor = actor_of(floor)
    keys = vtkInformation()
    keys.Set(vtkshadow.vtkPlanarShadowPass.RECEIVER(), 1)
    floor_actor.SetPropertyKeys(keys)
    renderer.AddActor(floor_actor)
    for k, (x, y) in enumerate([(0, 0), (2, 1), (-2, -1)]):
        s = vtkSphereSource()
        s.SetCenter(x, y, 1.0 + 0.3 * k)
        s.SetRadius(0.6)
        s.SetThetaResolution(24)
        s.SetPhiResolution(16)
        renderer.AddActor(actor_of(s))

    renderer.AutomaticLightCreationOff()
    lights = []
    for position, focal, positional, cone in (((4, 3, 8), (0, 0, 0), False, 30),
                                              ((-3, 2, 6), (0, 0, 0), True, 40),
                                              ((1, -3, 5), (0, 0, 0), True, 180)):
        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPosition(*position)
        light.SetFocalPoint(*focal)
        light.SetPositional(positional)
        light.SetConeAngle(cone)
        light.SetIntensity(0.6)
        renderer.AddLight(light)
        lights.append(light)

    def new_extra(i):
        s = vtkSphereSource()
        a = 2 * math.pi * (i % PERIOD) / PERIOD
        s.SetCenter(3 * math.cos(a), 3 * math.sin(a), 0.8)
        s.SetRadius(0.4)
        s.SetThetaResolution(12 + (i // 20) % 3)
        s.SetPhiResolution(10)
        return actor_of(s)

    return lights, new_extra


def child(technique, frames, leak_kib=0):
    import vtkshadow
    from vtkmodules.vtkRenderingCore import vtkRenderWindow
    from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderer

    window = vtkRenderWindow()
    if not vtkshadow.vtkShadowDisplay.Attach(window):
        raise SystemExit(vtkshadow.vtkShadowDisplay.GetErrorMessage())
    window.SetOffScreenRendering(1)
    window.SetMultiSamples(0)
    window.SetSize(160, 120)
    renderer = vtkOpenGLRenderer()
    window.AddRenderer(renderer)
    lights, new_extra = build_scene(renderer)
    tech = vtkshadow.vtkShadowTechnique()
    tech.SetName(technique)
    tech.SetMapResolution(512)
    if not tech.Install(renderer):
        raise SystemExit(f"cannot install {technique}")
    camera = renderer.GetActiveCamera()
    camera.SetViewUp(0, 0, 1)
    camera.SetFocalPoint(0, 0, 0.5)
    camera.SetViewAngle(40)
    counter = None
    extras = []
    samples = []
    kept = []  # --leak-kib: what a leaking frame would keep
    start = time.monotonic()
    for i in range(frames + 1):
        a = 2 * math.pi * (i % PERIOD) / PERIOD
        camera.SetPosition(12 * math.cos(a), 12 * math.sin(a), 5 + 2 * math.sin(2 * a))
        if i % 20 == 0:
            extra = new_extra(i)
            renderer.AddActor(extra)
            extras.append(extra)
        elif i % 20 == 10 and len(extras) >= 3:
            renderer.RemoveActor(extras.pop(0))
        if i % 50 == 25:
            lights[2].SetSwitch(not lights[2].GetSwitch())
        vtkshadow.vtkShadowScene.ResetCameraClippingRange(renderer)
        window.Render()
        if leak_kib:
            kept.append(bytearray(b"x" * (1024 * leak_kib)))
        if i % 100 == 0:
            sample = {"frame": i, "rss_kib": rss_kib(),
                      "shadow_map_bytes": tech.GetShadowMapMemory(renderer)}
            if i % PERIOD == 0 and i >= frames // 3:
                window.MakeCurrent()
                counter = counter or GLCounter()
                sample["gl"] = counter.count()
            samples.append(sample)
    seconds = time.monotonic() - start
    renderer.RemoveAllViewProps()
    window.Finalize()
    return {"technique": technique, "frames": frames, "seconds": seconds, "samples": samples}


def floor_rise_per_frame(samples):
    """How fast RSS climbs for sure: the samples in three windows, the floor
    (least RSS) of each, and the smaller of the two rises from one window's
    floor to the next, per frame between the windows' starts. Returns
    (KiB per frame, the two rises in KiB)."""
    third = len(samples) // 3
    windows = [samples[:third], samples[third:2 * third], samples[2 * third:]]
    floors = [min(s["rss_kib"] for s in w) for w in windows]
    steps = (floors[1] - floors[0], floors[2] - floors[1])
    spacing = (windows[2][0]["frame"] - windows[0][0]["frame"]) / 2
    return max(min(steps), 0) / spacing, steps


def judge(result, expect_leak=False):
    frames = result["frames"]
    tail = [s for s in result["samples"] if s["frame"] >= frames // 3]
    rss0 = tail[0]["rss_kib"]
    rate, steps = floor_rise_per_frame(tail)
    peak = max(s["rss_kib"] for s in tail) - rss0
    same_state = [s for s in tail if "gl" in s]
    gl_first, gl_last = same_state[0]["gl"], same_state[-1]["gl"]
    gl_flat = all(s["gl"] == gl_first for s in same_state)
    maps = {s["shadow_map_bytes"] for s in same_state}
    problems = []
    if rate >= LEAK_BOUND_KIB:
        problems.append(f"RSS climbs {rate:.2f} KiB/frame >= {LEAK_BOUND_KIB} "
                        f"(window floors rose {steps[0]} and {steps[1]} KiB)")
    if not gl_flat:
        problems.append("GL object counts changed: " +
                        "; ".join(f"{s['frame']}: {s['gl']}" for s in same_state))
    if len(maps) != 1:
        problems.append(f"shadow-map memory changed: {sorted(maps)}")
    print(f"{result['technique']:>7}: {frames} frames in {result['seconds']:.1f} s "
          f"({1000 * result['seconds'] / frames:.1f} ms/frame); RSS at frame {tail[0]['frame']} "
          f"{rss0 / 1024:.1f} MiB, at {tail[-1]['frame']} {tail[-1]['rss_kib'] / 1024:.1f} MiB, "
          f"floor steps {steps[0]}, {steps[1]} KiB (peak {peak} KiB), climb {rate:.3f} KiB/frame; "
          f"shadow maps "
          f"{sorted(maps)} B; GL objects {gl_first} at frame {same_state[0]['frame']}, "
          f"{gl_last} at {same_state[-1]['frame']}")
    if expect_leak:
        leaked = any(p.startswith("RSS climbs") for p in problems)
        print(f"{'ok' if leaked else 'FAIL'} ({result['technique']}): the leak put in "
              f"{'was' if leaked else 'was NOT'} reported")
        return leaked
    for p in problems:
        print(f"FAIL ({result['technique']}): {p}")
    return not problems


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin")
    ap.add_argument("--frames", type=int, default=3000)
    ap.add_argument("--child")
    ap.add_argument("--json")
    ap.add_argument("--techniques", help="default: every one GetKnownTechniques lists")
    ap.add_argument("--leak-kib", type=int, default=0)
    ap.add_argument("--expect-leak", action="store_true")
    args = ap.parse_args()
    if args.expect_leak and args.leak_kib <= 0:
        ap.error("--expect-leak needs --leak-kib K > 0")
    if args.child:
        print(json.dumps(child(args.child, args.frames, args.leak_kib)))
        return
    import vtkshadow
    techniques = (args.techniques or vtkshadow.vtkShadowTechnique.GetKnownTechniques()).split()
    if not techniques:
        sys.exit("GetKnownTechniques() lists no technique")
    ok, results = True, []
    # One process per technique, a few at a time (each is single-threaded).
    # llvmpipe keeps textures (shadow maps: 9 MiB here) in process memory.
    # glibc raises its mmap threshold after such a block is freed, so later
    # ones come from the heap and RSS climbs in 9 MiB steps that are the
    # allocator's, not leaks. A fixed threshold keeps big blocks mmapped and
    # returned when freed, so RSS follows what is alive.
    env = dict(os.environ, MALLOC_MMAP_THRESHOLD_="131072")
    start = time.monotonic()
    jobs = min(4, os.cpu_count() or 1)
    running = {}
    finished = {}
    pending = list(techniques)
    while pending or running:
        while pending and len(running) < jobs:
            t = pending.pop(0)
            running[t] = subprocess.Popen(
                [os.path.join(args.bin, "vtkshadow-python"), os.path.abspath(__file__),
                 "--child", t, "--frames", str(args.frames),
                 "--leak-kib", str(args.leak_kib)],
                stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
        t = next(iter(running))
        out, err = running[t].communicate()
        finished[t] = subprocess.CompletedProcess([], running.pop(t).returncode, out, err)
    print(f"soak: {len(techniques)} techniques ({' '.join(techniques)}), {args.frames} frames "
          f"each, {jobs} at a time, {time.monotonic() - start:.1f} s in all")
    for t in techniques:
        r = finished[t]
        if r.returncode != 0:
            print(f"FAIL ({t}): status {r.returncode}\n{r.stdout[-2000:]}\n{r.stderr[-4000:]}")
            ok = False
            continue
        result = json.loads(r.stdout.strip().splitlines()[-1])
        results.append(result)
        ok = judge(result, args.expect_leak) and ok
    if args.json:
        with open(args.json, "w") as f:
            json.dump(results, f, indent=1)
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
