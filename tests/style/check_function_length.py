#!/usr/bin/env python3
"""Style check: no function in the given source trees is longer than a limit,
in any language (the project's rule: 120 lines; split long ones into named
stages). C and C++ functions are measured with ctags, Python functions
(.py and .py.in files) with the ast module.

C and C++ function extents come from universal-ctags (Debian package universal-ctags):
  ctags --output-format=json --fields=+ne --kinds-C=f --kinds-C++=f -R DIR
gives every function definition with its first line ("line") and last line
("end"); the length counted is end - line + 1, the signature line through the
closing brace, comments and blank lines included. Lambdas and macros are not
functions to ctags: a long lambda counts towards the function holding it.

Python: every def (methods and nested functions too, each counted on its
own) is end_lineno - lineno + 1 lines, the def line through its last line
(decorators not counted). A Python file that does not parse fails the check.

Prints one line per function over the limit (file:line name length) and exits
1 when there is any; exits 2 when ctags is missing or is not universal-ctags
(exuberant ctags has no "end" field) or a Python file does not parse.

  check_function_length.py [--ctags PATH] [--max 120] ROOT DIR [DIR ...]
"""
import argparse
import ast
import json
import os
import shutil
import subprocess
import sys

# ctags' language names for the sources we check (.h counts as C++ to ctags).
LANGUAGES = "C,C++"
EXTENSIONS = (".c", ".h", ".cxx", ".cpp", ".cc", ".hxx", ".hpp", ".txx")


def functions(ctags, root, dirs):
    """(path, name, first line, last line) of every function definition."""
    cmd = [ctags, "--output-format=json", "--fields=+ne", f"--languages={LANGUAGES}",
           "--kinds-C=f", "--kinds-C++=f", "-R", "-f", "-"] + dirs
    run = subprocess.run(cmd, cwd=root, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit(f"check_function_length: {' '.join(cmd)} failed ({run.returncode}): "
                 f"{run.stderr.strip()}")
    found, missing_end = [], []
    for line in run.stdout.splitlines():
        tag = json.loads(line)
        if tag.get("_type") != "tag" or not tag["path"].endswith(EXTENSIONS):
            continue
        if "end" not in tag:
            missing_end.append(f"{tag['path']}:{tag.get('line')} {tag['name']}")
            continue
        scope = tag.get("scope")
        name = f"{scope}::{tag['name']}" if scope else tag["name"]
        found.append((tag["path"], name, int(tag["line"]), int(tag["end"])))
    return found, missing_end


PYTHON_EXTENSIONS = (".py", ".py.in")


def python_functions(root, dirs):
    """(path, name, first line, last line) of every Python def, and the
    files that do not parse."""
    found, broken = [], []
    for d in dirs:
        for folder, subdirs, files in os.walk(os.path.join(root, d)):
            subdirs[:] = sorted(s for s in subdirs if not s.startswith((".", "__pycache__")))
            for name in sorted(files):
                if not name.endswith(PYTHON_EXTENSIONS):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, root)
                try:
                    with open(path, encoding="utf-8") as f:
                        tree = ast.parse(f.read(), filename=rel)
                except (SyntaxError, UnicodeDecodeError) as e:
                    broken.append(f"{rel}: {e}")
                    continue
                found.extend((rel, name, first, last) for name, first, last in python_defs(tree))
    return found, broken


def python_defs(tree, scope=""):
    """(qualified name, first line, last line) of each def under `tree`."""
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield scope + node.name, node.lineno, node.end_lineno
            yield from python_defs(node, scope + node.name + ".")
        elif isinstance(node, ast.ClassDef):
            yield from python_defs(node, scope + node.name + ".")
        else:
            yield from python_defs(node, scope)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--ctags", default=shutil.which("ctags") or "ctags")
    ap.add_argument("--max", type=int, default=120, help="longest allowed function, in lines")
    ap.add_argument("root", help="the source tree the directories are relative to")
    ap.add_argument("dirs", nargs="+")
    args = ap.parse_args()
    try:
        version = subprocess.run([args.ctags, "--version"], capture_output=True, text=True).stdout
    except OSError as e:
        print(f"check_function_length: cannot run ctags '{args.ctags}': {e} "
              f"(apt-get install universal-ctags)")
        sys.exit(2)
    if "Universal Ctags" not in version:
        print(f"check_function_length: '{args.ctags}' is not universal-ctags "
              f"(apt-get install universal-ctags)")
        sys.exit(2)
    for d in args.dirs:
        if not os.path.isdir(os.path.join(args.root, d)):
            print(f"check_function_length: no directory '{d}' under '{args.root}'")
            sys.exit(2)
    found, missing_end = functions(args.ctags, args.root, args.dirs)
    if missing_end:
        # A definition without an end line cannot be measured: fail, never skip.
        print("check_function_length: ctags gave no end line for: " + ", ".join(missing_end))
        sys.exit(2)
    python, broken = python_functions(args.root, args.dirs)
    if broken:
        print("check_function_length: Python files that do not parse: " + "; ".join(broken))
        sys.exit(2)
    found += python
    long = sorted(((end - first + 1, path, first, name) for path, name, first, end in found
                   if end - first + 1 > args.max), key=lambda t: (t[1], t[2]))
    files = len({f[0] for f in found})
    print(f"check_function_length: {len(found)} functions in {files} files under "
          f"{', '.join(args.dirs)}; limit {args.max} lines")
    for length, path, first, name in long:
        print(f"{path}:{first}: {name}: {length} lines")
    if long:
        print(f"check_function_length: {len(long)} functions over {args.max} lines")
        sys.exit(1)
    print("check_function_length: none over the limit")


if __name__ == "__main__":
    main()
