"""Soft shadows: penumbra error against frame time for every soft technique
and sample count, with the Pareto front and Blender EEVEE's soft shadows as
the peer (issue 15, docs/soft-shadows.md).

  tests/gl-run.sh build/bin/vtkshadow-python bench/bench_soft.py --out DIR
      [--frames 15] [--rounds 4] [--warmup 5] [--noise-tolerance 0.03]
      [--scale 0.5] [--timing-scale 1] [--light 0] [--cache DIR]
      [--renderers povray,cycles,eevee,eevee-best] [SCENE...]

Default scenes: scenes/soft/*.json (lights with a radius or an angle). Per
scene:

- references through vtkshadow-compare (cached with --cache): POV-Ray's
  area light is the reference; Cycles, EEVEE and EEVEE at its best settings
  are scored against it by the harness, so Cycles' row is the references'
  own disagreement and EEVEE's the peer;
- every configuration of CONFIGS whose technique is registered, timed in one
  vtkshadow-render process, interleaved in blocks with the order changed
  every round and none timed twice as the noise floor (the scene's own size
  times --timing-scale);
- each configuration rendered at the scene's size times --scale and scored
  by vtkshadow-metrics against POV-Ray's visibility of light --light: the
  penumbra figures pen_mae (mean absolute visibility error inside the
  reference's penumbra, 0.02 < v < 0.98 dilated by one pixel), pen_bias and
  the width ratio (docs/metrics.md, "Penumbra metrics");
- the Pareto front of (time ratio to none, pen_mae).

Writes DIR/soft.json (every row) and DIR/soft.md (a Markdown section that
bench/make_results.py puts into docs/results.md). Progress goes to stderr.
"""
import argparse
import glob
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtkshadow_bench as vb  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

# (technique, [(setting, value)]): the soft settings of each technique, and
# the hard techniques as the baseline a soft technique must beat. planar
# averages soft_samples hard shadows from points on the light; raytrace
# traces `samples` rays per pixel towards the light's disk; csm filters by
# PCSS (its default for lights with a size: 16 blocker and 24 filter taps;
# soft=0 is the hard shadow of the light's centre, and a 32 / 64-tap
# variant; soft=2 averages soft_samples hard maps from points on the
# light, adaptive=1 stopping after 8 where they agree); volume averages
# soft_samples counts of shadow volumes from
# points on the light (1: the hard shadow of the light's centre); auto as it
# is by default.
CONFIGS = ([("planar", [("soft_samples", n)]) for n in (1, 4, 16, 64)] +
           [("raytrace", [("samples", n)]) for n in (1, 4, 16, 64, 128)] +
           [("csm", [("soft", 0)]), ("csm", []),
            ("csm", [("pcss_blocker_taps", 32), ("pcss_filter_taps", 64)])] +
           [("volume", [("soft_samples", n)]) for n in (1, 4, 16, 64)] +
           [("csm", [("soft", 2), ("soft_samples", n)]) for n in (4, 16, 64)] +
           [("csm", [("soft", 2), ("soft_samples", 64), ("adaptive", 1)])] +
           [("auto", [])])
PEERS = ("cycles", "eevee", "eevee-best")


def configs(scene, registered):
    """The CONFIGS that apply to `scene`: the technique registered, planar
    only where the scene has a receiver."""
    _, receivers = vb.scene_info(scene)
    return [(t, v) for t, v in CONFIGS
            if t in registered and (t != "planar" or receivers)]


def peer_rows(key, results_json, light):
    """Rows of the reference renderers scored by the harness against
    POV-Ray (Cycles, EEVEE): test name, pen figures, seconds per frame."""
    try:
        with open(results_json) as f:
            doc = json.load(f)
    except (OSError, ValueError) as e:
        vb.log("bench_soft: %s: no harness results (%s)" % (key, e))
        return []
    rows = []
    for sc in doc.get("scenes", []):
        if sc.get("scene", "").replace("/", "-") != key:
            continue
        seconds = sc.get("frame_seconds") or {}
        for r in sc.get("results", []):
            if r.get("test") in PEERS and r.get("light") == light:
                rows.append({"config": r["test"], "pen_mae": r.get("pen_mae"),
                             "pen_bias": r.get("pen_bias"),
                             "pen_width_ratio": r.get("pen_width_ratio"),
                             "seconds": seconds.get(r["test"])})
    return rows


