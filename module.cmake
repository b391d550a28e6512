# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The project's single list of VTK modules, and the VTK module scan/build that turns them into
# libraries. VTK 9 reads each module's declaration from its `vtk.module` file; this file says
# which of them the project builds.
set(vtkMLAA_MODULE_DIRECTORIES
  "${CMAKE_CURRENT_SOURCE_DIR}/Filters"    # MLAA::FiltersMLAA   (vtkFiltersMLAA)
  "${CMAKE_CURRENT_SOURCE_DIR}/Rendering"  # MLAA::RenderingMLAA (vtkRenderingMLAA)
  )

# A fuzzing build (vtkMLAA_ENABLE_FUZZING) needs the filters only.
set(vtkMLAA_REQUESTED_MODULES MLAA::FiltersMLAA)
if (NOT vtkMLAA_ENABLE_FUZZING)
  list(APPEND vtkMLAA_REQUESTED_MODULES MLAA::RenderingMLAA)
endif ()

vtk_module_find_modules(vtkMLAA_MODULE_FILES ${vtkMLAA_MODULE_DIRECTORIES})

vtk_module_scan(
  MODULE_FILES      ${vtkMLAA_MODULE_FILES}
  REQUEST_MODULES   ${vtkMLAA_REQUESTED_MODULES}
  PROVIDES_MODULES  vtkMLAA_MODULES
  ENABLE_TESTS      "${BUILD_TESTING}")

if (BUILD_TESTING)
  include("${VTK_DIR}/vtkModuleTesting.cmake")
endif ()

vtk_module_build(
  MODULES             ${vtkMLAA_MODULES}
  PACKAGE             vtkMLAA
  INSTALL_EXPORT      vtkMLAA
  VERSION             "${PROJECT_VERSION}"
  SOVERSION           "${PROJECT_VERSION_MAJOR}"
  HEADERS_DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/vtkMLAA"
  CMAKE_DESTINATION   "${CMAKE_INSTALL_LIBDIR}/cmake/vtkMLAA"
  TEST_DIRECTORY_NAME "Testing")
