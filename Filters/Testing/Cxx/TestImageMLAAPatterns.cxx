// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Exact expected pixels of vtkImageMLAA on small synthetic images: a straight step edge, the
// L, U and Z patterns of the GPU Pro 2 chapter, a rectangle's corner (left alone, issue 50), thin lines alone and side by side, T junctions
// that a line goes on past (no step) and a rim's one-pixel crossing edge (a step), a line
// longer than the search distance,
// one-pixel-wide images, and a diagonal staircase (DiagonalDetection), whose effect on the error
// against exact coverage is measured too. The expected blending weights were worked out by hand from sections
// 4.3.1-4.3.3 (search, crossing edges, areas); see the comments at each case.
#include "vtkAntialiasingTestUtilities.h"

#include <vector>

using namespace vtkMLAATest;

namespace
{
const double White = 255.0;

// Round a weight to the 8 bits it is stored with, as 0..255.
int Q(double area)
{
  return static_cast<int>(std::lround(255.0 * area));
}

// Area of an L shape for the p-th pixel from its crossing edge on a line of `length` pixels.
double LArea(int p, int length)
{
  if (2 * p + 2 <= length)
  {
    return 0.5 * (1.0 - (2.0 * p + 1.0) / length);
  }
  return (2 * p + 1 == length) ? 1.0 / (8.0 * length) : 0.0;
}

vtkSmartPointer<vtkImageData> Grey(int w, int h, const std::function<bool(int, int)>& white)
{
  auto image = MakeImage(w, h, 1);
  FillImage(image, [&](int x, int y, int, int) { return white(x, y) ? White : 0.0; });
  return image;
}

vtkSmartPointer<vtkImageData> Weights(
  vtkImageData* input, int searchSteps = 8, bool diagonals = true)
{
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->SetDebugOutputToBlendingWeights();
  options->SetMaxSearchSteps(searchSteps);
  options->SetDiagonalDetection(diagonals);
  return RunMLAA(input, options);
}

// The output with the chapter's blending (DominantDirectionBlending off): every neighbour's
// blend averaged.
vtkSmartPointer<vtkImageData> ChapterBlending(vtkImageData* input)
{
  vtkNew<vtkMLAAOptions> options;
  options->SetPresetToMedium(); // the settings the expected values assume
  options->DominantDirectionBlendingOff();
  return RunMLAA(input, options);
}

// Every pixel other than the listed ones is unchanged.
bool OthersUnchanged(vtkImageData* in, vtkImageData* out, const std::vector<std::pair<int, int>>& changed)
{
  int dims[3];
  in->GetDimensions(dims);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      if (std::find(changed.begin(), changed.end(), std::make_pair(x, y)) != changed.end())
      {
        continue;
      }
      if (GetValue(in, x, y) != GetValue(out, x, y))
      {
        std::cerr << "pixel (" << x << ", " << y << ") changed from " << GetValue(in, x, y)
                  << " to " << GetValue(out, x, y) << std::endl;
        return false;
      }
    }
  }
  return true;
}

void StraightEdges()
{
  // A vertical and a horizontal edge across the whole image: no crossing edges, no pattern,
  // nothing to blend (MLAA never blurs straight edges).
  for (auto white : { std::function<bool(int, int)>([](int x, int) { return x >= 5; }),
         std::function<bool(int, int)>([](int, int y) { return y >= 3; }) })
  {
    auto in = Grey(11, 7, white);
    auto out = RunMLAA(in, MediumOptions());
    MLAA_CHECK(Compare(in, out).Count == 0);
  }
}

