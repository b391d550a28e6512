// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Straight and premultiplied alpha (vtkMLAAOptions::PremultipliedAlpha): a grey disc over a
// transparent black background, antialiased, must composite over white and over black like the
// supersampled disc does, with no dark or bright fringe:
// - straight alpha (the default, as in PNG files): the colour of partly covered pixels stays
//   the disc's colour, only alpha is blended;
// - premultiplied alpha: the same pixels read as premultiplied values blend as they are.
// Blending straight values as if they were premultiplied (what the filter did before the
// option) darkens the edge to half grey over white: the test shows that too. Grey + alpha and
// RGBA, 8-bit, 16-bit and float.
#include "vtkAntialiasingTestUtilities.h"

#include <string>

using namespace vtkMLAATest;

namespace
{
const int Size = 64;
const double Grey = 0.6; // the disc's colour

bool Inside(double x, double y)
{
  return (x - 32.2) * (x - 32.2) + (y - 31.7) * (y - 31.7) < 20.3 * 20.3;
}

// Coverage of pixel (x, y) by the disc, from 16 x 16 samples.
double Coverage(int x, int y)
{
  int n = 0;
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      n += Inside(x + (i + 0.5) / 16.0, y + (j + 0.5) / 16.0) ? 1 : 0;
    }
  }
  return n / 256.0;
}

// Mean squared error, over the pixels near the disc's outline, of the image composited over a
// background of grey level `background` (0..1) against the supersampled disc composited the
// same way. `premultiplied` says how to read the image's colour.
double CompositeError(vtkImageData* image, double full, double background, bool premultiplied)
{
  const int c = image->GetNumberOfScalarComponents();
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const double coverage = Coverage(x, y);
      const bool nearEdge = std::abs(std::hypot(x + 0.5 - 32.2, y + 0.5 - 31.7) - 20.3) < 2.0;
      if (!nearEdge)
      {
        continue;
      }
      const double alpha = GetValue(image, x, y, c - 1) / full;
      const double colour = GetValue(image, x, y, 0) / full;
      const double composited =
        premultiplied ? colour + (1.0 - alpha) * background : alpha * colour + (1.0 - alpha) * background;
      const double reference = coverage * Grey + (1.0 - coverage) * background;
      sum += (composited - reference) * (composited - reference);
      ++count;
    }
  }
  return sum / count;
}

void Disc(int type, int components)
{
  const double full = type == VTK_UNSIGNED_CHAR ? 255.0 : (type == VTK_UNSIGNED_SHORT ? 65535.0 : 1.0);
  auto image = MakeImage(Size, Size, components, type);
  const bool real = type == VTK_FLOAT;
  const double grey = real ? Grey : std::round(Grey * full);
  FillImage(image, [&](int x, int y, int, int k) {
    return Inside(x + 0.5, y + 0.5) ? (k == components - 1 ? full : grey) : 0.0;
  });
  const std::string what = std::string(vtkImageScalarTypeNameMacro(type)) + " x " +
    std::to_string(components);

  vtkNew<vtkMLAAOptions> straightOptions;
  MLAA_CHECK(!straightOptions->GetPremultipliedAlpha()); // the default
  auto straight = RunMLAA(image, straightOptions);
  vtkNew<vtkMLAAOptions> premultipliedOptions;
  premultipliedOptions->PremultipliedAlphaOn();
  auto premultiplied = RunMLAA(image, premultipliedOptions);

  // Straight: wherever anything is covered, the colour is the disc's (to the last bit, or within
  // float rounding); alpha carries the edge.
  int partial = 0;
  bool fringe = false;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const double alpha = GetValue(straight, x, y, components - 1);
      if (alpha > 0.0 && alpha < full)
      {
        ++partial;
      }
      for (int k = 0; k + 1 < components; ++k)
      {
        fringe = fringe || (alpha > 0.0 && std::abs(GetValue(straight, x, y, k) - grey) > 1e-5);
      }
    }
  }
  MLAA_CHECK(partial > 40); // the outline was antialiased
  if (!MLAA_CHECK(!fringe))
  {
    std::cerr << what << ": straight alpha gave a fringe" << std::endl;
  }

  // Both conventions, each read as what it is, composite like the supersampled disc over white
  // and over black: at least halving the error of the aliased disc.
  for (double background : { 0.0, 1.0 })
  {
    const double none = CompositeError(image, full, background, false);
    const double s = CompositeError(straight, full, background, false);
    const double p = CompositeError(premultiplied, full, background, true);
    if (!MLAA_CHECK(s < 0.5 * none && p < 0.5 * none))
    {
      std::cerr << what << " over " << background << ": error of the aliased disc " << none
                << ", straight " << s << ", premultiplied " << p << std::endl;
    }
  }
  // Premultiplied blending of straight data, read as straight (the old behaviour), darkens
  // the edge over white: its error there is far above the straight result's.
  const double wrong = CompositeError(premultiplied, full, 1.0, false);
  const double right = CompositeError(straight, full, 1.0, false);
  std::cout << what << " over white: premultiplied blending read as straight " << wrong
            << ", straight " << right << std::endl;
  MLAA_CHECK(wrong > 2.0 * right);
}
}

int TestImageMLAAStraightAlpha(int, char*[])
{
  for (int type : { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT, VTK_FLOAT })
  {
    for (int components : { 2, 4 })
    {
      Disc(type, components);
    }
  }
  return Result();
}
