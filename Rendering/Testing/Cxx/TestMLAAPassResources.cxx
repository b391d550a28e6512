// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLMLAAPass's own targets (what every pass shares, on every method, is in
// TestAntialiasingPassResources): its MLAA targets take 1.5 times an RGBA8 back buffer (the
// chapter's figure) and follow a resize; the pass keeps matching the CPU filter when an option
// changes the area texture, with line lengths by recursive doubling, and when reconstruction is
// turned on and off; ReleaseGraphicsResources frees every target (the doubling textures and the
// reconstructed colour's included). No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

namespace
{
void CheckParity(vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLMLAAPass* pass,
  const char* when)
{
  vtkMLAATest::CheckParity(MLAAPassMethod(), window, renderer, pass, when);
}
}

int TestMLAAPassResources(int, char*[])
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(300, 200);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  auto pass = UseMLAA(renderer);
  vtkNew<MessageObserver> messages;
  messages->Watch(pass);

  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  CheckParity(window, renderer, pass, "first render");
  // Edges RG8 + weights RGBA8 = 6 bytes per pixel: 1.5 x an RGBA8 back buffer.
  MLAA_CHECK(pass->GetMLAATargetMemorySize() == 300 * 200 * 6);
  MLAA_CHECK(pass->GetTargetMemorySize() > pass->GetMLAATargetMemorySize());

  window->SetSize(421, 263);
  CheckParity(window, renderer, pass, "after a resize to 421 x 263");
  MLAA_CHECK(pass->GetMLAATargetMemorySize() == 421 * 263 * 6);

  pass->GetOptions()->SetMaxSearchSteps(32); // a new area texture
  CheckParity(window, renderer, pass, "with 32 search steps");
  pass->GetOptions()->SetMaxSearchSteps(2);
  CheckParity(window, renderer, pass, "with 2 search steps");

  // Line lengths by recursive doubling: its two RGBA16F textures (8 bytes per pixel each) and the
  // RG8 counts of staircase units follow a resize, and ReleaseGraphicsResources frees them.
  pass->SetLineLengthsToRecursiveDoubling();
  CheckParity(window, renderer, pass, "with recursive doubling");
  window->SetSize(300, 200);
  CheckParity(window, renderer, pass, "with recursive doubling after a resize to 300 x 200");
  const vtkIdType withDoubling = pass->GetTargetMemorySize();
  pass->SetLineLengthsToSearchLoop();
  window->Render();
  MLAA_CHECK(withDoubling - pass->GetTargetMemorySize() == 300 * 200 * 18);
  pass->SetLineLengthsToRecursiveDoubling();
  window->Render();
  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  pass->SetLineLengthsToAutomatic();
  window->SetSize(421, 263);
  CheckParity(window, renderer, pass, "after a resize back to 421 x 263");
  // Reconstruction adds one RGBA8 copy of the colour, which ReleaseGraphicsResources frees and
  // turning it off deletes.
  const vtkIdType withoutReconstruction = pass->GetTargetMemorySize();
  pass->GetOptions()->ReconstructionOn();
  CheckParity(window, renderer, pass, "with reconstruction");
  MLAA_CHECK(pass->GetTargetMemorySize() == withoutReconstruction + 421 * 263 * 4);
  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  CheckParity(window, renderer, pass, "with reconstruction, after ReleaseGraphicsResources");
  pass->GetOptions()->ReconstructionOff();
  CheckParity(window, renderer, pass, "with reconstruction turned off again");
  MLAA_CHECK(pass->GetTargetMemorySize() == withoutReconstruction);

  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(messages->Errors.empty());
  for (const auto& e : messages->Errors)
  {
    std::cerr << "error: " << e << std::endl;
  }
  return Result();
}
