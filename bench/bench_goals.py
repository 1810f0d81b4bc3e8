"""Issue 14's speed goals, evaluated on the rows of one scene of a
vtkshadow-bench run (bench.json), with a verdict that respects the run's
noise floor. Shared by vtkshadow_bench.py (summary.md), make_results.py
(docs/results.md) and bench_planar.py (docs/performance.md), so the three
say the same thing about the same numbers.

The goals (interleaved ratios, 800x600, every non-hard library scene):
  - csm at its defaults at most 1.0x vtk's frame time (vtk at
    vtkshadow-render's default map, 2048);
  - auto at its default error target at most 1.5x none;
  - planar at most 1.15x none, on scenes with one receiver and one light.

A figure is a ratio of frame times measured in the same window and the same
rounds (csm / vtk divides their ratios to none). The verdict:
  - "met" / "missed by D (P%)": figure against its limit;
  - "too noisy": the run's noise floor (none#2 / none) is outside its
    tolerance AND the figure is no further from the limit than the floor is
    from 1 (relatively), so the run cannot tell met from missed. Where the
    margin is larger than the floor's error, met or missed stands and is
    marked as from a noisy run.
Plain Python, no VTK: tests/timing/test_make_results.py runs it on synthetic
rows.
"""
import json

NOISE_LABEL = "none#2"

# (key, what is measured, limit, needs one receiver and one light)
GOALS = (
    ("csm_vs_vtk", "csm (defaults) / vtk (map 2048) frame time", 1.0, False),
    ("auto", "auto (default error target) / none", 1.5, False),
    ("planar", "planar / none (one receiver, one light)", 1.15, True),
)


def headline(rows, tech):
    """The row that stands for a technique in tables: its defaults ("-" or
    "default"), else vtkshadow-render's default map (map=2048), else its
    first timed row. None when the technique has no timed row."""
    timed = [r for r in rows if r["technique"] == tech and r.get("ratio") is not None]
    for want in ("-", "default", "map=2048"):
        hit = next((r for r in timed if r["settings"] == want), None)
        if hit:
            return hit
    return timed[0] if timed else None


def floor_row(rows):
    return next((r for r in rows if r["technique"] == NOISE_LABEL
                 and r.get("ratio") is not None), None)


def scene_counts(path):
    """(lights, receivers) of a scene file."""
    with open(path) as f:
        doc = json.load(f)
    return (len(doc.get("lights", [])),
            sum(1 for o in doc.get("objects", []) if o.get("receiver")))


def figure(key, rows):
    """The figure of goal `key` on a scene's rows, or None without rows."""
    none = headline(rows, "none")
    if key == "csm_vs_vtk":
        csm, vtk = headline(rows, "csm"), headline(rows, "vtk")
        return csm["ratio"] / vtk["ratio"] if csm and vtk and none and vtk["ratio"] > 0 else None
    tech = headline(rows, key)
    return tech["ratio"] if tech and none else None


def verdict(value, limit, floor, too_noisy):
    """(state, text): state is "met", "missed" or "too noisy" (see the module
    docstring); value None gives ("-", "-")."""
    if value is None:
        return "-", "-"
    margin = value / limit - 1.0
    noise = abs(floor - 1.0) if floor is not None else float("inf")
    if too_noisy and abs(margin) <= noise:
        return "too noisy", "too noisy (%.2fx against %.2fx; floor %.3f)" % (value, limit, floor)
    mark = "; noisy run, floor %.3f" % floor if too_noisy else ""
    if value <= limit:
        return "met", "met (%.2fx%s)" % (value, mark)
    return "missed", "missed by %.2fx (%.2fx, +%.0f%%%s)" % (value - limit, value,
                                                             100 * margin, mark)


def count(n, noun):
    return "? %ss" % noun if n is None else "%d %s%s" % (n, noun, "" if n == 1 else "s")


def scene_goals(key, rows, lights=None, receivers=None):
    """Every goal on one scene: [{goal, what, limit, counted, applies,
    value, state, text}]. `counted`: the scene takes part in the tally (not
    a hard scene); `applies`: the goal is defined on it (planar: one
    receiver and one light; lights/receivers None means unknown: not
    applied)."""
    fl = floor_row(rows)
    floor, noisy = (fl["ratio"], bool(fl.get("too_noisy"))) if fl else (None, False)
    hard = key.startswith("hard-")
    out = []
    for goal, what, limit, single in GOALS:
        applies = not single or (lights == 1 and receivers == 1)
        value = figure(goal, rows) if applies else None
        state, text = verdict(value, limit, floor, noisy)
        if not applies:
            text = "n/a (%s, %s)" % (count(lights, "light"), count(receivers, "receiver"))
        out.append(dict(goal=goal, what=what, limit=limit, counted=not hard, applies=applies,
                        value=value, state=state, text=text))
    return out
