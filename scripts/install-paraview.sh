#!/bin/sh
# ParaView 5.11 for the vtkshadow plugin (paraview/), next to Debian's VTK 9.1.
#
# Debian 12's python3-paraview Conflicts with python3-vtk9 (both install
# /usr/lib/python3/dist-packages/vtkmodules), and paraview-dev's CMake files
# name python3-paraview's modules, so ParaView cannot be found by CMake
# without it. So:
#   1. apt installs paraview and paraview-dev without recommends (that pulls
#      every run-time library and removes nothing; with recommends apt would
#      install python3-paraview and remove python3-vtk9 and libvtk9-dev);
#   2. a private prefix, $VTKSHADOW_PARAVIEW_PREFIX (default
#      /opt/vtkshadow/paraview-5.11), holds paraview-dev and python3-paraview
#      unpacked with dpkg-deb -x (nothing registered with dpkg), paraview's
#      programs copied and its other files linked. CMake finds ParaView in
#      the prefix; its pvpython and pvbatch find the prefix's vtkmodules
#      (they look next to their own executable), never python3-vtk9's.
# Run as root (or with sudo available). Safe to run again: the prefix is
# rebuilt only when the paraview package's version changes.
set -eu
prefix="${VTKSHADOW_PARAVIEW_PREFIX:-/opt/vtkshadow/paraview-5.11}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive

missing=""
for p in paraview paraview-dev; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
  echo "install-paraview: installing$missing (without recommends: keeps python3-vtk9)"
  $sudo apt-get update -q
  # shellcheck disable=SC2086
  $sudo apt-get install -y -q --no-install-recommends $missing
fi

# The vtkshadow-paraview package (docs/install.md) installs into /usr's
# ParaView: bin/paraview.conf, and vtkshadow.plugins.xml and VTKShadow/ in
# its plugin folder. The prefix's programs read paraview.conf beside
# themselves and resolve it against their own prefix, so these three paths
# of the prefix link to /usr's: with the package installed, the prefix's
# pvpython/pvbatch/paraview load VTKShadow by name too. The links dangle
# (ParaView ignores them) while the package is not installed.
link_vtkshadow_paraview() {
  plugins=usr/lib/x86_64-linux-gnu/paraview-5.11/plugins
  for path in usr/bin/paraview.conf "$plugins/vtkshadow.plugins.xml" "$plugins/VTKShadow"; do
    $sudo ln -sfn "/$path" "$1/$path"
  done
}

version="$(dpkg-query -W -f='${Version}' paraview)"
if [ -f "$prefix/.vtkshadow-paraview" ] && [ "$(cat "$prefix/.vtkshadow-paraview")" = "$version" ]; then
  link_vtkshadow_paraview "$prefix"
  echo "install-paraview: $prefix holds ParaView $version"
  exit 0
fi

echo "install-paraview: unpacking paraview-dev and python3-paraview $version into $prefix"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
chmod 755 "$work" # apt-get download runs as _apt
(cd "$work" && apt-get download -q "paraview-dev=$version" "python3-paraview=$version")
stage="$work/prefix"
mkdir -p "$stage"
for deb in "$work"/*.deb; do
  dpkg-deb -x "$deb" "$stage"
done
# paraview's own files: programs copied (ParaView finds its Python package
# next to the real executable, so a link to /usr/bin would find
# python3-vtk9's), everything else linked to the installed package.
dpkg -L paraview | while read -r f; do
  if [ -d "$f" ] || [ -e "$stage$f" ] || [ -L "$stage$f" ]; then
    continue
  fi
  mkdir -p "$(dirname "$stage$f")"
  case "$f" in
    /usr/bin/*) cp -a "$f" "$stage$f" ;;
    *) ln -s "$f" "$stage$f" ;;
  esac
done
echo "$version" > "$stage/.vtkshadow-paraview"
$sudo mkdir -p "$(dirname "$prefix")"
$sudo rm -rf "$prefix"
$sudo cp -a "$stage" "$prefix"
link_vtkshadow_paraview "$prefix"
echo "install-paraview: ParaView $version in $prefix (ParaView_DIR=$prefix/usr/lib/x86_64-linux-gnu/cmake/paraview-5.11)"
