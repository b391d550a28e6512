// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// A vtkImageAntialiasingAlgorithm (every method and every configuration of FilterMethods()) on
// every scalar type and component count VTK images have, on 2D images and 3D volumes, odd sizes
// and single pixels. The same picture, stored in each type (values lo + n (hi - lo) of the type's
// range, or n for floating point), gives the same normalised result as the 8-bit image within
// 1/255; the output keeps the input's type and components; each z slice of a volume is
// antialiased on its own. ValueRange says what full scale is: floating-point images outside
// [0, 1], and 12-bit data stored in 16 bits, give the normalised result of the 8-bit image.
#include "vtkAntialiasingTestUtilities.h"

using namespace vtkMLAATest;

namespace
{
// Two pictures in normalised units; the last of 2 or 4 components is alpha. Component k gets
// its own brightness.
// - A shallow staircase (a step every 4 pixels) of one colour over another on an odd-sized
//   image, with a thin diagonal line with a gap at (18, 12) above it; alpha nearly opaque
//   (0.99: full scale of a 64-bit type does not round-trip through double).
double Staircase(int x, int y, int z, int k, int components)
{
  if ((components == 2 || components == 4) && k == components - 1)
  {
    return 0.99;
  }
  const bool inside = y < 4 + (x + 2 * z) / 4;
  if (!inside && x - y == 6 && x > 12 && x != 18)
  {
    return 0.6 + 0.1 * k;
  }
  return inside ? 0.85 - 0.1 * k : 0.15 + 0.05 * k;
}

// - A long staircase (a step every 12 pixels, long enough for DLAA's long-edge step) and a
//   short steep one; alpha opaque above the edge and 0.2 below it.
double LongStaircase(int x, int y, int z, int k, int components)
{
  const bool inside = y < 4 + (x + 3 * z) / 12 || (x > 30 && y < 2 * x - 50);
  if ((components == 2 || components == 4) && k == components - 1)
  {
    return inside ? 0.2 : 0.99;
  }
  return inside ? 0.85 - 0.1 * k : 0.15 + 0.05 * k;
}

struct Picture
{
  const char* Name;
  double (*Value)(int, int, int, int, int);
  int Width;
  int Height;
};

const Picture Pictures[] = { { "staircase", &Staircase, 23, 17 },
  { "long staircase", &LongStaircase, 41, 17 } };

// How far a result in another type, normalised, may be from the 8-bit result: 1/255 (the
// rounding of the 8-bit output), for every method (DLAA was allowed 2/255 before).
const double Tolerance = 1.0 / 255.0 + 1e-9;

vtkSmartPointer<vtkImageData> MakePicture(
  const Picture& picture, int type, int components, int depth, double lo, double hi)
{
  return MakeTypedImage(picture.Width, picture.Height, depth, type, components, lo, hi,
    [&](int x, int y, int z, int k) { return picture.Value(x, y, z, k, components); });
}

// The largest difference between `output` (normalised by [lo, hi]) and `reference` (8-bit).
double WorstNormalisedDifference(vtkImageData* output, vtkImageData* reference, double lo, double hi)
{
  int dims[3];
  output->GetDimensions(dims);
  const int components = output->GetNumberOfScalarComponents();
  double worst = 0.0;
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        for (int k = 0; k < components; ++k)
        {
          const double n = (GetValue(output, x, y, k, z) - lo) / (hi - lo);
          const double r = GetValue(reference, x, y, k, z) / 255.0;
          worst = std::max(worst, std::abs(n - r));
        }
      }
    }
  }
  return worst;
}

void CheckType(const FilterMethod& method, const FilterConfiguration& configuration,
  const Picture& picture, int type)
{
  double lo, hi;
  TypeRange(type, lo, hi);
  for (int components = 1; components <= 4; ++components)
  {
    auto reference = RunConfigured(
      method, MakePicture(picture, VTK_UNSIGNED_CHAR, components, 1, 0.0, 255.0), &configuration);
    auto input = MakePicture(picture, type, components, 1, lo, hi);
    auto output = RunConfigured(method, input, &configuration);
    if (!MLAA_CHECK(output->GetScalarType() == type) ||
      !MLAA_CHECK(output->GetNumberOfScalarComponents() == components))
    {
      continue;
    }
    const double worst = WorstNormalisedDifference(output, reference, lo, hi);
    const vtkIdType changed = Compare(input, output).Count;
    if (!MLAA_CHECK(worst <= Tolerance) || !MLAA_CHECK(changed > 10))
    {
      std::cerr << method.Name << ", " << configuration.Name << ", " << picture.Name << ", type "
                << vtkImageScalarTypeNameMacro(type) << ", " << components
                << " components: largest normalised difference " << worst * 255 << "/255, "
                << changed << " values changed" << std::endl;
    }
  }

  // A volume: slice z of the output is the filter's result on slice z alone.
  auto volume = MakePicture(picture, type, 3, 3, lo, hi);
  auto volumeOut = RunConfigured(method, volume, &configuration);
  for (int z = 0; z < 3; ++z)
  {
    auto slice = MakeImage(picture.Width, picture.Height, 3, type);
    FillImage(slice, [&](int x, int y, int, int k) { return GetValue(volume, x, y, k, z); });
    auto sliceOut = RunConfigured(method, slice, &configuration);
    bool same = true;
    for (int y = 0; y < picture.Height; ++y)
    {
      for (int x = 0; x < picture.Width; ++x)
      {
        for (int k = 0; k < 3; ++k)
        {
          same = same && GetValue(sliceOut, x, y, k) == GetValue(volumeOut, x, y, k, z);
        }
      }
    }
    if (!MLAA_CHECK(same))
    {
      std::cerr << method.Name << ", " << configuration.Name << ", " << picture.Name << ", type "
                << vtkImageScalarTypeNameMacro(type) << ": slice " << z << " differs"
                << std::endl;
    }
  }
}

