#!/usr/bin/env python3
"""Write corpus.json's include/exclude lists from a discovery run
(corpus.py discover: every vedo example once with technique none).

  choose.py DISCOVER_JSON [corpus.json]

Included: the program captured a frame (no exception, crash, timeout),
within MAX_SECONDS for the whole run and MAX_FRAME_MS a frame, and shows at
least one 3D surface (a visible polydata actor with polygons that is not
flat) covering at least MIN_FG_PCT of the frame. Everything else is listed
under exclude with the reason. Bounds, subsets and known failures already
in corpus.json are kept."""
import json
import os
import re
import sys

MAX_SECONDS = 6.0
MAX_FRAME_MS = 400.0
MIN_FG_PCT = 2.0


def reason_for(r):
    tail = "\n".join(r.get("stderr_tail") or [])
    if r["status"] == "exception":
        if "urlopen error" in tail or "Name or service not known" in tail:
            return "network: downloads data (vedo.dataurl), no network on CI"
        m = re.search(r"No module named '([^']+)'", tail)
        if m:
            return f"module: needs Python module {m.group(1)}, not in Debian 12"
        last = (r.get("stderr_tail") or ["?"])[-1]
        return "exception: " + last[-160:]
    if r["status"] == "timeout":
        return "slow: no show() within the discovery timeout (20 s)"
    if r["status"] == "crash":
        return f"crash: exit {r.get('exit')} without shadows (technique none)"
    if r["status"] == "no-show":
        return "no-show: the program ends without show()"
    props = r.get("props") or {}
    if props.get("surface", 0) == 0:
        kinds = ", ".join(sorted(props))
        return f"no 3D surface: shows only {kinds or 'nothing'}"
    if (r.get("fg_pct") or 0) < MIN_FG_PCT:
        return f"tiny: the surfaces cover {r.get('fg_pct')}% of the frame"
    if r["seconds"] > MAX_SECONDS or (r.get("frame_ms_median") or 0) > MAX_FRAME_MS:
        return (f"slow: {r['seconds']} s for the run, {r.get('frame_ms_median', 0):.0f} ms "
                "a frame without shadows")
    if r.get("errors"):
        return "vtk-error: VTK errors after enable_shadows even with technique none"
    return None


def main():
    found = json.load(open(sys.argv[1]))
    path = sys.argv[2] if len(sys.argv) > 2 else os.path.join(os.path.dirname(__file__),
                                                              "corpus.json")
    corpus = json.load(open(path))
    old = {e["name"]: e for e in corpus["include"]}
    include, exclude = [], []
    for r in found:
        name = r["path"][:-3].replace("/", ".")
        why = reason_for(r)
        if why:
            exclude.append({"name": name, "root": r["root"], "path": r["path"], "reason": why})
        else:
            entry = old.get(name, {"name": name, "root": r["root"], "path": r["path"]})
            include.append(entry)
    corpus["include"], corpus["exclude"] = include, exclude
    with open(path, "w") as f:
        json.dump(corpus, f, indent=1)
        f.write("\n")
    print(f"{len(include)} included, {len(exclude)} excluded")


if __name__ == "__main__":
    main()
