"""Per-test times of a ctest run, as the COST table and as the docs' table.

    python3 scripts/test-costs.py BUILD [--write-cmake tests/test_costs.cmake]
                                        [--markdown]

Reads BUILD/Testing/Temporary/LastTest.log (what ctest records: each test's
"Test time"), prints the tests sorted by time with their share of the whole,
and with --write-cmake writes the COST of every test over MIN_SECONDS so that
ctest starts the long tests first on a fresh clone, where it has no cost
data of its own (docs/testing.md).
"""
import argparse
import os
import re
import sys

MIN_SECONDS = 20


def read_times(build):
    path = os.path.join(build, "Testing", "Temporary", "LastTest.log")
    try:
        with open(path, errors="replace") as f:
            text = f.read()
    except OSError as e:
        sys.exit("test-costs: cannot read %s (%s): run ctest first" % (path, e.strerror))
    times = {}
    # Each test's block: '<n>/<m> Test: NAME' ... 'Test time = S sec'.
    for name, seconds in re.findall(r"^\d+/\d+ Test: (\S+)\n.*?^\"?Test time\"? = +([\d.]+) sec",
                                    text, re.M | re.S):
        times[name] = float(seconds)
    if not times:
        sys.exit("test-costs: no test times in %s" % path)
    return times


def cmake_table(times):
    lines = ["# COST of the long tests (seconds on 2 cores, written by scripts/test-costs.py",
             "# from a whole ctest run): ctest starts the longest first, so that the run",
             "# does not end on one long test. Tests of this directory only.",
             "set(_vtkshadow_test_costs"]
    for name, s in sorted(times.items(), key=lambda kv: -kv[1]):
        if s >= MIN_SECONDS:
            lines.append("  \"%s=%d\"" % (name, round(s)))
    lines += [")",
              "foreach(entry IN LISTS _vtkshadow_test_costs)",
              "  string(REPLACE \"=\" \";\" pair \"${entry}\")",
              "  list(GET pair 0 name)",
              "  list(GET pair 1 cost)",
              "  if(TEST ${name})",
              "    set_tests_properties(${name} PROPERTIES COST ${cost})",
              "  endif()",
              "endforeach()", ""]
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("build")
    ap.add_argument("--write-cmake", metavar="FILE")
    ap.add_argument("--markdown", action="store_true", help="print a markdown table")
    a = ap.parse_args()
    times = read_times(a.build)
    total = sum(times.values())
    rows = sorted(times.items(), key=lambda kv: -kv[1])
    if a.markdown:
        print("| test | seconds | share |\n|---|---|---|")
        for name, s in rows:
            print("| %s | %.1f | %.1f %% |" % (name, s, 100 * s / total))
    else:
        for name, s in rows:
            print("%-48s %8.1f s %5.1f %%" % (name, s, 100 * s / total))
    print("%d tests, %.0f s of test time" % (len(times), total), file=sys.stderr)
    if a.write_cmake:
        tmp = a.write_cmake + ".tmp"
        with open(tmp, "w") as f:
            f.write(cmake_table(times))
        os.replace(tmp, a.write_cmake)


if __name__ == "__main__":
    main()
