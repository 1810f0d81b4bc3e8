"""Write or verify scenes/thresholds.json, the --check limits of vtkshadow-compare.

Regenerate after a deliberate change (review the diff: a limit that goes up
is a regression). The library run is what the harness.library.* tests run
(docs/harness.md, "Writing limits"); with the shipped references it
renders only the VTK techniques:

    sh scripts/library-run.sh /tmp/t
    python3 scenes/update_thresholds.py /tmp/t/*/results.json --write scenes/thresholds.json

Verify a thresholds file against a run without changing it (the test
harness.thresholds does this on every CI run):

    python3 scenes/update_thresholds.py --verify scenes/thresholds.json /tmp/t/*/results.json

Rules (docs/harness.md, "--check, thresholds and known failures"):

- A limit is GEN_FACTOR (1.25) x the measured value plus an allowance of
  A pixels expressed in the metric's own denominator: A = ALLOW_PX (16) where
  the reference has no shadow, else min(16, max(1, shadow / 5)) with shadow
  the reference's shadow pixels, so that a lost shadow, however small, is
  more than the allowance. Rounded up to 0.01 (1e-4 for pen_mae,
  reflection_mae and colour_mae).
- Rows of our techniques (every vtk/<technique> but the controls vtk/none
  and vtk/vtk, variants included) bound wrong_pct, false_shadow_pct,
  wrong_of_shadow_pct (wrong pixels per pixel of the reference's shadow)
  and wrong_of_test_shadow_pct (per pixel of the technique's shadow).
  Where the reference has a penumbra or a partial shadow (pen_pixels > 0: a
  light with a size, or translucent casters) they also bound pen_mae
  (+ 0.01) and the 0.1 / 0.5 / 0.9 contour distances (+ 0.5 px), so that a
  hard shadow fails a soft row.
- On a tinted scene (an object with a coloured filter: the rows have
  colour_mae) they also bound colour_mae, the green and blue channels'
  mean error: GEN_FACTOR x measured + COLOUR_ALLOW (0.005).
- The controls vtk/none and vtk/vtk, and the EEVEE presets, bound wrong_pct
  and false_shadow_pct (regressions of VTK's own render).
- Rows of "cycles" (POV-Ray against Cycles) are bounded by the file's
  default (0.1% wrong), except where the reference has a penumbra, where
  both renderers sample the light and the row gets a generated wrong_pct.
  On a tinted scene the cycles row also gets a generated colour_mae (the
  check that both references tint the shadow alike).
- Exact techniques (EXACT: volume and raytrace, and their variants) also
  get, on every row of a hard light (the scene's light has no radius or
  angle; partial shadows of translucent casters included), the fixed 0.05%
  bound on wrong_band_pct (issues 12 and 13), not a generated limit.
- A wrong_pct or false_shadow_pct limit of REFUSED_PCT (50%) or more bounds
  nothing; nor does a limit set under which a render with no shadow
  (vtk/none's row of the same scene and light) or, on a row of a light with
  a size, a hard shadow (HARD_TEST, raytrace with one ray, run on the soft
  scenes) would pass. The script refuses to write either and names the row: such a row
  goes into known-failures.json with its reason.
- Known failures (known-failures.json) are bounded on both sides: fixed once
  no metric of fails_while is above its value, worse once a metric of
  at_most is above its value. --write rewrites each listed row's at_most
  from its measurement with the rule above.
- --verify refuses (exit 1) every such problem, any limit more than the
  margin above the measured value (MARGIN_FACTOR x measured + 2 allowances:
  a hand-raised limit), any row with neither a limit nor a known-failure
  entry, and a known failure whose at_most is under its measurement or over
  the margin. The same verification runs on every file this script writes.
- A row with no valid pixels (status "empty") gets no limit; --check fails it
  unless thresholds.json gives the reason under
  scenes[SCENE].no_valid_pixels[LIGHT] (kept from the base file).

Files are written to a temporary name and renamed, and only when every row
passes: a refusal leaves the old files untouched.
"""
import argparse
import json
import math
import os
import sys

