// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// CornerExtrapolation (vtkMLAAOptions; WeightsComputer::ExtrapolateCorners in
// vtkMLAABlendingWeights.cxx), with exact weights on a synthetic shape: a dark polygon on white
// whose top side is a staircase falling to the right in whole runs of 12 pixels, cut by the
// polygon's vertical right side after 6 pixels of the fourth run, whose first run starts at the
// image's left border, and whose bottom side is flat:
// - the run cut by the corner is ramped as the whole 12-pixel run it is part of (a Z from the
//   step at its left to a virtual step 12 pixels on), where the chapter's reading of the corner
//   as a one-pixel step gives a Z over the 6 pixels (the corner rounded);
// - the run at the image border likewise: a Z over 12 pixels, where the clamped reads gave an L
//   from its right end only;
// - the whole runs keep the chapter's Z; the bottom side and the right side, with no step at
//   either end, get the same weights as without extrapolation (none since issue 50: nothing is
//   seen to extrapolate from, nor any step);
// - the transposed image gives the transposed weights (the vertical lines follow the same rule);
// - with CornerExtrapolation off, the chapter's weights everywhere.
// Sides with one step (issue 20), on a second shape: a dark rectangle whose top side, 20 pixels
// long, ends at a corner on the right and on the left at a step up to a run of 2 pixels (a
// narrower, taller rectangle beside it) that ends at a corner too, so that the step is the
// side's only one: both runs are ramped as one run twice as long as the longer (40 pixels, the
// virtual step beyond the reach of 16 steps for the 7 pixels nearest the step), exactly the
// table's weights, in rows and, transposed, in columns; the long run's ramp falls to nothing at
// its corner and never changes sign. Ends of unknown height, on a third shape, the second with
// one more step up past the 2-pixel run: that run ends at a step but is too short to belong to
// one straight staircase with the side, so nothing is extrapolated: the corner takes half the
// chapter's ramp (the side's first half keeps the chapter's Z exactly, the second half gets the
// step's part plus half the corner's, quantised after the sum), in rows and in columns; a
// rectangle whose sides are longer than the search's reach (a corner at one end, the reach at
// the other) and have corners at both ends gets no weight anywhere (issue 50).
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMLAAAreaTexture.h"

#include <cmath>
#include <iostream>

using namespace vtkMLAATest;

