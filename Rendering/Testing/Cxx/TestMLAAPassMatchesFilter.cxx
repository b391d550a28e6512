// CPU/GPU parity: for every scene of the project, vtkOpenGLMLAAPass's output equals vtkImageMLAA
// run on the single-sample render of the same scene within 2/255 on at least 99.5 % of the
// pixels, with the default options, with colour edges, a longer search and a stricter local
// contrast factor, without diagonal detection, without local contrast adaptation, and with the
// chapter's blending (DominantDirectionBlending off). The pass must also actually change the
// image (edge pixels differ from the plain render).
// The renders are read as RGBA: the window has alpha planes (VTK's offscreen default), so the
// pass sees alpha (background 0, geometry 1) and, like the filter on 4-component images, treats
// an alpha change as an edge.
#include "vtkMLAAScenes.h"
#include "vtkMLAATestUtilities.h"

#include "vtkOpenGLMLAAPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

using namespace vtkMLAATest;

int TestMLAAPassMatchesFilter(int, char*[])
{
  const int width = 400, height = 300;
  double worstShare = 1.0;
  for (int variant = 0; variant < 5; ++variant)
  {
    vtkNew<vtkMLAAOptions> options;
    if (variant == 1)
    {
      options->SetEdgeDetectionToColor();
      options->SetMaxSearchSteps(16);
      options->SetThreshold(0.05);
      options->SetLocalContrastFactor(1.25); // keeps fewer edges than the default 2
    }
    if (variant == 2)
    {
      options->DiagonalDetectionOff();
    }
    if (variant == 3)
    {
      options->SetLocalContrastFactor(0.0);
    }
    if (variant == 4)
    {
      options->DominantDirectionBlendingOff();
    }
    for (const std::string& name : vtkMLAAScenes::Names())
    {
      auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      vtkMLAAScenes::Build(name, renderer);
      auto plain = vtkMLAAScenes::Capture(window, true);
      auto cpu = RunMLAA(plain, options);

      vtkNew<vtkRenderStepsPass> steps;
      vtkNew<vtkOpenGLMLAAPass> pass;
      pass->SetDelegatePass(steps);
      pass->SetOptions(options);
      pass->AntialiasOverlaysOn(); // the CPU filter sees the overlays in the render too
      renderer->SetPass(pass);
      auto gpu = vtkMLAAScenes::Capture(window, true);

      const Difference parity = Compare(cpu, gpu, 2.0);
      const Difference changed = Compare(plain, gpu, 0.0);
      const double share = 1.0 - static_cast<double>(parity.Pixels) / parity.Total;
      worstShare = std::min(worstShare, share);
      std::cout << "options " << variant << ", scene " << name << ": " << 100.0 * share
                << " % of pixels within 2/255 of the CPU filter (largest difference "
                << parity.Max << "); the pass changed " << changed.Pixels << " pixels" << std::endl;
      MLAA_CHECK(parity.Count >= 0);
      MLAA_CHECK(share >= 0.995);
      MLAA_CHECK(changed.Pixels > 100);
      if (share < 0.995)
      {
        WritePNG(cpu, name + "-cpu.png");
        WritePNG(gpu, name + "-gpu.png");
      }
      renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(window);
    }
  }
  std::cout << "worst scene: " << 100.0 * worstShare << " % of pixels within 2/255" << std::endl;
  return Result();
}
