// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Depth edges: the pass detects edges in its delegate's depth buffer; the CPU filter given the
// same render and the window's z-buffer as its depth input produces the same image. Shading
// edges inside a surface are left alone (unlike luma edges).
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassDepthEdges(int, char*[])
{
  SceneWindow scene("isosurface", 400, 300);
  auto depth = ZBuffer(scene.Window);

  vtkNew<vtkMLAAOptions> options;
  options->SetEdgeDetectionToDepth();
  options->SetThreshold(0.005);
  UseMLAA(scene.Renderer, options);
  auto gpu = vtkMLAAScenes::Capture(scene.Window);

  vtkNew<vtkImageMLAA> filter;
  filter->SetOptions(options);
  filter->SetInputData(scene.Plain);
  filter->SetDepthInputData(depth);
  filter->Update();
  const Difference parity = Compare(filter->GetOutput(), gpu, 2.0);
  const Difference changed = Compare(scene.Plain, gpu, 0.0);
  std::cout << "depth edges: " << parity.Pixels << " pixels off the CPU filter by more than 2/255; "
            << changed.Pixels << " antialiased" << std::endl;
  MLAA_CHECK(parity.Count == 0);
  MLAA_CHECK(changed.Pixels > 100);

  // Luma edges find more (shading inside the surfaces) than depth edges.
  options->SetEdgeDetectionToLuma();
  options->SetThreshold(0.1);
  options->SetDebugOutputToEdges();
  auto lumaEdges = vtkMLAAScenes::Capture(scene.Window);
  options->SetEdgeDetectionToDepth();
  options->SetThreshold(0.005);
  auto depthEdges = vtkMLAAScenes::Capture(scene.Window);
  MLAA_CHECK(Compare(lumaEdges, depthEdges, 0.0).Pixels > 0);
  return Result();
}
