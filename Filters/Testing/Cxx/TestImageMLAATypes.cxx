// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageMLAA's reconstruction in every scalar type and component count: a one-pixel diagonal
// line with a gap at (18, 12), above a shallow staircase, is closed by coverage (six pixels of
// the line in the gap's window: the gap moves 3/7 of the way from the background to the line's
// colour, where without reconstruction it stays), in every type alike (within 1/255 of 3/7). What every method shares on every type
// (the same normalised result as the 8-bit image, volumes slice by slice, ValueRange) is tested
// in TestAntialiasingAlgorithmTypes, for MLAA's configurations with reconstruction among them.
#include "vtkAntialiasingTestUtilities.h"

using namespace vtkMLAATest;

namespace
{
// The picture in normalised units (as TestAntialiasingAlgorithmTypes's staircase): component k
// gets its own brightness; the last of 2 or 4 components is alpha, nearly opaque.
double Picture(int x, int y, int k, int components)
{
  if ((components == 2 || components == 4) && k == components - 1)
  {
    return 0.99;
  }
  const bool inside = y < 4 + x / 4;
  if (!inside && x - y == 6 && x > 12 && x != 18)
  {
    return 0.6 + 0.1 * k; // the thin diagonal line with its gap at (18, 12)
  }
  return inside ? 0.85 - 0.1 * k : 0.15 + 0.05 * k;
}

void CheckGapClosed(int type, vtkMLAAOptions* options)
{
  double lo, hi;
  TypeRange(type, lo, hi);
  for (int components = 1; components <= 4; ++components)
  {
    auto input = MakeTypedImage(23, 17, 1, type, components, lo, hi,
      [components](int x, int y, int, int k) { return Picture(x, y, k, components); });
    auto output = RunMLAA(input, options);
    for (int k = 0; k < components - ((components == 2 || components == 4) ? 1 : 0); ++k)
    {
      const double n = (GetValue(output, 18, 12, k) - lo) / (hi - lo);
      const double v = (GetValue(input, 18, 12, k) - lo) / (hi - lo);
      const double background = 0.15 + 0.05 * k;
      const double line = 0.6 + 0.1 * k;
      const double expected = background + 3.0 / 7.0 * (line - background);
      if (!MLAA_CHECK(std::abs(n - expected) <= 1.5 / 255.0) ||
        !MLAA_CHECK(std::abs(v - (0.15 + 0.05 * k)) < 1.0 / 255.0))
      {
        std::cerr << "type " << vtkImageScalarTypeNameMacro(type) << ", " << components
                  << " components, component " << k << ": gap " << n << ", input " << v
                  << std::endl;
      }
    }
  }
}
}

int TestImageMLAATypes(int, char*[])
{
  vtkNew<vtkMLAAOptions> options;
  options->SetEdgeDetectionToLab();
  options->ReconstructionOn();
  for (int type : ScalarTypes())
  {
    CheckGapClosed(type, options);
  }
  return Result();
}
