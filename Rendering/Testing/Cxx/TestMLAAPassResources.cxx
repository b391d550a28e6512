// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Resource handling and window changes: the pass keeps matching the CPU filter after a window
// resize, after ReleaseGraphicsResources, after its renderer is removed from the window and added
// again, when an option changes the area texture, with line lengths by recursive doubling, and
// when reconstruction is turned on and off; ReleaseGraphicsResources frees every target (the
// doubling textures and the reconstructed colour's included);
// its MLAA targets take 1.5 times an RGBA8 back buffer (the chapter's figure); tiled rendering
// (vtkRenderLargeImage) works; a multisampled window works; a pass without a delegate warns and
// draws nothing. No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkRenderLargeImage.h"

using namespace vtkMLAATest;

namespace
{
// The pass's render equals the CPU filter on the plain RGB render.
void CheckParity(vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLMLAAPass* pass,
  const char* when)
{
  renderer->SetPass(nullptr);
  auto plain = vtkMLAAScenes::Capture(window);
  renderer->SetPass(pass);
  auto result = vtkMLAAScenes::Capture(window);
  auto expected = RunMLAA(plain, pass->GetOptions());
  const Difference d = Compare(expected, result, 2.0);
  const Difference changed = Compare(plain, result, 0.0);
  std::cout << when << ": " << d.Pixels << " pixels off by more than 2/255, " << changed.Pixels
            << " antialiased" << std::endl;
  Check(d.Count == 0, when, __FILE__, __LINE__);
  Check(changed.Pixels > 50, when, __FILE__, __LINE__);
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

  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  CheckParity(window, renderer, pass, "after ReleaseGraphicsResources");

  window->RemoveRenderer(renderer);
  window->Render();
  window->AddRenderer(renderer);
  CheckParity(window, renderer, pass, "after re-adding the renderer");

  pass->GetOptions()->SetMaxSearchSteps(32); // a new area texture
  CheckParity(window, renderer, pass, "with 32 search steps");
  pass->GetOptions()->SetMaxSearchSteps(2);
  CheckParity(window, renderer, pass, "with 2 search steps");

  // Line lengths by recursive doubling: its four RGBA16F textures (8 bytes per pixel each, two
  // for rows and columns and two for staircases) follow a resize, and ReleaseGraphicsResources
  // frees them.
  pass->SetLineLengthsToRecursiveDoubling();
  CheckParity(window, renderer, pass, "with recursive doubling");
  window->SetSize(300, 200);
  CheckParity(window, renderer, pass, "with recursive doubling after a resize to 300 x 200");
  const vtkIdType withDoubling = pass->GetTargetMemorySize();
  pass->SetLineLengthsToSearchLoop();
  window->Render();
  MLAA_CHECK(withDoubling - pass->GetTargetMemorySize() == 300 * 200 * 32);
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

  // Tiled rendering at twice the window size.
  renderer->SetPass(nullptr);
  vtkNew<vtkRenderLargeImage> plainLarge;
  plainLarge->SetInput(renderer);
  plainLarge->SetMagnification(2);
  plainLarge->Update();
  renderer->SetPass(pass);
  vtkNew<vtkRenderLargeImage> large;
  large->SetInput(renderer);
  large->SetMagnification(2);
  large->Update();
  int dims[3];
  large->GetOutput()->GetDimensions(dims);
  MLAA_CHECK(dims[0] == 842 && dims[1] == 526);
  const Difference tiled = Compare(plainLarge->GetOutput(), large->GetOutput(), 0.0);
  std::cout << "tiled 842 x 526: " << tiled.Pixels << " pixels antialiased" << std::endl;
  MLAA_CHECK(tiled.Pixels > 100);

  // A multisampled window (the pass renders in place into a multisampled framebuffer, and
  // copies a resolved image): no error, and the result differs from the plain multisampled
  // render only near edges (a small share of the pixels).
  window->SetMultiSamples(4);
  renderer->SetPass(nullptr);
  auto plainMultisampled = vtkMLAAScenes::Capture(window);
  renderer->SetPass(pass);
  auto multisampled = vtkMLAAScenes::Capture(window);
  const Difference msaa = Compare(plainMultisampled, multisampled, 2.0);
  std::cout << "4 x multisampling: " << msaa.Pixels << " pixels changed by more than 2/255"
            << std::endl;
  MLAA_CHECK(msaa.Count >= 0 && msaa.Pixels < msaa.Total / 20);
  window->SetMultiSamples(0);

  // No delegate: a warning, nothing drawn, no crash.
  pass->ReleaseGraphicsResources(window);
  vtkNew<vtkOpenGLMLAAPass> lonely;
  vtkNew<MessageObserver> lonelyMessages;
  lonelyMessages->Watch(lonely);
  renderer->SetPass(lonely);
  window->Render();
  MLAA_CHECK(!lonelyMessages->Warnings.empty());
  renderer->SetPass(nullptr);
  lonely->ReleaseGraphicsResources(window);

  MLAA_CHECK(messages->Errors.empty());
  for (const auto& e : messages->Errors)
  {
    std::cerr << "error: " << e << std::endl;
  }
  return Result();
}