// Single pixels, single rows and columns, and odd sizes: no reads outside the image, and the
// expected results where they follow from the clamping (a single pixel has no edge, so it is
// unchanged; values stay within the input's).
void SmallImages(const FilterMethod& method)
{
  for (int components = 1; components <= 4; ++components)
  {
    for (int type : { VTK_UNSIGNED_CHAR, VTK_FLOAT })
    {
      auto pixel = MakeImage(1, 1, components, type, type == VTK_FLOAT ? 0.7 : 77.0);
      MLAA_CHECK(Compare(pixel, RunConfigured(method, pixel)).Count == 0);
    }
  }
  for (int w : { 1, 2, 3, 5, 17, 18 })
  {
    for (int h : { 1, 2, 3, 6, 19 })
    {
      auto image = MakeImage(w, h, 3);
      FillImage(image,
        [](int x, int y, int, int k) { return (x * 7 + y * 13 + k * 5) % 3 ? 255.0 : 0.0; });
      auto output = RunConfigured(method, image);
      MLAA_CHECK(output->GetNumberOfPoints() == w * h);
      if (w == 1 || h == 1)
      {
        for (int y = 0; y < h; ++y)
        {
          for (int x = 0; x < w; ++x)
          {
            const double v = GetValue(output, x, y, 0);
            MLAA_CHECK(v >= 0 && v <= 255);
          }
        }
      }
    }
  }
}

void ValueRanges(const FilterMethod& method)
{
  // Floating-point images outside [0, 1]: ValueRange says what full scale is.
  const Picture& staircase = Pictures[0];
  auto picture = MakePicture(staircase, VTK_DOUBLE, 1, 1, -500.0, 1500.0);
  auto filter = method.New();
  filter->SetInputData(picture);
  filter->SetValueRange(-500.0, 1500.0);
  filter->Update();
  auto reference = RunConfigured(method, MakePicture(staircase, VTK_DOUBLE, 1, 1, 0.0, 1.0));
  double worst = 0.0;
  for (int y = 0; y < staircase.Height; ++y)
  {
    for (int x = 0; x < staircase.Width; ++x)
    {
      worst = std::max(worst,
        std::abs((GetValue(filter->GetOutput(), x, y) + 500.0) / 2000.0 - GetValue(reference, x, y)));
    }
  }
  MLAA_CHECK(worst < 1e-9);
  // With the default range [0, 1] the same image has differences of hundreds of "full scales":
  // every boundary is an edge, but blending only mixes neighbours, so the result stays within
  // the input's values.
  auto unscaled = RunConfigured(method, picture);
  const double* inRange = picture->GetPointData()->GetScalars()->GetRange();
  const double* outRange = unscaled->GetPointData()->GetScalars()->GetRange();
  MLAA_CHECK(outRange[0] >= inRange[0] && outRange[1] <= inRange[1]);
  MLAA_CHECK(Compare(picture, unscaled).Count > 0);

  // 12-bit data in 16-bit integers with SetValueRange(0, 4095) gives the 8-bit result.
  const Picture& longStaircase = Pictures[1];
  auto reference8 =
    RunConfigured(method, MakePicture(longStaircase, VTK_UNSIGNED_CHAR, 3, 1, 0.0, 255.0));
  auto input = MakePicture(longStaircase, VTK_UNSIGNED_SHORT, 3, 1, 0.0, 4095.0);
  auto twelveBits = method.New();
  twelveBits->SetValueRange(0, 4095);
  twelveBits->SetInputData(input);
  twelveBits->Update();
  MLAA_CHECK(WorstNormalisedDifference(twelveBits->GetOutput(), reference8, 0.0, 4095.0) <=
    Tolerance);
  // Without it, the edges look 16 times fainter and nothing changes.
  MLAA_CHECK(Compare(input, RunConfigured(method, input)).Count == 0);
}
}

int TestAntialiasingAlgorithmTypes(int, char*[])
{
  for (const auto& method : FilterMethods())
  {
    for (const auto& configuration : method.Configurations)
    {
      for (const auto& picture : Pictures)
      {
        for (int type : ScalarTypes())
        {
          CheckType(method, configuration, picture, type);
        }
      }
    }
    SmallImages(method);
    ValueRanges(method);
  }
  return Result();
}
