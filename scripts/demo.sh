#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The main job: installs what is needed, builds vtkMLAA, renders the demo scene without and with
# the MLAA render pass, and writes the comparison picture mlaa-demo.png (top: the two renders;
# bottom: magnified crops, none | MLAA).
#   scripts/demo.sh [mlaa-demo arguments, e.g. --scene lines --output lines.png]
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$source_dir/scripts/install-deps.sh"
"$source_dir/scripts/build.sh" "$source_dir/build"
if (($# == 0)); then
  set -- --output "$source_dir/mlaa-demo.png"
fi
"$source_dir/scripts/with-xvfb.sh" "$source_dir/build/bin/mlaa-demo" "$@"
