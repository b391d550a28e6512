// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// NaN and infinities in floating-point images never spread: pixels holding them are neither
// part of an edge nor mixed into their neighbours, and keep their values; the rest of the image
// is antialiased as usual.
#include "vtkAntialiasingTestUtilities.h"

#include <limits>

using namespace vtkMLAATest;

int TestImageMLAANonFinite(int, char*[])
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    for (int components : { 1, 3, 4 })
    {
      // A staircase with non-finite pixels on its edges and in a flat region.
      auto input = MakeImage(31, 21, components, type);
      FillImage(input, [](int x, int y, int, int k) {
        return (y < 5 + x / 5) ? 0.9 - 0.1 * k : 0.1;
      });
      vtkDataArray* s = input->GetPointData()->GetScalars();
      auto setPixel = [&](int x, int y, double v, int onlyComponent = -1) {
        for (int k = 0; k < components; ++k)
        {
          if (onlyComponent < 0 || onlyComponent == k)
          {
            s->SetComponent(y * 31 + x, k, v);
          }
        }
      };
      setPixel(10, 6, nan);                      // on the staircase
      setPixel(20, 8, inf);                      // on the staircase
      setPixel(5, 15, -inf);                     // flat region
      setPixel(25, 10, nan, components - 1);     // one channel only
      auto output = RunMLAA(input);

      bool nonFiniteKept = true;
      bool othersFinite = true;
      int changed = 0;
      for (int y = 0; y < 21; ++y)
      {
        for (int x = 0; x < 31; ++x)
        {
          for (int k = 0; k < components; ++k)
          {
            const double in = GetValue(input, x, y, k);
            const double out = GetValue(output, x, y, k);
            if (!std::isfinite(in))
            {
              nonFiniteKept = nonFiniteKept && (std::isnan(in) ? std::isnan(out) : in == out);
            }
            else
            {
              othersFinite = othersFinite && std::isfinite(out);
              changed += (out != in) ? 1 : 0;
            }
          }
        }
      }
      MLAA_CHECK(nonFiniteKept);
      MLAA_CHECK(othersFinite);
      MLAA_CHECK(changed > 10); // the staircase elsewhere is still antialiased
      // The neighbours of the non-finite pixels that are part of no other edge keep their values.
      MLAA_CHECK(GetValue(output, 5, 16) == GetValue(input, 5, 16));
      MLAA_CHECK(GetValue(output, 6, 15) == GetValue(input, 6, 15));
    }
  }

  // An image of nothing but NaN comes out as it went in, without errors.
  auto allNaN = MakeImage(9, 7, 3, VTK_FLOAT, nan);
  vtkNew<MessageObserver> messages;
  vtkNew<vtkImageMLAA> filter;
  messages->Watch(filter);
  filter->SetInputData(allNaN);
  filter->Update();
  MLAA_CHECK(messages->Errors.empty());
  const Difference d = Compare(allNaN, filter->GetOutput());
  MLAA_CHECK(d.Count == 0);
  return Result();
}
