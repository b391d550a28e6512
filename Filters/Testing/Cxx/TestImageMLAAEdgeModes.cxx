// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// What counts as an edge: luma (default) misses colours of equal luminance that colour edges
// find; depth edges follow a depth image instead of the colours; alpha edges give a silhouette
// over a transparent background a soft alpha border; the threshold decides how faint an edge may
// be; zero threshold means any difference; local contrast adaptation drops faint edges next to
// strong ones only, and edges inside ramps of shading. Lab edges (Biri et al. section 3.2) find
// red against blue of equal luma, which luma edges miss; the conversion gives reference CIELAB
// values; the contrast is Delta E / 100 (an edge appears just below a reference Delta E and not
// just above it, with and without alpha).
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMLAALab.h"

#include <algorithm>

using namespace vtkMLAATest;

namespace
{
// A shallow staircase: inside(x, y) for the region below it.
bool Inside(int x, int y)
{
  return y < 4 + x / 4;
}

int ChangedPixels(vtkImageData* a, vtkImageData* b)
{
  return static_cast<int>(Compare(a, b).Pixels);
}

void LumaAndColor()
{
  // Pure red over a green of (almost) the same luma: 0.2126 vs 0.7152 * 76 / 255 = 0.2132.
  auto input = MakeImage(24, 16, 3);
  FillImage(input, [](int x, int y, int, int k) {
    return Inside(x, y) ? (k == 0 ? 255.0 : 0.0) : (k == 1 ? 76.0 : 0.0);
  });
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input, MediumOptions())) == 0);
  vtkNew<vtkMLAAOptions> color;
  color->SetPresetToMedium(); // the settings the expected values assume
  color->SetEdgeDetectionToColor();
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input, color)) > 10);
}

void Depth()
{
  // The colours have the staircase everywhere; the depth image has it only in the left half.
  // Depth edges blend the left half only; luma edges blend both.
  auto input = MakeImage(48, 16, 3);
  FillImage(input, [](int x, int y, int, int) { return Inside(x % 24, y) ? 230.0 : 20.0; });
  auto depth = MakeImage(48, 16, 1, VTK_FLOAT);
  FillImage(depth, [](int x, int y, int, int) { return (x < 24 && Inside(x, y)) ? 0.3 : 0.6; });
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->SetEdgeDetectionToDepth();
  vtkNew<vtkImageMLAA> filter;
  filter->SetOptions(options);
  filter->SetInputData(input);
  filter->SetDepthInputData(depth);
  filter->Update();
  vtkImageData* out = filter->GetOutput();
  int left = 0, right = 0;
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 48; ++x)
    {
      const bool changed = GetValue(out, x, y) != GetValue(input, x, y);
      (x < 24 ? left : right) += changed ? 1 : 0;
    }
  }
  MLAA_CHECK(left > 5);
  MLAA_CHECK(right == 0);
  // With luma edges the right half is blended too.
  auto luma = RunMLAA(input, MediumOptions());
  int lumaRight = 0;
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 24; x < 48; ++x)
    {
      lumaRight += GetValue(luma, x, y) != GetValue(input, x, y) ? 1 : 0;
    }
  }
  MLAA_CHECK(lumaRight > 5);
  // The depth edges give the same weights as the same staircase in luma.
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 20; ++x)
    {
      MLAA_CHECK(GetValue(out, x, y) == GetValue(luma, x, y));
    }
  }
  // 16-bit depth is normalised by its type range.
  auto depth16 = MakeImage(48, 16, 1, VTK_UNSIGNED_SHORT);
  FillImage(depth16, [&](int x, int y, int, int) { return std::round(GetValue(depth, x, y) * 65535.0); });
  filter->SetDepthInputData(depth16);
  filter->Update();
  MLAA_CHECK(Compare(out, filter->GetOutput()).Count == 0);
}

