// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAntialiasingOpenGL.h
 * @brief  VTK's OpenGL loader header, whichever this VTK has.
 *
 * VTK up to 9.3 loads OpenGL with GLEW (vtk_glew.h); VTK 9.4 and later with glad (vtk_glad.h).
 * Both declare the GL enums and entry points under their usual names, which is all the passes
 * use, so this one header serves VTK 9.1 to 9.6. Include it instead of either.
 */
#ifndef vtkAntialiasingOpenGL_h
#define vtkAntialiasingOpenGL_h

#if __has_include("vtk_glad.h")
#include "vtk_glad.h" // VTK 9.4 and later
#else
#include "vtk_glew.h" // VTK 9.1 to 9.3
#endif

#endif
// VTK-HeaderTest-Exclude: vtkAntialiasingOpenGL.h
