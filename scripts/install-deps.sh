#!/bin/sh
# Install the Debian 12 packages vtkshadow needs to build, test and run.
# Run as root (or with sudo available). Safe to run again.
set -eu
packages="cmake make gcc g++ pkg-config libvtk9-dev python3-vtk9 python3-numpy
  libcjson-dev libpng-dev xvfb xauth povray blender gnuplot-nox
  universal-ctags clang-format
  libx11-dev libembree-dev python3-pil
  openmpi-bin
  python3-vedo python3-vedo-examples vtk9-examples"
missing=""
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
# ParaView 5.11 for the plugin: apt without recommends plus a private
# prefix (python3-paraview conflicts with python3-vtk9; see the script).
here="$(dirname "$0")"
if [ -z "$missing" ]; then
  echo "install-deps: all packages present"
  sh "$here/install-paraview.sh"
  exit 0
fi
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "install-deps: installing$missing"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
# shellcheck disable=SC2086
$sudo apt-get install -y -q --no-install-recommends $missing
sh "$here/install-paraview.sh"