void Alpha()
{
  // One colour everywhere; a disc is opaque, the rest transparent. Only alpha has edges: the
  // colour stays as it is, alpha gets intermediate values along the disc's border.
  for (int components : { 2, 4 })
  {
    auto input = MakeImage(40, 40, components);
    FillImage(input, [&](int x, int y, int, int k) {
      if (k == components - 1)
      {
        return (x - 20.3) * (x - 20.3) + (y - 19.6) * (y - 19.6) < 13.0 * 13.0 ? 255.0 : 0.0;
      }
      return 200.0 - 50.0 * k;
    });
    auto output = RunMLAA(input, MediumOptions());
    int softAlpha = 0;
    bool colourKept = true;
    bool farKept = true;
    for (int y = 0; y < 40; ++y)
    {
      for (int x = 0; x < 40; ++x)
      {
        const double a = GetValue(output, x, y, components - 1);
        softAlpha += (a > 0.0 && a < 255.0) ? 1 : 0;
        for (int k = 0; k < components - 1; ++k)
        {
          colourKept = colourKept && GetValue(output, x, y, k) == GetValue(input, x, y, k);
        }
        const double r = std::sqrt((x - 20.3) * (x - 20.3) + (y - 19.6) * (y - 19.6));
        if (std::abs(r - 13.0) > 3.0)
        {
          farKept = farKept && a == GetValue(input, x, y, components - 1);
        }
      }
    }
    MLAA_CHECK(softAlpha > 20);
    MLAA_CHECK(colourKept);
    MLAA_CHECK(farKept);
  }
}

void Threshold()
{
  // A faint staircase (difference 20/255 ~ 0.078): below the default threshold of 0.1, above
  // 0.05. Threshold 0 finds every difference; threshold 1 only differences of full scale.
  auto faint = MakeImage(24, 16, 1);
  FillImage(faint, [](int x, int y, int, int) { return Inside(x, y) ? 120.0 : 100.0; });
  MLAA_CHECK(ChangedPixels(faint, RunMLAA(faint, MediumOptions())) == 0);
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->SetThreshold(0.05);
  MLAA_CHECK(ChangedPixels(faint, RunMLAA(faint, options)) > 5);
  options->SetThreshold(0.0);
  MLAA_CHECK(ChangedPixels(faint, RunMLAA(faint, options)) > 5);
  // Zero threshold on a flat image changes nothing (no difference, no edge).
  auto flat = MakeImage(24, 16, 3, VTK_UNSIGNED_CHAR, 77.0);
  MLAA_CHECK(ChangedPixels(flat, RunMLAA(flat, options)) == 0);
  options->SetThreshold(1.0);
  MLAA_CHECK(ChangedPixels(faint, RunMLAA(faint, options)) == 0);
  auto full = MakeImage(24, 16, 1);
  FillImage(full, [](int x, int y, int, int) { return Inside(x, y) ? 255.0 : 0.0; });
  MLAA_CHECK(ChangedPixels(full, RunMLAA(full, options)) > 5);
}

void LocalContrast()
{
  // A straight vertical silhouette, white (x < 6) against a dark region in which shading steps
  // from 0 to 40 (0.157, above the threshold) between rows 4 and 5. The shading edge is a line
  // of top edgels on row 4 from x = 6 to the right border.
  auto input = MakeImage(16, 12, 1);
  FillImage(input, [](int x, int y, int, int) { return x < 6 ? 255.0 : (y < 5 ? 0.0 : 40.0); });
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->SetDebugOutputToEdges();
  for (double factor : { 0.0, 2.0, 6.0, 7.0 })
  {
    options->SetLocalContrastFactor(factor);
    auto edges = RunMLAA(input, options);
    for (int y = 0; y < 12; ++y)
    {
      for (int x = 0; x < 16; ++x)
      {
        // The silhouette's edgels are always kept (the strongest around). The shading edgel of
        // (6, 4) shares pixel (6, 4) with the silhouette's edgel of contrast 1 (255/255) and
        // that of (6, 5) of contrast 215/255: kept when factor * 40 >= 255, so with factors 0
        // (off) and 7, not with 2 or 6. The rest of the shading line has no stronger
        // neighbour and is kept.
        const bool left = x == 6;
        const bool top = y == 4 && x >= 6 && (x > 6 || factor == 0.0 || factor * 40.0 >= 255.0);
        MLAA_CHECK(GetValue(edges, x, y, 0) == (left ? 255.0 : 0.0));
        MLAA_CHECK(GetValue(edges, x, y, 1) == (top ? 255.0 : 0.0));
      }
    }
  }

  // Without adaptation the shading edgel is a crossing edge that cuts the silhouette in two at
  // row 4/5. The silhouette goes on straight past it and the shading edge goes on along the row:
  // a T junction, which is no step (issue 20), so nothing is blended with or without adaptation.
  vtkNew<vtkMLAAOptions> off;
  off->SetPresetToMedium(); // the settings the expected values assume
  off->SetLocalContrastFactor(0.0);
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input, off)) == 0);
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input, MediumOptions())) == 0);
  // Where only the silhouette's rim pixels are shaded (x = 6, y >= 5), the shading edgel is one
  // pixel long: a crossing edge that may be a step, read as the chapter does. Without adaptation
  // it cuts the silhouette in two, and each half ends in an L whose pixels are blended; with the
  // default factor the faint edgel is dropped, the silhouette is one straight line with no
  // crossing edge, and nothing is blended.
  auto rim = MakeImage(16, 12, 1);
  FillImage(rim, [](int x, int y, int, int) { return x < 6 ? 255.0 : (x == 6 && y >= 5 ? 40.0 : 0.0); });
  MLAA_CHECK(ChangedPixels(rim, RunMLAA(rim, off)) > 0);
  MLAA_CHECK(ChangedPixels(rim, RunMLAA(rim, MediumOptions())) == 0);
}

