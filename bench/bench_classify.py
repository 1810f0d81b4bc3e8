"""Exact shadows at the cost of a map: raytrace with its classifier
(classify=1, the default) against every pixel traced (classify=0), csm,
auto at its default target and at max_error 0.05, and none, timed
interleaved in one window over vtkshadow-render's camera orbit, with the
fraction of (pixel, light) pairs the classifier leaves to rays and auto's
pick per light.

  python3 bench/bench_classify.py --bin build/bin --out DIR SCENE.json...
      [--size 800x600] [--frames 8] [--rounds 4] [--warmup 3] [--results docs/results.md]

Writes DIR/classify.json (one row per scene) and prints a Markdown table
(with --results, also puts it in that file's "Exact shadows at the cost of
a map" section, replacing the one there or appending it):
ms per frame (median over rounds x frames), each configuration against
none and against csm, the noise floor (none#2 / none), the traced fraction
per light, and the classifier's maps built over the orbit (one per hard
light when they are kept while only the camera moves)."""
import argparse
import json
import os
import subprocess
import sys

CONFIGS = ["raytrace:classify=0", "volume", "csm", "auto", "auto:max_error=0.05"]
SECTION = "## Exact shadows at the cost of a map"


def run(args, scene):
    """One interleaved vtkshadow-render run; its stats."""
    name = os.path.splitext(os.path.relpath(scene, args.scenes))[0].replace("/", "-")
    stats = os.path.join(args.out, name + ".json")
    cmd = [os.path.join(args.bin, "vtkshadow-render"), scene, "--technique", "raytrace",
           "--image", os.path.join(args.out, name + ".png"), "--stats", stats,
           "--size", args.size, "--frames", str(args.frames), "--rounds", str(args.rounds),
           "--warmup", str(args.warmup), "--quiet"]
    for c in CONFIGS:
        cmd += ["--time-also", c]
    print("bench_classify: %s" % name, file=sys.stderr, flush=True)
    subprocess.run(cmd, check=True, stderr=subprocess.DEVNULL)
    return name, json.load(open(stats))


def row(name, data):
    entries = {e["label"]: e for e in data["timing"]["entries"]}
    ms = {label: e["ms"]["median"] for label, e in entries.items()}
    t = entries["raytrace"]["technique_stats"]
    picks = {label: entries[label]["technique_stats"].get("light_choices", [])
             for label in ("auto", "auto:max_error=0.05")}
    trial = entries["auto:max_error=0.05"]["technique_stats"].get("exact_trial", {})
    return {
        "scene": name,
        "ms": ms,
        "noise_floor": data["noise_floor"]["ratio"],
        "traced_fraction_light": t.get("traced_fraction_light", []),
        "block_decided_pixels": t.get("block_decided_pixels", 0),
        "surface_pixels": t.get("surface_pixels", 0),
        "classify_maps_built": t.get("classify_maps_built", 0),
        "classify_build_ms": t.get("classify_build_ms", 0.0),
        "auto_picks": picks,
        "exact_trial": trial,
    }


def interleaved_faster(r):
    """The faster exact technique in the interleaved timing."""
    return "volume" if r["ms"]["volume"] <= r["ms"]["raytrace"] else "raytrace"


def trial_cell(r):
    """auto at 0.05's timings of the exact techniques, and whether what it
    drew is the faster of the two in the interleaved timing."""
    t = r["exact_trial"]
    if not t.get("lights"):
        return "not timed"
    faster = interleaved_faster(r)

    def timed(name):
        v = t.get(name + "_timed_ms")
        return "%.0f" % v if isinstance(v, (int, float)) else "untried"
    return "%s / %s: %s (%s)" % (timed("volume"), timed("raytrace"), t["drawn"],
                                  "as timed here" if t["drawn"] == faster else
                                  "interleaved: " + faster)


