#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs the Debian 12 packages vtkMLAA needs to build, test and run (VTK 9.1 and its Python
# with numpy, OpenImageIO, Xvfb with Mesa's llvmpipe for offscreen OpenGL, clang with its
# libFuzzer runtime for the fuzz targets). Packages already present are skipped, so a machine
# that has them all needs no root rights and no network.
set -euo pipefail

packages=(
  cmake g++ ninja-build pkg-config      # build tools
  libvtk9-dev                           # VTK 9.1 (modules, OpenGL2 rendering, testing)
  python3-vtk9 python3-numpy            # VTK's Python (vtkmodules) for the vtkmlaa package
  libopenimageio-dev openimageio-tools  # image files for the mlaa tool (oiiotool, idiff)
  xvfb xauth libgl1-mesa-dri            # offscreen OpenGL: Xvfb + Mesa llvmpipe
  clang libclang-rt-14-dev              # the fuzz targets (libFuzzer), scripts/fuzz.sh
)

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if ((${#missing[@]} == 0)); then
  echo "install-deps: all packages present"
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: run as root or install sudo" >&2; exit 1; }
  sudo=(sudo)
fi
echo "install-deps: installing ${missing[*]}"
"${sudo[@]}" apt-get update
DEBIAN_FRONTEND=noninteractive "${sudo[@]}" apt-get install -y "${missing[@]}"