namespace
{
const int Width = 64;
const int Height = 24;
const int RunLength = 12;
const int RightSide = 41; // the polygon's last column
const int Bottom = 2;     // its lowest row

// The top row of the polygon in column x: 16 in the first run, one lower in each next one.
int TopRow(int x)
{
  return 16 - x / RunLength;
}

bool Inside(int x, int y)
{
  return x <= RightSide && y >= Bottom && y <= TopRow(x);
}

vtkSmartPointer<vtkImageData> Shape(bool transposed, bool (*inside)(int, int) = &Inside)
{
  auto image = transposed ? MakeImage(Height, Width, 1) : MakeImage(Width, Height, 1);
  FillImage(image, [transposed, inside](int x, int y, int, int) {
    const bool in = transposed ? inside(y, x) : inside(x, y);
    return in ? 0.0 : 255.0;
  });
  return image;
}

// The second shape: the side's columns and row, and the taller rectangle's columns.
const int SideX0 = 10;
const int SideX1 = 29;
const int SideRow = 14;
const int StepX0 = 8;
bool InsideStepAndCorner(int x, int y)
{
  return (x >= SideX0 && x <= SideX1 && y >= Bottom && y <= SideRow) ||
    (x >= StepX0 && x < SideX0 && y >= Bottom && y <= SideRow + 1);
}

// The third shape: the second with one more step up, to a 3-pixel run (columns 5 to 7 of row
// 16), left of the 2-pixel run: that run ends at a step, a whole run too short to belong to one
// straight staircase with the side.
const int TopStepX0 = 5;
bool InsideTwoSteps(int x, int y)
{
  return InsideStepAndCorner(x, y) ||
    (x >= TopStepX0 && x < StepX0 && y >= Bottom && y <= SideRow + 2);
}

vtkSmartPointer<vtkMLAAOptions> Options(bool corners)
{
  auto options = vtkSmartPointer<vtkMLAAOptions>::New();
  options->SetPresetToHigh(); // 16 steps: lines followed 32 pixels each way
  options->SetEdgeDetection(vtkMLAAOptions::LUMA);
  options->SetLocalContrastFactor(0.0);
  options->SetDiagonalDetection(false);
  options->SetCornerExtrapolation(corners);
  options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
  return options;
}

// The quantised area of the table (channel 0: the pixel under the edge, 1: the one above).
double Area(int e1, int e2, int d1, int d2, int channel, int maxDistance)
{
  // Held for the whole check: a table no one holds may be freed (vtkAntialiasingTableCache).
  const auto held = vtkMLAAAreaTexture::GetSharedTable(maxDistance);
  const std::vector<float>& table = *held;
  const int cell = maxDistance + 1;
  const int size = vtkMLAAAreaTexture::NumberOfCodes * cell;
  const size_t texel = static_cast<size_t>(cell * e2 + d2) * size + (cell * e1 + d1);
  return std::nearbyint(table[2 * texel + channel] * 255.0);
}

// Whether the weights of the top edgels of row `row`, columns x0..x1, are the table's for codes
// e1, e2 and distances x - x0 + shift1, x1 - x + shift2.
bool RowHasAreas(vtkImageData* weights, int row, int x0, int x1, int e1, int e2, int shift1,
  int shift2, int maxDistance)
{
  bool same = true;
  for (int x = x0; x <= x1; ++x)
  {
    for (int channel = 0; channel < 2; ++channel)
    {
      const double expected =
        Area(e1, e2, x - x0 + shift1, x1 - x + shift2, channel, maxDistance);
      const double got = GetValue(weights, x, row, channel);
      if (got != expected)
      {
        std::cerr << "row " << row << ", x " << x << ", channel " << channel << ": " << got
                  << ", expected " << expected << std::endl;
        same = false;
      }
    }
  }
  return same;
}

void Corners()
{
  auto image = Shape(false);
  auto on = Options(true);
  auto off = Options(false);
  const int maxDistance = on->GetMaxDistance();
  auto weights = RunMLAA(image, on);
  auto chapter = RunMLAA(image, off);
  // Codes of the top side's runs: a step up at the left end (the edge on the row above: 1), a
  // step down at the right end (the edge on the run's own row: 3).
  // The run cut by the corner, columns 36 to 41 of row 13: the whole run is 12 pixels long, so
  // its virtual right end lies 6 pixels beyond the corner.
  const int x0 = 3 * RunLength;
  MLAA_CHECK(RowHasAreas(weights, TopRow(x0), x0, RightSide, 1, 3, 0, RunLength - 6, maxDistance));
  // The chapter: the corner read as a step, a Z over the 6 pixels.
  MLAA_CHECK(RowHasAreas(chapter, TopRow(x0), x0, RightSide, 1, 3, 0, 0, maxDistance));
  // The run at the left border, columns 0 to 11 of row 16: a Z over its 12 pixels with the
  // option; without, the clamped reads continue it to the search's reach (code 0 there), which
  // leaves an L ramp from its right end only.
  MLAA_CHECK(RowHasAreas(weights, TopRow(0), 0, RunLength - 1, 1, 3, 0, 0, maxDistance));
  // The whole runs in between are the same either way.
  for (int run = 1; run <= 2; ++run)
  {
    const int a = run * RunLength;
    MLAA_CHECK(RowHasAreas(weights, TopRow(a), a, a + RunLength - 1, 1, 3, 0, 0, maxDistance));
  }
  // Everything but the top side's first and last runs is as without extrapolation: the bottom
  // side (the border and a corner) and the right side (corners at both ends).
  int different = 0;
  int elsewhere = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      for (int channel = 0; channel < 4; ++channel)
      {
        if (GetValue(weights, x, y, channel) != GetValue(chapter, x, y, channel))
        {
          ++different;
          const bool cutRun = channel < 2 &&
            ((y == TopRow(x0) && x >= x0 && x <= RightSide) ||
              (y == TopRow(0) && x < RunLength));
          elsewhere += cutRun ? 0 : 1;
        }
      }
    }
  }
  MLAA_CHECK(different > 0);
  MLAA_CHECK(elsewhere == 0);

  // The transposed image: a top edgel of (x, y) becomes the left edgel of (y + 1, x), whose
  // owner (the pixel right of it) is the image of the pixel above the top edgel: channels 0 and
  // 1 become 3 and 2.
  auto transposedWeights = RunMLAA(Shape(true), on);
  bool transposes = true;
  for (int y = 0; y + 1 < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      if (GetValue(transposedWeights, y + 1, x, 3) != GetValue(weights, x, y, 0) ||
        GetValue(transposedWeights, y + 1, x, 2) != GetValue(weights, x, y, 1))
      {
        transposes = false;
      }
    }
  }
  MLAA_CHECK(transposes);
}

