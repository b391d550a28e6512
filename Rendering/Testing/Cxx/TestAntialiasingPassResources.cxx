// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLAntialiasingPass's resource handling and window changes, for every method of
// PassMethods() (what each method's own targets take is in TestMLAAPassResources and
// TestDLAAPass):
// - the pass holds no targets before its first render, at least an RGBA8 copy of the colour
//   after it, more after a resize to a larger window, none after ReleaseGraphicsResources and as
//   many as before after the next render;
// - it keeps matching the CPU filter at the first render, after a window resize, after
//   ReleaseGraphicsResources, and after its renderer is removed from the window and added again;
// - tiled rendering (vtkRenderLargeImage) works;
// - a multisampled window works (the pass renders in place into a multisampled framebuffer and
//   copies a resolved image): the result differs from the plain multisampled render only near
//   edges;
// - a pass without a delegate warns and draws nothing;
// - the pass leaves the window's texture units as it found them, in every mode (single frame,
//   multisampled, temporal with the camera moving and still; for MLAA also with reconstruction
//   and recursive doubling): each draw's textures are released after it.
// No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkMLAAOptions.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderLargeImage.h"
#include "vtkTextureUnitManager.h"

using namespace vtkMLAATest;

namespace
{
void Resources(const PassMethod& method, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkOpenGLAntialiasingPass* pass)
{
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  CheckParity(method, window, renderer, pass, "first render");
  const vtkIdType first = pass->GetTargetMemorySize();
  std::cout << method.Name << ": " << first << " bytes of targets at 300 x 200" << std::endl;
  MLAA_CHECK(first >= 300 * 200 * 4);

  window->SetSize(421, 263);
  CheckParity(method, window, renderer, pass, "after a resize to 421 x 263");
  const vtkIdType resized = pass->GetTargetMemorySize();
  MLAA_CHECK(resized >= 421 * 263 * 4 && resized > first);

  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  CheckParity(method, window, renderer, pass, "after ReleaseGraphicsResources");
  MLAA_CHECK(pass->GetTargetMemorySize() == resized);

  window->RemoveRenderer(renderer);
  window->Render();
  window->AddRenderer(renderer);
  CheckParity(method, window, renderer, pass, "after re-adding the renderer");
}

void Tiling(vtkRenderer* renderer, vtkOpenGLAntialiasingPass* pass)
{
  // Tiled rendering at twice the window size (421 x 263).
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
}

void Multisampling(vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLAntialiasingPass* pass)
{
  // No error, and the result differs from the plain multisampled render only near edges (a small
  // share of the pixels).
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
}

int AllocatedTextureUnits(vtkRenderWindow* window)
{
  vtkTextureUnitManager* units =
    vtkOpenGLRenderWindow::SafeDownCast(window)->GetTextureUnitManager();
  int allocated = 0;
  for (int i = 0; i < units->GetNumberOfTextureUnits(); ++i)
  {
    allocated += units->IsAllocated(i) ? 1 : 0;
  }
  return allocated;
}

void TextureUnits(vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLAntialiasingPass* pass)
{
  renderer->SetPass(nullptr);
  window->Render();
  const int before = AllocatedTextureUnits(window);
  renderer->SetPass(pass);
  auto check = [&](const char* mode) {
    window->Render();
    const int after = AllocatedTextureUnits(window);
    std::cout << "texture units allocated after a render, " << mode << ": " << after << " ("
              << before << " without the pass)" << std::endl;
    MLAA_CHECK(after == before);
  };
  check("single frame");
  pass->SetMultiSamples(4);
  check("multisampled");
  pass->SetMultiSamples(0);
  if (auto* mlaa = vtkOpenGLMLAAPass::SafeDownCast(pass))
  {
    // Reconstruction, and 32 search steps: line lengths by recursive doubling.
    mlaa->GetOptions()->SetPreset(vtkMLAAOptions::MAX);
    check("MLAA max preset");
    mlaa->GetOptions()->SetPreset(vtkMLAAOptions::HIGH);
  }
  pass->SetTemporal(true);
  check("temporal, first render");
  check("temporal, still");
  renderer->GetActiveCamera()->Azimuth(1.0);
  check("temporal, camera moving");
  pass->SetTemporal(false);
}

void NoDelegate(const PassMethod& method, vtkRenderWindow* window, vtkRenderer* renderer)
{
  // A pass of the method without a delegate: a warning, nothing drawn, no crash.
  renderer->SetPass(nullptr);
  auto expected = vtkMLAAScenes::Capture(window);
  vtkNew<vtkRenderer> other;
  vtkOpenGLAntialiasingPass* lonely = method.Use(other);
  lonely->SetDelegatePass(nullptr);
  vtkNew<MessageObserver> lonelyMessages;
  lonelyMessages->Watch(lonely);
  renderer->SetPass(lonely);
  window->Render();
  MLAA_CHECK(!lonelyMessages->Warnings.empty());
  MLAA_CHECK(lonelyMessages->Errors.empty());
  renderer->SetPass(nullptr);
  lonely->ReleaseGraphicsResources(window);
  other->SetPass(nullptr);
  MLAA_CHECK(Compare(expected, vtkMLAAScenes::Capture(window), 0.0).Count == 0);
}
}

int TestAntialiasingPassResources(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    auto window = vtkMLAAScenes::NewOffscreenWindow(300, 200);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build("silhouettes", renderer);
    // Held here too: the checks take the pass off the renderer and put it back.
    vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(renderer);
    messages->Watch(pass);

    Resources(method, window, renderer, pass);
    Tiling(renderer, pass);
    Multisampling(window, renderer, pass);
    TextureUnits(window, renderer, pass);
    pass->ReleaseGraphicsResources(window);
    NoDelegate(method, window, renderer);
  });
  return Result();
}
