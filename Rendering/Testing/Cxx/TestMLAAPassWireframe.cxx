// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of vtkOpenGLMLAAPass on the "wireframe" scene (wireframe torus-like superquadric), rendered offscreen
// without multisampling: strict comparison with the committed baseline, and the result must
// differ from the plain render (see vtkAntialiasingRenderTestUtilities.h).
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassWireframe(int argc, char* argv[])
{
  SceneWindow scene("wireframe");
  UseMLAA(scene.Renderer);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  CheckBaseline(argc, argv, "TestMLAAPassWireframe", scene.Window, result, scene.Plain, 300);
  return Result();
}