void LShape()
{
  // The L pattern: a line with a one-pixel step at one end and nothing at the other. A white
  // region in a 16 x 8 black image: rows 5 to 7 whole, and row 4 from x = 6 on, so that its
  // lower outline steps down by one pixel at x = 6. The line of top edgels on row 3 runs from
  // x = 6 into the right border (distance clamped to 16) and starts at the step's crossing edge,
  // on the white side (code 1 seen from row 3): pixel (6 + p, 4) is p from the crossing edge on a
  // line of p + 17, so it takes the black below it with the L area 1/2 (1 - (2p + 1)/(p + 17)).
  // The line of top edgels on row 4, from the left border to x = 5, ends at the same crossing
  // edge, on its own (black) side (code 3): pixel (5 - p, 4) takes the white above it with the
  // same areas. The crossing edge itself is a vertical line of one pixel between two steps on
  // opposite sides (a Z of length 1, area 1/8 on each side), and (5, 4) and (6, 4) blend along
  // their horizontal lines only, whose weight 8/17 is the larger (dominant direction).
  auto in = Grey(16, 8, [](int x, int y) { return y >= 5 || (x >= 6 && y >= 4); });
  auto weights = Weights(in);
  MLAA_CHECK(GetValue(weights, 6, 3, 1) == Q(8.0 / 17.0)); // 120
  MLAA_CHECK(GetValue(weights, 6, 3, 0) == 0.0);
  MLAA_CHECK(GetValue(weights, 5, 4, 0) == Q(8.0 / 17.0));
  MLAA_CHECK(GetValue(weights, 5, 4, 1) == 0.0);
  MLAA_CHECK(GetValue(weights, 6, 4, 2) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 6, 4, 3) == Q(1.0 / 8.0));

  auto out = RunMLAA(in, MediumOptions());
  std::vector<std::pair<int, int>> changed;
  for (int p = 0; p <= 9; ++p)
  {
    MLAA_CHECK(GetValue(weights, 6 + p, 3, 1) == Q(LArea(p, p + 17)));
    MLAA_CHECK(GetValue(out, 6 + p, 4) == White - Q(LArea(p, p + 17)));
    changed.emplace_back(6 + p, 4);
  }
  for (int p = 0; p <= 5; ++p)
  {
    MLAA_CHECK(GetValue(weights, 5 - p, 4, 0) == Q(LArea(p, p + 17)));
    MLAA_CHECK(GetValue(out, 5 - p, 4) == Q(LArea(p, p + 17)));
    changed.emplace_back(5 - p, 4);
  }
  MLAA_CHECK(OthersUnchanged(in, out, changed));
}

void RectangleCorner()
{
  // The corner of a white rectangle (x >= 6, y >= 4) in a 16 x 8 black image, its sides on pixel
  // boundaries. The chapter reads its bottom side as an L (the crossing edge at x = 6 as a step,
  // the right border as nothing) and ramps it, but the crossing edge is the rectangle's left
  // side, which goes on for more than one pixel: a corner, not a step, and nothing seen tells
  // that the sides leave the pixel boundaries (issue 50). Nothing changes, at every preset and
  // search length, with and without corner extrapolation.
  auto in = Grey(16, 8, [](int x, int y) { return x >= 6 && y >= 4; });
  for (int steps : { 1, 2, 4, 8, 16, 32, 64, 128 })
  {
    for (bool corners : { false, true })
    {
      auto options = MediumOptions();
      options->SetMaxSearchSteps(steps);
      options->SetCornerExtrapolation(corners);
      MLAA_CHECK(Compare(in, RunMLAA(in, options)).Count == 0);
    }
  }
}

