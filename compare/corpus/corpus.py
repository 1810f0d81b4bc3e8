#!/usr/bin/env python3
"""The real-client corpus: third-party example programs run unmodified with
vtkshadow.enable_shadows injected (run_example.py), every technique
compared with raytrace (the exact reference) and with none.

  corpus.py discover [--python PY] [--out DIR] [--jobs 2] [--timeout 20]
      run every candidate example once with technique none and write
      DIR/discover.json (status, seconds, props): the input for choosing
      corpus.json's include/exclude lists.
  corpus.py run [--python PY] [--out DIR] [--subset ctest] [--only NAME...]
                [--techniques T,...] [--markdown FILE] [--sabotage KIND
                --sabotage-technique T] [--as none=csm] [--expect-fail CHECK]
      run the corpus, print one progress line per run with an ETA, write
      DIR/corpus.json and the markdown table; exit 1 when a check fails
      (a failure corpus.json lists as known is reported, not counted).
      --expect-fail CHECK inverts the verdict for negative controls: exit 0
      only when CHECK (crash, error, vanish, bound, none-lighting) failed.

Checks per example and technique (docs/corpus.md says why):
  crash         the program ran and captured a frame (exit 0, no timeout);
  error         no VTK error after enable_shadows (vtkStringOutputWindow),
                no "ERROR" line in the program's stderr;
  vanish        the foreground without shadows (technique none), eroded by
                2 px, lies within the technique's foreground but for at
                most VANISH_PX pixels;
  bound         differing(T, raytrace) <= the technique's bound (percent
                of the frame);
  shadow        where the example has a shadow (shadow px: pixels differing
                between none and raytrace, at least MIN_SHADOW_PX), the
                pixels T differs from raytrace are at most the technique's
                shadow share of them plus SHADOW_ALLOWANCE_PX: a lost shadow
                differs on all of them, so it fails however small the
                shadow is in the frame;
  none-lighting where nothing casts (auto chooses none for every light, or
                raytrace's frame equals none's), differing(T, none) <=
                NONE_BOUND.
differing(A, B): percent of the frame's pixels p whose colour differs by
more than DIFF_LEVEL/255 in some channel from every pixel of the other
frame's 3x3 neighbourhood of p, either way round (a 1-px shift of an
edge is not a difference; a shadow lost or added is).
"""
import argparse
import json
import os
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TECHNIQUES = ["raytrace", "none", "vtk", "planar", "csm", "auto", "volume"]
DIFF_LEVEL = 32
VANISH_PX = 20
NONE_BOUND = 0.3
NOTHING_CASTS_PCT = 0.05
# vtk is VTK's own vtkShadowMapPass: its lighting is not VTK's default
# lighting even where nothing casts, so it is held to crash/error/vanish only.
NO_LIGHTING_CHECK = {"vtk"}
MIN_SHADOW_PX = 50
SHADOW_ALLOWANCE_PX = 16
CHECKS = ["crash", "error", "vanish", "bound", "shadow", "none-lighting"]


def load_corpus(path=None):
    with open(path or os.path.join(HERE, "corpus.json")) as f:
        return json.load(f)


def default_python():
    return os.path.join(ROOT, "build", "bin", "vtkshadow-python")


def run_one(python, example, technique, prefix, timeout, sabotage=None):
    cmd = [python, os.path.join(HERE, "run_example.py"), "--example", example,
           "--technique", technique, "--out", prefix]
    if sabotage:
        cmd += ["--sabotage", sabotage]
    t0 = time.time()
    try:
        proc = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout,
                              stdin=subprocess.DEVNULL)
        code, out, err = proc.returncode, proc.stdout, proc.stderr
    except subprocess.TimeoutExpired as e:
        code, out, err = "timeout", e.stdout or "", e.stderr or ""
        out = out.decode(errors="replace") if isinstance(out, bytes) else out
        err = err.decode(errors="replace") if isinstance(err, bytes) else err
    seconds = time.time() - t0
    result = {"exit": code, "seconds": round(seconds, 2)}
    try:
        with open(prefix + ".json") as f:
            result.update(json.load(f))
    except (OSError, ValueError):
        pass
    if code == "timeout":
        result["status"] = "timeout"
    elif code == 1:
        result["status"] = "exception"  # a Python exception (the example's or ours)
    elif code != 0 and code != 3:
        result["status"] = "crash"  # a signal or another exit status
    result.setdefault("status", "crash")
    result["stderr_errors"] = [ln for ln in err.splitlines()
                              if "ERROR" in ln or "ERR|" in ln][:20]
    result["stderr_tail"] = err.splitlines()[-8:]
    return result


