// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageDLAA on every scalar type and component count VTK images have, on 2D images, 3D
// volumes, odd sizes and single pixels. The same picture, stored in each type (values
// lo + n (hi - lo) of the type's range, or n for floating point), gives the same normalised
// result as the 8-bit image within the rounding of the two inputs and outputs (2/255); the
// output keeps the input's type and components; each z slice of a volume is antialiased on its
// own; ValueRange normalises 12-bit data stored in 16 bits like 8-bit data.
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkAntialiasingTestUtilities.h"

#include <limits>
#include <type_traits>

using namespace vtkMLAATest;

namespace
{
// The picture in normalised units: a shallow staircase (a step every 12 pixels, long enough
// for the long-edge step) of one colour over another, on an odd-sized image, and a short
// steep one. Component k gets its own brightness; the last of 2 or 4 components is alpha,
// opaque above the edge and 0.2 below it.
double Picture(int x, int y, int z, int k, int components)
{
  const bool inside = y < 4 + (x + 3 * z) / 12 || (x > 30 && y < 2 * x - 50);
  if ((components == 2 || components == 4) && k == components - 1)
  {
    return inside ? 0.2 : 0.99;
  }
  return inside ? 0.85 - 0.1 * k : 0.15 + 0.05 * k;
}

template <typename T>
void Range(double& lo, double& hi)
{
  if (std::is_floating_point<T>::value)
  {
    lo = 0.0;
    hi = 1.0;
  }
  else
  {
    lo = static_cast<double>(std::numeric_limits<T>::lowest());
    hi = static_cast<double>(std::numeric_limits<T>::max());
  }
}

vtkSmartPointer<vtkImageData> MakePicture(
  int type, int components, int depth, double lo, double hi, int width = 41, int height = 17)
{
  auto image = MakeImage(width, height, components, type, 0.0, depth);
  FillImage(image, [&](int x, int y, int z, int k) {
    const double v = lo + Picture(x, y, z, k, components) * (hi - lo);
    return type == VTK_FLOAT || type == VTK_DOUBLE ? v : std::round(v);
  });
  return image;
}

// The largest difference between `output` (normalised by [lo, hi]) and `reference` (8-bit).
double WorstNormalisedDifference(
  vtkImageData* output, vtkImageData* reference, double lo, double hi)
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

template <typename T>
void CheckType(int type, vtkDLAAOptions* options)
{
  double lo, hi;
  Range<T>(lo, hi);
  for (int components = 1; components <= 4; ++components)
  {
    auto reference = RunDLAA(MakePicture(VTK_UNSIGNED_CHAR, components, 1, 0.0, 255.0), options);
    auto input = MakePicture(type, components, 1, lo, hi);
    auto output = RunDLAA(input, options);
    if (!MLAA_CHECK(output->GetScalarType() == type) ||
      !MLAA_CHECK(output->GetNumberOfScalarComponents() == components))
    {
      continue;
    }
    const double worst = WorstNormalisedDifference(output, reference, lo, hi);
    const vtkIdType changed = Compare(input, output).Count;
    if (!MLAA_CHECK(worst <= 2.0 / 255.0) || !MLAA_CHECK(changed > 10))
    {
      std::cerr << "type " << vtkImageScalarTypeNameMacro(type) << ", " << components
                << " components, long edges " << options->GetLongEdges()
                << ": largest normalised difference " << worst * 255 << "/255, " << changed
                << " values changed" << std::endl;
    }
  }

  // A volume: slice z of the output is the filter's result on slice z alone.
  auto volume = MakePicture(type, 3, 3, lo, hi);
  auto volumeOut = RunDLAA(volume, options);
  for (int z = 0; z < 3; ++z)
  {
    auto slice = MakeImage(41, 17, 3, type);
    FillImage(slice, [&](int x, int y, int, int k) { return GetValue(volume, x, y, k, z); });
    auto sliceOut = RunDLAA(slice, options);
    bool same = true;
    for (int y = 0; y < 17; ++y)
    {
      for (int x = 0; x < 41; ++x)
      {
        for (int k = 0; k < 3; ++k)
        {
          same = same && GetValue(sliceOut, x, y, k) == GetValue(volumeOut, x, y, k, z);
        }
      }
    }
    MLAA_CHECK(same);
  }
}

void CheckAllTypes(vtkDLAAOptions* options)
{
  CheckType<unsigned char>(VTK_UNSIGNED_CHAR, options);
  CheckType<signed char>(VTK_SIGNED_CHAR, options);
  CheckType<char>(VTK_CHAR, options);
  CheckType<short>(VTK_SHORT, options);
  CheckType<unsigned short>(VTK_UNSIGNED_SHORT, options);
  CheckType<int>(VTK_INT, options);
  CheckType<unsigned int>(VTK_UNSIGNED_INT, options);
  CheckType<long>(VTK_LONG, options);
  CheckType<unsigned long>(VTK_UNSIGNED_LONG, options);
  CheckType<long long>(VTK_LONG_LONG, options);
  CheckType<unsigned long long>(VTK_UNSIGNED_LONG_LONG, options);
  CheckType<float>(VTK_FLOAT, options);
  CheckType<double>(VTK_DOUBLE, options);
}

// Single pixels, single rows and columns, and odd sizes: no reads outside the image, and the
// expected results where they follow from the clamping (a single pixel, row or column has no
// high-pass response across it, so one pixel and a uniform line are unchanged).
void SmallImages()
{
  for (int components = 1; components <= 4; ++components)
  {
    for (int type : { VTK_UNSIGNED_CHAR, VTK_FLOAT })
    {
      auto pixel = MakeImage(1, 1, components, type, type == VTK_FLOAT ? 0.7 : 77.0);
      MLAA_CHECK(Compare(pixel, RunDLAA(pixel)).Count == 0);
    }
  }
  for (int w : { 1, 2, 3, 5, 17, 18 })
  {
    for (int h : { 1, 2, 3, 6, 19 })
    {
      auto image = MakeImage(w, h, 3);
      FillImage(image, [](int x, int y, int, int k) { return (x * 7 + y * 13 + k * 5) % 3 ? 255.0 : 0.0; });
      auto output = RunDLAA(image);
      MLAA_CHECK(output->GetNumberOfPoints() == w * h);
      if (w == 1 || h == 1)
      {
        // Along the single row or column only: the values stay between their neighbours'.
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

// 12-bit data in 16-bit integers with SetValueRange(0, 4095) gives the 8-bit result.
void TwelveBits()
{
  vtkNew<vtkDLAAOptions> options;
  auto reference = RunDLAA(MakePicture(VTK_UNSIGNED_CHAR, 3, 1, 0.0, 255.0), options);
  auto input = MakePicture(VTK_UNSIGNED_SHORT, 3, 1, 0.0, 4095.0);
  vtkNew<vtkImageDLAA> filter;
  filter->SetValueRange(0, 4095);
  filter->SetInputData(input);
  filter->Update();
  MLAA_CHECK(WorstNormalisedDifference(filter->GetOutput(), reference, 0.0, 4095.0) <= 2.0 / 255.0);
  // Without it, the edges look 16 times fainter and nothing changes.
  MLAA_CHECK(Compare(input, RunDLAA(input)).Count == 0);
}
}

int TestImageDLAATypes(int, char*[])
{
  vtkNew<vtkDLAAOptions> options;
  CheckAllTypes(options);
  options->LongEdgesOff();
  CheckAllTypes(options);
  SmallImages();
  TwelveBits();
  return Result();
}
