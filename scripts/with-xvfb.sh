#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Runs a command with its own virtual X display (Xvfb; Mesa's llvmpipe renders OpenGL), which
# VTK's X11 render windows need even offscreen. Xvfb picks a free display number itself
# (-displayfd), so several of these can run at once. -noreset: an X server normally resets when
# its last client disconnects, and a window opened during the reset fails ("bad X server
# connection"); tests that close one window and open the next would fail now and then.
# With MLAA_DISPLAY=egl (the Debian testing root of scripts/testing-root.sh, whose VTK renders
# through EGL and which has no X server), it starts no Xvfb and runs the command as it is, with
# DISPLAY unset and VTK's EGL window chosen.
#   scripts/with-xvfb.sh COMMAND [ARGUMENTS...]
set -euo pipefail
(($# > 0)) || { echo "usage: with-xvfb.sh COMMAND [ARGUMENTS...]" >&2; exit 2; }

if [ "${MLAA_DISPLAY:-}" = egl ]; then
  unset DISPLAY
  export VTK_DEFAULT_OPENGL_WINDOW=vtkEGLRenderWindow
  exec "$@"
fi

display_file="$(mktemp)"
Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3>"$display_file" 2>/dev/null &
xvfb_pid=$!
cleanup() {
  kill "$xvfb_pid" 2>/dev/null || true
  wait "$xvfb_pid" 2>/dev/null || true
  rm -f "$display_file"
}
trap cleanup EXIT

for _ in $(seq 100); do
  [ -s "$display_file" ] && break
  kill -0 "$xvfb_pid" 2>/dev/null || { echo "with-xvfb: Xvfb did not start" >&2; exit 1; }
  sleep 0.1
done
[ -s "$display_file" ] || { echo "with-xvfb: Xvfb gave no display" >&2; exit 1; }
export DISPLAY=":$(head -n1 "$display_file")"
# Mesa's software rasteriser, whatever the machine has.
export LIBGL_ALWAYS_SOFTWARE=1
"$@"