GEN_FACTOR = 1.25
ALLOW_PX = 16
MARGIN_FACTOR = 1.5
REFUSED_PCT = 50.0
# The generated metrics relative to the frame.
FRAME_PCT = ("wrong_pct", "false_shadow_pct")
SHADOW_PCT = ("wrong_of_shadow_pct", "wrong_of_test_shadow_pct")
PENUMBRA = {"pen_mae": 0.01, "pen_contour_01_px": 0.5, "pen_contour_05_px": 0.5,
            "pen_contour_09_px": 0.5}
CONTROLS = ("vtk/none", "vtk/vtk")
SHADOWLESS_TEST = "vtk/none"
HARD_TEST = "vtk/raytrace:samples=1"
DESCRIPTION = ("Per-scene, per-light --check limits of vtkshadow-compare (docs/harness.md); "
               "measured at --scale 0.4, written by scenes/update_thresholds.py")
DEFAULT = {"cycles": {"wrong_pct": 0.1}}
# Issues 12 and 13: an exact technique is at most 0.05% wrong outside the
# one-pixel band, on every scene whose lights are points (no penumbra).
EXACT = {"vtk/volume": 0.05, "vtk/raytrace": 0.05}
EXACT_METRIC = "wrong_band_pct"
# Tinted scenes: the green and blue channels' mean error, and its allowance.
COLOUR = "colour_mae"
COLOUR_ALLOW = 0.005


def load_known(path):
    """(whole file, {(scene, test, light): entry}) of known-failures.json;
    a missing file has no entry."""
    if not path or not os.path.exists(path):
        return {"failures": []}, {}
    with open(path) as f:
        data = json.load(f)
    return data, {(e["scene"], e["test"], int(e["light"])): e for e in data["failures"]}


def rows_of(results_files):
    """[(scene, lights, row)] of every results.json given."""
    out = []
    for p in results_files:
        try:
            with open(p) as f:
                scenes = json.load(f)["scenes"]
        except (OSError, ValueError, KeyError) as e:
            print("update_thresholds: %s: not a results.json of vtkshadow-compare (%s); run "
                  "sh scripts/library-run.sh OUT first" % (p, e), file=sys.stderr)
            sys.exit(2)
        for s in scenes:
            sized = sized_lights(s.get("file"))
            for r in s["results"]:
                r["light_sized"] = sized.get(r["light"], False)
                out.append((s["scene"], s["lights"], r))
    return out


def sized_lights(path):
    """{light index: whether it has a size (radius or angle above 0)} of the
    scene file at `path` ({} when it cannot be read: no light counts as
    sized)."""
    try:
        with open(path) as f:
            lights = json.load(f)["lights"]
    except (OSError, ValueError, KeyError, TypeError):
        return {}
    return {k: (light.get("radius") or 0) > 0 or (light.get("angle") or 0) > 0
            for k, light in enumerate(lights)}


def base_test(test):
    """The test of a technique variant without its settings: vtk/volume for
    vtk/volume:soft_samples=64 (docs/harness.md, "Technique variants")."""
    return test.split(":", 1)[0]


def ours(test):
    return test.startswith("vtk/") and base_test(test) not in CONTROLS


def soft(r):
    """A row whose reference has a penumbra or a partial shadow (a light
    with a size, or translucent casters): the penumbra metrics apply."""
    return (r.get("pen_pixels") or 0) > 0


def sized(r):
    """A row of a light with a size: a hard shadow (HARD_TEST) must fail it.
    A partial shadow under a hard light (translucent casters) has no such
    control: vtk/none's row shows the shadow is not lost."""
    return soft(r) and r.get("light_sized", False)