void UShape()
{
  // A white bar of 4 x 1 pixels (x = 4..7, y = 2) on black. Above and below it, lines of
  // 4 edgels end in crossing edges on the bar's side at both ends: U shapes. Areas 3/8 at the
  // ends, 1/8 inside (L = 4). The bar's left and right edgels are lines of 1 with crossing
  // edges on the bar's side at both ends: area 1/4. Only the bar darkens.
  auto in = Grey(12, 6, [](int x, int y) { return y == 2 && x >= 4 && x <= 7; });
  auto weights = Weights(in);
  // Lower line (top edgels of row 1): the bar is the opposite side (green).
  MLAA_CHECK(GetValue(weights, 4, 1, 1) == Q(3.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 5, 1, 1) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 6, 1, 1) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 7, 1, 1) == Q(3.0 / 8.0));
  // Upper line (top edgels of row 2): the bar owns them (red).
  MLAA_CHECK(GetValue(weights, 4, 2, 0) == Q(3.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 5, 2, 0) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 7, 2, 0) == Q(3.0 / 8.0));
  // Left side: owned by the bar (blue); right side: owned by the black pixel (8, 2), so the
  // bar's pixel (7, 2) gets the opposite weight (alpha).
  MLAA_CHECK(GetValue(weights, 4, 2, 2) == Q(1.0 / 4.0));
  MLAA_CHECK(GetValue(weights, 8, 2, 3) == Q(1.0 / 4.0));
  MLAA_CHECK(GetValue(weights, 8, 2, 2) == 0.0);

  auto out = RunMLAA(in, MediumOptions());
  // End pixels: weights 96, 96 (above, below) and 64 (side). The vertical line dominates, so
  // only it blends: 255 (1 - 96/255) = 159. The chapter's blending averages all three:
  // c' = 255 sum a(1 - a) / sum a, which is 42752 / 256 = 167 exactly.
  MLAA_CHECK(GetValue(out, 4, 2) == 159.0);
  MLAA_CHECK(GetValue(out, 7, 2) == 159.0);
  auto chapter = ChapterBlending(in);
  MLAA_CHECK(GetValue(chapter, 4, 2) == 167.0);
  MLAA_CHECK(GetValue(chapter, 7, 2) == 167.0);
  MLAA_CHECK(GetValue(chapter, 5, 2) == 223.0);
  // Inner pixels: 32 above and below: 255 - 32.
  MLAA_CHECK(GetValue(out, 5, 2) == 223.0);
  MLAA_CHECK(GetValue(out, 6, 2) == 223.0);
  MLAA_CHECK(OthersUnchanged(in, out, { { 4, 2 }, { 5, 2 }, { 6, 2 }, { 7, 2 } }));
}

void ZShape()
{
  // A staircase: white below height h(x) = 2, 3, 4 for x < 4, 4 <= x < 8, x >= 8. The middle
  // step (top edgels of row 2, x = 4..7) has a crossing edge on its own (white, lower) side at
  // the left end and on the opposite side at the right end: a Z. Its pixels get 3/8, 1/8 on the
  // white side and 1/8, 3/8 on the black side. The one-pixel risers are Z shapes of length 1:
  // 1/8 on each side.
  auto in = Grey(12, 6, [](int x, int y) { return y < (x < 4 ? 2 : (x < 8 ? 3 : 4)); });
  auto weights = Weights(in);
  MLAA_CHECK(GetValue(weights, 4, 2, 0) == Q(3.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 5, 2, 0) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 6, 2, 0) == 0.0);
  MLAA_CHECK(GetValue(weights, 6, 2, 1) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 7, 2, 1) == Q(3.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 4, 2, 2) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 4, 2, 3) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 8, 3, 2) == Q(1.0 / 8.0));
  MLAA_CHECK(GetValue(weights, 8, 3, 3) == Q(1.0 / 8.0));
  // The outer steps run into the border: L shapes of 17 + p pixels.
  MLAA_CHECK(GetValue(weights, 3, 1, 1) == Q(LArea(0, 17)));
  MLAA_CHECK(GetValue(weights, 2, 1, 1) == Q(LArea(1, 18)));
  MLAA_CHECK(GetValue(weights, 8, 3, 0) == Q(LArea(0, 17)));
  MLAA_CHECK(GetValue(weights, 9, 3, 0) == Q(LArea(1, 18)));

  auto out = RunMLAA(in, MediumOptions());
  // (3, 2) is black: it takes white from below (120/255) and from the right (32/255). The
  // vertical weight dominates: 120. The chapter's blending averages both:
  // 255 (a1^2 + a2^2) / (a1 + a2) = (120^2 + 32^2) / 152 = 101.47.
  MLAA_CHECK(GetValue(out, 3, 2) == 120.0);
  MLAA_CHECK(GetValue(ChapterBlending(in), 3, 2) == 101.0);
  // (5, 2) is white and takes black from above only: 255 - 32.
  MLAA_CHECK(GetValue(out, 5, 2) == 223.0);
  // (6, 3) is black and takes white from below only: 32.
  MLAA_CHECK(GetValue(out, 6, 3) == 32.0);
}

