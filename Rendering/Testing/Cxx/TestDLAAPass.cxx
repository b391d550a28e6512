// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLDLAAPass, its own behaviour without the CPU filter (what every pass shares, on every
// method, is in TestAntialiasingPass):
// - option changes take effect at the next render (Lambda 0 turns it off, LongEdges off and the
//   green luma change the result, without touching pixels whose 7 x 7 neighbourhood is flat;
//   SetOptions shares an object, nullptr restores defaults);
// - its targets are the RGBA8 colour copy, the RG32F masks (8 pixels wider each side with long
//   edges) and one byte per tile of 8 x 8 masks, follow resizes, and ReleaseGraphicsResources
//   frees them; the result is the same after a release.
// No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestDLAAPass(int, char*[])
{
  vtkNew<MessageObserver> messages;

  // Options and resources on one scene.
  SceneWindow scene("silhouettes", 300, 200);
  auto pass = UseDLAA(scene.Renderer);
  messages->Watch(pass);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  auto defaults = vtkMLAAScenes::Capture(scene.Window);
  // Masks (8 bytes, 8 pixels of padding each side), tiles, the sides of corners (RGBA8) and
  // their candidates (16-bit depth).
  MLAA_CHECK(pass->GetDLAATargetMemorySize() == 316 * 216 * 8 + 40 * 27 + 300 * 200 * 6);
  MLAA_CHECK(pass->GetTargetMemorySize() == 316 * 216 * 8 + 40 * 27 + 300 * 200 * (6 + 4));

  pass->GetOptions()->SetLambda(0.0);
  MLAA_CHECK(Compare(scene.Plain, vtkMLAAScenes::Capture(scene.Window), 0.0).Count == 0);
  pass->GetOptions()->SetLambda(3.0);
  pass->GetOptions()->LongEdgesOff();
  auto shortOnly = vtkMLAAScenes::Capture(scene.Window);
  MLAA_CHECK(pass->GetDLAATargetMemorySize() == 300 * 200 * (8 + 6)); // no padding, no tiles
  const Difference longEdges = Compare(defaults, shortOnly, 0.0);
  std::cout << "LongEdges off changes " << longEdges.Pixels << " pixels" << std::endl;
  MLAA_CHECK(longEdges.Pixels > 20);
  MLAA_CHECK(CountChanges(scene.Plain, shortOnly, 3).FlatChanged == 0);
  pass->GetOptions()->LongEdgesOn();
  pass->GetOptions()->SetLumaFunctionToGreen();
  MLAA_CHECK(Compare(defaults, vtkMLAAScenes::Capture(scene.Window), 0.0).Pixels > 20);
  vtkNew<vtkDLAAOptions> shared;
  shared->SetEpsilon(0.5);
  pass->SetOptions(shared);
  MLAA_CHECK(pass->GetOptions() == shared.GetPointer());
  MLAA_CHECK(Compare(defaults, vtkMLAAScenes::Capture(scene.Window), 0.0).Pixels > 20);
  pass->SetOptions(nullptr);
  MLAA_CHECK(pass->GetOptions() && pass->GetOptions() != shared.GetPointer());
  MLAA_CHECK(Compare(defaults, vtkMLAAScenes::Capture(scene.Window), 0.0).Count == 0);

  scene.Window->SetSize(321, 243);
  auto resized = vtkMLAAScenes::Capture(scene.Window);
  MLAA_CHECK(pass->GetDLAATargetMemorySize() == 337 * 259 * 8 + 43 * 33 + 321 * 243 * 6);
  pass->ReleaseGraphicsResources(scene.Window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  MLAA_CHECK(Compare(resized, vtkMLAAScenes::Capture(scene.Window), 0.0).Count == 0);
  scene.Window->SetSize(300, 200);
  MLAA_CHECK(Compare(defaults, vtkMLAAScenes::Capture(scene.Window), 0.0).Count == 0);

  for (const auto& e : messages->Errors)
  {
    std::cerr << "error: " << e << std::endl;
  }
  MLAA_CHECK(messages->Errors.empty());
  StopPass(scene.Renderer, scene.Window);
  return Result();
}