def allowance_px(r):
    """Pixels of slack a limit gives over 1.25 x the measurement: fewer than
    the reference's shadow, so that losing it fails."""
    shadow = r.get("ref_shadow_pixels") or 0
    return ALLOW_PX if shadow == 0 else min(ALLOW_PX, max(1, shadow // 5))


def allowance(r, metric):
    """The allowance of `metric` in its own unit."""
    if metric in PENUMBRA:
        return PENUMBRA[metric]
    if metric == "reflection_mae":
        return 0.005
    if metric == COLOUR:
        return COLOUR_ALLOW
    denominator = {"wrong_of_shadow_pct": r.get("ref_shadow_pixels"),
                   "wrong_of_test_shadow_pct": r.get("test_shadow_pixels")}.get(
                       metric, r.get("compared_pixels"))
    return 100.0 * allowance_px(r) / max(denominator or 0, 1)


def generated(r, metric):
    step = 1e4 if metric in ("pen_mae", "reflection_mae", COLOUR) else 1e2
    return math.ceil((r[metric] * GEN_FACTOR + allowance(r, metric)) * step - 1e-9) / step


def tinted(r):
    """A row of a tinted scene: it has colour_mae."""
    return r.get(COLOUR) is not None


def limited_metrics(r):
    """The generated metrics of a row (of "cycles": beyond the default)."""
    if r["test"] == "cycles":
        return ["wrong_pct"] * soft(r) + [COLOUR] * tinted(r)
    if not ours(r["test"]):
        return list(FRAME_PCT)
    metrics = list(FRAME_PCT + SHADOW_PCT)
    if soft(r):
        metrics += sorted(PENUMBRA)
    if tinted(r):
        metrics.append(COLOUR)
    return metrics


def where(scene, r):
    return "scene %s, light %d, %s" % (scene, r["light"], r["test"])


def row_limits(thresholds, scene, r):
    """Limits of a row as vtkshadow-compare's --check reads them."""
    limits = {}
    levels = (thresholds.get("default", {}), thresholds.get("scenes", {}).get(scene, {}))
    for level in levels:
        for metric, v in level.get(r["test"], {}).items():
            if isinstance(v, list):
                v = v[r["light"]] if r["light"] < len(v) else None
                if v is None:
                    continue
            if v is None:
                limits.pop(metric, None)
            else:
                limits[metric] = v
    return limits


def passes(limits, r):
    """Whether row `r` passes every limit (as --check decides)."""
    return all(r.get(m) is not None and r[m] <= v for m, v in limits.items())


def exact_bound(r):
    """The fixed wrong_band_pct bound of a row, or None when it has none.
    A variant of an exact technique is exact too (its settings sample lights
    with a size, which these rows do not have)."""
    if base_test(r["test"]) not in EXACT or sized(r):
        return None
    return EXACT[base_test(r["test"])]


def index_rows(rows):
    return {(scene, r["test"], r["light"]): r for scene, _, r in rows if r["status"] == "ok"}


def bounds_nothing(limits, scene, r, by_key, require_controls):
    """Why `limits` of row `r` would let a shadowless render (or, on a soft
    row, a hard shadow) pass, or None. A control row the run does not have
    is a problem only with `require_controls` (the library run has both)."""
    if not ours(r["test"]) or r["test"] == HARD_TEST:
        return None
    controls = []
    if (r.get("ref_shadow_pixels") or 0) > 0:
        controls.append((SHADOWLESS_TEST, "a render with no shadow"))
    if sized(r):
        controls.append((HARD_TEST, "a hard shadow"))
    for test, what in controls:
        control = by_key.get((scene, test, r["light"]))
        if control is None and require_controls:
            return "the run has no %s row to test the limits against" % test
        if control is not None and passes(limits, control):
            return "%s (%s) passes them" % (what, test)
    return None


def frame_pct(metric):
    """A percentage of the frame, where a limit of REFUSED_PCT or more bounds
    nothing (as --check decides: percentages of the shadow, wrong_of_*, and
    the penumbra figures are not)."""
    return metric.endswith("_pct") and not metric.startswith(("wrong_of_", "pen_"))


def margin_problems(scene, r, metric, limit, what="limit"):
    measured = r.get(metric)
    if what == "limit" and frame_pct(metric) and limit >= REFUSED_PCT:
        return ["%s: %s limit %g is %g%% or more, which bounds nothing: list the row in "
                "known-failures.json with its reason" % (where(scene, r), metric, limit,
                                                         REFUSED_PCT)]
    if metric == EXACT_METRIC or measured is None:
        return []
    most = measured * MARGIN_FACTOR + 2 * allowance(r, metric) + 0.01
    if limit > most:
        return ["%s: %s %s %g is more than the margin above the measured %.4g (at most "
                "%.4g = %g x + 2 allowances): regenerate it"
                % (where(scene, r), metric, what, limit, measured, most, MARGIN_FACTOR)]
    return []


def verify_known(scene, r, entry):
    """Problems of a known failure's bounds against its measured row."""
    problems = []
    if not entry.get("at_most"):
        return ["%s: known failure without at_most (its upper bound): write it with --write"
                % where(scene, r)]
    for metric, bound in sorted(entry["at_most"].items()):
        measured = r.get(metric)
        if measured is not None and measured > bound:
            problems.append("%s: known failure got worse: %s = %.4g > at_most %g"
                            % (where(scene, r), metric, measured, bound))
        problems += margin_problems(scene, r, metric, bound, what="at_most")
    return problems


def verify(thresholds, rows, known, require_controls=False):
    """Every problem of `thresholds` against the measured rows, one line each."""
    problems = []
    by_key = index_rows(rows)
    for scene, _, r in rows:
        key = (scene, r["test"], r["light"])
        if r["status"] != "ok":
            continue
        if key in known:
            problems += verify_known(scene, r, known[key])
            continue
        limits = row_limits(thresholds, scene, r)
        if not limits:
            problems.append("%s: no limit (and not a known failure)" % where(scene, r))
            continue
        if exact_bound(r) is not None and limits.get(EXACT_METRIC) != exact_bound(r):
            problems.append("%s: %s limit %s, but an exact technique on a hard light is bound "
                            "by %g" % (where(scene, r), EXACT_METRIC, limits.get(EXACT_METRIC),
                                       exact_bound(r)))
        for metric in limited_metrics(r):
            if metric not in limits:
                problems.append("%s: no %s limit" % (where(scene, r), metric))
        # The default trust limit of POV-Ray against Cycles is a stated
        # bound, not a measurement's: no margin to keep to (its generated
        # limits have one).
        trusted = r["test"] == "cycles" and not soft(r)
        for metric, limit in sorted(limits.items()):
            if not trusted or metric == COLOUR:
                problems += margin_problems(scene, r, metric, limit)
        why = bounds_nothing(limits, scene, r, by_key, require_controls)
        if why:
            problems.append("%s: the limits bound nothing: %s; fix the technique or list the "
                            "row in known-failures.json with its reason" % (where(scene, r), why))
    return problems


def set_limit(entry, r, lights, metric, value):
    entry.setdefault(r["test"], {}).setdefault(metric, [None] * lights)[r["light"]] = value


def row_entry(r, lights, entry):
    """Writes the limits of one measured row into the scene's `entry`;
    returns the refusals."""
    refused = []
    for metric in limited_metrics(r):
        limit = generated(r, metric)
        if frame_pct(metric) and limit >= REFUSED_PCT:
            refused.append("%s measured %.4g, a limit would be %g (>= %g%%): list the row in "
                           "known-failures.json with its reason instead"
                           % (metric, r[metric], limit, REFUSED_PCT))
            continue
        set_limit(entry, r, lights, metric, limit)
    bound = exact_bound(r)
    if bound is not None:
        measured = r.get(EXACT_METRIC)
        if measured is None or measured > bound:
            refused.append("%s measured %s, over the exact bound %g: fix the technique or list "
                           "the row in known-failures.json with its reason"
                           % (EXACT_METRIC, measured, bound))
        else:
            set_limit(entry, r, lights, EXACT_METRIC, bound)
    if r.get("reflection_mae") is not None:
        set_limit(entry, r, lights, "reflection_mae", generated(r, "reflection_mae"))
    return refused


def generate(base, rows, known):
    """(new thresholds, refusals); the at_most of `known` entries is rewritten."""
    out = {"description": DESCRIPTION, "default": base.get("default", DEFAULT),
           "scenes": dict(base.get("scenes", {}))}
    refused, fresh = [], {}
    for scene, lights, r in rows:
        entry = fresh.setdefault(scene, {})
        old = out["scenes"].get(scene, {})
        if "no_valid_pixels" in old:
            entry["no_valid_pixels"] = old["no_valid_pixels"]
        key = (scene, r["test"], r["light"])
        if r["test"] == "cycles":
            # POV-Ray against Cycles: the file's default bounds it, except
            # where the reference has a penumbra (a light with a size): both
            # renderers sample the light there, so their agreement gets a
            # limit from its measurement like every other row; and on a
            # tinted scene their colour_mae.
            for metric in limited_metrics(r) if r["status"] == "ok" else []:
                set_limit(entry, r, lights, metric, generated(r, metric))
            continue
        if key in known:
            if r["status"] == "ok":
                known[key]["at_most"] = {m: generated(r, m)
                                         for m in sorted(known[key]["fails_while"])}
            continue
        if r["status"] == "error":
            refused.append("%s: the row failed (%s); no limit from a failed run"
                           % (where(scene, r), r.get("check", "error")))
        elif r["status"] == "ok":
            refused += ["%s: %s" % (where(scene, r), x) for x in row_entry(r, lights, entry)]
    out["scenes"].update(fresh)
    return out, refused


def write_atomic(path, text):
    tmp = "%s.tmp%d" % (path, os.getpid())
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results", nargs="+", help="results.json of vtkshadow-compare runs")
    ap.add_argument("--verify", metavar="THRESHOLDS", help="check this file, change nothing")
    ap.add_argument("--write", metavar="FILE", help="write here (default: stdout)")
    ap.add_argument("--base", metavar="FILE", help="limits of scenes not in the results "
                    "(default: the --write file)")
    ap.add_argument("--known", metavar="FILE", help="known failures (default: "
                    "known-failures.json beside the thresholds file)")
    ap.add_argument("--require-controls", action="store_true",
                    help="with --verify: every row whose reference has a shadow must be tested "
                    "against %s's row, every soft row against %s's" % (SHADOWLESS_TEST, HARD_TEST))
    a = ap.parse_args()
    target = a.verify or a.write or os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                 "thresholds.json")
    known_path = a.known or os.path.join(os.path.dirname(os.path.abspath(target)),
                                         "known-failures.json")
    known_file, known = load_known(known_path)
    rows = rows_of(a.results)
    if a.verify:
        with open(a.verify) as f:
            problems = verify(json.load(f), rows, known, a.require_controls)
        for p in problems:
            print("update_thresholds: REFUSED %s" % p, file=sys.stderr)
        print("update_thresholds: %s: %d row(s) verified, %d problem(s)"
              % (a.verify, len(rows), len(problems)), file=sys.stderr)
        sys.exit(1 if problems else 0)
    base_path = a.base or a.write
    base = {}
    if base_path and os.path.exists(base_path):
        with open(base_path) as f:
            base = json.load(f)
    out, refused = generate(base, rows, known)
    refused += verify(out, rows, known)
    for p in refused:
        print("update_thresholds: REFUSED %s" % p, file=sys.stderr)
    if refused:
        print("update_thresholds: %d refusal(s), nothing written" % len(refused), file=sys.stderr)
        sys.exit(2)
    text = json.dumps(out, indent=1, sort_keys=True) + "\n"
    if a.write:
        if known:
            write_atomic(known_path, json.dumps(known_file, indent=1) + "\n")
        write_atomic(a.write, text)
        print("update_thresholds: wrote %s (%d row(s))" % (a.write, len(rows)), file=sys.stderr)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
