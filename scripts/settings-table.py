#!/usr/bin/env python3
"""The settings tables of docs/techniques.md, made from what the binary
lists (`vtkshadow-render --list-settings`: technique, key, range, integer,
default, doc line, tab-separated), so the docs cannot drift from the
settings tables in the code (vtkShadowSettings.h).

  scripts/settings-table.py BUILD/bin/vtkshadow-render [DOC]          rewrite
  scripts/settings-table.py --check BUILD/bin/vtkshadow-render [DOC]  compare

The tables go between the marker comments BEGIN and END below; --check
exits 1 when the file differs from what would be written."""
import argparse
import os
import subprocess
import sys

BEGIN = "<!-- settings-table:begin (scripts/settings-table.py writes this) -->"
END = "<!-- settings-table:end -->"


def listing(render):
    env = dict(os.environ)
    env.pop("DISPLAY", None)  # listing renders nothing
    out = subprocess.run([render, "--list-settings"], capture_output=True, text=True,
                         env=env, check=True, timeout=120).stdout
    return [line.split("\t") for line in out.splitlines() if line]


def tables(rows):
    text = []
    for technique in dict.fromkeys(r[0] for r in rows):
        text += ["", f"### `{technique}`", "",
                 "| key | range | integer | default | what |", "|---|---|---|---|---|"]
        for _, key, rng, integer, default, doc in (r for r in rows if r[0] == technique):
            doc = doc.replace("|", "\\|")
            text.append(f"| `{key}` | `{rng}` | {integer} | {default} | {doc} |")
    return "\n".join(text[1:]) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--check", action="store_true")
    parser.add_argument("render")
    parser.add_argument("doc", nargs="?", default=os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "docs", "techniques.md"))
    args = parser.parse_args()
    with open(args.doc) as f:
        old = f.read()
    if BEGIN not in old or END not in old:
        sys.exit(f"{args.doc}: no {BEGIN} ... {END} markers")
    head, rest = old.split(BEGIN, 1)
    new = head + BEGIN + "\n" + tables(listing(args.render)) + END + rest.split(END, 1)[1]
    if args.check:
        if new != old:
            print(f"{args.doc}: the settings tables differ from --list-settings; "
                  f"run scripts/settings-table.py {args.render}")
            sys.exit(1)
        print("settings tables match --list-settings")
    elif new != old:
        with open(args.doc, "w") as f:
            f.write(new)


main()
