"""The verdicts of a Python test script: check() prints each one and keeps
the failures; finish() prints their count and exits 1 if there is any."""
import sys

failures = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        failures.append(what)


def finish():
    print(f"{len(failures)} failure(s)")
    sys.exit(1 if failures else 0)
