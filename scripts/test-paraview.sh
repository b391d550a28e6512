#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Builds the ParaView plugin (ParaView/) against Debian's ParaView (5.11 on Debian 12, 6.1 in the
# Debian testing root of scripts/testing-root.sh) into PLUGIN_DIR/build (default
# build-paraview/) and runs its tests (pvbatch on one and two ranks, client and server; under
# Xvfb, or through EGL where MLAA_DISPLAY=egl).
#   scripts/test-paraview.sh [MAIN_BUILD_DIR [PLUGIN_DIR]]
# MAIN_BUILD_DIR (default build/) is the main project's build, whose `mlaa` tool is the tests'
# reference (vtkImageMLAA outside ParaView); its mlaa target is brought up to date first.
# scripts/install-paraview.sh installs and unpacks what is missing (and is quick when nothing
# is).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
main_build="$(cd "${1:-$source_dir/build}" 2>/dev/null && pwd)" || {
  echo "test-paraview: no main build at ${1:-$source_dir/build}: run scripts/build.sh first" >&2
  exit 1
}
plugin_dir="${2:-$source_dir/build-paraview}"
paraview_root="$plugin_dir/paraview-root"
build_dir="$plugin_dir/build"

"$source_dir/scripts/install-paraview.sh" "$paraview_root"
cmake --build "$main_build" --target mlaa

cmake -S "$source_dir/ParaView" -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  "-DParaView_DIR=$paraview_root/prefix/lib/x86_64-linux-gnu/cmake/paraview-$(cat "$paraview_root/series")" \
  "-DvtkMLAAParaView_PYTHONPATH=$(readlink -f "$paraview_root/python-path")" \
  "-DvtkMLAAParaView_MLAA_TOOL=$main_build/bin/mlaa"
cmake --build "$build_dir" --parallel "$(nproc)"
(cd "$build_dir" && "$source_dir/scripts/with-xvfb.sh" ctest --output-on-failure)
echo "test-paraview: all tests passed"
