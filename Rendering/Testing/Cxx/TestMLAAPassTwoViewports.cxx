// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Two renderers side by side in one window, each with its own pass: each viewport equals the CPU
// filter on the same viewport of the plain render (so the pass reads and writes its own viewport
// only, at the right offset). A single pass object shared by both renderers gives the same image.
// Plus a strict baseline comparison.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassTwoViewports(int argc, char* argv[])
{
  const int width = 600, height = 300;
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> left;
  vtkNew<vtkRenderer> right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkMLAAScenes::Build("silhouettes", left);
  vtkMLAAScenes::Build("wireframe", right);
  window->AddRenderer(left);
  window->AddRenderer(right);
  auto plain = vtkMLAAScenes::Capture(window);

  UseMLAA(left);
  UseMLAA(right);
  auto result = vtkMLAAScenes::Capture(window);
  for (int side = 0; side < 2; ++side)
  {
    auto expected = RunMLAA(Crop(plain, side * 300, 0, 300, 300));
    auto got = Crop(result, side * 300, 0, 300, 300);
    const Difference d = Compare(expected, got, 2.0);
    std::cout << "viewport " << side << ": " << d.Pixels << " pixels differ from the CPU filter "
              << "by more than 2/255 (largest difference " << d.Max << ")" << std::endl;
    MLAA_CHECK(d.Count == 0);
  }

  // One pass for both renderers.
  StopPass(left, window);
  StopPass(right, window);
  auto shared = UseMLAA(left);
  right->SetPass(shared);
  auto sharedResult = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(Compare(result, sharedResult, 0.0).Count == 0);
  right->SetPass(nullptr);
  StopPass(left, window);

  UseMLAA(left);
  UseMLAA(right);
  auto rgb = vtkMLAAScenes::Capture(window);
  CheckBaseline(argc, argv, "TestMLAAPassTwoViewports", window, rgb, plain, 300);
  StopPass(left, window);
  StopPass(right, window);
  return Result();
}