// The float areas of the table (channel 0: the pixel under the edge, 1: the one above), as
// the pass reads them.
float FloatArea(int e1, int e2, int d1, int d2, int channel, int maxDistance)
{
  // Held for the whole check: a table no one holds may be freed (vtkAntialiasingTableCache).
  const auto held = vtkMLAAAreaTexture::GetSharedTable(maxDistance);
  const std::vector<float>& table = *held;
  const int cell = maxDistance + 1;
  const int size = vtkMLAAAreaTexture::NumberOfCodes * cell;
  return table[2 * (static_cast<size_t>(cell * e2 + d2) * size + (cell * e1 + d1)) + channel];
}

// The table's quantised weights of a line of which one end, a step of code `stepCode` at
// distance `stepDistance`, is the only step of a side whose other runs end at corners: the
// corner end is a virtual step `run` - 1 - stepDistance away, or code 0 at the maximum distance
// beyond it (ExtrapolateCorners).
double OneStepArea(bool stepFirst, int stepCode, int stepDistance, int run, int channel,
  int maxDistance)
{
  int cornerCode = 4 - stepCode;
  int cornerDistance = run - 1 - stepDistance;
  if (cornerDistance > maxDistance)
  {
    cornerCode = 0;
    cornerDistance = maxDistance;
  }
  return stepFirst ? Area(stepCode, cornerCode, stepDistance, cornerDistance, channel, maxDistance)
                   : Area(cornerCode, stepCode, cornerDistance, stepDistance, channel, maxDistance);
}

void OneStepSide()
{
  auto on = Options(true);
  auto off = Options(false);
  const int maxDistance = on->GetMaxDistance();
  for (const bool transposed : { false, true })
  {
    auto image = Shape(transposed, &InsideStepAndCorner);
    auto weights = RunMLAA(image, on);
    auto chapter = RunMLAA(image, off);
    // A top edgel of (x, y) is, transposed, the left edgel of (y + 1, x), whose channels 3 and 2
    // hold what 0 and 1 hold (see Corners).
    auto weight = [transposed](vtkImageData* w, int x, int y, int channel) {
      return transposed ? GetValue(w, y + 1, x, 3 - channel) : GetValue(w, x, y, channel);
    };
    // The side's two runs: columns 10 to 29 of row 14 and 8 to 9 of row 15, one step between
    // them, corners at both ends. The expected run is twice the longer one seen: 40 pixels.
    const int length = SideX1 - SideX0 + 1;
    const int run = 2 * length;
    int fewer = 0;
    for (int x = SideX0; x <= SideX1; ++x)
    {
      const int d1 = x - SideX0;
      const int d2 = SideX1 - x;
      for (int channel = 0; channel < 2; ++channel)
      {
        // The step on the row above at the left end (code 1), the corner at the right end.
        const double expected = OneStepArea(true, 1, d1, run, channel, maxDistance);
        const double got = weight(weights, x, SideRow, channel);
        const double theirs = weight(chapter, x, SideRow, channel);
        if (!MLAA_CHECK(got == expected))
        {
          std::cerr << (transposed ? "transposed, " : "") << "x " << x << ", channel "
                    << channel << ": " << got << ", expected " << expected << std::endl;
        }
        // The chapter's Z over the 20 pixels: the step's ramp now reaches the whole side,
        // the corner's (to the other side of the boundary) is gone.
        MLAA_CHECK(theirs == Area(1, 3, d1, d2, channel, maxDistance));
        fewer += got < theirs ? 1 : 0;
      }
      // The ramp from the step falls to nothing at the corner, and never changes sign.
      MLAA_CHECK(weight(weights, x, SideRow, 0) == 0.0 || weight(weights, x, SideRow, 1) == 0.0);
    }
    MLAA_CHECK(fewer > 0);
    MLAA_CHECK(weight(weights, SideX1, SideRow, 0) + weight(weights, SideX1, SideRow, 1) <= 3.0);
    // The short run: its corner at the left, the step down (code 3) at its right end.
    for (int x = StepX0; x < SideX0; ++x)
    {
      for (int channel = 0; channel < 2; ++channel)
      {
        const double expected =
          OneStepArea(false, 3, SideX0 - 1 - x, run, channel, maxDistance);
        const double got = weight(weights, x, SideRow + 1, channel);
        if (!MLAA_CHECK(got == expected))
        {
          std::cerr << (transposed ? "transposed, " : "") << "short run, x " << x
                    << ", channel " << channel << ": " << got << ", expected " << expected
                    << std::endl;
        }
      }
    }
  }

  // Sides of 60 pixels, twice the reach of 16 steps: the pixels nearer one corner see the other
  // end beyond the reach, where nothing is seen either. No step is seen anywhere: the sides are
  // left alone, with and without extrapolation (issue 50; the chapter ramped them from the
  // corners).
  auto rectangle = MakeImage(Width, Height, 1);
  FillImage(rectangle, [](int x, int y, int, int) {
    return (x >= 2 && x <= 61 && y >= Bottom && y <= SideRow) ? 0.0 : 255.0;
  });
  MLAA_CHECK(2 * on->GetMaxSearchSteps() < 61 - 2);
  auto weights = RunMLAA(rectangle, on);
  MLAA_CHECK(Compare(weights, RunMLAA(rectangle, off), 0.0).Count == 0);
  auto none = vtkSmartPointer<vtkImageData>::New();
  none->DeepCopy(weights);
  none->GetPointData()->GetScalars()->Fill(0.0);
  MLAA_CHECK(Compare(weights, none, 0.0).Count == 0);
}

