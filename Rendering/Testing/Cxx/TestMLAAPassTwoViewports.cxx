// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Two renderers side by side in one window, each with its own vtkOpenGLMLAAPass: a strict
// baseline comparison. (The viewports' behaviour, on every method, is in TestAntialiasingPass:
// each viewport equals the CPU filter on the same viewport of the plain render and the pass on a
// window of its own, and one pass object shared by both renderers gives the same image.)
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassTwoViewports(int argc, char* argv[])
{
  TwoViewportWindow two;
  for (auto& renderer : two.Renderers)
  {
    UseMLAA(renderer);
  }
  auto rgb = vtkMLAAScenes::Capture(two.Window);
  CheckBaseline(argc, argv, "TestMLAAPassTwoViewports", two.Window, rgb, two.Plain, 300);
  return Result();
}
