# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# ctest script: installs the build tree into a fresh prefix, then configures, builds and runs the
# consumer project of this directory against the build tree (-DvtkMLAA_DIR=<build>) or the
# install prefix (CMAKE_PREFIX_PATH), and checks the installed layout.
#
# cmake -DMODE=build-tree|install-prefix -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=...
#       -DGENERATOR=... -P TestPackage.cmake
foreach (var MODE BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "${var} is not set")
  endif ()
endforeach ()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

function (run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "command failed (${result}): ${ARGN}\n${out}\n${err}")
  endif ()
  message(STATUS "${out}")
endfunction ()

if (MODE STREQUAL "install-prefix")
  set(prefix "${WORK_DIR}/install")
  run("${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
  foreach (installed
      bin/mlaa
      include/vtkMLAA/vtkImageMLAA.h
      include/vtkMLAA/vtkMLAAOptions.h
      include/vtkMLAA/vtkMLAAAreaTexture.h
      include/vtkMLAA/vtkOpenGLMLAAPass.h
      lib/cmake/vtkMLAA/vtkMLAAConfig.cmake
      lib/cmake/vtkMLAA/vtkMLAAConfigVersion.cmake
      lib/cmake/vtkMLAA/vtkMLAA-targets.cmake)
    if (NOT EXISTS "${prefix}/${installed}")
      message(FATAL_ERROR "not installed: ${installed}")
    endif ()
  endforeach ()
  file(GLOB libraries "${prefix}/lib/libvtkFiltersMLAA*" "${prefix}/lib/libvtkRenderingMLAA*")
  if (NOT libraries)
    message(FATAL_ERROR "the libraries were not installed under ${prefix}/lib")
  endif ()
  set(find_args "-DCMAKE_PREFIX_PATH=${prefix}")
else ()
  set(find_args "-DvtkMLAA_DIR=${BUILD_DIR}")
endif ()

run("${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${WORK_DIR}/consumer" -G "${GENERATOR}"
  -DCMAKE_BUILD_TYPE=Release ${find_args})
run("${CMAKE_COMMAND}" --build "${WORK_DIR}/consumer")
run("${WORK_DIR}/consumer/consumer")
if (MODE STREQUAL "install-prefix")
  # The installed tool runs from the prefix.
  run("${prefix}/bin/mlaa" --help)
endif ()