def score(scene, tech, values, size, a, d, ref_vis, ref_mask):
    """pen figures of one configuration against the reference (or {})."""
    if not vb.run_render(scene, ["--technique", tech] + vb.render_args(values), size, a.light, d):
        return {}
    return vb.metrics(ref_vis, ref_mask, os.path.join(d, "visibility.png"),
                      os.path.join(d, "metrics.json"))


def bench_scene(scene, a, registered, refs_dir):
    key = vb.scene_key(scene)
    size0, _ = vb.scene_info(scene)
    size = (max(1, round(size0[0] * a.scale)), max(1, round(size0[1] * a.scale)))
    tsize = (max(1, round(size0[0] * a.timing_scale)), max(1, round(size0[1] * a.timing_scale)))
    cfgs = configs(scene, registered)
    labels = [vb.timing_label(t, v) for t, v in cfgs]
    out = os.path.join(a.out, key)
    st = vb.run_timing(scene, labels, tsize, out, (a.frames, a.rounds, a.warmup,
                                                   a.noise_tolerance))
    if st is None:
        sys.exit("bench_soft: %s: vtkshadow-render failed (see %s)" % (scene, out))
    entries = {e["label"]: e for e in st["timing"]["entries"]}
    ref_vis = os.path.join(refs_dir, key, "povray", "light%d_visibility.png" % a.light)
    ref_mask = os.path.join(refs_dir, key, "povray", "light%d_mask.png" % a.light)
    if not (os.path.exists(ref_vis) and os.path.exists(ref_mask)):
        sys.exit("bench_soft: %s: no POV-Ray reference at %s (see %s/refs.log)" % (
            key, ref_vis, a.out))
    rows = []
    for (tech, values), label in zip(cfgs, labels):
        e = entries[label]
        m = score(scene, tech, values, size, a, os.path.join(out, vb.config_dir(
            tech, ",".join("%s=%s" % kv for kv in values) or "default")), ref_vis, ref_mask)
        rows.append({"config": label, "ms": e["ms"]["median"],
                     "ratio": e["ratio_to_none"]["median"],
                     "ratio_min": e["ratio_to_none"]["min"], "ratio_max": e["ratio_to_none"]["max"],
                     "pen_pixels": m.get("pen_pixels"), "pen_mae": m.get("pen_mae"),
                     "pen_bias": m.get("pen_bias"), "pen_width_ratio": m.get("pen_width_ratio")})
        vb.log("bench_soft %s %s: %.1f ms (x%.2f), pen_mae %s" % (
            key, label, rows[-1]["ms"], rows[-1]["ratio"], vb.fmt(rows[-1]["pen_mae"], 4)))
    front = pareto(rows)
    for r in rows:
        r["front"] = r in front
    return {"scene": key, "size": size, "timing_size": tsize, "rows": rows,
            "noise_floor": st["noise_floor"], "none_ms": entries["none"]["ms"]["median"],
            "peers": peer_rows(key, os.path.join(refs_dir, "results.json"), a.light)}


def pareto(rows):
    """Rows not dominated in (time ratio, pen_mae), sorted by time."""
    pts = sorted((r for r in rows if r["pen_mae"] is not None),
                 key=lambda r: (r["ratio"], r["pen_mae"]))
    front, best = [], float("inf")
    for r in pts:
        if r["pen_mae"] < best:
            front.append(r)
            best = r["pen_mae"]
    return front


