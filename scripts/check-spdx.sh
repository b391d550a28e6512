#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
#
# Lists every source file of the project (C++, GLSL, Python, CMake, shell, sanitizer
# suppressions, ParaView XML) that lacks the SPDX licence line at its head, and fails if there is
# one. The files are those git tracks, or, outside a git checkout, those under the source tree
# (build directories left out). vtk.module and paraview.plugin files are keyword lists that take
# no comments, and Markdown and images are not source: they are not checked.
#   scripts/check-spdx.sh [SOURCE_DIR]
set -euo pipefail
source_dir="$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/..}" && pwd)"
cd "$source_dir"

if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files)
else
  mapfile -t files < <(find . -path './build*' -prune -o -type f -print | sed 's#^\./##')
fi

missing=0
checked=0
for file in "${files[@]}"; do
  case "$file" in
    *.h | *.cxx | *.glsl | *.py | *.cmake | *.sh | *.in | *.supp | *.xml | */CMakeLists.txt | \
      CMakeLists.txt | .ci/run) ;;
    *) continue ;;
  esac
  [ -f "$file" ] || continue
  checked=$((checked + 1))
  if ! head -n 5 "$file" | grep -q 'SPDX-License-Identifier: BSD-3-Clause'; then
    echo "check-spdx: no SPDX-License-Identifier in the first lines of $file" >&2
    missing=$((missing + 1))
  fi
done
if ((checked == 0)); then
  echo "check-spdx: no source files found under $source_dir" >&2
  exit 1
fi
if ((missing > 0)); then
  echo "check-spdx: $missing of $checked source files lack the SPDX lines" >&2
  exit 1
fi
echo "check-spdx: all $checked source files carry the SPDX lines"
