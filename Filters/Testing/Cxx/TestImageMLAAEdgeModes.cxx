// What counts as an edge: luma (default) misses colours of equal luminance that colour edges
// find; depth edges follow a depth image instead of the colours; alpha edges give a silhouette
// over a transparent background a soft alpha border; the threshold decides how faint an edge may
// be; zero threshold means any difference; local contrast adaptation drops faint edges next to
// strong ones only.
#include "vtkMLAATestUtilities.h"

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
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input)) == 0);
  vtkNew<vtkMLAAOptions> color;
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
  auto luma = RunMLAA(input);
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
    auto output = RunMLAA(input);
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
  MLAA_CHECK(ChangedPixels(faint, RunMLAA(faint)) == 0);
  vtkNew<vtkMLAAOptions> options;
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
  // row 4/5, and each half ends in an L whose pixels are blended. With the default factor the
  // silhouette is one straight line with no crossing edge, so nothing is blended, and the
  // shading line, which starts with no crossing edge either, is left alone too.
  vtkNew<vtkMLAAOptions> off;
  off->SetLocalContrastFactor(0.0);
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input, off)) > 0);
  MLAA_CHECK(ChangedPixels(input, RunMLAA(input)) == 0);
}
}

int TestImageMLAAEdgeModes(int, char*[])
{
  LumaAndColor();
  Depth();
  Alpha();
  Threshold();
  LocalContrast();
  return Result();
}