void ThinLine()
{
  // A one-pixel-wide black line rising one row every 4 pixels: pixel (x, 2 + x / 4). Run B is
  // (4..7, 3). Its top outline (top edgels of row 3, owned by the line) starts with a crossing
  // edge on the line's side at x = 4 and ends at x = 8 where the line steps up: crossing edgels
  // on both sides (code 4). The search stops there (x = 8 also has top edgels, those of the white
  // pixels under run C, but a crossing edge ends the line), and code 4 opposite a code 3 reads as
  // a Z: the line's pixels lose 3/8, 1/8 to the white above on the left half, and the white
  // pixels above the right half take 1/8, 3/8 of the line. The bottom outline (top edgels of row
  // 2, owned by the white pixels below) is the same Z seen from below, and the one-pixel risers
  // at x = 4 are Z shapes of length 1 (1/8 each side).
  auto in = Grey(24, 10, [](int x, int y) { return y != 2 + x / 4; });
  auto weights = Weights(in);
  const int q3 = Q(3.0 / 8.0), q1 = Q(1.0 / 8.0);
  // Top outline of run B.
  MLAA_CHECK(GetValue(weights, 4, 3, 0) == q3 && GetValue(weights, 4, 3, 1) == 0);
  MLAA_CHECK(GetValue(weights, 5, 3, 0) == q1 && GetValue(weights, 5, 3, 1) == 0);
  MLAA_CHECK(GetValue(weights, 6, 3, 0) == 0 && GetValue(weights, 6, 3, 1) == q1);
  MLAA_CHECK(GetValue(weights, 7, 3, 0) == 0 && GetValue(weights, 7, 3, 1) == q3);
  // Bottom outline of run B.
  MLAA_CHECK(GetValue(weights, 4, 2, 0) == q3 && GetValue(weights, 5, 2, 0) == q1);
  MLAA_CHECK(GetValue(weights, 6, 2, 1) == q1 && GetValue(weights, 7, 2, 1) == q3);
  // Risers.
  MLAA_CHECK(GetValue(weights, 4, 3, 2) == q1 && GetValue(weights, 4, 3, 3) == q1);
  MLAA_CHECK(GetValue(weights, 4, 2, 2) == q1 && GetValue(weights, 4, 2, 3) == q1);

  auto out = RunMLAA(in, MediumOptions());
  // A line pixel that loses 1/8 to the white above; a white pixel that takes 1/8 of the line
  // below it; a white pixel under the start of run B taking 3/8 from above and 1/8 from its
  // black left neighbour: the vertical weight dominates, 255 - 96 = 159; the chapter's blending
  // averages both, 255 (96 * 159 + 32 * 223) / 255^2 / (128 / 255) = 22400 / 128 = 175.
  MLAA_CHECK(GetValue(out, 5, 3) == q1);
  MLAA_CHECK(GetValue(out, 6, 4) == White - q1);
  MLAA_CHECK(GetValue(out, 4, 2) == 159.0);
  MLAA_CHECK(GetValue(ChapterBlending(in), 4, 2) == 175.0);
}

