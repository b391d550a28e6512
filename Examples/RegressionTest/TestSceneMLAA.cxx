// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// An offscreen VTK regression test of an antialiased render, as a project would write one
// (docs/regression-tests.md). It renders a small scene offscreen (EGL or Xvfb: whatever window
// VTK makes), antialiases it, and compares the result with the baseline given by -V using VTK's
// own tester: VTK 9.1's thresholded image difference, or the SSIM in CIELAB of VTK 9.4 and later
// (VTK_TESTING_IMAGE_COMPARE_METHOD: TIGHT_VALID or LOOSE_VALID, set by CMakeLists.txt).
//   TestSceneMLAA --mode pass|filter|still -V BASELINE.png -T OUTPUT_DIR
// pass: vtkOpenGLMLAAPass on the renderer; filter: vtkImageMLAA on a screenshot of the plain
// render; still: the pass with temporal antialiasing, a converged still (RenderConverged).
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkImageMLAA.h"
#include "vtkNew.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTesting.h"
#include "vtkVersionMacros.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>
#include <string>

namespace
{
// A lit sphere and a faceted cone on a dark background: silhouettes at every angle.
void BuildScene(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  sphere->SetCenter(-0.6, 0.0, 0.0);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(7);
  cone->SetCenter(0.7, 0.0, 0.0);
  const double colours[2][3] = { { 1.0, 0.8, 0.3 }, { 0.9, 0.3, 0.3 } };
  vtkPolyDataAlgorithm* sources[2] = { sphere, cone };
  for (int i = 0; i < 2; ++i)
  {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sources[i]->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colours[i][0], colours[i][1], colours[i][2]);
    renderer->AddActor(actor);
  }
  renderer->SetBackground(0.1, 0.2, 0.4);
  renderer->GetActiveCamera()->SetPosition(0.0, 0.4, 4.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();
}

// VTK's default threshold for its comparison method (9.1: 0.15 of the legacy difference).
double DefaultThreshold()
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 4, 0)
  return vtkRegressionTester::ErrorThreshold;
#else
  return 0.15;
#endif
}
}

int main(int argc, char* argv[])
{
  std::string mode = "pass";
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::string(argv[i]) == "--mode")
    {
      mode = argv[i + 1];
    }
  }
  if (mode != "pass" && mode != "filter" && mode != "still")
  {
    std::cerr << "unknown --mode " << mode << " (pass, filter or still)" << std::endl;
    return 2;
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0); // the antialiasing replaces multisampling
  window->SetSize(300, 200);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildScene(renderer);
  std::cout << "rendering in a " << window->GetClassName() << std::endl;

  int result = vtkTesting::FAILED;
  if (mode == "filter")
  {
    // The plain render's screenshot, antialiased on the CPU, compared as an image.
    window->Render();
    vtkNew<vtkWindowToImageFilter> screenshot;
    screenshot->SetInput(window);
    screenshot->ReadFrontBufferOff();
    vtkNew<vtkImageMLAA> mlaa;
    mlaa->SetInputConnection(screenshot->GetOutputPort());
    vtkNew<vtkTesting> testing;
    for (int i = 0; i < argc; ++i)
    {
      testing->AddArgument(argv[i]);
    }
    result = testing->RegressionTest(mlaa, DefaultThreshold());
  }
  else
  {
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkOpenGLMLAAPass> pass;
    pass->SetDelegatePass(steps);
    renderer->SetPass(pass);
    if (mode == "still")
    {
      pass->TemporalOn();
      pass->RenderConverged(window); // 16 jittered renders of the unchanged scene, averaged
    }
    window->Render();
    result = vtkRegressionTestImage(window);
    pass->ReleaseGraphicsResources(window);
  }
  return result == vtkTesting::FAILED ? 1 : 0;
}
