# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# ctest script of the main project (the test example-regression-test): configures and builds the
# example project of this directory against the main project's build tree, then runs its tests,
# in the display the main tests run in (Xvfb, or EGL with none).
#   cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -P RunExample.cmake
foreach (var BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif ()
endforeach ()
file(REMOVE_RECURSE "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${out}${err}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "command failed (${result}): ${ARGN}")
  endif ()
endfunction ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release "-DvtkMLAA_DIR=${BUILD_DIR}")
run("${CMAKE_COMMAND}" --build "${WORK_DIR}")
run("${CMAKE_CTEST_COMMAND}" --test-dir "${WORK_DIR}" --output-on-failure)
