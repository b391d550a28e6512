// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Text and a scalar bar over a coloured surface with vtkOpenGLMLAAPass: a strict baseline
// comparison of the default result (overlays drawn after the antialiasing). (The overlays'
// behaviour, on every method, is in TestAntialiasingPass: overlay pixels over a flat background
// untouched by default, the surface antialiased, the overlays antialiased with
// AntialiasOverlaysOn().)
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassTextOverlay(int argc, char* argv[])
{
  SceneWindow scene("text");
  UseMLAA(scene.Renderer);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  CheckBaseline(argc, argv, "TestMLAAPassTextOverlay", scene.Window, result, scene.Plain, 100);
  return Result();
}