def section(results, cmd, a):
    lines = ["## Soft shadows: penumbra error against frame time", "",
             "Produced by `%s` (also run by `sh scripts/results.sh`). Scenes with lights with a "
             "size (scenes/soft/). Errors: light %d at %.2g x the scene's size against POV-Ray's "
             "area light (docs/harness.md), inside the reference's penumbra: pen_mae is the mean "
             "absolute visibility error, pen_bias its sign (< 0 too dark), width the penumbra "
             "width ratio (docs/metrics.md). Times: every configuration in one vtkshadow-render "
             "process at %.2g x the scene's size, interleaved (%d warm-up frames, %d rounds of "
             "%d frames, the order changed every round); x none is the median ratio to none of "
             "the same round, with the range over rounds. Front: on the Pareto front of (time, "
             "pen_mae). The peer rows are the harness's own renders scored against the same "
             "POV-Ray image: Cycles (the other reference, so its row is the references' own "
             "disagreement) and Blender EEVEE's soft shadows, with Blender's seconds per frame "
             "(offline, not comparable to the ratios)." % (
                 cmd, a.light, a.scale, a.timing_scale, a.warmup, a.rounds, a.frames), ""]
    for res in results:
        nf = res["noise_floor"]
        lines += ["### %s" % res["scene"], "",
                  "none: %.1f ms a frame at %dx%d; noise floor none#2 / none %.3f%s." % (
                      res["none_ms"], res["timing_size"][0], res["timing_size"][1],
                      nf["ratio"], " (TOO NOISY)" if nf["too_noisy"] else ""), "",
                  "| configuration | ms | x none [range] | pen_mae | pen_bias | width | front |",
                  "|---|---:|---:|---:|---:|---:|---|"]
        for r in res["rows"]:
            lines.append("| %s | %.1f | %.2f [%.2f-%.2f] | %s | %s | %s | %s |" % (
                r["config"], r["ms"], r["ratio"], r["ratio_min"], r["ratio_max"],
                vb.fmt(r["pen_mae"], 4), vb.fmt(r["pen_bias"], 4),
                vb.fmt(r["pen_width_ratio"], 2), "front" if r["front"] else ""))
        for p in res["peers"]:
            lines.append("| %s (peer) | %s s | - | %s | %s | %s | |" % (
                p["config"], vb.fmt(p["seconds"], 2), vb.fmt(p["pen_mae"], 4),
                vb.fmt(p["pen_bias"], 4), vb.fmt(p["pen_width_ratio"], 2)))
        lines.append("")
    return "\n".join(lines) + "\n"


def options():
    ap = argparse.ArgumentParser(prog="bench_soft.py", description=__doc__.split("\n")[0])
    ap.add_argument("scenes", nargs="*")
    ap.add_argument("--out", required=True)
    ap.add_argument("--frames", type=int, default=15)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--warmup", type=int, default=5)
    ap.add_argument("--noise-tolerance", type=float, default=0.03)
    ap.add_argument("--scale", type=float, default=0.5, help="size of the scored renders")
    ap.add_argument("--timing-scale", type=float, default=1.0, help="size of the timed frames")
    ap.add_argument("--light", type=int, default=0)
    ap.add_argument("--cache", default=None, help="reference cache of vtkshadow-compare")
    ap.add_argument("--renderers", default="povray,cycles,eevee,eevee-best",
                    help="harness renderers; povray (the reference) is required")
    a = ap.parse_args()
    vb.check_ranges(ap, vb.timing_checks(a) + [
        ("--scale", a.scale, 0 < a.scale <= 4, "a number in (0, 4]"),
        ("--timing-scale", a.timing_scale, 0 < a.timing_scale <= 4, "a number in (0, 4]"),
        ("--light", a.light, 0 <= a.light <= 7, "an integer in [0, 7]")])
    if "povray" not in a.renderers.split(","):
        ap.error("--renderers: povray is the reference and must be listed (got %r)" % a.renderers)
    a.scenes = a.scenes or sorted(glob.glob(os.path.join(REPO, "scenes", "soft", "*.json")))
    for s in a.scenes:
        if not os.path.isfile(s):
            ap.error("scene %r: no such file" % s)
    return a


def main():
    a = options()
    os.makedirs(a.out, exist_ok=True)
    vb.CACHE = os.path.abspath(a.cache) if a.cache else None
    registered = vb.registered_techniques()
    refs = vb.run_compare(a.scenes, a.out, a.scale, a.renderers, "refs")
    results = [bench_scene(s, a, registered, refs) for s in a.scenes]
    with open(os.path.join(a.out, "soft.json"), "w") as f:
        json.dump(results, f, indent=1)
    cmd = "tests/gl-run.sh build/bin/vtkshadow-python bench/bench_soft.py " + " ".join(
        sys.argv[1:])
    md = section(results, cmd, a)
    with open(os.path.join(a.out, "soft.md"), "w") as f:
        f.write(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
