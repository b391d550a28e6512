// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Integer data that uses part of its type: a 12-bit picture stored in 16-bit integers is
// antialiased as well as the same picture in 8 bits once SetValueRange(0, 4095) says so
// (within 0.03 AAR, measured against supersampled coverage as MEASURING.md does); with the
// type's range (the default) its edges look 16 times fainter and are left alone. The value
// range applies to every type, SetValueRangeToTypeDefault restores the defaults, and the
// result with an explicit range does not depend on streaming.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkImageDataStreamer.h"

using namespace vtkMLAATest;

namespace
{
const int Width = 160;
const int Height = 120;

// Two shapes at odd angles: a rotated square and a disc, grey levels 0.2 and 0.75 on 0.45.
double Shade(double x, double y)
{
  const double u = 0.93 * (x - 50.0) + 0.37 * (y - 60.0);
  const double v = -0.37 * (x - 50.0) + 0.93 * (y - 60.0);
  if (std::abs(u) < 28.0 && std::abs(v) < 28.0)
  {
    return 0.2;
  }
  if ((x - 115.3) * (x - 115.3) + (y - 58.6) * (y - 58.6) < 31.0 * 31.0)
  {
    return 0.75;
  }
  return 0.45;
}

double Reference(int x, int y)
{
  double sum = 0.0;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      sum += Shade(x + (i + 0.5) / 8.0, y + (j + 0.5) / 8.0);
    }
  }
  return sum / 64.0;
}

// The picture point-sampled at pixel centres and stored with values 0..full.
vtkSmartPointer<vtkImageData> Picture(int type, double full)
{
  auto image = MakeImage(Width, Height, 1, type);
  FillImage(image, [&](int x, int y, int, int) { return std::round(full * Shade(x + 0.5, y + 0.5)); });
  return image;
}

// The share of the aliasing error (against the supersampled picture, over the pixels where
// the plain picture differs from it) that `result` removes.
double AAR(vtkImageData* plain, vtkImageData* result, double full)
{
  double before = 0.0, after = 0.0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const double reference = Reference(x, y);
      const double a = GetValue(plain, x, y) / full - reference;
      if (std::abs(a) <= 4.0 / 255.0)
      {
        continue;
      }
      const double b = GetValue(result, x, y) / full - reference;
      before += a * a;
      after += b * b;
    }
  }
  return 1.0 - after / before;
}

vtkSmartPointer<vtkImageData> Run(vtkImageData* input, const double* range)
{
  vtkNew<vtkImageMLAA> filter;
  if (range)
  {
    filter->SetValueRange(range[0], range[1]);
  }
  filter->SetInputData(input);
  filter->Update();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}
}

int TestImageMLAAValueRange(int, char*[])
{
  // The settings themselves.
  vtkNew<vtkImageMLAA> filter;
  double range[2];
  MLAA_CHECK(filter->GetValueRangeIsTypeDefault());
  filter->GetEffectiveValueRange(VTK_UNSIGNED_SHORT, range);
  MLAA_CHECK(range[0] == 0.0 && range[1] == 65535.0);
  filter->GetEffectiveValueRange(VTK_SHORT, range);
  MLAA_CHECK(range[0] == -32768.0 && range[1] == 32767.0);
  filter->GetEffectiveValueRange(VTK_FLOAT, range);
  MLAA_CHECK(range[0] == 0.0 && range[1] == 1.0);
  const vtkMTimeType before = filter->GetMTime();
  filter->SetValueRange(0.0, 4095.0);
  MLAA_CHECK(!filter->GetValueRangeIsTypeDefault() && filter->GetMTime() > before);
  filter->GetEffectiveValueRange(VTK_UNSIGNED_SHORT, range);
  MLAA_CHECK(range[0] == 0.0 && range[1] == 4095.0);
  filter->GetEffectiveValueRange(VTK_DOUBLE, range);
  MLAA_CHECK(range[0] == 0.0 && range[1] == 4095.0);
  filter->SetValueRangeToTypeDefault();
  filter->GetEffectiveValueRange(VTK_UNSIGNED_CHAR, range);
  MLAA_CHECK(filter->GetValueRangeIsTypeDefault() && range[0] == 0.0 && range[1] == 255.0);

  // 8-bit, 12-bit in 16-bit integers with and without the range, and 12-bit in floats.
  auto eight = Picture(VTK_UNSIGNED_CHAR, 255.0);
  auto twelve = Picture(VTK_UNSIGNED_SHORT, 4095.0);
  auto twelveFloat = Picture(VTK_FLOAT, 4095.0);
  const double twelveBits[2] = { 0.0, 4095.0 };
  const double aar8 = AAR(eight, Run(eight, nullptr), 255.0);
  const double aar12 = AAR(twelve, Run(twelve, twelveBits), 4095.0);
  const double aar12Float = AAR(twelveFloat, Run(twelveFloat, twelveBits), 4095.0);
  const double aar12TypeRange = AAR(twelve, Run(twelve, nullptr), 4095.0);
  std::cout << "AAR: 8-bit " << aar8 << ", 12-bit in 16 with its range " << aar12
            << ", 12-bit in float with its range " << aar12Float
            << ", 12-bit in 16 with the type's range " << aar12TypeRange << std::endl;
  MLAA_CHECK(aar8 > 0.5);
  MLAA_CHECK(std::abs(aar12 - aar8) <= 0.03);
  MLAA_CHECK(std::abs(aar12Float - aar8) <= 0.03);
  MLAA_CHECK(aar12TypeRange < 0.05); // the edges (0.25 x 4095 / 65535 = 0.016) are below 0.1

  // Streaming with an explicit range gives the unstreamed result.
  vtkNew<vtkImageMLAA> streamed;
  streamed->SetValueRange(twelveBits);
  streamed->SetInputData(twelve);
  vtkNew<vtkImageDataStreamer> streamer;
  streamer->SetInputConnection(streamed->GetOutputPort());
  streamer->SetNumberOfStreamDivisions(5);
  streamer->Update();
  MLAA_CHECK(Compare(Run(twelve, twelveBits), streamer->GetOutput()).Count == 0);
  return Result();
}
