#!/bin/sh
# The real-client corpus (docs/corpus.md): every included third-party example
# (compare/corpus/corpus.json) x every technique, run unmodified with
# enable_shadows injected; writes OUT/corpus.json and docs/corpus.md.
#   scripts/corpus.sh [--python PY] [--out DIR] [--subset ctest] [corpus.py run options]
# PY defaults to build/bin/vtkshadow-python (an installed vtkshadow: /usr/bin/python3).
set -eu
here=$(cd "$(dirname "$0")/.." && pwd)
python="$here/build/bin/vtkshadow-python"
out="$here/build/corpus-out"
markdown="$here/docs/corpus.md"
while [ $# -gt 0 ]; do
  case "$1" in
    --python) python=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --markdown) markdown=$2; shift 2 ;;
    *) break ;;
  esac
done
# corpus.py itself needs only numpy; the examples run under $python.
exec "$here/tests/gl-run.sh" /usr/bin/python3 "$here/compare/corpus/corpus.py" run \
  --python "$python" --out "$out" --markdown "$markdown" "$@"
