// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of vtkOpenGLMLAAPass on the "lines" scene (1- and 3-pixel lines at 48 angles), rendered offscreen
// without multisampling: strict comparison with the committed baseline, and the result must
// differ from the plain render (see vtkAntialiasingRenderTestUtilities.h).
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassLines(int argc, char* argv[])
{
  SceneWindow scene("lines");
  UseMLAA(scene.Renderer);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  CheckBaseline(argc, argv, "TestMLAAPassLines", scene.Window, result, scene.Plain, 300);
  return Result();
}
