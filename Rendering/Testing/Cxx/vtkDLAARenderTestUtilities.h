// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers for the offscreen rendering tests of vtkOpenGLDLAAPass.
#ifndef vtkDLAARenderTestUtilities_h
#define vtkDLAARenderTestUtilities_h

#include "vtkMLAARenderTestUtilities.h"

#include "vtkDLAAOptions.h"
#include "vtkOpenGLDLAAPass.h"

namespace vtkMLAATest
{
// Sets a DLAA pass (delegate: the standard render steps) on a renderer.
inline vtkSmartPointer<vtkOpenGLDLAAPass> UseDLAA(
  vtkRenderer* renderer, vtkDLAAOptions* options = nullptr)
{
  vtkNew<vtkRenderStepsPass> steps;
  auto pass = vtkSmartPointer<vtkOpenGLDLAAPass>::New();
  pass->SetDelegatePass(steps);
  if (options)
  {
    pass->SetOptions(options);
  }
  renderer->SetPass(pass);
  return pass;
}
}

#endif
