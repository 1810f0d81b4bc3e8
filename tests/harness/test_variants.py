"""Technique variants in vtkshadow-compare --techniques (docs/harness.md,
"Technique variants"; issue 15).

    test_variants.py {usage,render} --bin BUILD/bin --source SRC --out DIR

usage   bad entries exit 2 with a message naming --techniques, the entry and
        what is wrong (unknown technique, malformed pair, non-number, unknown
        key, out-of-range value, a key or entry given twice), before anything
        is written: the output folder is not even created.
render  (needs an X display) scenes/soft/sphere-disk.json at --scale 0.25
        with volume:soft_samples=1 and volume:soft_samples=16 against POV-Ray:
        - rows, folders and the report are named by the full variant;
        - the settings reach vtkshadow-render: N = 1 (the hard shadow) has
          a penumbra error at least PEN_RATIO times that of N = 16 on every
          light, and their visibility images differ;
        - thresholds round trip: scenes/update_thresholds.py writes limits
          for the variant rows (verified by --verify), --check passes with
          them; without the N = 1 limits --check exits 3 naming the row
          (light 1), and a known failure listed for the variant (light 0)
          is reported as one.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys

PEN_RATIO = 2.0
BAD = [
    ("bogus", "unknown technique 'bogus'"),
    ("bogus:samples=4", "unknown technique 'bogus'"),
    ("volume:soft_samples", "expected KEY=NUMBER"),
    ("volume:", "expected KEY=NUMBER"),
    ("volume:=4", "expected KEY=NUMBER"),
    ("volume:soft_samples=abc", "the value of soft_samples is not a number (got 'abc')"),
    ("volume:soft_samples=", "the value of soft_samples is not a number (got '')"),
    ("volume:soft_samples=nan", "the value of soft_samples is not a number (got 'nan')"),
    ("volume:no_such_key=3", "technique volume has no setting 'no_such_key'"),
    ("volume:soft_samples=0", "out of range (got soft_samples=0;"),
    ("raytrace:samples=100000", "out of range (got samples=100000;"),
    ("volume:soft_samples=4:soft_samples=8", "the setting soft_samples is given twice"),
]
failures = []


def run(args, cmd, expect):
    p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if p.returncode != expect:
        failures.append("exit %d, expected %d: %s\n%s" % (p.returncode, expect, " ".join(cmd),
                                                           p.stdout[-3000:]))
    return p.stdout


def compare(args, out, techniques, *extra, expect=0):
    cmd = [os.path.join(args.bin, "vtkshadow-compare"),
           os.path.join(args.source, "scenes", "soft", "sphere-disk.json"), "--out", out,
           "--renderers", "vtk,povray", "--techniques", techniques, "--scale", "0.25",
           "--cache", os.path.join(args.out, "cache"),
           # Every run names the scene the same way (by its file name: the
           # thresholds file is not above it), so the limits written from
           # the first run apply to the --check runs.
           "--thresholds", os.path.join(args.out, "thresholds.json")] + list(extra)
    return run(args, cmd, expect)


def test_usage(args):
    cases = [(e, ["--techniques: '%s': " % e, w]) for e, w in BAD]
    cases.append(("volume,volume:soft_samples=2,volume", ["--techniques: 'volume' is given twice"]))
    for entry, words in cases:
        out = os.path.join(args.out, "bad")
        shutil.rmtree(out, ignore_errors=True)
        text = compare(args, out, entry, expect=2)
        for w in words:
            if w not in text:
                failures.append("%s: expected %r in the message, got: %s" % (entry, w, text.strip()))
        if os.path.exists(out):
            failures.append("%s: the output folder was created" % entry)
        print("%-40s -> %s" % (entry, text.strip().splitlines()[0] if text.strip() else ""))


def rows_of(out):
    with open(os.path.join(out, "results.json")) as f:
        return [r for s in json.load(f)["scenes"] for r in s["results"]]


def test_render(args):
    one, sixteen = "volume:soft_samples=1", "volume:soft_samples=16"
    out = os.path.join(args.out, "run")
    compare(args, out, "%s,%s" % (one, sixteen), "--keep-work")
    rows = {(r["test"], r["light"]): r for r in rows_of(out)}
    for k in (0, 1):
        a, b = rows.get(("vtk/" + one, k)), rows.get(("vtk/" + sixteen, k))
        if not a or not b:
            failures.append("light %d: no row named vtk/%s or vtk/%s: %s" % (k, one, sixteen,
                                                                             sorted(rows)))
            continue
        print("light %d: pen_mae N=1 %.4f, N=16 %.4f (pen px %d)" % (k, a["pen_mae"], b["pen_mae"],
                                                                    b["pen_pixels"]))
        if not (b["pen_pixels"] > 100 and a["pen_mae"] >= PEN_RATIO * b["pen_mae"]):
            failures.append("light %d: N=1 pen_mae %g is not %g x N=16's %g: the setting did not "
                            "reach the render" % (k, a["pen_mae"], PEN_RATIO, b["pen_mae"]))
        pa, pb = (os.path.join(out, "sphere-disk", "vtk", t, "light%d_visibility.png" % k)
                  for t in (one, sixteen))
        if not (os.path.exists(pa) and os.path.exists(pb)) or open(pa, "rb").read() == open(pb, "rb").read():
            failures.append("light %d: visibility images missing or identical: %s %s" % (k, pa, pb))
    with open(os.path.join(out, "results.csv")) as f:
        if ",vtk/%s,povray," % one not in f.read():
            failures.append("results.csv: no row named vtk/%s" % one)
    with open(os.path.join(out, "index.html")) as f:
        if "vtk/" + one not in f.read():
            failures.append("index.html: vtk/%s not shown" % one)
    round_trip(args, out, one, sixteen)


def round_trip(args, out, one, sixteen):
    upd = os.path.join(args.source, "scenes", "update_thresholds.py")
    th = os.path.join(args.out, "thresholds.json")  # the runs' --thresholds
    known = os.path.join(args.out, "known-failures.json")
    with open(known, "w") as f:
        json.dump({"failures": []}, f)
    run(args, [sys.executable, upd, os.path.join(out, "results.json"), "--write", th,
               "--base", os.path.join(args.out, "none.json"), "--known", known], 0)
    with open(th) as f:
        limits = json.load(f)
    entry = limits.get("scenes", {}).get("sphere-disk", {})
    if "vtk/" + one not in entry or "vtk/" + sixteen not in entry:
        failures.append("update_thresholds wrote no limits for the variants: %s" % sorted(entry))
        return
    run(args, [sys.executable, upd, "--verify", th, os.path.join(out, "results.json"),
               "--known", known], 0)
    compare(args, os.path.join(args.out, "check-ok"), "%s,%s" % (one, sixteen), "--check",
            "--known-failures", known, expect=0)
    # The N = 1 limits removed; light 0 of it listed as a known failure
    # (wrong_pct above 0: still failing), light 1 left without a limit.
    del entry["vtk/" + one]
    with open(th, "w") as f:
        json.dump(limits, f)
    with open(known, "w") as f:
        json.dump({"failures": [{"scene": "sphere-disk", "test": "vtk/" + one, "light": 0,
                                 "reason": "test_variants: listed on purpose",
                                 "fails_while": {"wrong_pct": 0.0},
                                 "at_most": {"wrong_pct": 100.0}}]}, f)
    text = compare(args, os.path.join(args.out, "check-bad"), "%s,%s" % (one, sixteen), "--check",
                   "--known-failures", known, expect=3)
    for w in ("scene sphere-disk, light 1, vtk/%s: no limit" % one,):
        if w not in text:
            failures.append("--check: expected %r in: %s" % (w, text[-2000:]))
    with open(os.path.join(args.out, "check-bad", "results.json")) as f:
        checks = {(r["test"], r["light"]): r.get("check", "") for s in json.load(f)["scenes"]
                  for r in s["results"]}
    print("check of the listed row: %r" % checks.get(("vtk/" + one, 0)))
    if not checks.get(("vtk/" + one, 0), "").startswith("known failure"):
        failures.append("the variant row listed in known-failures.json was not reported as a known "
                        "failure: %r" % checks.get(("vtk/" + one, 0)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("what", choices=("usage", "render"))
    ap.add_argument("--bin", required=True)
    ap.add_argument("--source", required=True)
    ap.add_argument("--out", required=True)
    args = ap.parse_args()
    shutil.rmtree(args.out, ignore_errors=True)
    os.makedirs(args.out)
    (test_usage if args.what == "usage" else test_render)(args)
    for f in failures:
        print("FAIL: " + f)
    print("%s: %s" % (args.what, "FAILED" if failures else "passed"))
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