// A grey ramp is no edge (issue 20): a shape whose columns rise in grey from 30 to 230, 20 levels
// a column, under a staircase top (Inside), on black. Its columns' boundaries are above the
// threshold, and without local contrast adaptation they are lines of edgels that the top's steps
// cut, blended like any staircase. With it, the boundaries inside the ramp (each between two that
// change the grey the same way, by at least half as much) are dropped: the edgels at the ramp's
// ends and the top's stay, and no pixel of the ramp under the top's reach changes. The direction
// counts: with colour edges, red rising then green rising is no ramp (their changes are
// orthogonal), grey rising is one.
void Ramps()
{
  // The shape: the utilities' ramp (columns 8 to 18 under a staircase top, greys 30 to 230).
  auto input = MakeImage(32, 16, 3);
  FillImage(input, [](int x, int y, int, int) {
    return x >= RampFirst && x <= RampLast && y <= RampTop(x) ? RampGrey(x) : 0.0;
  });
  vtkNew<vtkMLAAOptions> options;
  options->SetEdgeDetectionToLuma();
  options->SetThreshold(0.05); // a column's 20 levels are 0.078
  const auto edges = EdgesWithAndWithoutAdaptation(input, options);
  for (int y = 0; y < 10; ++y)
  {
    for (int x = 0; x < 32; ++x)
    {
      // Every column boundary of the shape is an edge without adaptation. With it, the one
      // between black and 30 (the rise before it is 0) and the one from 230 down to black (the
      // strongest around) stay; the others lie inside the ramp (the last, from 210 to 230, is
      // also dropped for its contrast next to the drop to black).
      const bool boundary = x >= RampFirst && x <= RampLast + 1;
      const bool end = x == RampFirst || x == RampLast + 1;
      MLAA_CHECK(GetValue(edges[0], x, y, 0) == (end ? 255.0 : 0.0));
      MLAA_CHECK(GetValue(edges[1], x, y, 0) == (boundary ? 255.0 : 0.0));
    }
  }

  // Colour edges: along rows 0 to 3, black, red, red + green, red + green + blue (0.4 each):
  // each change is orthogonal to the one before, so every boundary is an edge. Along rows 4 to
  // 7, greys rising by 60 levels (0.235) a column: a ramp, which keeps its two ends only.
  auto colors = MakeImage(8, 8, 3);
  FillImage(colors, [](int x, int y, int, int c) {
    const int step = std::min(std::max(x - 2, 0), 3); // 0 0 0 1 2 3 3 3
    return y < 4 ? (step > c ? 102.0 : 0.0) : 60.0 * step;
  });
  vtkNew<vtkMLAAOptions> color;
  color->SetEdgeDetectionToColor();
  color->SetDebugOutputToEdges();
  auto colorEdges = RunMLAA(colors, color);
  for (int x = 0; x < 8; ++x)
  {
    MLAA_CHECK(GetValue(colorEdges, x, 1, 0) == (x >= 3 && x <= 5 ? 255.0 : 0.0));
    MLAA_CHECK(GetValue(colorEdges, x, 6, 0) == (x == 3 || x == 5 ? 255.0 : 0.0));
  }
}

