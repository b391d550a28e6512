// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The pass's debug outputs equal the CPU filter's on the RGB render of a mixed scene (its label
// is antialiased with the rest here, so that both see the same image): the edges texture on all
// but a few pixels, the blending weights within 1/255 (both are 8-bit) on all but a few; and the
// edges are what the scene should give (some pixels have edges, most have none). "A few": the
// GPU compares contrasts in single precision, the filter in double, so an exact tie of local
// contrast adaptation (twice one contrast equal to another, which this scene has at one pixel)
// may fall either way; at most 12 pixels (0.01 %) may differ in edges and 60 in weights.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

int TestMLAAPassDebugOutputs(int, char*[])
{
  SceneWindow scene("mixed", 400, 300);
  vtkNew<vtkMLAAOptions> options;
  auto pass = UseMLAA(scene.Renderer, options);
  pass->AntialiasOverlaysOn();

  options->SetDebugOutputToEdges();
  auto gpuEdges = vtkMLAAScenes::Capture(scene.Window, true);
  auto cpuEdges = RunMLAA(scene.Plain, options);
  const Difference edges = Compare(cpuEdges, gpuEdges, 0.0);
  std::cout << "edges: " << edges.Pixels << " pixels differ" << std::endl;
  MLAA_CHECK(edges.Count >= 0 && edges.Pixels <= 12);
  const Difference edgePixels = Compare(cpuEdges, MakeImage(400, 300, 4, VTK_UNSIGNED_CHAR, 0.0), 0.0);
  MLAA_CHECK(edgePixels.Pixels == 400 * 300); // alpha is 255 everywhere
  int withEdges = 0;
  for (int y = 0; y < 300; ++y)
  {
    for (int x = 0; x < 400; ++x)
    {
      withEdges += (GetValue(cpuEdges, x, y, 0) > 0 || GetValue(cpuEdges, x, y, 1) > 0) ? 1 : 0;
    }
  }
  MLAA_CHECK(withEdges > 500 && withEdges < 400 * 300 / 4);

  options->SetDebugOutputToBlendingWeights();
  auto gpuWeights = vtkMLAAScenes::Capture(scene.Window, true);
  auto cpuWeights = RunMLAA(scene.Plain, options);
  const Difference weights = Compare(cpuWeights, gpuWeights, 1.0);
  std::cout << "weights: " << weights.Pixels << " pixels differ by more than 1/255 (largest "
            << weights.Max << ")" << std::endl;
  MLAA_CHECK(weights.Count >= 0 && weights.Pixels <= 60);
  MLAA_CHECK(cpuWeights->GetPointData()->GetScalars()->GetRange(0)[1] > 64.0);
  return Result();
}
