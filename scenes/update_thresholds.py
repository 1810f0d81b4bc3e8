"""Write or verify scenes/thresholds.json, the --check limits of vtkshadow-compare.

Regenerate after a deliberate change (review the diff: a limit that goes up
is a regression):

    tests/gl-run.sh build/bin/vtkshadow-compare scenes --out /tmp/t --scale 0.4 --no-cache
    python3 scenes/update_thresholds.py /tmp/t/results.json --write scenes/thresholds.json
    tests/gl-run.sh build/bin/vtkshadow-compare scenes/soft --out /tmp/t-soft --scale 0.4 \
        --cache /tmp/t/cache --techniques all,volume:soft_samples=64,planar:soft_samples=64
    python3 scenes/update_thresholds.py /tmp/t-soft/results.json --write scenes/thresholds.json

(the second run: the soft scenes with the technique variants that
harness.library.soft also runs; a scene's limits are replaced whole by the
rows of the results given, so that run has every technique too).

Several results files may be given (e.g. one per library group); scenes not
in them keep their limits from the current file (--base, default: the file
being written). Verify a thresholds file against a run without changing it:

    python3 scenes/update_thresholds.py --verify scenes/thresholds.json /tmp/t/results.json

Rules (docs/harness.md, "--check, thresholds and known failures"):

- Every row (scene, light, test) of a VTK technique or an EEVEE preset gets,
  for each metric of LIMITED, the limit ceil100(MEASURED * GEN_FACTOR +
  GEN_POINTS): measured at --scale 0.4 (320x240), 1.25 x + 0.25 points, so a
  regression fails --check while renderer noise does not. Rows of "cycles"
  (POV-Ray against Cycles) are bounded by the file's default (0.1% wrong),
  except where the reference has a penumbra (pen_pixels > 0: a light with a
  size, sampled by both renderers), which get the same generated limit.
- Rows are keyed by their test as the harness names it, technique variants
  included (vtk/volume:soft_samples=64, docs/harness.md "Technique
  variants"); each variant row gets its own limits like any other row.
- Exact techniques (EXACT: volume and raytrace, and their variants) also get, on every row of a
  hard light (no penumbra in the reference), the fixed bound of issues 12 and
  13 on wrong_band_pct (wrong pixels outside the one-pixel band along the
  reference's shadow boundary): 0.05%, not a generated limit. A row over it
  is refused like a 50% row: fix the technique or list the row as a known
  failure with its reason. --verify checks that each such row has it.
- A limit of REFUSED_PCT (50%) or more bounds nothing: the script refuses to
  write it (exit 2) and names the row. Such a row goes into
  known-failures.json (beside the thresholds file) with its reason; listed
  rows get no limit.
- --verify refuses (exit 1) any limit of 50% or more, any limit more than the
  MARGIN above the measured value (above MEASURED * MARGIN_FACTOR +
  MARGIN_POINTS = 1.5 x + 0.5 points, so a hand-raised limit is caught while
  a limit written by this script survives a measurement drifting down a
  little), and any row with neither a limit nor a known-failure entry. The
  same verification runs on every file this script writes.
- A row with no valid pixels (status "empty") gets no limit; --check fails it
  unless thresholds.json gives the reason under
  scenes[SCENE].no_valid_pixels[LIGHT] (kept from the base file).

The file is written to a temporary name and renamed, and only when every row
passes: a refusal leaves the old file untouched.
"""
import argparse
import json
import math
import os
import sys

LIMITED = ("wrong_pct", "false_shadow_pct")
GEN_FACTOR, GEN_POINTS = 1.25, 0.25
MARGIN_FACTOR, MARGIN_POINTS = 1.5, 0.5
REFUSED_PCT = 50.0
DESCRIPTION = ("Per-scene, per-light --check limits of vtkshadow-compare (docs/harness.md); "
               "measured at --scale 0.4, written by scenes/update_thresholds.py")
DEFAULT = {"cycles": {"wrong_pct": 0.1}}
# Issues 12 and 13: an exact technique is at most 0.05% wrong outside the
# one-pixel band, on every scene whose lights are points (no penumbra).
EXACT = {"vtk/volume": 0.05, "vtk/raytrace": 0.05}
EXACT_METRIC = "wrong_band_pct"


def load_known(path):
    """{(scene, test, light): reason} of known-failures.json (missing file: none)."""
    if not path or not os.path.exists(path):
        return {}
    with open(path) as f:
        data = json.load(f)
    return {(e["scene"], e["test"], int(e["light"])): e["reason"] for e in data["failures"]}


def rows_of(results_files):
    """[(scene, lights, row)] of every results.json given."""
    out = []
    for p in results_files:
        with open(p) as f:
            for s in json.load(f)["scenes"]:
                for r in s["results"]:
                    out.append((s["scene"], s["lights"], r))
    return out


def generated(value):
    return math.ceil((value * GEN_FACTOR + GEN_POINTS) * 100) / 100


# reflection_mae (scenes with mirrors, docs/reflections.md) is a colour error
# in [0, 1], not a percentage: 1.25 x + 0.005, rounded up to 1e-4.
def generated_mae(value):
    return math.ceil((value * GEN_FACTOR + 0.005) * 10000) / 10000


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


