#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs what the ParaView plugin (ParaView/) needs beside the main project's packages:
# ParaView 5.11 with its development files, Open MPI's mpirun, and ParaView's Python package.
#
# Debian's python3-paraview conflicts with python3-vtk9 (which libvtk9-dev needs), so it is not
# installed. Instead, into a private directory (by default build-paraview/paraview-root):
# - python3/: the python3-paraview .deb, downloaded and unpacked; its
#   usr/lib/python3/dist-packages goes first on PYTHONPATH for pvbatch and pvpython;
# - prefix/: a prefix laid out like /usr that joins the installed paraview and paraview-dev (by
#   symbolic links) with that unpacked package, and holds a copy of ParaView's CMake package
#   (lib/x86_64-linux-gnu/cmake/paraview-5.11). ParaView's CMake package checks that every file
#   its imported targets name exists, python3-paraview's included, relative to the prefix it is
#   found in; found here (ParaView_DIR), it finds them all and no system file is touched.
# Nothing is installed or unpacked twice: on a machine that has it all, the script needs no root
# rights and no network.
#   scripts/install-paraview.sh [PRIVATE_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."

root_dir="${1:-build-paraview/paraview-root}"
private_dir="$root_dir/python3"
prefix_dir="$root_dir/prefix"

packages=(
  paraview paraview-dev   # pvbatch, pvpython, the libraries, headers and CMake package
  openmpi-bin             # mpirun, for the tests on two ranks
  python3-numpy           # paraview.simple's numpy support in the tests
  xvfb xauth libgl1-mesa-dri
)
missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  sudo=(sudo)
fi
if ((${#missing[@]} > 0)); then
  if ((${#sudo[@]} > 0)) && ! command -v sudo >/dev/null; then
    echo "install-paraview: run as root or install sudo" >&2
    exit 1
  fi
  echo "install-paraview: installing ${missing[*]}"
  "${sudo[@]}" apt-get update
  # Without recommends: paraview-dev recommends python3-paraview, which would remove python3-vtk9.
  DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y --no-install-recommends \
    "${missing[@]}"
else
  echo "install-paraview: all packages present"
fi

# ParaView's Python package, matching the installed paraview exactly.
version="$(dpkg-query -W -f='${Version}' paraview)"
stamp="$root_dir/.version"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$version" ] &&
  [ -f "$private_dir/usr/lib/python3/dist-packages/paraview/simple.py" ] &&
  [ -f "$prefix_dir/lib/x86_64-linux-gnu/cmake/paraview-5.11/paraview-config.cmake" ]; then
  echo "install-paraview: python3-paraview $version already unpacked in $root_dir"
  exit 0
fi
rm -rf "$root_dir"
mkdir -p "$private_dir" "$prefix_dir"
download_dir="$(mktemp -d)"
trap 'rm -rf "$download_dir"' EXIT
# apt-get download drops its rights to the _apt user, which must be able to write there.
chmod 777 "$download_dir"
# (With package lists older than the installed paraview, the download fails: update them once.)
if ! (cd "$download_dir" && apt-get download "python3-paraview=$version"); then
  "${sudo[@]}" apt-get update
  (cd "$download_dir" && apt-get download "python3-paraview=$version")
fi
dpkg-deb -x "$download_dir"/python3-paraview_*.deb "$private_dir"
python_dir="$(cd "$private_dir/usr/lib/python3/dist-packages" && pwd)"

# The prefix: /usr's headers and libraries by links, ParaView's programs and pvpython's.
libdir=lib/x86_64-linux-gnu
mkdir -p "$prefix_dir/bin" "$prefix_dir/$libdir" "$prefix_dir/lib/python3"
ln -s /usr/include "$prefix_dir/include"
ln -s /usr/share "$prefix_dir/share"
ln -s "$python_dir" "$prefix_dir/lib/python3/dist-packages"
# (One ln for all the entries: there are thousands.)
ln -s /usr/$libdir/* "$prefix_dir/$libdir/"
rm "$prefix_dir/$libdir/cmake"
mkdir "$prefix_dir/$libdir/cmake"
ln -s /usr/$libdir/cmake/* "$prefix_dir/$libdir/cmake/"
rm "$prefix_dir/$libdir/cmake/paraview-5.11"
# The wrapping's class hierarchies of ParaView's VTK (lib/x86_64-linux-gnu/vtk/hierarchy/ParaView)
# come with python3-paraview; /usr's lib/x86_64-linux-gnu/vtk has only the system VTK 9.1's.
rm "$prefix_dir/$libdir/vtk"
ln -s "$(cd "$private_dir/usr/$libdir/vtk" && pwd)" "$prefix_dir/$libdir/vtk"
cp -r /usr/$libdir/cmake/paraview-5.11 "$prefix_dir/$libdir/cmake/"
for file in $(dpkg -L paraview paraview-dev | grep '^/usr/bin/'); do
  ln -sf "$file" "$prefix_dir/bin/"
done
for file in "$private_dir"/usr/bin/*; do
  ln -sf "$(cd "$(dirname "$file")" && pwd)/$(basename "$file")" "$prefix_dir/bin/"
done
# python3-paraview ships pvpython3.11; its package (and the CMake package) also name pvpython.
ln -sf pvpython3.11 "$prefix_dir/bin/pvpython"

echo "$version" >"$stamp"
echo "install-paraview: unpacked python3-paraview $version and set up the prefix in $root_dir"