void UnknownHeight()
{
  auto on = Options(true);
  auto off = Options(false);
  const int maxDistance = on->GetMaxDistance();
  for (const bool transposed : { false, true })
  {
    auto image = Shape(transposed, &InsideTwoSteps);
    auto weights = RunMLAA(image, on);
    auto chapter = RunMLAA(image, off);
    // The side's left end: the crossing edge on the row above (code 1), past it the 2-pixel run;
    // its right end: the crossing edge on its own row (code 3), a corner.
    const int length = SideX1 - SideX0 + 1;
    int halved = 0;
    for (int x = SideX0; x <= SideX1; ++x)
    {
      const int d1 = x - SideX0;
      const int d2 = SideX1 - x;
      for (int channel = 0; channel < 2; ++channel)
      {
        // A top edgel of (x, y) is, transposed, the left edgel of (y + 1, x), whose channels 3
        // and 2 hold what 0 and 1 hold (see Corners).
        const double got = transposed ? GetValue(weights, SideRow + 1, x, 3 - channel)
                                      : GetValue(weights, x, SideRow, channel);
        const double theirs = transposed ? GetValue(chapter, SideRow + 1, x, 3 - channel)
                                         : GetValue(chapter, x, SideRow, channel);
        const double expected = std::nearbyint(
          (FloatArea(1, 0, d1, d2, channel, maxDistance) +
            0.5f * FloatArea(0, 3, d1, d2, channel, maxDistance)) *
          255.0f);
        if (!MLAA_CHECK(got == expected))
        {
          std::cerr << (transposed ? "transposed, " : "") << "x " << x << ", channel "
                    << channel << ": " << got << ", expected " << expected << std::endl;
        }
        // The chapter's Z: the same over the half nearer the step, where the corner's ramp does
        // not reach.
        MLAA_CHECK(theirs == Area(1, 3, d1, d2, channel, maxDistance));
        if (2 * (d1 + 1) <= length)
        {
          MLAA_CHECK(got == theirs);
        }
        else if (theirs >= 2.0)
        {
          MLAA_CHECK(got < theirs);
          ++halved;
        }
      }
    }
    MLAA_CHECK(halved >= length / 2 - 2);
  }
}
}

int TestImageMLAACorners(int, char*[])
{
  Corners();
  OneStepSide();
  UnknownHeight();
  return Result();
}