void ThinLinesSideBySide()
{
  // Two one-pixel-wide black lines rising one row every 4 pixels, two rows apart: (x, 2 + x / 4)
  // and (x, 4 + x / 4), with a one-pixel white gap between them. Over x = 4..7 the gap is row 4;
  // the outlines on either side of it (top edgels of rows 3 and 4) each end at x = 4 and x = 8
  // with crossing edgels on both sides (code 4 at both ends): one line steps on at one end, the
  // other line at the other, and the pixels cannot tell which. A pixel on either side is one
  // pixel thin across the edge (the gap, the line), so both take the U shape's area, 3/8, 1/8,
  // 1/8, 3/8 along the run, each of the other's colour (vtkMLAAAreaTexture, code 4 at both
  // ends).
  auto in = Grey(24, 12, [](int x, int y) { return y != 2 + x / 4 && y != 4 + x / 4; });
  auto weights = Weights(in);
  const int expected[4] = { Q(3.0 / 8.0), Q(1.0 / 8.0), Q(1.0 / 8.0), Q(3.0 / 8.0) };
  for (int x = 4; x <= 7; ++x)
  {
    for (int y : { 3, 4 })
    {
      MLAA_CHECK(GetValue(weights, x, y, 0) == expected[x - 4] &&
        GetValue(weights, x, y, 1) == expected[x - 4]);
    }
  }
  auto out = RunMLAA(in, MediumOptions());
  // The gap pixel at the run's end takes 3/8 of the black from above and from below alike (the
  // same weight both ways, whose blend is that weight's): 255 - 96.
  MLAA_CHECK(GetValue(out, 4, 4) == White - Q(3.0 / 8.0));

  // A checkerboard of 4 x 4 squares: every side lies between two corners where four squares
  // meet (code 4 at both ends), but no pixel is one pixel thin across it: no slope, nothing is
  // blended.
  auto board = Grey(16, 16, [](int x, int y) { return (x / 4 + y / 4) % 2 == 0; });
  MLAA_CHECK(Compare(board, RunMLAA(board, MediumOptions())).Count == 0);
}

void TJunctions()
{
  // The side of a plane on a pixel boundary (x < 10 the plane, x >= 10 black), with a band of the
  // plane's colour map meeting it from the inside (rows y >= 8 darker). The search stops at the
  // band's border, a crossing edge on one side of the side's line, but the side's own edge goes
  // on straight past it and the border goes on for more than one pixel: a T junction, not a step
  // (issue 20). The side's vertical lines take no weight on either side of the junction (the
  // area table read it as a step before, and ramped the side towards it).
  auto plane = MakeImage(16, 16, 1);
  FillImage(plane, [](int x, int y, int, int) { return x < 10 ? (y < 8 ? 240.0 : 120.0) : 0.0; });
  auto weights = Weights(plane);
  bool none = true;
  for (int y = 0; y < 16; ++y)
  {
    for (int k : { 2, 3 })
    {
      if (GetValue(weights, 10, y, k) != 0.0)
      {
        std::cerr << "side pixel (10, " << y << ") weight " << k << ": "
                  << GetValue(weights, 10, y, k) << ", expected 0" << std::endl;
        none = false;
      }
    }
  }
  MLAA_CHECK(none);

  // The same side where only its rim pixels change colour (x = 9, y >= 8): a crossing edge one
  // pixel long, which may be the step of a feature narrower than a pixel, keeps the chapter's
  // reading: the side is ramped towards it.
  auto rim = MakeImage(16, 16, 1);
  FillImage(rim, [](int x, int y, int, int) {
    return x < 10 ? (x == 9 && y >= 8 ? 120.0 : 240.0) : 0.0;
  });
  auto rimWeights = Weights(rim);
  double ramp = 0.0;
  for (int y = 0; y < 16; ++y)
  {
    ramp += GetValue(rimWeights, 10, y, 2) + GetValue(rimWeights, 10, y, 3);
  }
  MLAA_CHECK(ramp > 0.0);
}

void LongLine(int searchSteps)
{
  // A single step at x = 20 in a 64 x 4 image: the line of top edgels on row 0 (x < 20) ends
  // at x = 19 with a crossing edge on the opposite side. The search follows lines for at most
  // 2 * steps pixels each way, so pixel 19 - k sees its left end at 2 * steps (the line runs into
  // the border) and the crossing edge at k only while k <= 2 * steps: its area is the L area of
  // the k-th pixel of a line of 2 * steps + k + 1. Farther pixels cannot see the crossing edge
  // and are left alone.
  const int reach = 2 * searchSteps;
  auto in = Grey(64, 4, [](int x, int y) { return y <= (x < 20 ? 0 : 1); });
  auto weights = Weights(in, searchSteps);
  bool all = true;
  for (int k = 0; k < 20; ++k)
  {
    const int expected = k <= reach ? Q(LArea(k, reach + k + 1)) : 0;
    if (GetValue(weights, 19 - k, 0, 1) != expected || GetValue(weights, 19 - k, 0, 0) != 0.0)
    {
      std::cerr << "steps " << searchSteps << ", pixel " << 19 - k << ": weight "
                << GetValue(weights, 19 - k, 0, 1) << ", expected " << expected << std::endl;
      all = false;
    }
  }
  MLAA_CHECK(all);
}

