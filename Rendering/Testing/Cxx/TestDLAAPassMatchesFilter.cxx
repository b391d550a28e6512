// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// CPU/GPU parity of directionally localized antialiasing: for every shared scene, the render of
// vtkOpenGLDLAAPass equals vtkImageDLAA run on the single-sample screenshot of the same scene
// within 2/255 (on llvmpipe on every pixel; the check allows 0.1 % of the pixels, where another
// driver's rounding may flip one of the method's thresholds: the ends of (0, 1] for k, the noise
// rejection's Mx, My > 0), and the pass changes the image (but for the axis-aligned voxels, which
// both leave as they are). Default options on every scene; on
// a few scenes LongEdges off, the green luminosity and other thresholds; and with KeepAlpha the
// RGBA result equals the filter on the RGBA screenshot. The windows are opaque ordinary windows
// (the filter runs on the RGB screenshot); overlays are antialiased, as the filter sees them.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkImageDLAA.h"

#include <iomanip>

using namespace vtkMLAATest;

namespace
{
double worstShare = 1.0;
std::string worstCase;

void CheckScene(const std::string& name, vtkDLAAOptions* options, const char* variant,
  bool keepAlpha = false)
{
  SceneWindow scene(name, 400, 300, keepAlpha);
  auto pass = UseDLAA(scene.Renderer, options);
  pass->SetKeepAlpha(keepAlpha);
  pass->AntialiasOverlaysOn(); // the CPU filter sees the overlays in the render too
  auto result = vtkMLAAScenes::Capture(scene.Window, keepAlpha);
  auto expected = RunDLAA(scene.Plain, options);
  const Difference d = Compare(expected, result, 2.0);
  const Difference changed = Compare(scene.Plain, result, 0.0);
  const double share = d.Count < 0 ? 0.0 : 1.0 - static_cast<double>(d.Pixels) / d.Total;
  const std::string what = name + " (" + variant + (keepAlpha ? ", RGBA" : "") + ")";
  std::cout << what << ": " << std::fixed << std::setprecision(3) << 100.0 * share
            << " % of pixels within 2/255 of vtkImageDLAA (largest difference " << d.Max
            << "); the pass changed " << changed.Pixels << " pixels" << std::endl;
  if (share < worstShare)
  {
    worstShare = share;
    worstCase = what;
  }
  Check(d.Count >= 0 && share >= 0.999, (what + ": the pass equals vtkImageDLAA").c_str(),
    __FILE__, __LINE__);
  // An axis-aligned scene (the voxels) has only sides on pixel borders, which end at the sides of
  // corners: nothing changes there (issue 50); on every other scene the parity is not trivial.
  Check(changed.Pixels > 50 || vtkMLAAScenes::AxisAligned(name),
    (what + ": antialiased").c_str(), __FILE__, __LINE__);
}
}

int TestDLAAPassMatchesFilter(int, char*[])
{
  vtkNew<vtkDLAAOptions> defaults;
  for (const std::string& name : vtkMLAAScenes::Names())
  {
    CheckScene(name, defaults, "defaults");
  }
  vtkNew<vtkDLAAOptions> shortEdges;
  shortEdges->LongEdgesOff();
  vtkNew<vtkDLAAOptions> green;
  green->SetLumaFunctionToGreen();
  vtkNew<vtkDLAAOptions> strong;
  strong->SetEpsilon(0.02);
  strong->SetLambda(8.0);
  for (const char* name : { "silhouettes", "lines", "horizon", "texture" })
  {
    CheckScene(name, shortEdges, "short edges only");
    CheckScene(name, green, "green luminosity");
    CheckScene(name, strong, "epsilon 0.02, lambda 8");
  }
  for (const char* name : { "silhouettes", "wireframe" })
  {
    CheckScene(name, defaults, "defaults", true);
  }
  std::cout << "worst: " << 100.0 * worstShare << " % of pixels within 2/255, " << worstCase
            << std::endl;
  return Result();
}
