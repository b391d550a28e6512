# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Runs one gallery program and checks its exit status and what it printed, for the gallery tests
# (a plain CTest test checks either the exit status or the output, not both).
#   cmake -DPROGRAM=... "-DARGS=a|b" -DEXPECT_RESULT=N [-DEXPECT_OUTPUT=regex (stdout)]
#         [-DEXPECT_ERROR=regex (stderr)]
#         [-DEXPECT_FILES=path|...] [-DEXPECT_NO_FILES_LIKE=glob] -P RunAndCheck.cmake
string(REPLACE "|" ";" args "${ARGS}")
execute_process(COMMAND "${PROGRAM}" ${args}
  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit status ${result}\n--- stdout\n${out}--- stderr\n${err}---")
if (NOT "${result}" STREQUAL "${EXPECT_RESULT}")
  message(FATAL_ERROR "expected exit status ${EXPECT_RESULT}, got ${result}")
endif ()
if (DEFINED EXPECT_OUTPUT AND NOT "${out}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "stdout does not match: ${EXPECT_OUTPUT}")
endif ()
if (DEFINED EXPECT_ERROR AND NOT "${err}" MATCHES "${EXPECT_ERROR}")
  message(FATAL_ERROR "stderr does not match: ${EXPECT_ERROR}")
endif ()
string(REPLACE "|" ";" expect_files "${EXPECT_FILES}")
foreach (file IN LISTS expect_files)
  if (NOT EXISTS "${file}")
    message(FATAL_ERROR "missing: ${file}")
  endif ()
endforeach ()
if (DEFINED EXPECT_NO_FILES_LIKE)
  file(GLOB left "${EXPECT_NO_FILES_LIKE}")
  if (left)
    message(FATAL_ERROR "left behind: ${left}")
  endif ()
endif ()
