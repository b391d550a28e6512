#!/usr/bin/env bash
# Installs what is needed, builds vtkMLAA with its tests, and runs every test (rendering tests
# offscreen under Xvfb). Then, unless --quick, the same with AddressSanitizer and
# LeakSanitizer (build-asan/): memory errors and leaks fail the run.
#   scripts/test.sh [--quick]
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
quick=0
[ "${1:-}" = "--quick" ] && quick=1

"$source_dir/scripts/install-deps.sh"
jobs="$(nproc)"

"$source_dir/scripts/build.sh" "$source_dir/build" -DBUILD_TESTING=ON
(cd "$source_dir/build" &&
  "$source_dir/scripts/with-xvfb.sh" ctest --output-on-failure --parallel "$jobs")

if ((quick == 0)); then
  "$source_dir/scripts/build.sh" "$source_dir/build-asan" -DBUILD_TESTING=ON \
    -DvtkMLAA_ENABLE_ASAN=ON
  # CMake gives each test its sanitizer environment (cmake/vtkMLAASanitizers.cmake).
  (cd "$source_dir/build-asan" &&
    "$source_dir/scripts/with-xvfb.sh" ctest --output-on-failure --parallel "$jobs" \
      --label-exclude package)
fi
echo "test: all tests passed"