void ThinImages()
{
  // 1 x 1, 1 x N and N x 1 images: any edgels form lines of one pixel running into the border
  // on both sides, so nothing is blended; the output equals the input.
  for (auto size : { std::make_pair(1, 1), std::make_pair(1, 9), std::make_pair(9, 1),
         std::make_pair(2, 1), std::make_pair(1, 2) })
  {
    auto in = MakeImage(size.first, size.second, 3);
    FillImage(in, [](int x, int y, int, int k) { return ((x * 7 + y * 13 + k * 5) % 4) * 80.0; });
    auto out = RunMLAA(in, MediumOptions());
    MLAA_CHECK(Compare(in, out).Count == 0);
    vtkNew<vtkMLAAOptions> options;
    options->SetPresetToMedium(); // the settings the expected values assume
    options->SetDebugOutputToEdges();
    auto edges = RunMLAA(in, options);
    int dims[3];
    edges->GetDimensions(dims);
    MLAA_CHECK(dims[0] == size.first && dims[1] == size.second);
  }
}
}

void DiagonalStaircase()
{
  // White below the height h(x) = 3 for x <= 4, x - 1 for x = 5..8, 7 for x >= 8, in a 16 x 12
  // image: a rising staircase of four units, the white corner pixels (5, 3), (6, 4), (7, 5),
  // (8, 6), each with a top and a left edgel. Past both ends the boundary runs along x (the top
  // edgels of (4, 2) and (9, 6)): the line is flatter than 45 degrees, out of the corner pixels
  // at the lower-left end (code 1) and into them at the upper-right end (code 2), a Z of four
  // units along the diagonal. Shift s(t) = -1/2 (1 - t/2) for t < 2, 1/2 (1 - (4 - t)/2) after;
  // unit k takes (1/2 + s(k + 1/2))^2 / 2 from above and from the left (1/128, 9/128, 25/128,
  // 49/128), the pixel above it gives (1/2 - s(k + 1))^2 / 2 (9/32, 1/8, 1/32, 0) and the one
  // left of it (1/2 - s(k))^2 / 2 (1/2, 9/32, 1/8, 1/32).
  auto in = Grey(16, 12, [](int x, int y) {
    const int h = x <= 4 ? 3 : (x >= 8 ? 7 : x - 1);
    return y < h;
  });
  auto w = Weights(in);
  const double in_[4] = { 1.0 / 128, 9.0 / 128, 25.0 / 128, 49.0 / 128 };
  const double above[4] = { 9.0 / 32, 1.0 / 8, 1.0 / 32, 0.0 };
  const double left[4] = { 0.5, 9.0 / 32, 1.0 / 8, 1.0 / 32 };
  for (int k = 0; k < 4; ++k)
  {
    const int x = 5 + k, y = 3 + k;
    MLAA_CHECK(GetValue(w, x, y, 0) == Q(in_[k]) && GetValue(w, x, y, 2) == Q(in_[k]));
    MLAA_CHECK(GetValue(w, x, y, 1) == Q(above[k]));
    MLAA_CHECK(GetValue(w, x, y, 3) == Q(left[k]));
  }
  // Without diagonal detection, the inner corners' edgels are Z shapes of one pixel: 1/8
  // everywhere.
  auto plain = Weights(in, 8, false);
  for (int k = 1; k < 3; ++k)
  {
    for (int c = 0; c < 4; ++c)
    {
      MLAA_CHECK(GetValue(plain, 5 + k, 3 + k, c) == Q(0.125));
    }
  }
  // A single corner (a staircase of one unit) keeps the orthogonal weights.
  auto box = Grey(12, 10, [](int x, int y) { return x >= 4 && y < 6; });
  MLAA_CHECK(Compare(Weights(box), Weights(box, 8, false)).Count == 0);

  // The same staircase mirrored left to right is a falling one: the same weights on the mirrored
  // edgels. Pixel (x, y) maps to (15 - x, y); the corner's top edgel stays with the white pixel
  // q = (10 - k, 3 + k), its left edgel moves to r = (11 - k, 3 + k), the black pixel right of q.
  auto mirrored = Grey(16, 12, [](int x, int y) {
    const int m = 15 - x;
    const int h = m <= 4 ? 3 : (m >= 8 ? 7 : m - 1);
    return y < h;
  });
  auto wm = Weights(mirrored);
  for (int k = 0; k < 4; ++k)
  {
    const int qx = 10 - k, y = 3 + k;
    MLAA_CHECK(GetValue(wm, qx, y, 0) == Q(in_[k]));      // q takes the black above it
    MLAA_CHECK(GetValue(wm, qx, y, 1) == Q(above[k]));    // the pixel above q takes white
    MLAA_CHECK(GetValue(wm, qx + 1, y, 2) == Q(left[k])); // r takes white from q
    MLAA_CHECK(GetValue(wm, qx + 1, y, 3) == Q(in_[k]));  // q takes black from r
  }
}