# ---- image metrics -------------------------------------------------------

def _shifts(a):
    """The 9 one-pixel shifts of a (edge-replicated)."""
    p = np.pad(a, ((1, 1), (1, 1), (0, 0)), mode="edge")
    h, w = a.shape[:2]
    return [p[1 + dy:1 + dy + h, 1 + dx:1 + dx + w] for dy in (-1, 0, 1) for dx in (-1, 0, 1)]


def _one_way(a, b):
    a16 = a.astype(np.int16)
    best = None
    for s in _shifts(b.astype(np.int16)):
        d = np.abs(a16 - s).max(axis=2)
        best = d if best is None else np.minimum(best, d)
    return best > DIFF_LEVEL


def differing_mask(a, b):
    return _one_way(a, b) | _one_way(b, a)


def differing_pct(a, b):
    if a.shape != b.shape:
        return 100.0
    return 100.0 * float(differing_mask(a, b).mean())


def erode(mask, n):
    for _ in range(n):
        p = np.pad(mask, 1, mode="constant", constant_values=False)
        h, w = mask.shape
        out = np.ones_like(mask)
        for dy in (-1, 0, 1):
            for dx in (-1, 0, 1):
                out &= p[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
        mask = out
    return mask


def vanished_px(fg_none, fg_t):
    if fg_none.shape != fg_t.shape:
        return int(fg_none.sum())
    return int((erode(fg_none, 2) & ~fg_t).sum())


# ---- verdicts ------------------------------------------------------------

def nothing_casts(runs, frames):
    """True when auto chose none for every light, or raytrace equals none."""
    auto = runs.get("auto", {})
    choices = [s.get("choice") for s in auto.get("stats", []) if s]
    if choices and all(c == "none" for c in choices):
        return True, "auto chooses none"
    if "raytrace" in frames and "none" in frames:
        pct = differing_pct(frames["raytrace"]["rgb"], frames["none"]["rgb"])
        if pct <= NOTHING_CASTS_PCT:
            return True, f"raytrace = none ({pct:.3f}%)"
    return False, ""


def bound_for(entry, technique, defaults):
    bounds = dict(defaults)
    bounds.update(entry.get("bounds", {}))
    return bounds.get(technique)


def shadow_check(entry, technique, wrong, shadow_px, shares):
    """(ok, detail) of the shadow check for a technique that differs from
    raytrace on `wrong` pixels (None: frames of different sizes), or None
    where it does not apply."""
    share = bound_for(entry, technique, shares)
    if share is None or shadow_px < MIN_SHADOW_PX or wrong is None:
        return None
    limit = share * shadow_px + SHADOW_ALLOWANCE_PX
    return (wrong <= limit, f"{wrong} px <= {share} x {shadow_px} shadow px + "
            f"{SHADOW_ALLOWANCE_PX}")


def judge(entry, runs, frames, defaults, shares=None):
    """Fill each run's checks {check: (ok, detail)}."""
    casts_none, why = nothing_casts(runs, frames)
    none_frame = frames.get("none")
    ref = frames.get("raytrace")
    shadow_px = 0
    if ref is not None and none_frame is not None and \
            ref["rgb"].shape == none_frame["rgb"].shape:
        shadow_px = int(differing_mask(none_frame["rgb"], ref["rgb"]).sum())
    for t, run in runs.items():
        checks = {}
        ok_run = run.get("status") == "ok" and t in frames
        checks["crash"] = (ok_run, run.get("status", "?") + f" exit {run.get('exit')}")
        # VTK errors after enable_shadows, and "ERROR" lines in stderr beyond
        # those of the run without shadows (the example's own)
        extra = len(run.get("stderr_errors", [])) - len(runs.get("none", {}).get(
            "stderr_errors", [])) if t != "none" else 0
        errs = run.get("errors", []) + run.get("stderr_errors", [])[:max(extra, 0)]
        checks["error"] = (ok_run and not errs, f"{len(errs)} error(s)" +
                           (": " + errs[0].replace("\n", " ")[:160] if errs else ""))
        if ok_run and none_frame is not None:
            v = vanished_px(none_frame["fg"], frames[t]["fg"])
            checks["vanish"] = (v <= VANISH_PX, f"{v} px")
        if ok_run and ref is not None:
            # One mask for the frame bound and the shadow check.
            wrong, pct = None, 100.0
            if frames[t]["rgb"].shape == ref["rgb"].shape:
                mask = differing_mask(frames[t]["rgb"], ref["rgb"])
                wrong, pct = int(mask.sum()), 100.0 * float(mask.mean())
            run["diff_raytrace_pct"] = round(pct, 3)
            bound = bound_for(entry, t, defaults)
            if bound is not None:
                checks["bound"] = (pct <= bound, f"{pct:.2f}% <= {bound}%")
            shadow = shadow_check(entry, t, wrong, shadow_px, shares or {})
            if shadow is not None:
                checks["shadow"] = shadow
            run["shadow_px"] = shadow_px
        if ok_run and none_frame is not None:
            pct_none = differing_pct(frames[t]["rgb"], none_frame["rgb"])
            run["diff_none_pct"] = round(pct_none, 3)
            if casts_none and t not in NO_LIGHTING_CHECK:
                checks["none-lighting"] = (pct_none <= NONE_BOUND,
                                           f"{pct_none:.2f}% <= {NONE_BOUND}% ({why})")
        if ok_run and runs.get("none", {}).get("frame_ms_median"):
            run["time_ratio"] = round(run["frame_ms_median"] / runs["none"]["frame_ms_median"], 2)
        run["checks"] = {k: [bool(v[0]), v[1]] for k, v in checks.items()}
    return casts_none, why


def known(entry, technique, check, everywhere=()):
    for k in list(entry.get("known_failures", [])) + list(everywhere):
        if k["technique"] in (technique, "*") and k["check"] in (check, "*"):
            return k
    return None


# ---- the run -------------------------------------------------------------

def load_frame(prefix):
    try:
        with np.load(prefix + ".npz") as d:
            return {"rgb": d["rgb"], "fg": d["fg"]}
    except (OSError, ValueError, KeyError):
        return None


def selected(corpus, args):
    entries = corpus["include"]
    if args.subset:
        names = set(corpus["subsets"][args.subset])
        entries = [e for e in entries if e["name"] in names]
    if args.only:
        entries = [e for e in entries if e["name"] in args.only]
    return entries


def example_path(corpus, entry):
    return os.path.join(corpus["roots"][entry["root"]], entry["path"])


def run_example(corpus, entry, techniques, args, progress):
    name = entry["name"]
    outdir = os.path.join(args.out, name)
    os.makedirs(outdir, exist_ok=True)
    runs, frames = {}, {}
    for t in techniques:
        run_as = args.as_map.get(t, t)
        prefix = os.path.join(outdir, t)
        for ext in (".json", ".npz", ".png"):
            if os.path.exists(prefix + ext):
                os.remove(prefix + ext)
        sab = args.sabotage if args.sabotage and t == args.sabotage_technique else None
        run = run_one(args.python, example_path(corpus, entry), run_as, prefix,
                      args.timeout, sab)
        if run_as != t:
            run["ran_as"] = run_as
        runs[t] = run
        frame = load_frame(prefix) if run.get("status") == "ok" else None
        if frame is not None:
            frames[t] = frame
        progress(name, t, run)
    casts_none, why = judge(entry, runs, frames, corpus["bounds"],
                            corpus.get("shadow_shares"))
    return {"name": name, "path": entry["path"], "nothing_casts": casts_none,
            "nothing_casts_why": why, "runs": runs}


def failures_of(corpus_entry, result, everywhere=()):
    failed, known_failed = [], []
    for t, run in result["runs"].items():
        for check, (ok, detail) in run.get("checks", {}).items():
            if ok:
                continue
            k = known(corpus_entry, t, check, everywhere)
            item = {"example": result["name"], "technique": t, "check": check,
                    "detail": detail}
            if k:
                item["known"] = k.get("reason", "")
                known_failed.append(item)
            else:
                failed.append(item)
    return failed, known_failed


def make_progress(total):
    state = {"done": 0, "t0": time.time()}

    def progress(name, technique, run):
        state["done"] += 1
        elapsed = time.time() - state["t0"]
        eta = elapsed / state["done"] * (total - state["done"])
        print(f"[{state['done']}/{total}] {name} {technique}: {run.get('status')} "
              f"{run.get('seconds')} s; elapsed {elapsed:.0f} s, ETA {eta:.0f} s", flush=True)
    return progress


def cmd_run(args):
    corpus = load_corpus(args.corpus)
    entries = selected(corpus, args)
    techniques = args.techniques.split(",") if args.techniques else TECHNIQUES
    os.makedirs(args.out, exist_ok=True)
    progress = make_progress(len(entries) * len(techniques))
    t0 = time.time()
    results, failed, known_failed = [], [], []
    for entry in entries:
        result = run_example(corpus, entry, techniques, args, progress)
        results.append(result)
        f, k = failures_of(entry, result, corpus.get("known_failures", []))
        failed += f
        known_failed += k
    modules = sorted({run.get("vtkshadow_module") for res in results
                      for run in res["runs"].values() if run.get("vtkshadow_module")})
    print(f"corpus: vtkshadow imported from {', '.join(modules) or '(no run got that far)'} "
          f"by {args.python}")
    if args.require_module and any(not m.startswith(args.require_module) for m in modules):
        print(f"FAIL  vtkshadow was not imported from {args.require_module}")
        failed.append({"example": "-", "technique": "-", "check": "module",
                       "detail": f"vtkshadow from {modules}, not {args.require_module}"})
    report = {"command": " ".join(sys.argv), "python": args.python,
              "vtkshadow_modules": modules,
              "seconds": round(time.time() - t0, 1), "techniques": techniques,
              "bounds": corpus["bounds"], "shadow_shares": corpus.get("shadow_shares"),
              "min_shadow_px": MIN_SHADOW_PX, "shadow_allowance_px": SHADOW_ALLOWANCE_PX,
              "diff_level": DIFF_LEVEL, "vanish_px": VANISH_PX,
              "none_bound": NONE_BOUND, "results": results, "failures": failed,
              "known_failures": known_failed}
    with open(os.path.join(args.out, "corpus.json"), "w") as f:
        json.dump(report, f, indent=1)
    if args.markdown:
        from corpus_report import write_markdown
        write_markdown(report, corpus, args.markdown)
    return verdict(report, args)


def verdict(report, args):
    for item in report["known_failures"]:
        print(f"KNOWN {item['example']} {item['technique']} {item['check']}: "
              f"{item['detail']} ({item['known']})")
    for item in report["failures"]:
        print(f"FAIL  {item['example']} {item['technique']} {item['check']}: {item['detail']}")
    n = len(report["failures"])
    print(f"corpus: {len(report['results'])} example(s), {n} failure(s), "
          f"{len(report['known_failures'])} known failure(s), {report['seconds']} s; "
          f"results in {args.out}")
    if args.expect_fail:
        hit = [i for i in report["failures"] if i["check"] == args.expect_fail]
        print(("ok   " if hit else "FAIL ") + f"negative control: check '{args.expect_fail}' "
              f"{'reports' if hit else 'does not report'} the sabotaged run")
        return 0 if hit else 1
    return 1 if n else 0


def cmd_rejudge(args):
    """Judge again the frames of an earlier run (DIR/corpus.json and its
    images) with the current corpus.json bounds and known failures."""
    corpus = load_corpus(args.corpus)
    with open(os.path.join(args.out, "corpus.json")) as f:
        report = json.load(f)
    entries = {e["name"]: e for e in corpus["include"]}
    report["failures"], report["known_failures"] = [], []
    for result in report["results"]:
        entry = entries.get(result["name"], {"name": result["name"]})
        frames = {}
        for t in result["runs"]:
            frame = load_frame(os.path.join(args.out, result["name"], t))
            if frame is not None and result["runs"][t].get("status") == "ok":
                frames[t] = frame
        casts_none, why = judge(entry, result["runs"], frames, corpus["bounds"],
                                corpus.get("shadow_shares"))
        result["nothing_casts"], result["nothing_casts_why"] = casts_none, why
        f, k = failures_of(entry, result, corpus.get("known_failures", []))
        report["failures"] += f
        report["known_failures"] += k
    report["bounds"] = corpus["bounds"]
    report["shadow_shares"] = corpus.get("shadow_shares")
    with open(os.path.join(args.out, "corpus.json"), "w") as f:
        json.dump(report, f, indent=1)
    if args.markdown:
        from corpus_report import write_markdown
        write_markdown(report, corpus, args.markdown)
    return verdict(report, args)


def cmd_discover(args):
    corpus = load_corpus(args.corpus)
    files = []
    for root_name, root in corpus["roots"].items():
        for dirpath, _, names in os.walk(root):
            for n in sorted(names):
                if n.endswith(".py") and n != "__init__.py":
                    files.append((root_name, os.path.relpath(os.path.join(dirpath, n), root)))
    files.sort()
    os.makedirs(args.out, exist_ok=True)
    from concurrent.futures import ThreadPoolExecutor
    progress = make_progress(len(files))

    def one(item):
        root_name, rel = item
        prefix = os.path.join(args.out, "discover", root_name, rel.replace("/", "__")[:-3])
        os.makedirs(os.path.dirname(prefix), exist_ok=True)
        run = run_one(args.python, os.path.join(corpus["roots"][root_name], rel), "none",
                      prefix, args.timeout)
        progress(rel, "none", run)
        keep = {k: run.get(k) for k in ("status", "exit", "seconds", "props", "renderers",
                                        "errors", "errors_before", "stderr_tail",
                                        "frame_ms_median", "detected_receivers")}
        keep["fg_pct"] = None
        frame = load_frame(prefix)
        if frame is not None:
            keep["fg_pct"] = round(100.0 * float(frame["fg"].mean()), 2)
        return {"root": root_name, "path": rel, **keep}
    with ThreadPoolExecutor(args.jobs) as pool:
        found = list(pool.map(one, files))
    with open(os.path.join(args.out, "discover.json"), "w") as f:
        json.dump(found, f, indent=1)
    return 0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("command", choices=["discover", "run", "rejudge"])
    ap.add_argument("--python", default=default_python())
    ap.add_argument("--out", default=os.path.join(ROOT, "build", "corpus-out"))
    ap.add_argument("--corpus", help="corpus.json (default: beside this script)")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--subset")
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--techniques")
    ap.add_argument("--markdown")
    ap.add_argument("--sabotage", choices=["hide", "error", "crash", "light"])
    ap.add_argument("--sabotage-technique", default="csm")
    ap.add_argument("--as", dest="as_list", default="",
                    help="T=U,...: run technique U where T is asked (negative controls)")
    ap.add_argument("--expect-fail", choices=CHECKS)
    ap.add_argument("--require-module",
                    help="fail unless vtkshadow is imported from under this directory "
                         "(e.g. /usr/lib/python3/dist-packages: the installed package)")
    args = ap.parse_args()
    args.as_map = dict(p.split("=") for p in args.as_list.split(",") if p)
    args.out = os.path.abspath(args.out)
    sys.path.insert(0, HERE)
    return {"discover": cmd_discover, "run": cmd_run, "rejudge": cmd_rejudge}[args.command](args)


if __name__ == "__main__":
    sys.exit(main())
