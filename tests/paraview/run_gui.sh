#!/bin/sh
# run_gui.sh BIN SOURCE OUT: the ParaView GUI (build/bin/vtkshadow-paraview,
# the plugin loaded by PV_PLUGIN_PATH) runs gui_script.py, which opens a
# Render View (Shadows), shows a sphere over a plane and saves a screenshot;
# the screenshot must exist and not be empty (mostly background).
set -eu
bin=$1 source=$2 out=$3
rm -rf "$out"
mkdir -p "$out"
export VTKSHADOW_GUI_SCREENSHOT="$out/gui.png"
status=0
timeout 240 "$bin/vtkshadow-paraview" --dr --script="$source/tests/paraview/gui_script.py" --exit \
  > "$out/gui.log" 2>&1 || status=$?
cat "$out/gui.log"
if [ ! -s "$out/gui.png" ]; then
  echo "run_gui.sh: the GUI wrote no screenshot (exit status $status)" >&2
  exit 1
fi
"$bin/vtkshadow-pvpython" -c "
import sys
sys.path.insert(0, '$source/tests/paraview')
import pv_scene
f = pv_scene.nonblank_fraction('$out/gui.png')
print('run_gui.sh: %.1f%% of the screenshot is not background' % (100 * f))
sys.exit(0 if f > 0.02 else 1)
"