// Half-plane edges at angles around 45 degrees against their exact pixel coverage (16 x 16
// samples per pixel): diagonal detection must at least halve the squared error that the
// orthogonal search leaves. At exactly 45 degrees the staircase has no ends within the search,
// so nothing tells the shift and both give 1/8: the same error.
void DiagonalCoverage()
{
  const int size = 96;
  for (double degrees : { 38.0, 45.0, 52.0 })
  {
    const double t = degrees * 3.14159265358979 / 180.0;
    auto inside = [&](double x, double y) {
      return -std::sin(t) * (x - 48.37) + std::cos(t) * (y - 48.21) < 0.0;
    };
    auto in = Grey(size, size, [&](int x, int y) { return inside(x + 0.5, y + 0.5); });
    std::vector<double> exact(size * size);
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        int covered = 0;
        for (int i = 0; i < 256; ++i)
        {
          covered += inside(x + (i % 16 + 0.5) / 16.0, y + (i / 16 + 0.5) / 16.0) ? 1 : 0;
        }
        exact[y * size + x] = White * covered / 256.0;
      }
    }
    double error[3] = { 0.0, 0.0, 0.0 }; // none, orthogonal only, with diagonals
    vtkNew<vtkMLAAOptions> orthogonal;
    orthogonal->SetPresetToMedium(); // the settings the expected values assume
    orthogonal->DiagonalDetectionOff();
    vtkSmartPointer<vtkImageData> images[3] = { in, RunMLAA(in, orthogonal),
      RunMLAA(in, MediumOptions()) };
    for (int y = 8; y < size - 8; ++y)
    {
      for (int x = 8; x < size - 8; ++x)
      {
        for (int m = 0; m < 3; ++m)
        {
          const double d = GetValue(images[m], x, y) - exact[y * size + x];
          error[m] += d * d;
        }
      }
    }
    std::cout << degrees << " degrees: squared error none " << error[0] << ", orthogonal "
              << error[1] << ", diagonal " << error[2] << std::endl;
    MLAA_CHECK(error[1] < error[0]);
    MLAA_CHECK(degrees == 45.0 ? error[2] == error[1] : error[2] < 0.5 * error[1]);
  }
}

int TestImageMLAAPatterns(int, char*[])
{
  StraightEdges();
  LShape();
  RectangleCorner();
  UShape();
  ZShape();
  ThinLine();
  ThinLinesSideBySide();
  TJunctions();
  for (int steps : { 1, 2, 4, 8, 16 })
  {
    LongLine(steps);
  }
  ThinImages();
  DiagonalStaircase();
  DiagonalCoverage();
  return Result();
}