def base_test(test):
    """The test of a technique variant without its settings: vtk/volume for
    vtk/volume:soft_samples=64 (docs/harness.md, "Technique variants")."""
    return test.split(":", 1)[0]


def exact_bound(r):
    """The fixed wrong_band_pct bound of a row, or None when it has none.
    A variant of an exact technique is exact too (its settings sample lights
    with a size, which these rows do not have)."""
    if base_test(r["test"]) not in EXACT or (r.get("pen_pixels") or 0) > 0:
        return None
    return EXACT[base_test(r["test"])]


def verify(thresholds, rows, known):
    """Every problem of `thresholds` against the measured rows, one line each."""
    problems = []
    for scene, _, r in rows:
        key = (scene, r["test"], r["light"])
        if key in known or r["status"] != "ok":
            continue
        limits = row_limits(thresholds, scene, r)
        if not limits:
            problems.append("%s: no limit (and not a known failure)" % where(scene, r))
        if exact_bound(r) is not None and limits.get(EXACT_METRIC) != exact_bound(r):
            problems.append("%s: %s limit %s, but an exact technique on a hard light is bound "
                            "by %g" % (where(scene, r), EXACT_METRIC, limits.get(EXACT_METRIC),
                                       exact_bound(r)))
        for metric, limit in sorted(limits.items()):
            measured = r.get(metric)
            if metric.endswith("_pct") and limit >= REFUSED_PCT:
                problems.append("%s: %s limit %g is %g%% or more, which bounds nothing: list "
                                "the row in known-failures.json with its reason"
                                % (where(scene, r), metric, limit, REFUSED_PCT))
            elif measured is not None and limit > measured * MARGIN_FACTOR + MARGIN_POINTS:
                problems.append("%s: %s limit %g is more than the margin above the measured "
                                "%.4g (at most %.4g = %g x + %g): regenerate it"
                                % (where(scene, r), metric, limit, measured,
                                   measured * MARGIN_FACTOR + MARGIN_POINTS, MARGIN_FACTOR,
                                   MARGIN_POINTS))
    return problems


def generate(base, rows, known):
    """(new thresholds, refusals)."""
    out = {"description": DESCRIPTION, "default": base.get("default", DEFAULT),
           "scenes": dict(base.get("scenes", {}))}
    refused, fresh = [], {}
    for scene, lights, r in rows:
        entry = fresh.setdefault(scene, {})
        old = out["scenes"].get(scene, {})
        if "no_valid_pixels" in old:
            entry["no_valid_pixels"] = old["no_valid_pixels"]
        if r["test"] == "cycles":
            # POV-Ray against Cycles: the file's default bounds it, except
            # where the reference has a penumbra (a light with a size): both
            # renderers sample the light there, so their agreement gets a
            # limit from its measurement like every other row.
            if r["status"] == "ok" and (r.get("pen_pixels") or 0) > 0:
                limit = generated(r["wrong_pct"])
                entry.setdefault("cycles", {}).setdefault("wrong_pct", [None] * lights)[
                    r["light"]] = limit
            continue
        if (scene, r["test"], r["light"]) in known:
            continue
        if r["status"] == "error":
            refused.append("%s: the row failed (%s); no limit from a failed run"
                           % (where(scene, r), r.get("check", "error")))
            continue
        if r["status"] != "ok":
            continue
        for metric in LIMITED:
            limit = generated(r[metric])
            if limit >= REFUSED_PCT:
                refused.append("%s: %s measured %.4g, a limit would be %g (>= %g%%): list the "
                               "row in known-failures.json with its reason instead"
                               % (where(scene, r), metric, r[metric], limit, REFUSED_PCT))
                continue
            per_light = entry.setdefault(r["test"], {}).setdefault(metric, [None] * lights)
            per_light[r["light"]] = limit
        bound = exact_bound(r)
        if bound is not None:
            measured = r.get(EXACT_METRIC)
            if measured is None or measured > bound:
                refused.append("%s: %s measured %s, over the exact bound %g: fix the technique "
                               "or list the row in known-failures.json with its reason"
                               % (where(scene, r), EXACT_METRIC, measured, bound))
            else:
                entry.setdefault(r["test"], {}).setdefault(EXACT_METRIC, [None] * lights)[
                    r["light"]] = bound
        if r.get("reflection_mae") is not None:
            per_light = entry.setdefault(r["test"], {}).setdefault("reflection_mae", [None] * lights)
            per_light[r["light"]] = generated_mae(r["reflection_mae"])
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
    a = ap.parse_args()
    target = a.verify or a.write or os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                 "thresholds.json")
    known = load_known(a.known or os.path.join(os.path.dirname(os.path.abspath(target)),
                                               "known-failures.json"))
    rows = rows_of(a.results)
    if a.verify:
        with open(a.verify) as f:
            problems = verify(json.load(f), rows, known)
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
        write_atomic(a.write, text)
        print("update_thresholds: wrote %s (%d row(s))" % (a.write, len(rows)), file=sys.stderr)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
