// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Text and a scalar bar over a coloured surface. By default the pass draws the overlay step of
// its vtkRenderStepsPass delegate after the antialiasing, so every overlay pixel over a flat
// background comes out exactly as in the plain render, while the surface is antialiased.
// AntialiasOverlaysOn() antialiases the overlays too (the text then changes). Plus a strict
// baseline comparison of the default result.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkActor2DCollection.h"
#include "vtkActorCollection.h"

using namespace vtkMLAATest;

int TestMLAAPassTextOverlay(int argc, char* argv[])
{
  SceneWindow scene("text");
  vtkRenderer* renderer = scene.Renderer;
  // Where the overlays are (rendered alone), and where the 3D content is flat.
  SetVisibility(renderer, false, true);
  auto overlaysOnly = vtkMLAAScenes::Capture(scene.Window);
  SetVisibility(renderer, true, false);
  auto geometryOnly = vtkMLAAScenes::Capture(scene.Window);
  SetVisibility(renderer, true, true);

  auto pass = UseMLAA(renderer);
  auto result = vtkMLAAScenes::Capture(scene.Window);
  pass->AntialiasOverlaysOn();
  auto overlaysAntialiased = vtkMLAAScenes::Capture(scene.Window);
  pass->AntialiasOverlaysOff();

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
        same = same && GetValue(result, x, y, k) == GetValue(scene.Plain, x, y, k);
        sameAA = sameAA && GetValue(overlaysAntialiased, x, y, k) == GetValue(scene.Plain, x, y, k);
      }
      if (isOverlay && IsFlatAround(geometryOnly, x, y))
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

  scene.Window->Render();
  CheckBaseline(argc, argv, "TestMLAAPassTextOverlay", scene.Window, result, scene.Plain, 100);
  return Result();
}
