// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageMLAA on every scalar type and component count VTK images have, on 2D images and 3D
// volumes. The same picture, stored in each type (values lo + n (hi - lo) of the type's range, or
// n for floating point), gives the same normalised result as the 8-bit image within 1/255; the
// output keeps the input's type and components; each z slice of a volume is antialiased on its
// own. All of this in luma mode (the default), in Lab mode, and in Lab mode with reconstruction
// (a one-pixel diagonal line with a gap is added to the picture, which reconstruction closes).
#include "vtkAntialiasingTestUtilities.h"

#include <limits>
#include <type_traits>

using namespace vtkMLAATest;

namespace
{
// The picture in normalised units: a shallow staircase (a step every 4 pixels) of one colour
// over another, on an odd-sized image. Component k gets its own brightness; the last of 2 or 4
// components is alpha, nearly opaque (0.99: full scale of a 64-bit type does not round-trip
// through double).
double Picture(int x, int y, int z, int k, int components)
{
  if ((components == 2 || components == 4) && k == components - 1)
  {
    return 0.99;
  }
  const bool inside = y < 4 + (x + 2 * z) / 4;
  if (!inside && x - y == 6 && x > 12 && x != 18)
  {
    return 0.6 + 0.1 * k; // a thin diagonal line with a gap at (18, 12), above the staircase
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

vtkSmartPointer<vtkImageData> MakePicture(int type, int components, int depth, double lo, double hi)
{
  auto image = MakeImage(23, 17, components, type, 0.0, depth);
  FillImage(image, [&](int x, int y, int z, int k) {
    const double v = lo + Picture(x, y, z, k, components) * (hi - lo);
    return type == VTK_FLOAT || type == VTK_DOUBLE ? v : std::round(v);
  });
  return image;
}

template <typename T>
void CheckType(int type, vtkMLAAOptions* options)
{
  double lo, hi;
  Range<T>(lo, hi);
  for (int components = 1; components <= 4; ++components)
  {
    auto reference = RunMLAA(MakePicture(VTK_UNSIGNED_CHAR, components, 1, 0.0, 255.0), options);
    auto input = MakePicture(type, components, 1, lo, hi);
    auto output = RunMLAA(input, options);
    if (!MLAA_CHECK(output->GetScalarType() == type) ||
      !MLAA_CHECK(output->GetNumberOfScalarComponents() == components))
    {
      continue;
    }
    // Normalised comparison with the 8-bit result.
    double worst = 0.0;
    int changed = 0;
    for (int y = 0; y < 17; ++y)
    {
      for (int x = 0; x < 23; ++x)
      {
        for (int k = 0; k < components; ++k)
        {
          const double n = (GetValue(output, x, y, k) - lo) / (hi - lo);
          const double r = GetValue(reference, x, y, k) / 255.0;
          worst = std::max(worst, std::abs(n - r));
          changed += GetValue(output, x, y, k) != GetValue(input, x, y, k) ? 1 : 0;
        }
      }
    }
    if (!MLAA_CHECK(worst <= 1.0 / 255.0 + 1e-9) || !MLAA_CHECK(changed > 10))
    {
      std::cerr << "type " << vtkImageScalarTypeNameMacro(type) << ", " << components
                << " components, edges " << options->GetEdgeDetectionAsString(options->GetEdgeDetection())
                << (options->GetReconstruction() ? " with reconstruction" : "")
                << ": largest normalised difference " << worst << ", " << changed
                << " values changed" << std::endl;
    }
    if (options->GetReconstruction())
    {
      // The gap is closed: (18, 12) takes the line's colour (then blended along the line,
      // so closer to it than to the background, where without reconstruction it stays).
      for (int k = 0; k < components - ((components == 2 || components == 4) ? 1 : 0); ++k)
      {
        const double n = (GetValue(output, 18, 12, k) - lo) / (hi - lo);
        const double v = (GetValue(input, 18, 12, k) - lo) / (hi - lo);
        MLAA_CHECK(std::abs(n - (0.6 + 0.1 * k)) < std::abs(n - (0.15 + 0.05 * k)));
        MLAA_CHECK(std::abs(v - (0.15 + 0.05 * k)) < 1.0 / 255.0);
      }
    }
  }

  // A volume: slice z of the output is the filter's result on slice z alone.
  auto volume = MakePicture(type, 3, 3, lo, hi);
  auto volumeOut = RunMLAA(volume, options);
  for (int z = 0; z < 3; ++z)
  {
    auto slice = MakeImage(23, 17, 3, type);
    FillImage(slice, [&](int x, int y, int, int k) { return GetValue(volume, x, y, k, z); });
    auto sliceOut = RunMLAA(slice, options);
    bool same = true;
    for (int y = 0; y < 17; ++y)
    {
      for (int x = 0; x < 23; ++x)
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
}

int TestImageMLAATypes(int, char*[])
{
  for (int config = 0; config < 3; ++config)
  {
    vtkNew<vtkMLAAOptions> options;
    if (config > 0)
    {
      options->SetEdgeDetectionToLab();
    }
    options->SetReconstruction(config == 2);
    CheckType<char>(VTK_CHAR, options);
    CheckType<signed char>(VTK_SIGNED_CHAR, options);
    CheckType<unsigned char>(VTK_UNSIGNED_CHAR, options);
    CheckType<short>(VTK_SHORT, options);
    CheckType<unsigned short>(VTK_UNSIGNED_SHORT, options);
    CheckType<int>(VTK_INT, options);
    CheckType<unsigned int>(VTK_UNSIGNED_INT, options);
    CheckType<long>(VTK_LONG, options);
    CheckType<unsigned long>(VTK_UNSIGNED_LONG, options);
    CheckType<long long>(VTK_LONG_LONG, options);
    CheckType<unsigned long long>(VTK_UNSIGNED_LONG_LONG, options);
    CheckType<vtkIdType>(VTK_ID_TYPE, options);
    CheckType<float>(VTK_FLOAT, options);
    CheckType<double>(VTK_DOUBLE, options);
  }

  // Floating-point images outside [0, 1]: ValueRange says what full scale is.
  auto picture = MakePicture(VTK_DOUBLE, 1, 1, -500.0, 1500.0);
  vtkNew<vtkImageMLAA> filter;
  filter->SetInputData(picture);
  filter->SetValueRange(-500.0, 1500.0);
  filter->Update();
  auto reference = RunMLAA(MakePicture(VTK_DOUBLE, 1, 1, 0.0, 1.0));
  double worst = 0.0;
  for (int y = 0; y < 17; ++y)
  {
    for (int x = 0; x < 23; ++x)
    {
      worst = std::max(worst,
        std::abs((GetValue(filter->GetOutput(), x, y) + 500.0) / 2000.0 - GetValue(reference, x, y)));
    }
  }
  MLAA_CHECK(worst < 1e-9);
  // With the default range [0, 1] the same image has differences of hundreds of "full scales":
  // every boundary is an edge, but blending only mixes neighbours, so the result stays within
  // the input's values.
  auto unscaled = RunMLAA(picture);
  const double* inRange = picture->GetPointData()->GetScalars()->GetRange();
  const double* outRange = unscaled->GetPointData()->GetScalars()->GetRange();
  MLAA_CHECK(outRange[0] >= inRange[0] && outRange[1] <= inRange[1]);
  MLAA_CHECK(Compare(picture, unscaled).Count > 0);
  return Result();
}
