// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLAntialiasingPass's behaviour, for every method of PassMethods() (vtkOpenGLMLAAPass,
// vtkOpenGLDLAAPass):
// - on every shared scene the pass changes pixels near edges, and pixels whose 21 x 21
//   neighbourhood is flat are exactly as rendered; an empty scene is left exactly as rendered;
// - text overlays over flat background are untouched by default and antialiased with
//   AntialiasOverlaysOn();
// - two viewports: each equals the pass on a window of the viewport's size alone, and the CPU
//   filter on the viewport's plain render;
// No errors are reported on the way. (Layers are tested in TestAntialiasingPassLayers, selection
// in TestAntialiasingPassSelection; the method-specific tests compare with the CPU filters and
// baselines: TestMLAAPassTwoViewports, TestMLAAPassTextOverlay; DLAA's options and targets are
// in TestDLAAPass.)
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkActor2DCollection.h"
#include "vtkActorCollection.h"

using namespace vtkMLAATest;

namespace
{

void Scenes(const PassMethod& method, MessageObserver* messages)
{
  // Every shared scene: changes near edges only.
  for (const std::string& name : vtkMLAAScenes::Names())
  {
    SceneWindow scene(name, 300, 200);
    auto pass = method.Use(scene.Renderer);
    messages->Watch(pass);
    auto result = vtkMLAAScenes::Capture(scene.Window);
    const Changes c = CountChanges(scene.Plain, result, 10);
    std::cout << name << ": " << c.Changed << " pixels changed, " << c.FlatChanged
              << " of them in flat regions" << std::endl;
    MLAA_CHECK(c.Changed > 50);
    MLAA_CHECK(c.FlatChanged == 0);
  }

  {
    // An empty scene.
    auto window = vtkMLAAScenes::NewOffscreenWindow(200, 150);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.3, 0.5, 0.7);
    window->AddRenderer(renderer);
    auto plain = vtkMLAAScenes::Capture(window);
    messages->Watch(method.Use(renderer));
    MLAA_CHECK(Compare(plain, vtkMLAAScenes::Capture(window), 0.0).Count == 0);
    StopPass(renderer, window);
  }
}

void TextOverlays(const PassMethod& method, MessageObserver* messages)
{
  // Text overlays.
  SceneWindow text("text");
  vtkRenderer* renderer = text.Renderer;
  SetVisibility(renderer, false, true);
  auto overlaysOnly = vtkMLAAScenes::Capture(text.Window);
  SetVisibility(renderer, true, false);
  auto geometryOnly = vtkMLAAScenes::Capture(text.Window);
  SetVisibility(renderer, true, true);
  auto textPass = method.Use(renderer);
  messages->Watch(textPass);
  auto result = vtkMLAAScenes::Capture(text.Window);
  textPass->AntialiasOverlaysOn();
  auto antialiased = vtkMLAAScenes::Capture(text.Window);
  int dims[3];
  result->GetDimensions(dims);
  int overlayPixels = 0, untouched = 0, changedWhenAntialiased = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool isOverlay = false, same = true, sameAA = true;
      for (int k = 0; k < 3; ++k)
      {
        isOverlay = isOverlay || GetValue(overlaysOnly, x, y, k) != 255.0;
        same = same && GetValue(result, x, y, k) == GetValue(text.Plain, x, y, k);
        sameAA = sameAA && GetValue(antialiased, x, y, k) == GetValue(text.Plain, x, y, k);
      }
      if (isOverlay && IsFlatAround(geometryOnly, x, y, 10))
      {
        ++overlayPixels;
        untouched += same ? 1 : 0;
        changedWhenAntialiased += sameAA ? 0 : 1;
      }
    }
  }
  std::cout << overlayPixels << " overlay pixels over flat background: " << untouched
            << " untouched by default, " << changedWhenAntialiased
            << " changed with AntialiasOverlaysOn" << std::endl;
  MLAA_CHECK(overlayPixels > 100 && untouched == overlayPixels);
  MLAA_CHECK(changedWhenAntialiased > 20);
}

void TwoViewports(const PassMethod& method, MessageObserver* messages)
{
  // Two viewports, each against the pass on a window of its own.
  auto window = vtkMLAAScenes::NewOffscreenWindow(600, 300);
  vtkNew<vtkRenderer> left;
  vtkNew<vtkRenderer> right;
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  vtkMLAAScenes::Build("silhouettes", left);
  vtkMLAAScenes::Build("wireframe", right);
  window->AddRenderer(left);
  window->AddRenderer(right);
  auto plain = vtkMLAAScenes::Capture(window);
  vtkOpenGLAntialiasingPass* passes[2] = { method.Use(left), method.Use(right) };
  messages->Watch(passes[0]);
  messages->Watch(passes[1]);
  auto result = vtkMLAAScenes::Capture(window);
  const char* names[2] = { "silhouettes", "wireframe" };
  for (int side = 0; side < 2; ++side)
  {
    SceneWindow alone(names[side], 300, 300);
    MLAA_CHECK(Compare(Crop(plain, side * 300, 0, 300, 300), alone.Plain, 0.0).Count == 0);
    method.Use(alone.Renderer);
    auto expected = vtkMLAAScenes::Capture(alone.Window);
    const Difference d = Compare(expected, Crop(result, side * 300, 0, 300, 300), 2.0);
    std::cout << "viewport " << side << ": " << d.Pixels << " pixels differ" << std::endl;
    MLAA_CHECK(d.Count == 0);
    MLAA_CHECK(Compare(alone.Plain, expected, 0.0).Pixels > 50);
    // And the CPU filter on the viewport's plain render.
    auto cpu = method.Filter(passes[side], Crop(plain, side * 300, 0, 300, 300));
    const Difference fromCPU = Compare(cpu, Crop(result, side * 300, 0, 300, 300), 2.0);
    std::cout << "viewport " << side << ": " << fromCPU.Pixels
              << " pixels differ from the CPU filter by more than 2/255" << std::endl;
    MLAA_CHECK(fromCPU.Count == 0);
  }
  StopPass(left, window);
  StopPass(right, window);
}
}

int TestAntialiasingPass(int, char*[])
{
  for (const auto& method : PassMethods())
  {
    std::cout << method.Name << std::endl;
    vtkNew<MessageObserver> messages;
    Scenes(method, messages);
    TextOverlays(method, messages);
    TwoViewports(method, messages);
    for (const auto& e : messages->Errors)
    {
      std::cerr << method.Name << ": error: " << e << std::endl;
    }
    MLAA_CHECK(messages->Errors.empty());
  }
  return Result();
}