// Reference CIELAB (L, a, b) of an sRGB colour in [0, 1], in double precision with std::cbrt.
void ReferenceLab(const double rgb[3], double lab[3])
{
  double lin[3];
  for (int k = 0; k < 3; ++k)
  {
    const double c = std::max(rgb[k], 0.0);
    lin[k] = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
  }
  const double xyz[3] = {
    (0.4124564 * lin[0] + 0.3575761 * lin[1] + 0.1804375 * lin[2]) / 0.95047,
    0.2126729 * lin[0] + 0.7151522 * lin[1] + 0.0721750 * lin[2],
    (0.0193339 * lin[0] + 0.1191920 * lin[1] + 0.9503041 * lin[2]) / 1.08883
  };
  double f[3];
  const double d = 6.0 / 29.0;
  for (int k = 0; k < 3; ++k)
  {
    f[k] = xyz[k] > d * d * d ? std::cbrt(xyz[k]) : xyz[k] / (3.0 * d * d) + 4.0 / 29.0;
  }
  lab[0] = 116.0 * f[1] - 16.0;
  lab[1] = 500.0 * (f[0] - f[1]);
  lab[2] = 200.0 * (f[1] - f[2]);
}

double ReferenceDeltaE(const double p[3], const double q[3])
{
  double a[3], b[3];
  ReferenceLab(p, a);
  ReferenceLab(q, b);
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]));
}

