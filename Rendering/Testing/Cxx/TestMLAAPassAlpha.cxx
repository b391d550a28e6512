// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Transparent backgrounds: a window read back as RGBA, a renderer whose background has alpha 0,
// and the pass with KeepAlphaOn(). The geometry is unlit, so every pixel it covers has one
// colour c; the plain render holds c with alpha 1 and the background colour (a light grey here)
// with alpha 0, so its alpha is 0 or 1 only.
// - Straight alpha (vtkMLAAOptions::PremultipliedAlpha off, the default): silhouettes get a soft
//   alpha border (alpha takes part in edge detection) whose colour is c: the background colour
//   stored under alpha 0 does not leak in, so composited over white or black there is no bright
//   or dark fringe. Composited over white and over black, the result equals vtkImageMLAA run on
//   the premultiplied render (blending premultiplied colours is what coverage blending is),
//   within 2/255.
// - Premultiplied alpha (PremultipliedAlpha on) over a transparent black background (what VTK's
//   blending gives): the result equals vtkImageMLAA with the same options on the RGBA render,
//   and its edge pixels un-premultiply to c.
// - An opaque background keeps alpha 1 everywhere.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkConeSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSphereSource.h"

using namespace vtkMLAATest;

namespace
{
const double ObjectColor[3] = { 0.85, 0.3, 0.1 };

void AddUnlit(vtkRenderer* renderer, vtkAlgorithm* source)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(ObjectColor[0], ObjectColor[1], ObjectColor[2]);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
}

int CountSoftAlpha(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  int soft = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const double a = GetValue(image, x, y, 3);
      soft += (a > 0.0 && a < 255.0) ? 1 : 0;
    }
  }
  return soft;
}

// An RGBA image with straight colour made premultiplied (rounded to 8 bits).
vtkSmartPointer<vtkImageData> Premultiplied(vtkImageData* straight)
{
  int dims[3];
  straight->GetDimensions(dims);
  auto out = MakeImage(dims[0], dims[1], 4);
  FillImage(out, [&](int x, int y, int, int k) {
    const double a = GetValue(straight, x, y, 3);
    return k == 3 ? a : std::round(GetValue(straight, x, y, k) * a / 255.0);
  });
  return out;
}

// A premultiplied RGBA image composited over a grey level `g` (0..255), RGB.
vtkSmartPointer<vtkImageData> Over(vtkImageData* premultiplied, double g)
{
  int dims[3];
  premultiplied->GetDimensions(dims);
  auto out = MakeImage(dims[0], dims[1], 3, VTK_DOUBLE);
  FillImage(out, [&](int x, int y, int, int k) {
    return GetValue(premultiplied, x, y, k) + (1.0 - GetValue(premultiplied, x, y, 3) / 255.0) * g;
  });
  return out;
}

// The largest distance, over the pixels with 0 < alpha < 1, between their un-premultiplied
// colour and the object's colour (in 1/255), for an image whose colour is straight or
// premultiplied. Pixels with alpha below 16/255 are skipped when premultiplied: 8-bit rounding
// dominates there.
double WorstEdgeColor(vtkImageData* image, bool premultiplied)
{
  int dims[3];
  image->GetDimensions(dims);
  double worst = 0.0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      const double a = GetValue(image, x, y, 3);
      if (a <= 0.0 || a >= 255.0 || (premultiplied && a < 16.0))
      {
        continue;
      }
      for (int k = 0; k < 3; ++k)
      {
        const double c = GetValue(image, x, y, k) / (premultiplied ? a / 255.0 : 1.0);
        worst = std::max(worst, std::abs(c - 255.0 * ObjectColor[k]));
      }
    }
  }
  return worst;
}
}

int TestMLAAPassAlpha(int, char*[])
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(400, 300);
  window->SetAlphaBitPlanes(1);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  AddUnlit(renderer, sphere);
  vtkNew<vtkConeSource> cone;
  cone->SetResolution(5);
  cone->SetCenter(1.1, 0.2, 0.0);
  cone->SetDirection(0.4, 1.0, 0.3);
  AddUnlit(renderer, cone);
  renderer->ResetCamera();
  renderer->SetBackground(0.92, 0.93, 0.95);
  renderer->SetBackgroundAlpha(0.0);
  auto plain = vtkMLAAScenes::Capture(window, true);
  MLAA_CHECK(CountSoftAlpha(plain) == 0);

  // Straight alpha (the default).
  auto pass = UseMLAA(renderer);
  pass->KeepAlphaOn();
  auto straight = vtkMLAAScenes::Capture(window, true);
  const int soft = CountSoftAlpha(straight);
  const double worstStraight = WorstEdgeColor(straight, false);
  vtkNew<vtkMLAAOptions> premultipliedOptions;
  premultipliedOptions->PremultipliedAlphaOn();
  auto expected = RunMLAA(Premultiplied(plain), premultipliedOptions);
  const auto resultPremultiplied = Premultiplied(straight);
  const Difference overWhite = Compare(Over(expected, 255.0), Over(resultPremultiplied, 255.0), 2.0);
  const Difference overBlack = Compare(Over(expected, 0.0), Over(resultPremultiplied, 0.0), 2.0);
  std::cout << "straight alpha: " << soft << " pixels with 0 < alpha < 1, their colour at most "
            << worstStraight << "/255 from the object's; over white " << overWhite.Pixels
            << " and over black " << overBlack.Pixels
            << " pixels off the CPU filter on the premultiplied render by more than 2/255 (largest "
            << std::max(overWhite.Max, overBlack.Max) << ")" << std::endl;
  MLAA_CHECK(soft > 200);
  MLAA_CHECK(worstStraight <= 2.0);
  MLAA_CHECK(overWhite.Count == 0);
  MLAA_CHECK(overBlack.Count == 0);
  StopPass(renderer, window);

  // Premultiplied alpha over transparent black.
  renderer->SetBackground(0.0, 0.0, 0.0);
  auto plainBlack = vtkMLAAScenes::Capture(window, true);
  pass = UseMLAA(renderer, premultipliedOptions);
  pass->KeepAlphaOn();
  auto premultiplied = vtkMLAAScenes::Capture(window, true);
  const double worstPremultiplied = WorstEdgeColor(premultiplied, true);
  const Difference parity = Compare(RunMLAA(plainBlack, premultipliedOptions), premultiplied, 2.0);
  std::cout << "premultiplied alpha: " << CountSoftAlpha(premultiplied)
            << " pixels with 0 < alpha < 1, un-premultiplied at most " << worstPremultiplied
            << "/255 from the object's colour; " << parity.Pixels
            << " pixels off the CPU filter by more than 2/255" << std::endl;
  MLAA_CHECK(CountSoftAlpha(premultiplied) > 200);
  MLAA_CHECK(worstPremultiplied <= 8.0);
  MLAA_CHECK(parity.Count == 0);
  StopPass(renderer, window);

  // Opaque background: alpha is 1 everywhere, before and after.
  renderer->SetBackground(0.92, 0.93, 0.95);
  renderer->SetBackgroundAlpha(1.0);
  pass = UseMLAA(renderer);
  pass->KeepAlphaOn();
  auto opaque = vtkMLAAScenes::Capture(window, true);
  MLAA_CHECK(opaque->GetPointData()->GetScalars()->GetRange(3)[0] == 255.0);
  StopPass(renderer, window);
  return Result();
}
