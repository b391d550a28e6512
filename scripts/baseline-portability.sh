#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# How portable regression-test baselines are across renderers (docs/regression-tests.md): renders
# the quality scenes (mlaa-quality --write-full: every method's full-size render) in four
# configurations, then compares, for each method, the renders of pairs of configurations that
# differ in one thing:
#   llvmpipe against softpipe (Mesa's two software rasterisers; VTK 9.1, GLX, Debian 12);
#   GLX against EGL (VTK 9.6 in the Debian testing root of scripts/testing-root.sh);
#   VTK 9.1 against 9.6 (Debian 12's GLX against the testing root's EGL, both llvmpipe).
# For each pair and method: the share of pixels whose largest channel difference exceeds 2/255
# and 32/255, over every scene; a Markdown table on standard output and in OUT/portability.md.
#   scripts/baseline-portability.sh [OUT_DIR [SIZE]]   (default build/portability, 400x300)
# Needs both builds: build/ (scripts/build.sh) and build-testing-root/main
# (scripts/test-testing-root.sh). About 10 minutes on 2 cores, most of it softpipe.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(mkdir -p "${1:-$source_dir/build/portability}" && cd "${1:-$source_dir/build/portability}" && pwd)"
size="${2:-400x300}"
case "$out" in
  "$source_dir"/*) ;;
  *) echo "baseline-portability: OUT_DIR must lie in the source tree (the root sees it at /src)" >&2
     exit 2 ;;
esac
inside="/src/${out#"$source_dir"/}"
quality=(--write-full --no-variants --samples 2 --size "$size")

"$source_dir/scripts/with-xvfb.sh" "$source_dir/build/bin/mlaa-quality" "${quality[@]}" \
  --output-dir "$out/vtk9.1-glx-llvmpipe" >/dev/null
GALLIUM_DRIVER=softpipe "$source_dir/scripts/with-xvfb.sh" \
  "$source_dir/build/bin/mlaa-quality" "${quality[@]}" \
  --output-dir "$out/vtk9.1-glx-softpipe" >/dev/null
"$source_dir/scripts/testing-root.sh" /usr/bin/env VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow \
  /src/build-testing-root/main/bin/mlaa-quality "${quality[@]}" \
  --output-dir "$inside/vtk9.6-egl-llvmpipe" >/dev/null
# VTK 9.6's GLX window, on an X server of the host's.
MLAA_TESTING_ROOT_X11=1 "$source_dir/scripts/with-xvfb.sh" "$source_dir/scripts/testing-root.sh" \
  /usr/bin/env VTK_DEFAULT_OPENGL_WINDOW=vtkXOpenGLRenderWindow \
  /src/build-testing-root/main/bin/mlaa-quality "${quality[@]}" \
  --output-dir "$inside/vtk9.6-glx-llvmpipe" >/dev/null

/usr/bin/python3 - "$out" <<'EOF' | tee "$out/portability.md"
import glob
import os
import sys

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

out = sys.argv[1]
pairs = [("llvmpipe / softpipe (VTK 9.1, GLX)", "vtk9.1-glx-llvmpipe", "vtk9.1-glx-softpipe"),
         ("GLX / EGL (VTK 9.6, llvmpipe)", "vtk9.6-glx-llvmpipe", "vtk9.6-egl-llvmpipe"),
         ("VTK 9.1 / 9.6 (GLX / EGL, llvmpipe)", "vtk9.1-glx-llvmpipe", "vtk9.6-egl-llvmpipe")]
methods = [("none", "none"), ("VTK's FXAA", "FXAA"), ("4x MSAA", "MSAA4"),
           ("MLAA pass", "MLAA-pass"), ("filter on the plain render", "MLAA-CPU"),
           ("MLAA pass, 4 samples", "MLAA-S4"), ("converged still (temporal, 16 renders)",
                                                  "MLAA-temporal")]


def read(path):
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[:, :, :3].astype(int)


scenes = sorted(os.path.basename(p)[len("quality-"):-len("-none.png")]
                for p in glob.glob(os.path.join(out, pairs[0][1], "quality-*-none.png")))
print("Share of pixels off by more than 2/255 | more than 32/255, %d scenes (%s)\n"
      % (len(scenes), ", ".join(scenes)))
print("| method | " + " | ".join(p[0] for p in pairs) + " |")
print("|---" * (len(pairs) + 1) + "|")
for label, method in methods:
    cells = []
    for _, a, b in pairs:
        total = over2 = over32 = 0
        for scene in scenes:
            name = "quality-%s-%s.png" % (scene, method)
            pa, pb = os.path.join(out, a, name), os.path.join(out, b, name)
            if not (os.path.exists(pa) and os.path.exists(pb)):
                continue
            diff = numpy.abs(read(pa) - read(pb)).max(axis=2)
            total += diff.size
            over2 += int((diff > 2).sum())
            over32 += int((diff > 32).sum())
        cells.append("%.3f %% \\| %.3f %%" % (100.0 * over2 / total, 100.0 * over32 / total)
                     if total else "n/a")
    print("| %s | %s |" % (label, " | ".join(cells)))
EOF
