// A transparent background in a window with alpha planes: geometry is opaque, the background has
// alpha 0. The pass gives silhouettes a soft alpha border (alpha takes part in edge detection and
// is blended with the same weights), equal to the CPU filter on the RGBA render. With an opaque
// background alpha stays 1 everywhere.
#include "vtkMLAARenderTestUtilities.h"

using namespace vtkMLAATest;

namespace
{
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
}

int TestMLAAPassAlpha(int, char*[])
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(400, 300);
  window->SetAlphaBitPlanes(1);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  renderer->SetBackgroundAlpha(0.0);
  auto plain = vtkMLAAScenes::Capture(window, true);
  UseMLAA(renderer);
  auto result = vtkMLAAScenes::Capture(window, true);

  const int plainSoft = CountSoftAlpha(plain);
  const int resultSoft = CountSoftAlpha(result);
  std::cout << "pixels with 0 < alpha < 1: " << plainSoft << " before, " << resultSoft
            << " after" << std::endl;
  MLAA_CHECK(plainSoft == 0);
  MLAA_CHECK(resultSoft > 200);
  const Difference d = Compare(RunMLAA(plain), result, 2.0);
  MLAA_CHECK(d.Count == 0);

  // Opaque background: alpha is 1 everywhere, before and after.
  StopMLAA(renderer, window);
  renderer->SetBackgroundAlpha(1.0);
  UseMLAA(renderer);
  auto opaque = vtkMLAAScenes::Capture(window, true);
  MLAA_CHECK(opaque->GetPointData()->GetScalars()->GetRange(3)[0] == 255.0);
  StopMLAA(renderer, window);
  return Result();
}
