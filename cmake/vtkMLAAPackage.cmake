# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# Writes vtkMLAAConfig.cmake and vtkMLAAConfigVersion.cmake for the build tree and for the
# install tree. vtk_module_build exports the targets and module properties but writes no
# <Package>Config.cmake of its own.
include(CMakePackageConfigHelpers)

set(vtkMLAA_CMAKE_DESTINATION "${CMAKE_INSTALL_LIBDIR}/cmake/vtkMLAA")

set(_vtkMLAA_mlaa_name "mlaa${CMAKE_EXECUTABLE_SUFFIX}")

# Build tree: <build>/vtkMLAAConfig.cmake, targets under <build>/lib/cmake/vtkMLAA.
set(vtkMLAA_CONFIG_TARGETS_DIR "${CMAKE_BINARY_DIR}/${vtkMLAA_CMAKE_DESTINATION}")
set(vtkMLAA_CONFIG_MLAA_EXECUTABLE "")
if (TARGET mlaa)
  set(vtkMLAA_CONFIG_MLAA_EXECUTABLE "${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/${_vtkMLAA_mlaa_name}")
endif ()
configure_file("${CMAKE_CURRENT_LIST_DIR}/vtkMLAAConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/vtkMLAAConfig.cmake" @ONLY)

# Install tree: the file sits beside the targets; paths are relative to it.
set(vtkMLAA_CONFIG_TARGETS_DIR "\${CMAKE_CURRENT_LIST_DIR}")
if (TARGET mlaa)
  file(RELATIVE_PATH _vtkMLAA_bin_from_cmake
    "/prefix/${vtkMLAA_CMAKE_DESTINATION}" "/prefix/${CMAKE_INSTALL_BINDIR}")
  set(vtkMLAA_CONFIG_MLAA_EXECUTABLE
    "\${CMAKE_CURRENT_LIST_DIR}/${_vtkMLAA_bin_from_cmake}/${_vtkMLAA_mlaa_name}")
endif ()
configure_file("${CMAKE_CURRENT_LIST_DIR}/vtkMLAAConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/CMakeFiles/vtkMLAAConfig.cmake.install" @ONLY)

write_basic_package_version_file("${CMAKE_BINARY_DIR}/vtkMLAAConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMajorVersion)

install(FILES "${CMAKE_BINARY_DIR}/CMakeFiles/vtkMLAAConfig.cmake.install"
  DESTINATION "${vtkMLAA_CMAKE_DESTINATION}" RENAME vtkMLAAConfig.cmake COMPONENT development)
install(FILES "${CMAKE_BINARY_DIR}/vtkMLAAConfigVersion.cmake"
  DESTINATION "${vtkMLAA_CMAKE_DESTINATION}" COMPONENT development)