void Lab()
{
  // The conversion: sRGB red and blue against published L*a*b* values, and the stage's fast
  // cube root against std::cbrt.
  struct Known
  {
    double Rgb[3];
    double Lab[3];
  };
  for (const Known& known : { Known{ { 1, 0, 0 }, { 53.24, 80.09, 67.20 } },
         Known{ { 0, 0, 1 }, { 32.30, 79.19, -107.86 } },
         Known{ { 1, 1, 1 }, { 100.0, 0.0, 0.0 } } })
  {
    for (int precision = 0; precision < 2; ++precision)
    {
      double lab[3];
      if (precision == 0)
      {
        float l, a, b;
        vtkAntialiasingKit::Lab::FromLinear(vtkAntialiasingKit::Lab::Linearise(float(known.Rgb[0])),
          vtkAntialiasingKit::Lab::Linearise(float(known.Rgb[1])),
          vtkAntialiasingKit::Lab::Linearise(float(known.Rgb[2])), l, a, b);
        lab[0] = l;
        lab[1] = a;
        lab[2] = b;
      }
      else
      {
        vtkAntialiasingKit::Lab::FromLinear(vtkAntialiasingKit::Lab::Linearise(known.Rgb[0]),
          vtkAntialiasingKit::Lab::Linearise(known.Rgb[1]), vtkAntialiasingKit::Lab::Linearise(known.Rgb[2]),
          lab[0], lab[1], lab[2]);
      }
      for (int k = 0; k < 3; ++k)
      {
        if (!MLAA_CHECK(std::abs(100.0 * lab[k] - known.Lab[k]) <= 0.05))
        {
          std::cerr << "Lab component " << k << ": " << 100.0 * lab[k] << " instead of "
                    << known.Lab[k] << std::endl;
        }
      }
    }
  }
  double worstFloat = 0.0, worstDouble = 0.0;
  for (double x = 0.008; x <= 1.2; x *= 1.01)
  {
    const double exact = std::cbrt(x);
    worstFloat = std::max(worstFloat,
      std::abs(vtkAntialiasingKit::Lab::FastCbrt(static_cast<float>(x)) - exact) / exact);
    worstDouble = std::max(worstDouble, std::abs(vtkAntialiasingKit::Lab::FastCbrt(x) - exact) / exact);
  }
  MLAA_CHECK(worstFloat < 1e-6);
  MLAA_CHECK(worstDouble < 1e-12);

  // Red against blue of (nearly) equal luma: 0.2126 * 87 / 255 = 0.0725 against 0.0722. Luma
  // finds no edge, Lab finds the vertical boundary (Delta E 176).
  auto redBlue = MakeImage(16, 8, 3);
  FillImage(redBlue, [](int x, int, int, int k) {
    return x < 8 ? (k == 0 ? 87.0 : 0.0) : (k == 2 ? 255.0 : 0.0);
  });
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->SetDebugOutputToEdges();
  auto lumaEdges = RunMLAA(redBlue, options);
  options->SetEdgeDetectionToLab();
  auto labEdges = RunMLAA(redBlue, options);
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      MLAA_CHECK(GetValue(lumaEdges, x, y, 0) == 0.0 && GetValue(lumaEdges, x, y, 1) == 0.0);
      MLAA_CHECK(GetValue(labEdges, x, y, 0) == (x == 8 ? 255.0 : 0.0));
      MLAA_CHECK(GetValue(labEdges, x, y, 1) == 0.0);
    }
  }

  // The contrast is the reference Delta E / 100: an edge at a threshold just below it, none
  // just above, for a few colour pairs, in 8-bit and float images, with and without alpha
  // (whose difference here is below both thresholds).
  const double pairs[][2][3] = { { { 200, 30, 40 }, { 120, 110, 150 } },
    { { 128, 128, 128 }, { 100, 100, 100 } }, { { 10, 200, 30 }, { 20, 190, 60 } },
    { { 250, 250, 240 }, { 255, 255, 255 } } };
  for (const auto& pair : pairs)
  {
    double p[3], q[3];
    for (int k = 0; k < 3; ++k)
    {
      p[k] = pair[0][k] / 255.0;
      q[k] = pair[1][k] / 255.0;
    }
    const double contrast = ReferenceDeltaE(p, q) / 100.0;
    MLAA_CHECK(contrast > 0.01 && contrast < 0.99); // thresholds lie in [0, 1]
    for (int type : { VTK_UNSIGNED_CHAR, VTK_FLOAT })
    {
      for (int components : { 3, 4 })
      {
        auto image = MakeImage(8, 4, components, type);
        FillImage(image, [&](int x, int, int, int k) {
          const double v = k == 3 ? (x < 4 ? 255.0 : 254.0) : pair[x < 4 ? 0 : 1][k];
          return type == VTK_FLOAT ? v / 255.0 : v;
        });
        for (double offset : { -1e-4, 1e-4 })
        {
          options->SetThreshold(contrast + offset);
          auto edges = RunMLAA(image, options);
          const bool edge = GetValue(edges, 4, 1, 0) == 255.0;
          if (!MLAA_CHECK(edge == (offset < 0.0)))
          {
            std::cerr << "Delta E " << 100.0 * contrast << ": threshold " << contrast + offset
                      << (edge ? " finds an edge" : " finds no edge") << std::endl;
          }
        }
      }
    }
  }
  options->SetThreshold(0.1);

  // Grey images are grey sRGB: the same edges as the RGB image with R = G = B.
  auto grey = MakeImage(24, 16, 1);
  FillImage(grey, [](int x, int y, int, int) { return Inside(x, y) ? 180.0 : 90.0; });
  auto greyRgb = MakeImage(24, 16, 3);
  FillImage(greyRgb, [](int x, int y, int, int) { return Inside(x, y) ? 180.0 : 90.0; });
  options->SetDebugOutputToNone();
  auto greyOut = RunMLAA(grey, options);
  auto greyRgbOut = RunMLAA(greyRgb, options);
  bool same = true;
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 24; ++x)
    {
      same = same && GetValue(greyOut, x, y) == GetValue(greyRgbOut, x, y, 1);
    }
  }
  MLAA_CHECK(same);
  MLAA_CHECK(ChangedPixels(grey, greyOut) > 5);
}
}

int TestImageMLAAEdgeModes(int, char*[])
{
  LumaAndColor();
  Depth();
  Alpha();
  Threshold();
  LocalContrast();
  Ramps();
  Lab();
  return Result();
}
