// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of vtkOpenGLDLAAPass on the "silhouettes" scene (shaded sphere, cube and
// cone), rendered offscreen without multisampling: strict comparison with the committed
// baseline, and the result must differ from the plain render (see vtkAntialiasingRenderTestUtilities.h).
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestDLAAPassSilhouettes(int argc, char* argv[])
{
  SceneWindow scene("silhouettes");
  UseDLAA(scene.Renderer);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  CheckBaseline(argc, argv, "TestDLAAPassSilhouettes", scene.Window, result, scene.Plain, 300);
  return Result();
}
