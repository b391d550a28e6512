// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLAntialiasingPass's behaviour, for every method of PassMethods() (vtkOpenGLMLAAPass,
// vtkOpenGLDLAAPass):
// - on every shared scene the pass changes pixels near edges, and pixels whose 21 x 21
//   neighbourhood is flat are exactly as rendered; an empty scene is left exactly as rendered,
//   and so, by MLAA in single sample and with 4 samples, are voxels whose sides all lie on pixel
//   boundaries (issue 50);
// - text and a scalar bar over a surface: by default the overlays are drawn after the
//   antialiasing, so every overlay pixel over a flat background is exactly as in the plain render
//   while the surface is antialiased; AntialiasOverlaysOn() antialiases the overlays too, and
//   turning it off again gives the default result back;
// - two viewports: each equals the pass on a window of the viewport's size alone, and the CPU
//   filter on the viewport's plain render (so the pass reads and writes its own viewport only, at
//   the right offset); one pass object shared by both renderers gives the same image, and with
//   Temporal on the same converged still as a pass per renderer.
// No errors are reported on the way. The base's resources, tiling, multisampling and the missing
// delegate are tested in TestAntialiasingPassResources, layers in TestAntialiasingPassLayers,
// selection in TestAntialiasingPassSelection; the baselines of TestMLAAPassTwoViewports and
// TestMLAAPassTextOverlay are MLAA's regression tests of these scenes.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

namespace
{

// Overlay pixels count as over flat background when the render without them is flat over
// (2 OverlayRadius + 1)^2 pixels around.
const int OverlayRadius = 2;

void Scenes(const PassMethod& method, MessageObserver* messages)
{
  // Every shared scene: changes near edges only.
  for (const std::string& name : vtkMLAAScenes::Names())
  {
    // An axis-aligned scene (the voxels, filling a 4:3 view) is rendered at 320 x 240, where its
    // sides lie on pixel boundaries, 10 pixels apart: nothing is aliased, and both methods leave
    // the pixels as rendered (issue 50), in single sample and with 4 samples: MLAA every pixel
    // exactly (it reads the sides as lines without steps); DLAA, whose blurs and long-edge
    // windows stop at the sides of corners, none by more than 4/255 (a window may cross a
    // junction of sides too faint for its masks: 1/255).
    const bool exact = vtkMLAAScenes::AxisAligned(name);
    SceneWindow scene(name, exact ? 320 : 300, exact ? 240 : 200);
    auto pass = method.Use(scene.Renderer);
    messages->Watch(pass);
    auto result = vtkMLAAScenes::Capture(scene.Window);
    const Changes c = CountChanges(scene.Plain, result, 10);
    std::cout << name << ": " << c.Changed << " pixels changed, " << c.FlatChanged
              << " of them in flat regions" << std::endl;
    MLAA_CHECK(c.FlatChanged == 0);
    if (exact)
    {
      const double tolerance = std::string(method.Name) == "vtkOpenGLMLAAPass" ? 0.0 : 4.0;
      MLAA_CHECK(Compare(scene.Plain, result, tolerance).Count == 0);
      pass->SetMultiSamples(4);
      const Difference sampled =
        Compare(scene.Plain, vtkMLAAScenes::Capture(scene.Window), tolerance);
      std::cout << name << ", 4 samples: " << sampled.Pixels << " pixels changed by more than "
                << tolerance << "/255" << std::endl;
      MLAA_CHECK(sampled.Count == 0);
      continue;
    }
    MLAA_CHECK(c.Changed > 50);
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
  // Text and a scalar bar over a coloured surface: where the overlays are (rendered alone), and
  // where the 3D content is flat.
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
  textPass->AntialiasOverlaysOff();
  MLAA_CHECK(Compare(result, vtkMLAAScenes::Capture(text.Window), 0.0).Count == 0);
  int dims[3];
  result->GetDimensions(dims);
  int overlayPixels = 0, untouched = 0, changedWhenAntialiased = 0, geometryChanged = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool isOverlay = false, same = true, sameAA = true;
      for (int k = 0; k < 3; ++k)
      {
        isOverlay = isOverlay || GetValue(overlaysOnly, x, y, k) != 255.0; // white background
        same = same && GetValue(result, x, y, k) == GetValue(text.Plain, x, y, k);
        sameAA = sameAA && GetValue(antialiased, x, y, k) == GetValue(text.Plain, x, y, k);
      }
      if (isOverlay && IsFlatAround(geometryOnly, x, y, OverlayRadius))
      {
        ++overlayPixels;
        untouched += same ? 1 : 0;
        changedWhenAntialiased += sameAA ? 0 : 1;
      }
      else if (!isOverlay && !same)
      {
        ++geometryChanged;
      }
    }
  }
  std::cout << overlayPixels << " overlay pixels over flat background: " << untouched
            << " untouched by default, " << changedWhenAntialiased
            << " changed with AntialiasOverlaysOn; " << geometryChanged
            << " other pixels antialiased" << std::endl;
  MLAA_CHECK(overlayPixels > 500);
  MLAA_CHECK(untouched == overlayPixels);
  MLAA_CHECK(changedWhenAntialiased > 50);
  MLAA_CHECK(geometryChanged > 100);
}

