#!/bin/sh
# install.package: the .debs CPack makes from the build tree hold what a
# user needs, install with dpkg, and work with no wrapper: Debian's
# /usr/bin/python3 imports vtkshadow and renders a shadow (and no shadow
# with technique "none"); ParaView's pvpython and pvbatch load the plugin
# by name. Needs root (dpkg -i); leaves the packages installed.
#   run.sh BUILD SOURCE [PVPYTHON PVBATCH]   (DISPLAY from gl-run.sh)
set -eu
build=$1
source=$2
pvpython=${3:-}
pvbatch=${4:-}
here=$(cd "$(dirname "$0")" && pwd)
fail() { echo "install.package: FAIL: $*" >&2; exit 1; }

[ "$(id -u)" -eq 0 ] || fail "this test installs Debian packages (dpkg -i) and needs root; run it as root (CI does)"

out="$build/test-package"
rm -rf "$out"
mkdir -p "$out"
(cd "$build" && cpack -G DEB -B "$out" >"$out/cpack.log" 2>&1) || { cat "$out/cpack.log"; fail "cpack -G DEB"; }
main=$(ls "$out"/vtkshadow_*.deb 2>/dev/null) || fail "cpack made no vtkshadow_*.deb"
echo "built $(basename "$main")"

# Contents: what a user of each package needs, each listed or the test fails:
# the library, headers, CMake and Python packages, the product's program
# (tools/: vtkshadow-render) and the harness (compare/: vtkshadow-compare,
# vtkshadow-metrics and the Blender script it runs).
dpkg-deb -c "$main" | awk '{print $6}' >"$out/main.txt"
for want in \
  '^\./usr/lib/python3/dist-packages/vtkshadow/__init__\.py$' \
  '^\./usr/lib/python3/dist-packages/vtkshadow/vtkshadow\.so$' \
  '^\./usr/lib/(x86_64-linux-gnu/)?libvtkshadow\.so\.' \
  '^\./usr/include/vtkshadow/vtkshadow\.h$' \
  '^\./usr/include/vtkshadow/vtkShadowTechnique\.h$' \
  '^\./usr/lib/(x86_64-linux-gnu/)?cmake/vtkshadow/vtkshadowConfig\.cmake$' \
  '^\./usr/bin/vtkshadow-render$' \
  '^\./usr/bin/vtkshadow-compare$' \
  '^\./usr/bin/vtkshadow-metrics$' \
  '^\./usr/share/vtkshadow/render_cycles\.py$'; do
  grep -Eq "$want" "$out/main.txt" || fail "$(basename "$main") lacks $want"
done
if grep -q paraview "$out/main.txt" || dpkg-deb -f "$main" Depends | grep -q paraview; then
  fail "$(basename "$main") holds or needs ParaView (the plugin belongs in vtkshadow-paraview)"
fi
debs=$main
plugin=""
if [ -n "$pvpython" ]; then
  plugin=$(ls "$out"/vtkshadow-paraview_*.deb 2>/dev/null) || fail "cpack made no vtkshadow-paraview_*.deb"
  dpkg-deb -c "$plugin" | awk '{print $6}' >"$out/plugin.txt"
  for want in \
    '^\./usr/lib/x86_64-linux-gnu/paraview-5\.11/plugins/VTKShadow/VTKShadow\.so$' \
    '^\./usr/lib/x86_64-linux-gnu/paraview-5\.11/plugins/vtkshadow\.plugins\.xml$' \
    '^\./usr/bin/paraview\.conf$'; do
    grep -Eq "$want" "$out/plugin.txt" || fail "$(basename "$plugin") lacks $want"
  done
  debs="$debs $plugin"
fi
echo "contents ok: $(wc -l <"$out/main.txt") entries in $(basename "$main")${plugin:+, $(wc -l <"$out/plugin.txt") in $(basename "$plugin")}"

# Install for real. All dependencies are on the machine already (the build
# needed them); apt-get install ./*.deb would fetch missing ones.
# shellcheck disable=SC2086
dpkg -i $debs >"$out/dpkg.log" 2>&1 || { cat "$out/dpkg.log"; fail "dpkg -i $debs"; }
echo "installed: $(dpkg-query -W -f='${Package} ${Version}  ' vtkshadow ${plugin:+vtkshadow-paraview})"

