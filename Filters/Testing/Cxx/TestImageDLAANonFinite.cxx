// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// NaN, infinity and values too large to blend in vtkImageDLAA's input: a pixel that reads one (within the short-edge
// cross, and with long edges within the long-edge windows, see vtkDLAAOptions) is left as it
// is; every other pixel gets exactly the result of the image without them. (Bad input, for
// every method, is in TestAntialiasingAlgorithmErrors.)
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkAntialiasingTestUtilities.h"

#include <limits>

using namespace vtkMLAATest;

namespace
{
// Whether the result of pixel (x, y) reads pixel (bx, by) (the dependency region in
// vtkDLAAOptions): the cross of radius 2 around any pixel within `reach` along x or y.
bool Reads(int x, int y, int bx, int by, int reach)
{
  const int dx = std::abs(bx - x);
  const int dy = std::abs(by - y);
  return (dy <= 2 && dx <= reach) || (dx <= 2 && dy <= reach) ||
    (dy == 0 && dx <= reach + 2) || (dx == 0 && dy <= reach + 2);
}

void NonFinite()
{
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    // NaN, the infinities, and a finite value so large that blending it would overflow (found
    // by the fuzz target mlaa_filter_fuzzer: -1.7e38 in a float image gave NaN).
    const double huge = type == VTK_FLOAT ? -1.7e38 : -1.7e308;
    const double bad[] = { std::numeric_limits<double>::quiet_NaN(),
      std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), huge };
    for (bool longEdges : { true, false })
    {
      vtkNew<vtkDLAAOptions> options;
      options->SetLongEdges(longEdges);
      const int reach = longEdges ? 8 : 0;
      // A long edge with 20-pixel steps and a short steep one, in RGBA.
      auto clean = MakeImage(90, 40, 4, type);
      FillImage(clean, [](int x, int y, int, int k) {
        const bool inside = y < 10 + x / 20 || (x > 60 && y < 2 * x - 100);
        return k == 3 ? 1.0 : (inside ? 0.9 - 0.2 * k : 0.1 + 0.1 * k);
      });
      const auto cleanOut = RunDLAA(clean, options);
      for (int b = 0; b < 4; ++b)
      {
        // One non-finite pixel on the ramp of the long edge (row 11 near x = 40), in one
        // channel.
        const int bx = 37, by = 11;
        auto image = vtkSmartPointer<vtkImageData>::New();
        image->DeepCopy(clean);
        image->SetScalarComponentFromDouble(bx, by, 0, 1, bad[b]);
        vtkNew<vtkImageDLAA> filter;
        filter->SetOptions(options);
        filter->SetInputData(image);
        filter->Update();
        vtkImageData* out = filter->GetOutput();
        int frozen = 0, wrong = 0;
        for (int y = 0; y < 40; ++y)
        {
          for (int x = 0; x < 90; ++x)
          {
            const bool reads = Reads(x, y, bx, by, reach);
            for (int k = 0; k < 4; ++k)
            {
              const double v = GetValue(out, x, y, k);
              const double expected = reads ? GetValue(image, x, y, k) : GetValue(cleanOut, x, y, k);
              const bool same = v == expected || (std::isnan(v) && std::isnan(expected));
              wrong += same ? 0 : 1;
            }
            frozen += reads ? 1 : 0;
          }
        }
        if (!MLAA_CHECK(wrong == 0))
        {
          std::cerr << "type " << type << ", long edges " << longEdges << ", value " << bad[b]
                    << ": " << wrong << " values differ from the expected ones" << std::endl;
        }
        MLAA_CHECK(frozen > 0);
        // The clean result changes pixels that the non-finite one freezes.
        const int cx = longEdges ? 36 : 38;
        MLAA_CHECK(Reads(cx, 11, bx, by, reach));
        MLAA_CHECK(GetValue(cleanOut, cx, 11, 0) != GetValue(clean, cx, 11, 0));
      }
    }
  }
}

// An image of a type blended in float under a ValueRange so narrow that its values normalise
// beyond what can be blended (1 / (hi - lo) is infinite in float): every pixel is left as it
// is. Found by the fuzz target mlaa_filter_fuzzer, where such a signed char image gave NaN,
// converted back to signed char (undefined).
void NarrowValueRange()
{
  for (int type : { VTK_SIGNED_CHAR, VTK_SHORT })
  {
    vtkNew<vtkDLAAOptions> options;
    options->SetLongEdges(true);
    options->SetEpsilon(0.0);
    auto image = MakeImage(40, 30, 2, type);
    // Negative and positive values: they normalise to -infinity and +infinity (and 0 to NaN).
    FillImage(image, [](int x, int y, int, int k) {
      return (x * 37 + y * 11 + k * 5) % 100 - 50.0;
    });
    vtkNew<vtkImageDLAA> filter;
    filter->SetOptions(options);
    filter->SetValueRange(1e-300, 1e-280);
    filter->SetInputData(image);
    filter->Update();
    vtkImageData* out = filter->GetOutput();
    int wrong = 0;
    for (int y = 0; y < 30; ++y)
    {
      for (int x = 0; x < 40; ++x)
      {
        for (int k = 0; k < 2; ++k)
        {
          wrong += GetValue(out, x, y, k) == GetValue(image, x, y, k) ? 0 : 1;
        }
      }
    }
    if (!MLAA_CHECK(wrong == 0))
    {
      std::cerr << "type " << type << ": " << wrong << " values changed" << std::endl;
    }
  }
}
}

int TestImageDLAANonFinite(int, char*[])
{
  NonFinite();
  NarrowValueRange();
  return Result();
}
