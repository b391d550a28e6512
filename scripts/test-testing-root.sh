#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The current stack: builds vtkMLAA in the Debian testing root of scripts/testing-root.sh (VTK
# 9.6, OpenImageIO 3, Python 3.14) into build-testing-root/main, runs every test there with no X
# server (VTK renders through EGL, and TestRenderWindowClass checks that the window is a
# vtkEGLRenderWindow), then builds the ParaView plugin against ParaView 6.1 and runs its tests
# (scripts/test-paraview.sh). Makes the root first if there is none (minutes; see
# testing-root.sh).
#   scripts/test-testing-root.sh
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

if [ "${1:-}" != "--inside" ]; then
  exec "$source_dir/scripts/testing-root.sh" /src/scripts/test-testing-root.sh --inside
fi

# In the root: no display at all, and no X server to start one, so VTK cannot fall back to X.
unset DISPLAY
if command -v Xvfb >/dev/null || command -v Xorg >/dev/null; then
  echo "test-testing-root: the root has an X server ($(command -v Xvfb Xorg)); it must not" >&2
  exit 1
fi
export MLAA_DISPLAY=egl # scripts/with-xvfb.sh: no Xvfb, the command as it is
build_dir=/src/build-testing-root/main
"$source_dir/scripts/build.sh" "$build_dir" -DBUILD_TESTING=ON \
  -DvtkMLAA_EXPECTED_RENDER_WINDOW=vtkEGLRenderWindow
(cd "$build_dir" && ctest --output-on-failure --parallel "$(nproc)")
"$source_dir/scripts/test-paraview.sh" "$build_dir" /src/build-testing-root/paraview
echo "test-testing-root: all tests passed"
