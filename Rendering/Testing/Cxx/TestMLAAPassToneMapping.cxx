// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The pass with floating-point colour and with other image-processing passes:
// - MLAA after tone mapping (the pass's delegate is a vtkToneMappingPass): equal to the CPU
//   filter on the tone-mapped render;
// - MLAA before tone mapping (the pass is the delegate of a vtkToneMappingPass, so it draws into
//   a floating-point framebuffer and renders its own delegate in floating point): edges are
//   antialiased, flat regions keep their colour, and no GL error is reported.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkToneMappingPass.h"

using namespace vtkMLAATest;

int TestMLAAPassToneMapping(int, char*[])
{
  SceneWindow scene("silhouettes", 400, 300);
  vtkRenderer* renderer = scene.Renderer;

  // Tone mapping alone.
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkToneMappingPass> toneMapping;
  toneMapping->SetToneMappingType(vtkToneMappingPass::Reinhard);
  toneMapping->SetDelegatePass(steps);
  renderer->SetPass(toneMapping);
  auto toneMapped = vtkMLAAScenes::Capture(scene.Window);
  renderer->SetPass(nullptr);

  // MLAA after tone mapping.
  vtkNew<vtkOpenGLMLAAPass> after;
  vtkNew<MessageObserver> messages;
  messages->Watch(after);
  after->SetDelegatePass(toneMapping);
  renderer->SetPass(after);
  auto mlaaAfter = vtkMLAAScenes::Capture(scene.Window);
  const Difference parity = Compare(RunMLAA(toneMapped), mlaaAfter, 2.0);
  std::cout << "MLAA after tone mapping: " << parity.Pixels
            << " pixels off the CPU filter by more than 2/255" << std::endl;
  MLAA_CHECK(parity.Count == 0);
  MLAA_CHECK(Compare(toneMapped, mlaaAfter, 0.0).Pixels > 200);
  renderer->SetPass(nullptr);
  after->ReleaseGraphicsResources(scene.Window);
  toneMapping->ReleaseGraphicsResources(scene.Window);

  // MLAA before tone mapping, on floating-point colour.
  vtkNew<vtkRenderStepsPass> innerSteps;
  vtkNew<vtkOpenGLMLAAPass> before;
  messages->Watch(before);
  before->GetOptions()->SetPresetToMedium(); // 8 steps: the area texture sizes below
  before->SetDelegatePass(innerSteps);
  vtkNew<vtkToneMappingPass> outer;
  outer->SetToneMappingType(vtkToneMappingPass::Reinhard);
  outer->SetDelegatePass(before);
  renderer->SetPass(outer);
  auto mlaaBefore = vtkMLAAScenes::Capture(scene.Window);
  // The pass copied its target's 32-bit float colour (16 bytes per pixel), blends into a
  // second such image, and holds edges, weights, mask and the two area textures (it renders in
  // place: no depth copy).
  const vtkIdType pixels = 400 * 300;
  MLAA_CHECK(before->GetTargetMemorySize() ==
    pixels * (16 + 16 + 2 + 4 + 2) + 85 * 85 * 8 + 51 * 51 * 12);
  int dims[3];
  toneMapped->GetDimensions(dims);
  int changed = 0, flatChanged = 0;
  for (int y = 2; y < dims[1] - 2; ++y)
  {
    for (int x = 2; x < dims[0] - 2; ++x)
    {
      // Flat: green within 4/255 over the 5 x 5 neighbourhood.
      const bool flat = IsFlatAround(toneMapped, x, y, 2, 4.0, 1);
      const bool differs = std::abs(GetValue(toneMapped, x, y, 1) - GetValue(mlaaBefore, x, y, 1)) > 1.0;
      changed += differs ? 1 : 0;
      flatChanged += (differs && flat) ? 1 : 0;
    }
  }
  std::cout << "MLAA before tone mapping: " << changed << " pixels changed, " << flatChanged
            << " of them in flat regions" << std::endl;
  MLAA_CHECK(changed > 200);
  MLAA_CHECK(flatChanged == 0);
  MLAA_CHECK(messages->Errors.empty());
  renderer->SetPass(nullptr);
  outer->ReleaseGraphicsResources(scene.Window);
  return Result();
}