def table(rows):
    lines = ["| scene | none ms | raytrace (classifier) x none | every pixel traced x none | "
             "volume x none | csm x none | raytrace / csm | auto x none (picks) | "
             "auto at 0.05 x none (picks) | auto at 0.05 / csm | "
             "auto at 0.05's timings, volume / raytrace ms: drawn | "
             "traced fraction per light | maps built | none#2 / none |",
             "|---|---:|---:|---:|---:|---:|---:|---|---|---:|---|---|---:|---:|"]
    for r in rows:
        ms, none = r["ms"], r["ms"]["none"]

        def x(label):
            return "%.2f" % (ms[label] / none)
        lines.append("| %s | %.1f | %s | %s | %s | %s | %.2f | %s (%s) | %s (%s) | %.2f | %s | %s | %d | %.3f |" % (
            r["scene"], none, x("raytrace"), x("raytrace:classify=0"), x("volume"), x("csm"),
            ms["raytrace"] / ms["csm"], x("auto"), ", ".join(r["auto_picks"]["auto"]),
            x("auto:max_error=0.05"), ", ".join(r["auto_picks"]["auto:max_error=0.05"]),
            ms["auto:max_error=0.05"] / ms["csm"], trial_cell(r),
            " / ".join("%.2f" % f for f in r["traced_fraction_light"]),
            r["classify_maps_built"], r["noise_floor"]))
    return "\n".join(lines)


def summary(rows):
    """The goal of auto at 0.05 against csm on the scivis scenes, and how
    often the exact technique it drew is the interleaved timing's faster."""
    scivis = [r for r in rows if r["scene"].startswith("scivis-")]
    met = [r["scene"] for r in scivis if r["ms"]["auto:max_error=0.05"] <= 1.25 * r["ms"]["csm"]]
    exact = [r for r in rows if r["exact_trial"].get("lights")]
    agree = [r for r in exact if r["exact_trial"]["drawn"] == interleaved_faster(r)]
    return ["- auto at 0.05 within 1.25x csm's frame: %d of %d scivis scenes%s" % (
                len(met), len(scivis), " (%s)" % ", ".join(met) if met else ""),
            "- auto at 0.05 drew the exact technique the interleaved timing has faster on "
            "%d of the %d scenes where it timed volumes and rays" % (len(agree), len(exact)), ""]


def section(rows, args):
    """The results' section: how it was measured, then the table."""
    return "\n".join([
        SECTION, "",
        "raytrace with its classifier (docs/raytraced-shadows.md, \"The classifier\") against",
        "every pixel traced (`classify=0`), volume, csm and auto at its default target and at",
        "`max_error` 0.05, each as a multiple of `none`'s frame, %s, vtkshadow-render's camera" % args.size,
        "orbit, interleaved in one window (%d rounds of %d frames after %d warm-up frames, the" % (
            args.rounds, args.frames, args.warmup),
        "order rotated). *traced fraction*: the (pixel, light) pairs the classifier left to",
        "rays in the last frame (1: it stood aside, `vtkShadowRayClassifier::Policy`); *maps",
        "built*: over the whole orbit. *auto at 0.05's timings*: what it timed of volumes and",
        "rays on this machine and drew (docs/auto.md, \"Volumes or rays: timed on this",
        "machine\"), and whether that is the faster of the two rows volume and raytrace.",
        "Produced by", "",
        "    tests/gl-run.sh /usr/bin/python3 bench/bench_classify.py --bin build/bin \\",
        "        --out out/classify --results docs/results.md SCENES", ""]
        + summary(rows) + [table(rows), ""])


def put_section(path, text):
    """Replace the file's section (up to the next "## ") or append it."""
    with open(path) as f:
        doc = f.read()
    start = doc.find(SECTION + "\n")
    if start < 0:
        doc = doc.rstrip("\n") + "\n\n" + text
    else:
        end = doc.find("\n## ", start + len(SECTION))
        doc = doc[:start] + text + (doc[end + 1:] if end >= 0 else "")
    with open(path, "w") as f:
        f.write(doc)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--bin", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--scenes", default=os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                     "..", "scenes"),
                    help="the folder scene names are given relative to")
    ap.add_argument("--size", default="800x600")
    ap.add_argument("--frames", type=int, default=8)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=3)
    ap.add_argument("--results", help="a results.md whose section to write")
    ap.add_argument("scene", nargs="+")
    args = ap.parse_args()
    os.makedirs(args.out, exist_ok=True)
    rows = [row(*run(args, s)) for s in args.scene]
    with open(os.path.join(args.out, "classify.json"), "w") as f:
        json.dump(rows, f, indent=1)
    text = section(rows, args)
    print(text)
    if args.results:
        put_section(args.results, text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
