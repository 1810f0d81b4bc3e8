"""One X display per process, and a clear exit where there is none.

1. `xvfb-run -a vtkshadow-render` (plain, as the README says: no -noreset) on
   a two-light scene, with the visibility renders and the colour image,
   RUNS times in a row: every run must succeed. Xvfb resets when its last
   client disconnects; a tool that closed its display between the
   visibility renders and the colour image and reopened it during the reset
   aborted ("bad X server connection ... Aborting") about one run in four.
   xvfb-run's own failure to start a server ("Xvfb failed to start", a race
   between concurrent xvfb-run -a picking the same display number) is not
   the tool's: such a run is retried (at most 3 times) and counted apart.
2. DISPLAY unset, and DISPLAY naming a display nobody serves: exit status 2,
   a message saying to run under xvfb-run -a, no output file, no abort.
3. The same through Python: vtkShadowVisibility.Compute() returns False with
   that message instead of VTK aborting the interpreter.

  test_display.py --bin BUILD/bin --source SRC --out DIR [--runs 30]
"""
import argparse
import os
import subprocess
import sys
import time


def render_cmd(args, out, tag):
    scene = os.path.join(args.source, "scenes", "basic", "two-lights.json")
    return [os.path.join(args.bin, "vtkshadow-render"), scene, "--technique", "csm",
            "--size", "160x120", "--light", "1", "--quiet",
            "--image", os.path.join(out, tag + "-image.png"),
            "--visibility", os.path.join(out, tag + "-visibility.png"),
            "--mask", os.path.join(out, tag + "-mask.png")]


def xvfb_loop(args):
    failures, server_retries = 0, 0
    start = time.monotonic()
    for i in range(args.runs):
        for attempt in range(4):
            env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "XAUTHORITY")}
            r = subprocess.run(["xvfb-run", "-a"] + render_cmd(args, args.out, f"run{i}"),
                               capture_output=True, text=True, env=env)
            if r.returncode != 0 and "Xvfb failed to start" in r.stderr and attempt < 3:
                server_retries += 1
                continue
            break
        if r.returncode != 0:
            failures += 1
            print(f"run {i}: status {r.returncode}\n{r.stderr.strip()}")
    elapsed = time.monotonic() - start
    print(f"xvfb-run -a loop: {args.runs - failures}/{args.runs} runs succeeded, "
          f"{failures} failed, {server_retries} xvfb-run server-start retries, "
          f"{elapsed:.1f} s")
    return failures == 0


def free_display():
    """A display number no X server serves."""
    for n in range(850, 999):
        if not os.path.exists(f"/tmp/.X11-unix/X{n}") and not os.path.exists(f"/tmp/.X{n}-lock"):
            return f":{n}"
    raise SystemExit("no free display number to test with")


def no_display(args):
    ok = True
    env_unset = {k: v for k, v in os.environ.items() if k != "DISPLAY"}
    for label, env in (("DISPLAY unset", env_unset),
                       ("DISPLAY=" + free_display(), dict(env_unset, DISPLAY=free_display()))):
        tag = "nodisplay"
        for suffix in ("-image.png", "-visibility.png", "-mask.png"):
            path = os.path.join(args.out, tag + suffix)
            if os.path.exists(path):
                os.remove(path)
        r = subprocess.run(render_cmd(args, args.out, tag), capture_output=True, text=True,
                           env=env)
        left = [s for s in ("-image.png", "-visibility.png", "-mask.png")
                if os.path.exists(os.path.join(args.out, tag + s))]
        print(f"{label}: status {r.returncode}: {r.stderr.strip()}")
        if r.returncode != 2 or "xvfb-run -a" not in r.stderr or "Abort" in r.stderr or left:
            print(f"FAIL ({label}): want status 2, a message naming xvfb-run -a, no abort and "
                  f"no output (left: {left})")
            ok = False
        # Python: the visibility path reports instead of aborting.
        code = (
            "import sys, vtkshadow\n"
            "s = vtkshadow.vtkShadowScene()\n"
            f"assert s.Load({os.path.join(args.source, 'scenes', 'basic', 'two-lights.json')!r})\n"
            "t = vtkshadow.vtkShadowTechnique(); t.SetName('csm')\n"
            "v = vtkshadow.vtkShadowVisibility(); v.SetScene(s); v.SetTechnique(t)\n"
            "v.SetSize(64, 48)\n"
            "if v.Compute(): sys.exit('Compute() succeeded without a display')\n"
            "print(v.GetErrorMessage()); sys.exit(2)\n")
        r = subprocess.run([os.path.join(args.bin, "vtkshadow-python"), "-c", code],
                           capture_output=True, text=True, env=env)
        print(f"{label}, Python vtkShadowVisibility: status {r.returncode}: {r.stdout.strip()}")
        if r.returncode != 2 or "xvfb-run -a" not in r.stdout:
            print(f"FAIL ({label}, Python): want Compute() False with the message\n{r.stderr}")
            ok = False
    return ok


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--bin", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--runs", type=int, default=30)
    ap.add_argument("--skip-loop", action="store_true")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    ok = no_display(args)
    if not args.skip_loop:
        ok = xvfb_loop(args) and ok
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
