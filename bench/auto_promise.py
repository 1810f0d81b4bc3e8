"""auto's promise on the library: for every scene and light, what auto picks
and how wrong it is (wrong_pct against POV-Ray) at its default target and at
max_error 0.05, next to the best exact technique's figure (docs/auto.md,
"Does auto keep its promise").

Inputs are two vtkshadow-compare runs at the library's size (320x240):
LIBRARY, a library run (sh scripts/library-run.sh LIBRARY all: every
technique, auto at its default target), and STRICT, the same scenes with
--techniques auto:max_error=0.05. auto's picks come from vtkshadow-render's
stats at each target (light_choices; the met flag of each light's general
pick). Prints the markdown table and the summary; --out keeps the stats.

  auto_promise.py --bin build/bin --library LIBRARY --strict STRICT --out DIR
      [--groups basic,cad,...] [--size 320x240]
"""
import argparse
import glob
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes")
EXACT = ("vtk/raytrace", "vtk/volume", "vtk/planar")
STRICT_TEST = "vtk/auto:max_error=0.05"


def wrong_pct(folder, groups):
    """(scene, light) -> {test: wrong_pct} against POV-Ray."""
    rows = {}
    for group in groups:
        for path in glob.glob(os.path.join(folder, group, "results.json")):
            with open(path) as f:
                for scene in json.load(f)["scenes"]:
                    for r in scene["results"]:
                        if r["reference"] == "povray":
                            key = (scene["scene"], r["light"])
                            rows.setdefault(key, {})[r["test"]] = r["wrong_pct"]
    return rows


def picks(args, scene, target):
    """auto's technique per light and whether each general pick met the target."""
    base = os.path.join(args.out, "%s-%s" % (scene.replace("/", "_"), target))
    subprocess.run([os.path.join(args.bin, "vtkshadow-render"),
                    os.path.join(SCENES, scene + ".json"), "--technique", "auto",
                    "--max-error", target, "--size", args.size, "--image", base + ".png",
                    "--stats", base + ".json", "--frames", "1", "--rounds", "1",
                    "--warmup", "0", "--quiet"], check=True, stderr=subprocess.DEVNULL)
    with open(base + ".json") as f:
        t = json.load(f)["technique_stats"]
    met = {g["light"]: g.get("met", True) for g in t.get("general", [])}
    return t["light_choices"], met


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--bin", required=True)
    p.add_argument("--library", required=True)
    p.add_argument("--strict", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--groups", default="basic,cad,hard,mirror,primitives,scivis,translucent")
    p.add_argument("--size", default="320x240")
    args = p.parse_args()
    groups = args.groups.split(",")
    os.makedirs(args.out, exist_ok=True)
    lib, strict = wrong_pct(args.library, groups), wrong_pct(args.strict, groups)
    print("| scene, light | auto at 0.5 | auto at 0.05 | best exact (raytrace, volume, planar) |")
    print("|---|---|---|---:|")
    chosen = {}
    rows = []
    for scene, light in sorted(lib):
        if scene not in chosen:
            chosen[scene] = (picks(args, scene, "0.5"), picks(args, scene, "0.05"))
        (loose, _), (tight, met) = chosen[scene]
        figures = lib[(scene, light)]
        at_loose = figures.get("vtk/auto")
        at_tight = strict.get((scene, light), {}).get(STRICT_TEST)
        exact = [figures[t] for t in EXACT if t in figures]
        if at_loose is None or at_tight is None or not exact:
            sys.exit("auto_promise.py: %s light %d lacks auto or an exact row" % (scene, light))
        tight_text = "%.3f" % at_tight
        if at_tight > 0.05:
            tight_text = "**%s**" % tight_text
        print("| %s %d | %s %.3f | %s %s | %.3f |" % (scene, light, loose[light], at_loose,
                                                      tight[light], tight_text, min(exact)))
        rows.append((scene, light, at_loose, at_tight, min(exact), met.get(light, True)))
    over_loose = [r for r in rows if r[2] > 0.5]
    over_tight = [r for r in rows if r[3] > 0.05]
    worst = max(rows, key=lambda r: r[2])
    print()
    print("At 0.5: %d of %d lights within the target (the worst %.3f, %s light %d)." %
          (len(rows) - len(over_loose), len(rows), worst[2], worst[0], worst[1]))
    print("At 0.05: %d of %d lights within it; over it:" % (len(rows) - len(over_tight), len(rows)))
    for scene, light, _, tight, exact, met in over_tight:
        print("  %s light %d: %.3f (best exact %.3f), auto's stats say met %s" %
              (scene, light, tight, exact, "true" if met else "false"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
