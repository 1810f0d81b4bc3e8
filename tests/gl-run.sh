#!/bin/sh
# gl-run.sh COMMAND...: run COMMAND with an X display (Debian's VTK renders
# through GLX only). Under ctest the display comes from the shared Xvfb of
# the `xvfb` fixture (VTKSHADOW_DISPLAY_FILE); run by hand, gl-run.sh starts
# a private Xvfb for the command and stops it afterwards.
set -eu
if [ -n "${VTKSHADOW_DISPLAY_FILE:-}" ]; then
  if [ ! -s "$VTKSHADOW_DISPLAY_FILE" ]; then
    echo "gl-run.sh: no display in $VTKSHADOW_DISPLAY_FILE (is the xvfb fixture running?)" >&2
    exit 1
  fi
  DISPLAY=$(cat "$VTKSHADOW_DISPLAY_FILE")
  export DISPLAY
  status=0
  "$@" || status=$?
  if [ "$status" -ne 0 ]; then
    fixture=$(dirname "$VTKSHADOW_DISPLAY_FILE")
    echo "gl-run.sh: failed on $DISPLAY; Xvfb pid $(cat "$fixture/pid" 2>/dev/null) alive: $(kill -0 "$(cat "$fixture/pid" 2>/dev/null)" 2>/dev/null && echo yes || echo no)" >&2
    ls -la /tmp/.X11-unix/ >&2
    cat "$fixture/xvfb.log" >&2
  fi
  exit "$status"
fi
dir=$(mktemp -d)
script_dir=$(cd "$(dirname "$0")" && pwd)
trap '"$script_dir/xvfb-fixture.sh" stop "$dir" >/dev/null; rm -rf "$dir"' EXIT INT TERM
"$script_dir/xvfb-fixture.sh" start "$dir" >/dev/null
DISPLAY=$(cat "$dir/display")
export DISPLAY
"$@"