void TwoViewports(const PassMethod& method, MessageObserver* messages)
{
  // Two viewports, each against the pass on a window of its own and the CPU filter on the
  // viewport's plain render.
  TwoViewportWindow two;
  vtkOpenGLAntialiasingPass* passes[2];
  for (int side = 0; side < 2; ++side)
  {
    passes[side] = method.Use(two.Renderers[side]);
    messages->Watch(passes[side]);
  }
  auto result = vtkMLAAScenes::Capture(two.Window);
  for (int side = 0; side < 2; ++side)
  {
    SceneWindow alone(TwoViewportWindow::Scenes[side], 300, 300);
    const auto plain = TwoViewportWindow::Viewport(two.Plain, side);
    const auto got = TwoViewportWindow::Viewport(result, side);
    MLAA_CHECK(Compare(plain, alone.Plain, 0.0).Count == 0);
    messages->Watch(method.Use(alone.Renderer));
    auto expected = vtkMLAAScenes::Capture(alone.Window);
    const Difference d = Compare(expected, got, 2.0);
    std::cout << "viewport " << side << ": " << d.Pixels << " pixels differ" << std::endl;
    MLAA_CHECK(d.Count == 0);
    MLAA_CHECK(Compare(alone.Plain, expected, 0.0).Pixels > 50);
    const Difference fromCPU = Compare(method.Filter(passes[side], plain), got, 2.0);
    std::cout << "viewport " << side << ": " << fromCPU.Pixels
              << " pixels differ from the CPU filter by more than 2/255 (largest difference "
              << fromCPU.Max << ")" << std::endl;
    MLAA_CHECK(fromCPU.Count == 0);
  }

  // One pass object for both renderers gives the same image.
  StopPass(two.Renderers[0], two.Window);
  StopPass(two.Renderers[1], two.Window);
  auto shared = method.Use(two.Renderers[0]);
  messages->Watch(shared);
  two.Renderers[1]->SetPass(shared);
  MLAA_CHECK(Compare(result, vtkMLAAScenes::Capture(two.Window), 0.0).Count == 0);

  // The same with Temporal on: the shared pass keeps a history per renderer, so that its
  // converged still is that of a pass per renderer (one history would be reset at every render,
  // the renderers' scenes differing).
  shared->SetTemporal(true);
  const int sharedRenders = shared->RenderConverged(two.Window);
  std::cout << "shared temporal pass: " << shared->GetAccumulatedFrames() << " frames after "
            << sharedRenders << " renders" << std::endl;
  MLAA_CHECK(shared->GetAccumulatedFrames() >= shared->GetConvergedFrames());
  auto sharedStill = vtkMLAAScenes::Capture(two.Window);
  StopPass(two.Renderers[0], two.Window);
  two.Renderers[1]->SetPass(nullptr);
  vtkOpenGLAntialiasingPass* own[2];
  for (int side = 0; side < 2; ++side)
  {
    own[side] = method.Use(two.Renderers[side]);
    messages->Watch(own[side]);
    own[side]->SetTemporal(true);
  }
  own[0]->RenderConverged(two.Window);
  MLAA_CHECK(own[0]->GetAccumulatedFrames() >= own[0]->GetConvergedFrames() &&
    own[1]->GetAccumulatedFrames() >= own[1]->GetConvergedFrames());
  const Difference stills = Compare(vtkMLAAScenes::Capture(two.Window), sharedStill, 2.0);
  std::cout << "converged stills, shared pass against a pass per renderer: " << stills.Pixels
            << " pixels differ" << std::endl;
  MLAA_CHECK(stills.Count == 0);
  MLAA_CHECK(Compare(sharedStill, result, 2.0).Pixels > 100); // the still is not the single frame
}
}

int TestAntialiasingPass(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    Scenes(method, messages);
    TextOverlays(method, messages);
    TwoViewports(method, messages);
  });
  return Result();
}