# A user's program: plain Debian python3, no wrapper, no paths, outside the
# repository.
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$here/shadow_program.py" "$work/"
for technique in csm none; do
  (cd "$work" && env -u PYTHONPATH -u LD_LIBRARY_PATH /usr/bin/python3 shadow_program.py "$technique") \
    >"$out/$technique.txt" 2>&1 || { cat "$out/$technique.txt"; fail "/usr/bin/python3 shadow_program.py $technique"; }
  cat "$out/$technique.txt"
done
grep -q "^vtkshadow from /usr/lib/python3/dist-packages/vtkshadow/" "$out/csm.txt" ||
  fail "python3 did not import the installed package"
csm=$(sed -n 's/^ratio //p' "$out/csm.txt")
none=$(sed -n 's/^ratio //p' "$out/none.txt")
# The floor under the sphere: under 60% of the open floor with csm, at
# least 90% with technique none (the same program without shadows).
awk -v r="$csm" 'BEGIN { exit !(r < 0.6) }' || fail "csm: no shadow under the sphere (ratio $csm, want < 0.6)"
awk -v r="$none" 'BEGIN { exit !(r >= 0.9) }' || fail "none: the floor under the sphere is dark (ratio $none, want >= 0.9)"

# The same install under another prefix (as /usr/local, where neither the
# library folder nor lib/python3/dist-packages is on the default paths):
# the tools and the Python module find libvtkshadow.so by their RUNPATH, and
# vtkshadow.pth in the site folder (read here by site.addsitedir, as site.py
# reads /usr/local/lib/python3.X/dist-packages) adds the package's folder to
# sys.path. That folder comes after /usr/lib/python3/dist-packages, where
# the .deb installed above is: the import puts it first to get the prefix's.
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" >"$out/install.log" 2>&1 || { cat "$out/install.log"; fail "cmake --install"; }
env -u LD_LIBRARY_PATH "$prefix/bin/vtkshadow-render" --list-techniques >"$out/tool.txt" 2>&1 ||
  { cat "$out/tool.txt"; fail "$prefix/bin/vtkshadow-render does not start without LD_LIBRARY_PATH"; }
# ... and find the prefix's own libvtkshadow.so (not the .deb's in /usr/lib).
for binary in "$prefix/bin/vtkshadow-render" "$prefix"/lib/python3/dist-packages/vtkshadow/vtkshadow*.so; do
  env -u LD_LIBRARY_PATH ldd "$binary" | grep "libvtkshadow\.so" | grep -q "=> $prefix/" ||
    fail "$binary does not find $prefix's libvtkshadow.so by its RUNPATH: $(env -u LD_LIBRARY_PATH ldd "$binary" | grep libvtkshadow)"
done
site=$(/usr/bin/python3 -c 'import sys; print("lib/python%d.%d/dist-packages" % sys.version_info[:2])')
(cd "$work" && env -u PYTHONPATH -u LD_LIBRARY_PATH /usr/bin/python3 -c "
import site, sys
site.addsitedir('$prefix/$site')
added = [p for p in sys.path if p.startswith('$prefix/')]
print('vtkshadow.pth added', added)
sys.path[:0] = added
import vtkshadow; print('prefix install: vtkshadow from', vtkshadow.__file__)") >"$out/prefix.txt" 2>&1 ||
  { cat "$out/prefix.txt"; fail "python3 cannot import vtkshadow from $prefix through $site/vtkshadow.pth"; }
grep -q "from $prefix/" "$out/prefix.txt" || { cat "$out/prefix.txt"; fail "python3 imported vtkshadow from elsewhere than $prefix"; }
cat "$out/prefix.txt"

if [ -n "$pvpython" ]; then
  so=/usr/lib/x86_64-linux-gnu/paraview-5.11/plugins/VTKShadow/VTKShadow.so
  for program in "$pvpython" "$pvbatch"; do
    name=$(basename "$program")
    (cd "$work" && env -u PV_PLUGIN_PATH -u PV_PLUGIN_CONFIG_FILE "$program" "$here/pv_by_name.py" "$so") \
      >"$out/$name.txt" 2>&1 || { cat "$out/$name.txt"; fail "$name: VTKShadow does not load by name from $so"; }
    echo "$name: $(grep 'loaded from' "$out/$name.txt")"
  done
fi
echo "install.package: ok"
