#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The GPU pass's speed against VTK's FXAA pass (MEASURING.md), at 1920 x 1080 and 3840 x 2160,
# on the benchmark's scenes: absolute frame times and overheads of FXAA, MLAA (defaults and the
# presets) and DLAA, from a build directory or a copy of one on another machine.
#   scripts/benchmark-gpu.sh [BUILD_DIR] [-- extra mlaa-benchmark-gpu arguments]
# BUILD_DIR (default: build/ beside this script's directory) must hold bin/mlaa-benchmark-gpu and
# lib/ with the project's libraries; copy both directories as they are (cp -a), anywhere.
#
# What the machine needs:
# - the VTK 9.1 runtime the build was made against (Debian 12: apt-get install libvtk9.1; the
#   script lists any library the benchmark cannot find and stops);
# - an OpenGL 3.2+ display: Debian's VTK renders through GLX only, so DISPLAY must name an X
#   server. On a machine with a GPU that means an X server driven by its driver (for NVIDIA:
#   Xorg with the NVIDIA driver, e.g. a headless one configured by nvidia-xconfig
#   --allow-empty-initial-configuration); with no DISPLAY the script starts Xvfb, which renders
#   with Mesa's llvmpipe on the CPU: the figures are then llvmpipe's, and the script says so.
# Timing: wall clock, Render() + glFinish per frame, medians; the renderer string printed first
# says which GPU ran it. Then the mean time of each stage of each pass (--stages: the GPU's own
# timestamps on a GPU, the steady clock under Xvfb).
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${1:-$source_dir/build}"
[ $# -gt 0 ] && shift
[ "${1:-}" = "--" ] && shift
extra=("$@")

benchmark="$build_dir/bin/mlaa-benchmark-gpu"
if [ ! -x "$benchmark" ]; then
  echo "benchmark-gpu: no $benchmark (build with scripts/build.sh, or copy bin/ and lib/ of a build)" >&2
  exit 2
fi
# The copy's own libraries first: its run path names the directory it was built in.
export LD_LIBRARY_PATH="$build_dir/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
missing="$(ldd "$benchmark" | awk '/not found/ {print $1}')"
if [ -n "$missing" ]; then
  echo "benchmark-gpu: libraries not found (install the VTK 9.1 runtime, libvtk9.1 on Debian 12):" >&2
  echo "$missing" | sed 's/^/  /' >&2
  exit 2
fi

run=()
stages=gl
if [ -z "${DISPLAY:-}" ]; then
  if ! command -v xvfb-run >/dev/null; then
    echo "benchmark-gpu: no DISPLAY and no xvfb-run: start an X server on the GPU and set DISPLAY" >&2
    exit 2
  fi
  echo "benchmark-gpu: no DISPLAY: running under Xvfb, which renders with llvmpipe on the CPU"
  run=(xvfb-run -a -s "-screen 0 4096x2304x24")
  stages=wall
fi

for size in 1920x1080 3840x2160; do
  for scene in mixed silhouettes lines horizon stripes-45 stripes-0.3; do
    echo "=== $scene at $size"
    "${run[@]}" "$benchmark" --size "$size" --scene "$scene" --frames 100 --rounds 5 \
      --no-long-lines --stages "$stages" "${extra[@]}"
  done
done
