# SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
# SPDX-License-Identifier: BSD-3-Clause
# The versions of VTK and OpenImageIO vtkMLAA supports, stated once and checked with a clear
# message: VTK 9.1 to 9.6 (Debian 12's 9.1.0 to Debian testing's 9.6.2) and OpenImageIO 2.4 to 3.x
# (Debian 12's 2.4.7, testing's 3.1.18). Both stacks are built and tested by scripts/test.sh.
set(vtkMLAA_VTK_MINIMUM 9.1)
set(vtkMLAA_VTK_MAXIMUM 9.6) # newest minor version tested
set(vtkMLAA_OIIO_MINIMUM 2.4)
set(vtkMLAA_OIIO_MAXIMUM_MAJOR 3)

# After find_package(VTK): stops outside the supported range.
function (vtkMLAA_check_vtk_version)
  set(_version "${VTK_VERSION_MAJOR}.${VTK_VERSION_MINOR}")
  if (_version VERSION_LESS vtkMLAA_VTK_MINIMUM OR _version VERSION_GREATER vtkMLAA_VTK_MAXIMUM)
    message(FATAL_ERROR "vtkMLAA supports VTK ${vtkMLAA_VTK_MINIMUM} to "
      "${vtkMLAA_VTK_MAXIMUM}; found VTK ${VTK_VERSION} at ${VTK_DIR}. Point VTK_DIR at a "
      "supported VTK.")
  endif ()
  message(STATUS "vtkMLAA: VTK ${VTK_VERSION} (supported: ${vtkMLAA_VTK_MINIMUM} to "
    "${vtkMLAA_VTK_MAXIMUM})")
endfunction ()

# find_package(OpenImageIO) for the supported range. OpenImageIO's own version file accepts only
# its own major version, so the package is found without a version and its version checked here.
# Also drops /usr/include/opencv4, which Debian's OpenImageIO 2.4 config lists among its include
# directories although it does not exist (CMake refuses a target whose interface names a missing
# directory).
macro (vtkMLAA_find_openimageio)
  find_package(OpenImageIO CONFIG REQUIRED)
  if (OpenImageIO_VERSION VERSION_LESS vtkMLAA_OIIO_MINIMUM OR
      OpenImageIO_VERSION_MAJOR GREATER vtkMLAA_OIIO_MAXIMUM_MAJOR)
    message(FATAL_ERROR "vtkMLAA supports OpenImageIO ${vtkMLAA_OIIO_MINIMUM} to "
      "${vtkMLAA_OIIO_MAXIMUM_MAJOR}.x; found ${OpenImageIO_VERSION} at ${OpenImageIO_DIR}. "
      "Point OpenImageIO_DIR at a supported one, or pass -DvtkMLAA_BUILD_EXAMPLES=OFF to build "
      "the libraries without the mlaa tool.")
  endif ()
  foreach (_mlaa_oiio_target IN ITEMS OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
    if (TARGET ${_mlaa_oiio_target})
      get_target_property(_mlaa_oiio_includes ${_mlaa_oiio_target} INTERFACE_INCLUDE_DIRECTORIES)
      if (_mlaa_oiio_includes)
        list(FILTER _mlaa_oiio_includes EXCLUDE REGEX "^/usr/include/opencv4/?$")
        set_property(TARGET ${_mlaa_oiio_target}
          PROPERTY INTERFACE_INCLUDE_DIRECTORIES "${_mlaa_oiio_includes}")
      endif ()
    endif ()
  endforeach ()
endmacro ()
