// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of a converged still of the temporal pass (vtkOpenGLMLAAPass with
// SetTemporal(true)) on the "orbit" scene (1-pixel lines, points, glyphs, a textured floor),
// rendered offscreen without multisampling: RenderConverged accumulates ConvergedFrames (16)
// renders; strict comparison with the committed baseline, and the result must differ from the
// plain render (see vtkAntialiasingRenderTestUtilities.h). Once converged, further renders (the
// capture's, one more) hold the still: the same image, and the camera is left alone.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestAntialiasingPassTemporalStill(int argc, char* argv[])
{
  SceneWindow scene("orbit");
  vtkSmartPointer<vtkOpenGLMLAAPass> pass = UseMLAA(scene.Renderer);
  pass->TemporalOn();
  const int renders = pass->RenderConverged(scene.Window);
  const vtkMTimeType cameraTime = scene.Renderer->GetActiveCamera()->GetMTime();
  auto result = vtkMLAAScenes::Capture(scene.Window);
  auto again = vtkMLAAScenes::Capture(scene.Window);
  std::cout << renders << " renders, then the captures' 2: " << pass->GetAccumulatedFrames()
            << " frames accumulated" << std::endl;
  Check(renders == 16 && pass->GetAccumulatedFrames() == 16, "16 frames accumulated", __FILE__,
    __LINE__);
  Check(Compare(result, again, 0.0).Count == 0, "a converged still holds", __FILE__, __LINE__);
  Check(scene.Renderer->GetActiveCamera()->GetMTime() == cameraTime,
    "renders of a converged still leave the camera alone", __FILE__, __LINE__);
  CheckBaseline(
    argc, argv, "TestAntialiasingPassTemporalStill", scene.Window, result, scene.Plain, 1000);
  return Result();
}
