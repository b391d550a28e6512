// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of a converged still of the temporal pass (vtkOpenGLMLAAPass with
// SetTemporal(true)) on the "orbit" scene (1-pixel lines, points, glyphs, a textured floor),
// rendered offscreen without multisampling: RenderConverged with ConvergedFrames 15 and the
// capture's render make 16 jittered renders; strict comparison with the committed baseline, and
// the result must differ from the plain render (see vtkAntialiasingRenderTestUtilities.h).
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestAntialiasingPassTemporalStill(int argc, char* argv[])
{
  SceneWindow scene("orbit");
  vtkSmartPointer<vtkOpenGLMLAAPass> pass = UseMLAA(scene.Renderer);
  pass->TemporalOn();
  pass->SetConvergedFrames(15);
  const int renders = pass->RenderConverged(scene.Window);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  std::cout << renders << " renders, then the capture's: " << pass->GetAccumulatedFrames()
            << " frames accumulated" << std::endl;
  Check(renders == 15 && pass->GetAccumulatedFrames() == 16, "16 frames accumulated", __FILE__,
    __LINE__);
  CheckBaseline(
    argc, argv, "TestAntialiasingPassTemporalStill", scene.Window, result, scene.Plain, 1000);
  return Result();
}
