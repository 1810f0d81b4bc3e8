"""Frame time of every technique on scene files, interleaved, from
vtkshadow-render --stats (same camera orbit for all), written as a section of
docs/performance.md.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_techniques.py \
      [--frames 15] [--rounds 4] [--warmup 5] [--size 800x600] SCENE...

Timings on a shared machine drift: per scene one vtkshadow-render process
times every technique in one window, interleaved in blocks with the order
changed every round, and each row gives the median over rounds of
(technique / none) of the same round; none#2 / none is the noise floor.
"""
import argparse
import os
import sys
import tempfile
import time

import vtkshadow

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from vtkshadow_bench import run_timing  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Every registered technique, in registry order ("none" first: the ratios
# are against it).
TECHNIQUES = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
BEGIN, END = "<!-- bench_techniques begin -->", "<!-- bench_techniques end -->"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--frames", type=int, default=15)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=5)
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--output", default=os.path.join(REPO, "docs", "performance.md"))
    args = ap.parse_args()
    try:
        size = tuple(int(v) for v in args.size.split("x"))
        assert len(size) == 2 and min(size) >= 1
    except (ValueError, AssertionError):
        ap.error(f"--size: expected WxH (got {args.size!r})")
    if not (1 <= args.frames and 1 <= args.rounds and 0 <= args.warmup):
        ap.error(f"--frames {args.frames} / --rounds {args.rounds} / --warmup {args.warmup}: "
                 "expected frames >= 1, rounds >= 1, warmup >= 0")
    rows, floors = [], []
    with tempfile.TemporaryDirectory() as out:
        for scene in args.scenes:
            st = run_timing(scene, TECHNIQUES, size, out, (args.frames, args.rounds,
                                                           args.warmup, 0.03))
            if st is None:
                sys.exit(f"bench_techniques: {scene}: vtkshadow-render failed")
            entries = {e["label"]: e for e in st["timing"]["entries"]}
            noise = st["noise_floor"]
            floors.append((os.path.relpath(scene, REPO), noise))
            for t in TECHNIQUES + ["none#2"]:
                e = entries[t]
                tech = e.get("technique_stats") or {}
                note = ""
                if t == "auto":
                    note = f"chose {tech.get('choice', '?')}"
                elif t == "csm" and tech.get("lights"):
                    px = [round(v, 2) for light in tech["lights"] for v in light.get("texel_px", [])]
                    note = f"texel px {px}"
                elif t == "none#2":
                    note = "noise floor" + (" TOO NOISY" if noise["too_noisy"] else "")
                rows.append((os.path.relpath(scene, REPO), t, e["ms"], e["ratio_to_none"],
                             e["shadow_map_bytes"], note))
    command = ("tests/gl-run.sh build/bin/vtkshadow-python bench/bench_techniques.py "
               f"--frames {args.frames} --rounds {args.rounds} --warmup {args.warmup} "
               f"--size {args.size} " + " ".join(os.path.relpath(s, REPO) for s in args.scenes))
    lines = [BEGIN, "## Frame time of every technique", "",
             "Produced by (from the repository root):", "", "    " + command, "",
             f"Run {time.strftime('%Y-%m-%d %H:%M')}; llvmpipe on 2 shared cores, so compare "
             "within a scene. Per scene one vtkshadow-render process times every technique in "
             f"one window, interleaved: {args.warmup} warm-up frames each, then {args.rounds} "
             f"rounds of one {args.frames}-frame block per technique, the order changed every "
             "round. *ms/frame*: median over rounds of the block medians [min-max over rounds]; "
             "*ratio*: median over rounds of technique / none in the same round [min-max]. "
             "none#2 is none timed again: the noise floor (TOO NOISY outside 1.00 +- 0.03). "
             "Camera: vtkshadow-render's orbit.",
             "", "| scene | technique | ms/frame [rounds] | ratio to none [rounds] | shadow memory "
             "| note |", "|---|---|---:|---:|---:|---|"]
    for scene, t, ms, ratio, mem, note in rows:
        lines.append(f"| {scene} | {t} | {ms['median']:.1f} [{ms['min']:.1f}-{ms['max']:.1f}] | "
                     f"{ratio['median']:.2f} [{ratio['min']:.2f}-{ratio['max']:.2f}] | "
                     f"{mem / 2**20:.1f} MiB | {note} |")
    lines += [""] + [f"- {scene}: noise floor none#2 / none = {n['ratio']:.3f} "
                     f"[{n['min']:.3f}-{n['max']:.3f}]"
                     f"{': TOO NOISY' if n['too_noisy'] else ': within 1.00 +- 0.03'}"
                     for scene, n in floors]
    lines += ["", END]
    text = open(args.output).read() if os.path.exists(args.output) else "# vtkshadow results\n"
    if BEGIN in text and END in text:
        text = text[:text.index(BEGIN)] + "\n".join(lines) + text[text.index(END) + len(END):]
    else:
        text = text.rstrip() + "\n\n" + "\n".join(lines) + "\n"
    with open(args.output, "w") as f:
        f.write(text)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
