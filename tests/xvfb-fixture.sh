#!/bin/sh
# xvfb-fixture.sh start|stop DIR: one Xvfb server shared by every GL test of a
# ctest run (a ctest fixture). One server per test raced: a server shutting
# down could remove the socket of a new server that had just taken the same
# display number. DIR/display holds ":N" for gl-run.sh.
set -eu
action=$1
dir=$2
case "$action" in
  start)
    mkdir -p "$dir"
    if [ -s "$dir/pid" ] && kill -0 "$(cat "$dir/pid")" 2>/dev/null; then
      echo "xvfb-fixture: already running on $(cat "$dir/display")"
      exit 0
    fi
    rm -f "$dir/display" "$dir/number" "$dir/pid"
    # setsid: the server outlives this script (ctest waits for it otherwise).
    # -noreset: without it the server resets whenever its last client leaves,
    # and a client connecting during the reset fails ("bad X server connection").
    setsid Xvfb -displayfd 3 -screen 0 1920x1080x24 -nolisten tcp -noreset \
      3>"$dir/number" </dev/null >"$dir/xvfb.log" 2>&1 &
    echo $! >"$dir/pid"
    tries=0
    while [ ! -s "$dir/number" ]; do
      tries=$((tries + 1))
      if [ "$tries" -gt 200 ] || ! kill -0 "$(cat "$dir/pid")" 2>/dev/null; then
        echo "xvfb-fixture: Xvfb did not start:" >&2
        cat "$dir/xvfb.log" >&2
        exit 1
      fi
      sleep 0.05
    done
    echo ":$(head -n 1 "$dir/number")" >"$dir/display"
    echo "xvfb-fixture: Xvfb running on $(cat "$dir/display")"
    ;;
  stop)
    if [ -s "$dir/pid" ]; then
      kill "$(cat "$dir/pid")" 2>/dev/null || true
    fi
    rm -f "$dir/display" "$dir/number" "$dir/pid"
    echo "xvfb-fixture: stopped"
    ;;
  *)
    echo "usage: xvfb-fixture.sh start|stop DIR" >&2
    exit 2
    ;;
esac
