// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Renderer layers, for every method of PassMethods(): the pass on a renderer of layer 1 (which
// preserves the colour buffer: VTK does not clear it, the layer draws over what layer 0 drew)
// composites its antialiased image over the framebuffer with premultiplied-alpha blending:
// - wherever layer 1 drew nothing (and no antialiased edge of it reaches), layer 0's pixels are
//   exactly as they were;
// - the result equals the method's CPU filter run on layer 1's image alone (RGBA, premultiplied:
//   VTK's blending over a transparent black background; PassMethod::UsePremultipliedAlpha),
//   composited "over" layer 0's image, within 2/255;
// - layer 1's silhouettes are antialiased (pixels differ from the plain two-layer render).
// The same holds for a layer-0 renderer that preserves the colour buffer, drawn after another
// renderer in the same window, and for a small sphere on layer 1 sharing layer 0's camera.
// No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkConeSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

using namespace vtkMLAATest;

namespace
{
// Adds the output of `source` to `renderer` in the given colour.
void AddSurface(vtkRenderer* renderer, vtkAlgorithm* source, double r, double g, double b)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  renderer->AddActor(actor);
}

// Fills `renderer` with a sphere and a cone (opaque, lit).
void BuildUpperScene(vtkRenderer* renderer)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(40);
  sphere->SetPhiResolution(20);
  sphere->SetCenter(-0.6, 0.0, 0.0);
  AddSurface(renderer, sphere, 0.95, 0.55, 0.1);

  vtkNew<vtkConeSource> cone;
  cone->SetResolution(7);
  cone->SetCenter(0.7, 0.1, 0.0);
  cone->SetDirection(0.3, 1.0, 0.2);
  AddSurface(renderer, cone, 0.2, 0.4, 0.9);
  renderer->ResetCamera();
}

// Pixels of `image` (RGB) within `radius` of a pixel where `mask` differs from `background`.
std::vector<bool> Near(vtkImageData* mask, vtkImageData* background, int radius)
{
  int dims[3];
  mask->GetDimensions(dims);
  std::vector<bool> drawn(static_cast<size_t>(dims[0]) * dims[1], false);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (GetValue(mask, x, y, k) != GetValue(background, x, y, k))
        {
          drawn[static_cast<size_t>(y) * dims[0] + x] = true;
        }
      }
    }
  }
  std::vector<bool> near(drawn.size(), false);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int dy = -radius; dy <= radius; ++dy)
      {
        for (int dx = -radius; dx <= radius; ++dx)
        {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && ny >= 0 && nx < dims[0] && ny < dims[1] &&
            drawn[static_cast<size_t>(ny) * dims[0] + nx])
          {
            near[static_cast<size_t>(y) * dims[0] + x] = true;
          }
        }
      }
    }
  }
  return near;
}

// Checks the pass on `upper`, drawn after `lower` in `window` with its colour buffer preserved.
void CheckComposite(const PassMethod& method, vtkRenderWindow* window, vtkRenderer* lower,
  vtkRenderer* upper, const char* what)
{
  // Layer 0 alone, and the two layers without antialiasing.
  SetVisibility(upper, false, false);
  auto lowerOnly = vtkMLAAScenes::Capture(window);
  SetVisibility(upper, true, true);
  auto plain = vtkMLAAScenes::Capture(window);

  // The upper renderer's image alone, over transparent black: premultiplied RGBA.
  auto upperOnly =
    CaptureWithoutLayer(lower, [&] { return vtkMLAAScenes::Capture(window, true); });

  vtkOpenGLAntialiasingPass* pass = method.Use(upper);
  method.UsePremultipliedAlpha(pass);
  vtkNew<MessageObserver> messages;
  messages->Watch(pass);
  auto result = vtkMLAAScenes::Capture(window);

  int dims[3];
  result->GetDimensions(dims);
  const std::vector<bool> near = Near(plain, lowerOnly, 2);
  int away = 0, kept = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      if (near[static_cast<size_t>(y) * dims[0] + x])
      {
        continue;
      }
      ++away;
      bool same = true;
      for (int k = 0; k < 3; ++k)
      {
        same = same && GetValue(result, x, y, k) == GetValue(lowerOnly, x, y, k);
      }
      kept += same ? 1 : 0;
    }
  }
  const Difference changed = Compare(plain, result, 0.0);
  const Difference parity = Compare(Over(method.Filter(pass, upperOnly), lowerOnly), result, 2.0);
  std::cout << method.Name << ", " << what << ": " << kept << " of the " << away
            << " pixels away from the upper layer's drawing kept layer 0's colour exactly; "
            << changed.Pixels << " pixels antialiased; " << parity.Pixels
            << " pixels off the CPU filter composited over layer 0 by more than 2/255 (largest "
            << parity.Max << ")" << std::endl;
  Check(away > 1000 && kept == away, "layer 0 kept where the upper layer drew nothing", __FILE__,
    __LINE__);
  Check(changed.Pixels > 100, "the upper layer's edges antialiased", __FILE__, __LINE__);
  Check(parity.Count == 0, "equal to the CPU filter composited over layer 0", __FILE__, __LINE__);
  for (const auto& e : messages->Errors)
  {
    std::cerr << method.Name << ": error: " << e << std::endl;
  }
  Check(messages->Errors.empty(), "no errors", __FILE__, __LINE__);
  StopPass(upper, window);
}
}

int TestAntialiasingPassLayers(int, char*[])
{
  const int width = 400, height = 300;
  for (const auto& method : PassMethods())
  {
    {
      // Layer 0: the silhouettes scene; layer 1: a sphere and a cone.
      auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
      window->SetNumberOfLayers(2);
      vtkNew<vtkRenderer> lower;
      vtkNew<vtkRenderer> upper;
      upper->SetLayer(1);
      vtkMLAAScenes::Build("silhouettes", lower);
      BuildUpperScene(upper);
      window->AddRenderer(lower);
      window->AddRenderer(upper);
      CheckComposite(method, window, lower, upper, "layer 1 over layer 0");
    }
    {
      // Two renderers on layer 0, the second preserving the colour buffer over the first.
      auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
      vtkNew<vtkRenderer> lower;
      vtkNew<vtkRenderer> upper;
      upper->SetPreserveColorBuffer(1);
      vtkMLAAScenes::Build("wireframe", lower);
      BuildUpperScene(upper);
      window->AddRenderer(lower);
      window->AddRenderer(upper);
      CheckComposite(method, window, lower, upper, "PreserveColorBuffer on layer 0");
    }
    {
      // A small, coarse sphere on layer 1 of a 300 x 200 window, with layer 0's camera.
      auto window = vtkMLAAScenes::NewOffscreenWindow(300, 200);
      window->SetNumberOfLayers(2);
      vtkNew<vtkRenderer> lower;
      vtkMLAAScenes::Build("silhouettes", lower);
      vtkNew<vtkRenderer> upper;
      upper->SetLayer(1);
      upper->SetActiveCamera(lower->GetActiveCamera());
      vtkNew<vtkSphereSource> sphere;
      sphere->SetThetaResolution(12);
      sphere->SetPhiResolution(8);
      sphere->SetRadius(0.4);
      AddSurface(upper, sphere, 0.1, 0.8, 0.3);
      window->AddRenderer(lower);
      window->AddRenderer(upper);
      CheckComposite(method, window, lower, upper, "a sphere on layer 1 with layer 0's camera");
    }
  }
  return Result();
}
