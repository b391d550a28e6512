#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs what the ParaView plugin (ParaView/) needs beside the main project's packages:
# Debian's ParaView with its development files, Open MPI's mpirun, and ParaView's Python
# package; then lays out a private prefix through which ParaView's CMake package is found
# (ParaView_DIR=PRIVATE_DIR/prefix/lib/x86_64-linux-gnu/cmake/paraview-X.Y; the script writes
# X.Y to PRIVATE_DIR/series). No system file is touched. Two stacks:
# - Debian 12, ParaView 5.11: python3-paraview conflicts with python3-vtk9 (which libvtk9-dev
#   needs), so it is not installed. Its .deb is downloaded and unpacked into PRIVATE_DIR/python3
#   instead; its usr/lib/python3/dist-packages goes first on PYTHONPATH for pvbatch and pvpython.
# - Debian testing, ParaView 6.1 (scripts/testing-root.sh): python3-paraview is installed as
#   usual, but ParaView's CMake package names its Python modules without the ABI suffix Debian
#   installs them with (.../paraview/modules/vtkRemotingClientServerStream.so for
#   vtkRemotingClientServerStream.cpython-314-x86_64-linux-gnu.so), and a CMake package that
#   names a missing file does not load. The prefix holds a link of each such name.
# The prefix (PRIVATE_DIR/prefix) is laid out like /usr, by symbolic links to /usr's headers,
# libraries and programs, joined with the Python package, and holds a copy of ParaView's CMake
# package: ParaView's CMake package checks that every file its imported targets name exists,
# relative to the prefix it is found in, and found here it finds them all.
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
  libgl1-mesa-dri
)
# Xvfb for the tests, except where VTK renders through EGL (MLAA_DISPLAY=egl, the testing root,
# which has no X server).
if [ "${MLAA_DISPLAY:-}" != egl ]; then
  packages+=(xvfb xauth)
fi
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

# The installed series (5.11, 6.1): the name of ParaView's CMake package directory.
libdir=lib/x86_64-linux-gnu
version="$(dpkg-query -W -f='${Version}' paraview)"
series="$(cd /usr/$libdir/cmake && ls -d paraview-* | sed -n 's/^paraview-//p' | head -n1)"
[ -n "$series" ] || { echo "install-paraview: no ParaView CMake package in /usr/$libdir/cmake" >&2; exit 1; }
stamp="$root_dir/.version"
if [ -f "$stamp" ] && [ "$(cat "$stamp")" = "$version" ] &&
  [ -f "$root_dir/python-path/paraview/__init__.py" ] &&
  [ -f "$prefix_dir/$libdir/cmake/paraview-$series/paraview-config.cmake" ]; then
  echo "install-paraview: ParaView $version already laid out in $root_dir"
  exit 0
fi
rm -rf "$root_dir"
mkdir -p "$prefix_dir"
if dpkg-query -W -f='${Status}' python3-paraview 2>/dev/null | grep -q "install ok installed"; then
  # Installed (Debian testing): ParaView's Python package is the system's.
  private_dir=/
else
  mkdir -p "$private_dir"
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
fi
python_dir="$(cd "$private_dir/usr/lib/python3/dist-packages" && pwd)"

# The prefix: /usr's headers and libraries by links, ParaView's programs and pvpython's.
mkdir -p "$prefix_dir/bin" "$prefix_dir/$libdir" "$prefix_dir/lib/python3"
ln -s /usr/include "$prefix_dir/include"
ln -s /usr/share "$prefix_dir/share"
ln -s "$python_dir" "$prefix_dir/lib/python3/dist-packages"
# (One ln for all the entries: there are thousands.)
ln -s /usr/$libdir/* "$prefix_dir/$libdir/"
rm "$prefix_dir/$libdir/cmake"
mkdir "$prefix_dir/$libdir/cmake"
ln -s /usr/$libdir/cmake/* "$prefix_dir/$libdir/cmake/"
rm "$prefix_dir/$libdir/cmake/paraview-$series"
cp -r /usr/$libdir/cmake/paraview-$series "$prefix_dir/$libdir/cmake/"
installed_python=()
[ "$private_dir" != / ] || installed_python=(python3-paraview)
for file in $(dpkg -L paraview paraview-dev "${installed_python[@]}" | grep '^/usr/bin/'); do
  ln -sf "$file" "$prefix_dir/bin/"
done
if [ "$private_dir" != / ]; then
  # The wrapping's class hierarchies of ParaView's VTK (lib/x86_64-linux-gnu/vtk/hierarchy/
  # ParaView) come with python3-paraview; /usr's lib/x86_64-linux-gnu/vtk has only the system
  # VTK 9.1's.
  rm "$prefix_dir/$libdir/vtk"
  ln -s "$(cd "$private_dir/usr/$libdir/vtk" && pwd)" "$prefix_dir/$libdir/vtk"
  for file in "$private_dir"/usr/bin/*; do
    ln -sf "$(cd "$(dirname "$file")" && pwd)/$(basename "$file")" "$prefix_dir/bin/"
  done
fi
# python3-paraview ships pvpython3.X; its package (and the CMake package) also name pvpython.
if [ ! -e "$prefix_dir/bin/pvpython" ]; then
  ln -sf "$(cd "$prefix_dir/bin" && ls pvpython3.* | head -n1)" "$prefix_dir/bin/pvpython"
fi

# Makes the prefix's directory $1 (relative) a real one, each level down: a linked directory is
# replaced by a directory of links to its entries, so that a link can be added inside it.
materialize() {
  local dir="$prefix_dir" part target
  local IFS=/
  for part in $1; do
    dir="$dir/$part"
    if [ -L "$dir" ]; then
      target="$(readlink -f "$dir")"
      rm "$dir"
      mkdir "$dir"
      ln -s "$target"/* "$dir/"
    fi
  done
}
# Each Python module the CMake package names but Debian installed with an ABI suffix
# (ParaView 6.1) gets a link of the name the package gives.
for location in $(sed -n 's|.*"${_IMPORT_PREFIX}/\(lib/python3/dist-packages/[^"]*\.so\)".*|\1|p' \
  "$prefix_dir/$libdir/cmake/paraview-$series"/*-targets-*.cmake | sort -u); do
  [ -e "$prefix_dir/$location" ] && continue
  suffixed=("$prefix_dir/${location%.so}".cpython-*.so)
  if [ -e "${suffixed[0]}" ]; then
    materialize "$(dirname "$location")"
    ln -s "$(readlink -f "${suffixed[0]}")" "$prefix_dir/$location"
    echo "install-paraview: $location -> $(basename "${suffixed[0]}") (ParaView's CMake package names it without its ABI suffix)"
  fi
done
# What the tests put first on PYTHONPATH (ParaView's Python package).
ln -s "$python_dir" "$root_dir/python-path"
echo "$series" >"$root_dir/series"
echo "$version" >"$stamp"
echo "install-paraview: ParaView $version ($series) laid out in $root_dir"
