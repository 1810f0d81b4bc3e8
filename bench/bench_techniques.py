"""Frame time of every technique on scene files, interleaved, from
vtkshadow-render --stats (same camera orbit for all), written as a section of
docs/performance.md.

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_techniques.py \
      [--frames 20] [--rounds 3] [--size 800x600] SCENE...

Timings on a shared machine drift: techniques are interleaved per round and
each row also gives the median over rounds of (technique / none) of the same
round.
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

import vtkshadow

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Every registered technique, in registry order ("none" first: the ratios
# are against it).
TECHNIQUES = vtkshadow.vtkShadowTechnique.GetKnownTechniques().split()
BEGIN, END = "<!-- bench_techniques begin -->", "<!-- bench_techniques end -->"


def run(scene, technique, frames, size, out):
    stats = os.path.join(out, "stats.json")
    cmd = [os.path.join(REPO, "build", "bin", "vtkshadow-render"), scene, "--technique", technique,
           "--image", os.path.join(out, "image.png"), "--stats", stats, "--frames", str(frames),
           "--size", size, "--quiet"]
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed ({done.returncode}): {done.stderr.strip()}")
    with open(stats) as f:
        return json.load(f)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="+")
    ap.add_argument("--frames", type=int, default=20)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--output", default=os.path.join(REPO, "docs", "performance.md"))
    args = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as out:
        for scene in args.scenes:
            times = {t: [] for t in TECHNIQUES}
            ratios = {t: [] for t in TECHNIQUES}
            details = {}
            for r in range(args.rounds):
                order = TECHNIQUES[r % len(TECHNIQUES):] + TECHNIQUES[:r % len(TECHNIQUES)]
                this_round = {}
                for t in order:
                    s = run(scene, t, args.frames, args.size, out)
                    this_round[t] = s["shadowed_ms"]["median"]
                    times[t].append(this_round[t])
                    details[t] = s
                    print(f"[{os.path.basename(scene)}] round {r + 1}/{args.rounds} {t}: "
                          f"{this_round[t]:.1f} ms", file=sys.stderr)
                for t in TECHNIQUES:
                    ratios[t].append(this_round[t] / this_round["none"])
            for t in TECHNIQUES:
                tech = details[t].get("technique_stats", {})
                note = ""
                if t == "auto":
                    note = f"chose {tech.get('choice', '?')}"
                elif t == "csm" and tech.get("lights"):
                    px = [round(v, 2) for light in tech["lights"] for v in light.get("texel_px", [])]
                    note = f"texel px {px}"
                rows.append((os.path.relpath(scene, REPO), t, statistics.median(times[t]),
                             statistics.median(ratios[t]), details[t]["shadow_map_bytes"], note))
    command = ("tests/gl-run.sh build/bin/vtkshadow-python bench/bench_techniques.py "
               f"--frames {args.frames} --rounds {args.rounds} --size {args.size} "
               + " ".join(os.path.relpath(s, REPO) for s in args.scenes))
    lines = [BEGIN, "## Frame time of every technique", "",
             "Produced by (from the repository root):", "", "    " + command, "",
             f"Run {time.strftime('%Y-%m-%d %H:%M')}; llvmpipe on 2 shared cores, so compare "
             "within a scene: *ratio* is the median over rounds of technique / none in the same "
             "round (techniques interleaved, order rotated). Camera: vtkshadow-render's orbit.",
             "", "| scene | technique | ms/frame | ratio to none | shadow memory | note |",
             "|---|---|---:|---:|---:|---|"]
    for scene, t, ms, ratio, mem, note in rows:
        lines.append(f"| {scene} | {t} | {ms:.1f} | {ratio:.2f} | {mem / 2**20:.1f} MiB | {note} |")
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
