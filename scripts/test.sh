#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Installs what is needed, builds vtkMLAA with its tests, and runs every test (rendering tests
# offscreen under Xvfb; the Python package's tests with /usr/bin/python3). Then builds the
# ParaView plugin against Debian's ParaView 5.11 and runs its pvbatch tests on one and two MPI
# ranks (scripts/test-paraview.sh). Then the same on the current stack (scripts/test-testing-root.sh):
# a Debian testing root that it makes once and reuses (VTK 9.6, OpenImageIO 3, ParaView 6.1,
# PyVista), everything built there and tested with no X server, through EGL; it needs root
# rights (chroot), as the package installs do. Then, unless --quick, the main tests again with
# AddressSanitizer and LeakSanitizer (build-asan/): memory errors and leaks fail the run; and
# the fuzz targets (scripts/fuzz.sh, build-fuzz/): both replay their committed seeds, then fuzz
# side by side for MLAA_FUZZ_SECONDS each (default 90): a finding fails the run.
#   scripts/test.sh [--quick]
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
quick=0
[ "${1:-}" = "--quick" ] && quick=1

# Each stage's wall time, printed as it ends and again at the end, so that a slow run says where
# its time went.
stage_times=()
stage() {
  local name="$1" start=$SECONDS
  shift
  "$@"
  stage_times+=("$(printf '%-28s %5d s' "$name" $((SECONDS - start)))")
  echo "test: stage '$name' took $((SECONDS - start)) s"
}

stage install "$source_dir/scripts/install-deps.sh"
jobs="$(nproc)"

stage build "$source_dir/scripts/build.sh" "$source_dir/build" -DBUILD_TESTING=ON
cd "$source_dir/build"
stage tests "$source_dir/scripts/with-xvfb.sh" ctest --output-on-failure --parallel "$jobs"
cd "$source_dir"

# The ParaView plugin (its own project; installs ParaView and unpacks its Python privately).
stage paraview-plugin "$source_dir/scripts/test-paraview.sh" "$source_dir/build"

# The current stack, in its Debian testing root (made on first use: minutes and about 4 GB).
stage testing-root "$source_dir/scripts/test-testing-root.sh"

if ((quick == 0)); then
  stage asan-build "$source_dir/scripts/build.sh" "$source_dir/build-asan" -DBUILD_TESTING=ON \
    -DvtkMLAA_ENABLE_ASAN=ON
  # CMake gives each test its sanitizer environment (cmake/vtkMLAASanitizers.cmake). The
  # quality measurement (label benchmark-quality: T-AAR of rendered orbits) is left out: it adds
  # no code path that the pass's own tests do not run here.
  cd "$source_dir/build-asan"
  stage asan-tests "$source_dir/scripts/with-xvfb.sh" ctest --output-on-failure --parallel "$jobs" \
    --label-exclude "package|benchmark-quality"
  cd "$source_dir"

  # A new corpus each time, in the build directory, where a finding's input stays to replay.
  rm -rf "$source_dir/build-fuzz/ci-run"
  stage fuzz "$source_dir/scripts/fuzz.sh" "${MLAA_FUZZ_SECONDS:-90}" "$source_dir/build-fuzz/ci-run"
fi
printf 'test: %s\n' "${stage_times[@]}"
echo "test: all tests passed in $SECONDS s"
