#!/usr/bin/env bash
# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Builds the libFuzzer targets of Testing/Fuzz with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer (build-fuzz/, -DvtkMLAA_ENABLE_FUZZING=ON), runs each once over its
# committed seeds (ctest -L fuzz), then fuzzes both side by side for SECONDS each. Exits non-zero
# on a finding (a crash, a sanitizer report, a leak, a broken invariant, a timeout or running
# out of memory), after naming the input that shows it and how to replay it.
#   scripts/fuzz.sh [SECONDS [CORPUS_DIR]]
# SECONDS: per target, default 600. CORPUS_DIR: where the corpus grows, run after run, and where
# findings and logs go; default ~/.cache/vtkMLAA-fuzz (outside the repository: only the seeds
# that make-corpus.py writes are committed). scripts/test.sh runs this for 90 seconds in a new
# directory.
set -euo pipefail
source_dir="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-600}"
corpus_root="${2:-${XDG_CACHE_HOME:-$HOME/.cache}/vtkMLAA-fuzz}"
build_dir="${MLAA_FUZZ_BUILD:-$source_dir/build-fuzz}"
# MLAA_FUZZ_TARGETS: which targets to fuzz (both by default; the seeds of both are replayed
# whatever it says).
read -r -a targets <<<"${MLAA_FUZZ_TARGETS:-mlaa_filter_fuzzer mlaa_tool_fuzzer}"
for target in "${targets[@]}"; do
  case "$target" in
  mlaa_filter_fuzzer | mlaa_tool_fuzzer) ;;
  *) echo "fuzz: unknown target '$target' in MLAA_FUZZ_TARGETS" >&2; exit 2 ;;
  esac
done
[[ "$seconds" =~ ^[1-9][0-9]*$ ]] || { echo "fuzz: SECONDS must be a positive integer" >&2; exit 2; }

command -v clang++ >/dev/null || { echo "fuzz: needs clang (scripts/install-deps.sh)" >&2; exit 1; }
start=$(date +%s)
"$source_dir/scripts/build.sh" "$build_dir" -DvtkMLAA_ENABLE_FUZZING=ON -DBUILD_TESTING=OFF \
  -DBUILD_SHARED_LIBS=OFF -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
echo "fuzz: built in $(($(date +%s) - start)) s"

# The seeds once (also the regression test of every input committed there).
(cd "$build_dir" && ctest --output-on-failure -L fuzz)

suppressions="$build_dir/Testing/Fuzz/lsan.supp"
# Full stack traces for leaks (slow unwinding), so that the suppressions can name the
# third-party functions that leak; the filter target allocates nothing in those libraries.
asan_options="detect_leaks=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$suppressions:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

pids=()
for target in "${targets[@]}"; do
  mkdir -p "$corpus_root/$target" "$corpus_root/findings/$target" "$corpus_root/logs"
  # The first directory receives new inputs; the committed seeds are only read.
  # -close_fd_mask=2: what the code under test prints on stderr is dropped (libFuzzer and the
  # sanitizers keep their own copy of stderr); -timeout and -rss_limit_mb make hangs and
  # runaway allocations findings too.
  unwind=""
  memory=(-rss_limit_mb=2048)
  if [ "$target" = mlaa_tool_fuzzer ]; then
    unwind=":fast_unwind_on_malloc=0"
    # OpenEXR 3.1 allocates a string attribute of the size its header gives (up to 2 GiB)
    # before any size check of ours can run (found by this target; oiiotool does the same):
    # allowed, but no single allocation larger.
    memory=(-rss_limit_mb=4096 -malloc_limit_mb=2048)
  fi
  ASAN_OPTIONS="$asan_options$unwind" "$build_dir/bin/$target" "$corpus_root/$target" \
    "$source_dir/Testing/Fuzz/corpus/$target" "${memory[@]}" \
    -max_total_time="$seconds" -timeout=60 -close_fd_mask=2 \
    -print_final_stats=1 -artifact_prefix="$corpus_root/findings/$target/" \
    >"$corpus_root/logs/$target.log" 2>&1 &
  pids+=($!)
done
fuzz_start=$(date +%s)

status=0
for i in "${!targets[@]}"; do
  target="${targets[$i]}"
  log="$corpus_root/logs/$target.log"
  if wait "${pids[$i]}"; then
    result="no finding"
  else
    result="FINDING (exit status $?)"
    status=1
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  echo "fuzz: $target: ${runs:-?} executions, $result, by $(($(date +%s) - fuzz_start)) s" \
    "(log: $log)"
  if [ "$result" != "no finding" ]; then
    grep -E "ERROR|mlaa fuzz|SUMMARY|Test unit written" "$log" | head -n 20 | sed 's/^/  /' || true
    for artifact in "$corpus_root/findings/$target/"*; do
      [ -e "$artifact" ] && echo "  replay: $build_dir/bin/$target $artifact"
    done
  fi
done
echo "fuzz: done in $(($(date +%s) - start)) s"
exit "$status"
