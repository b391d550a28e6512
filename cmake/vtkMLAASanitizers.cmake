# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# vtkMLAA_set_sanitizer_environment(): called at the end of each CMakeLists.txt that adds tests.
# With vtkMLAA_ENABLE_ASAN it gives every test of that directory the environment of an
# AddressSanitizer + LeakSanitizer run, so ctest needs no special environment and the programs
# around the tests (ctest, Xvfb, the shell) are not touched:
# - leak suppressions for third-party libraries (Testing/sanitizer/lsan.supp);
# - Mesa's software driver preloaded (after the sanitizer runtime, which must come first), so that
#   it is not unloaded at exit: its one-time allocations would otherwise be reported as leaks of
#   an "unknown module" that no suppression can name;
# - full stack traces (slow unwinding) for the tests labelled "third-party-leaks" (tool tests,
#   which use no OpenGL), so that suppressions can name third-party functions; the slow unwinder
#   deadlocks in llvmpipe's JIT code, and it costs each run of the tool about half a second at
#   start-up, so every other test keeps the fast one.
# (CMake 3.25 sets test properties only in the directory that added the tests.)
if (vtkMLAA_ENABLE_ASAN)
  execute_process(COMMAND "${CMAKE_CXX_COMPILER}" -print-file-name=libasan.so
    OUTPUT_VARIABLE vtkMLAA_ASAN_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
  file(GLOB vtkMLAA_DRI_DRIVER "/usr/lib/*/dri/swrast_dri.so" "/usr/lib/dri/swrast_dri.so")
  set(vtkMLAA_SANITIZER_PRELOAD "${vtkMLAA_ASAN_RUNTIME}")
  if (vtkMLAA_DRI_DRIVER)
    list(GET vtkMLAA_DRI_DRIVER 0 vtkMLAA_DRI_DRIVER)
    string(APPEND vtkMLAA_SANITIZER_PRELOAD " ${vtkMLAA_DRI_DRIVER}")
  endif ()
endif ()

function (vtkMLAA_set_sanitizer_environment)
  if (NOT vtkMLAA_ENABLE_ASAN)
    return ()
  endif ()
  get_property(tests DIRECTORY PROPERTY TESTS)
  foreach (test IN LISTS tests)
    get_property(labels TEST "${test}" PROPERTY LABELS)
    set(options "detect_leaks=1:halt_on_error=1")
    if ("third-party-leaks" IN_LIST labels)
      string(APPEND options ":fast_unwind_on_malloc=0")
    endif ()
    set_property(TEST "${test}" APPEND PROPERTY ENVIRONMENT
      "LD_PRELOAD=${vtkMLAA_SANITIZER_PRELOAD}"
      "ASAN_OPTIONS=${options}"
      "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/Testing/sanitizer/lsan.supp:print_suppressions=0"
      "UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1")
  endforeach ()
endfunction ()
