#!/bin/sh
# run_gui.sh BIN SOURCE OUT: the ParaView GUI (build/bin/vtkshadow-paraview,
# the plugin loaded by PV_PLUGIN_PATH) runs gui_script.py, which opens a
# Render View (Shadows), shows a sphere over a plane under ParaView's light
# kit, saves a screenshot and writes where in it the sphere's shadow from the
# key light falls and where lit floor beside it is (gui.json). The GUI must
# exit with status 0, and the floor in the shadow must be clearly darker than
# the lit floor (a 5x5 window's mean luminance below 0.7 of it).
set -eu
bin=$1 source=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
export VTKSHADOW_GUI_SCREENSHOT="$out/gui.png" VTKSHADOW_GUI_POINTS="$out/gui.json"
status=0
timeout 240 "$bin/vtkshadow-paraview" --dr --script="$source/tests/paraview/gui_script.py" --exit \
  > "$out/gui.log" 2>&1 || status=$?
cat "$out/gui.log"
if [ "$status" -ne 0 ]; then
  why=""
  [ "$status" -ne 124 ] || why=" (killed by timeout after 240 s)"
  echo "run_gui.sh: FAILED: the GUI exited with status $status$why; its log is above" >&2
  exit 1
fi
for f in gui.png gui.json; do
  if [ ! -s "$out/$f" ]; then
    echo "run_gui.sh: the GUI wrote no $out/$f; its log is above" >&2
    exit 1
  fi
done
echo "run_gui.sh: screenshot $out/gui.png, points $out/gui.json"
"$bin/vtkshadow-pvpython" -c "
import json, sys
sys.path.insert(0, '$source/tests/paraview')
import pv_scene
png = '$out/gui.png'
points = json.load(open('$out/gui.json'))
half = points['half_window']
shadow = pv_scene.luminance(png, points['shadow']['pixel'], half)
lit = pv_scene.luminance(png, points['lit']['pixel'], half)
print('run_gui.sh: floor luminance under the sphere (shadow, pixel %s) %.1f, beside it (lit, pixel %s) %.1f: ratio %.2f (must be below 0.70)'
      % (points['shadow']['pixel'], shadow, points['lit']['pixel'], lit, shadow / max(lit, 1e-9)))
if lit < 40:
    sys.exit('run_gui.sh: FAILED: the lit floor point is dark (%.1f): no floor there, or no light' % lit)
if not shadow < 0.7 * lit:
    sys.exit('run_gui.sh: FAILED: no shadow under the sphere in the GUI screenshot: %.1f vs %.1f beside it' % (shadow, lit))
print('run_gui.sh: ok, the GUI shows the shadow')
"
