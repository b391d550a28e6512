// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageDLAA on small synthetic patterns whose results follow by hand from the method in
// vtkDLAAOptions: straight edges are unchanged (blurring along an edge changes nothing), a
// one-pixel step gets the short-edge blend, a long nearly horizontal edge with 20-pixel steps
// gets a luminosity ramp of 17 levels across each step and nothing else, a distant colour does
// not bleed into a long edge, flat regions and faint noise come out bit for bit, and the GREEN
// luminosity and LongEdges off behave as specified.
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkAntialiasingTestUtilities.h"

#include <random>

using namespace vtkMLAATest;

namespace
{
// Grey RGB: every channel `v`.
double Grey(bool bright)
{
  return bright ? 255.0 : 0.0;
}

void StraightEdgesAreUnchanged()
{
  for (bool vertical : { true, false })
  {
    auto image = MakeImage(21, 19, 3);
    FillImage(image, [vertical](int x, int y, int, int) { return Grey(vertical ? x < 9 : y < 8); });
    auto output = RunDLAA(image);
    MLAA_CHECK(Compare(image, output).Count == 0);
  }
}

// One step of one pixel: bright below y = 4 for x < 8 and below y = 5 from x = 8 on. With
// short edges only, by hand (normalised): at (7, 4) (dark) Hx = Hy = 0.5, Bx = By = 1/3, both
// masks 1, so 1/3 (85); at (8, 4) (bright) Bx = By = 2/3 (170); at (9, 4) (bright) Hx = 0.25,
// Bx = 5/6, Hy = 0.5, By = 2/3, mx = 1, my = (3 * 0.25 - 0.1) / (2/3) = 0.975, so
// lerp(5/6, 2/3, 0.4875) = 0.752 (192).
void OnePixelStep()
{
  auto image = MakeImage(20, 12, 3);
  FillImage(image, [](int x, int y, int, int) { return Grey(y < (x < 8 ? 4 : 5)); });
  vtkNew<vtkDLAAOptions> options;
  options->LongEdgesOff();
  auto output = RunDLAA(image, options);
  for (int k = 0; k < 3; ++k)
  {
    MLAA_CHECK(GetValue(output, 7, 4, k) == 85);
    MLAA_CHECK(GetValue(output, 8, 4, k) == 170);
    MLAA_CHECK(GetValue(output, 9, 4, k) == 192);
    // Far from the step, the straight edge is unchanged.
    MLAA_CHECK(GetValue(output, 2, 3, k) == 255 && GetValue(output, 2, 4, k) == 0);
    MLAA_CHECK(GetValue(output, 15, 4, k) == 255 && GetValue(output, 15, 5, k) == 0);
  }
}

// A long, nearly horizontal edge: bright below y = 8 + x / 20 (steps at x = 20, 40, 60). Along
// each edge every mx is 1 (a horizontal high-pass of 0.5 over a blur of 0 or 1), so the long
// mask is 1; the vertical masks respond at the steps only, so the long vertical mask is 0. On
// the row of the step at X, a pixel x in X - 8 .. X + 7 has n = x - X + 9 bright pixels in its
// 17-pixel window (the steps, 20 pixels, are longer than the window: the neighbours across the
// edge keep their colours 8 pixels each way), t = n / 17, and moves to the neighbour across the edge (below for a dark
// pixel, above for a bright one) until its luminosity is t: 255 n / 17 = 15 n. Everything else
// is unchanged (t equals the pixel's own luminosity).
int LongEdgeExpected(int x, int y, bool& ramp)
{
  for (int X : { 20, 40, 60 })
  {
    if (y == 7 + X / 20 && x >= X - 8 && x <= X + 7)
    {
      ramp = true;
      return 15 * (x - X + 9);
    }
  }
  ramp = false;
  return y < 8 + x / 20 ? 255 : 0;
}

void LongEdgeRamp()
{
  auto image = MakeImage(80, 20, 3);
  FillImage(image, [](int x, int y, int, int) { return Grey(y < 8 + x / 20); });
  auto output = RunDLAA(image);
  int ramps = 0;
  for (int y = 0; y < 20; ++y)
  {
    for (int x = 0; x < 80; ++x)
    {
      bool ramp;
      const int expected = LongEdgeExpected(x, y, ramp);
      ramps += ramp ? 1 : 0;
      for (int k = 0; k < 3; ++k)
      {
        if (!MLAA_CHECK(GetValue(output, x, y, k) == expected))
        {
          std::cerr << "(" << x << ", " << y << ", " << k << "): " << GetValue(output, x, y, k)
                    << ", expected " << expected << std::endl;
        }
      }
    }
  }
  MLAA_CHECK(ramps == 48);

  // Without long edges, only the pixels next to each step change (the short-edge blend).
  vtkNew<vtkDLAAOptions> options;
  options->LongEdgesOff();
  auto shortOnly = RunDLAA(image, options);
  for (int y = 0; y < 20; ++y)
  {
    for (int x = 0; x < 80; ++x)
    {
      const bool nearStep = (x % 20 >= 18 || x % 20 <= 1) && x > 1 && x < 78;
      if (!nearStep)
      {
        MLAA_CHECK(GetValue(shortOnly, x, y, 0) == GetValue(image, x, y, 0));
      }
    }
  }
  MLAA_CHECK(GetValue(shortOnly, 36, 9, 0) == 0);   // on the ramp with long edges: 75
  MLAA_CHECK(GetValue(shortOnly, 39, 9, 0) == 85);  // the short-edge blend (1/3)
  MLAA_CHECK(GetValue(output, 36, 9, 0) == 75);
}

// The same long edge between red (below) and blue (above), with a green block on the edge's
// row 6 to 8 pixels to the right of the ramp's end: it lies within the 17-pixel windows of the
// ramp's last pixels, but only as a target luminosity, so no green reaches the pixels more than
// the short-edge reach (2 pixels) from it, while the ramp still mixes red and blue.
void NoColourBleeding()
{
  auto image = MakeImage(80, 20, 3);
  FillImage(image, [](int x, int y, int, int k) {
    if (y == 9 && x >= 53 && x <= 55)
    {
      return k == 1 ? 255.0 : 0.0;
    }
    const bool below = y < 8 + x / 20;
    return (below ? k == 0 : k == 2) ? 255.0 : 0.0;
  });
  auto output = RunDLAA(image);
  int mixed = 0;
  for (int y = 0; y < 20; ++y)
  {
    for (int x = 0; x < 51; ++x)
    {
      MLAA_CHECK(GetValue(output, x, y, 1) == 0);
      mixed += GetValue(output, x, y, 0) > 0 && GetValue(output, x, y, 2) > 0 ? 1 : 0;
    }
  }
  MLAA_CHECK(mixed >= 16);
}

// Flat regions, and noise whose high-pass responses stay below Epsilon / Lambda (2 x 4/255 at
// most, times 3, is under 0.1), come out bit for bit, in 8-bit and in float.
void FlatAndFaintNoise()
{
  std::mt19937 random(12);
  std::uniform_int_distribution<int> noise(-4, 4);
  auto image = MakeImage(61, 47, 3);
  FillImage(image, [&](int, int, int, int) { return 128.0 + noise(random); });
  MLAA_CHECK(Compare(image, RunDLAA(image)).Count == 0);

  auto flat = MakeImage(33, 17, 4, VTK_FLOAT, 0.3);
  MLAA_CHECK(Compare(flat, RunDLAA(flat)).Count == 0);
  auto flatDouble = MakeImage(9, 7, 2, VTK_DOUBLE, 0.123456789);
  MLAA_CHECK(Compare(flatDouble, RunDLAA(flatDouble)).Count == 0);
}

// GREEN reads the green channel alone: an edge in red only is no edge for it, while REC709
// sees it; an edge in green is one for both.
void GreenLuminosity()
{
  vtkNew<vtkDLAAOptions> green;
  green->SetLumaFunctionToGreen();
  for (int channel : { 0, 1 })
  {
    auto image = MakeImage(30, 20, 3);
    FillImage(image, [channel](int x, int y, int, int k) {
      return k == channel && y < 5 + x / 4 ? 255.0 : 0.0;
    });
    const vtkIdType rec709Changes = Compare(image, RunDLAA(image)).Count;
    const vtkIdType greenChanges = Compare(image, RunDLAA(image, green)).Count;
    MLAA_CHECK(rec709Changes > 0);
    MLAA_CHECK(channel == 0 ? greenChanges == 0 : greenChanges > 0);
  }
}
}

// A dark line one pixel wide on white, one row higher every 6 pixels (dark where y = 6 + x / 6):
// its steps are shorter than the long-edge window, so the long-edge step takes its mean over the
// step the pixel is on, not over 17 pixels.
// - A line pixel 2 pixels into its run sees both neighbours across the line stay white for 2
//   pixels each way and change beyond: its window is 5 dark pixels and it stays black (over 17
//   pixels it would take the luminosity of 11 white pixels in 17: 108 where the run starts at
//   x = 18).
// - The white pixels beside the line's run on the row below, 3 before the line moves into
//   their row and 2 after it leaves (x = 15 and 26 for the run at 18 .. 23), see the line below
//   them (or above them) end where it moves into their row: the step goes on through that place
//   (once), so their windows hold pixels of the run and they darken, as a slanted line's coverage
//   does. Were the step to end there, they would keep their white (255).
void ShortStepsOfAThinLine()
{
  auto image = MakeImage(80, 20, 3);
  FillImage(image, [](int x, int y, int, int) { return Grey(y != 6 + x / 6); });
  auto output = RunDLAA(image);
  for (int m = 3; m <= 9; ++m)
  {
    const int start = 6 * m; // the run on row 6 + m: x = start .. start + 5
    const int y = 6 + m;
    for (int k = 0; k < 3; ++k)
    {
      if (!MLAA_CHECK(GetValue(output, start + 2, y, k) == 0))
      {
        std::cerr << "line pixel (" << start + 2 << ", " << y
                  << "): " << GetValue(output, start + 2, y, k) << ", expected 0" << std::endl;
      }
      for (int x : { start - 3, start + 8 })
      {
        if (!MLAA_CHECK(GetValue(output, x, y, k) < 255))
        {
          std::cerr << "white pixel beside the run (" << x << ", " << y << ") unchanged"
                    << std::endl;
        }
      }
    }
  }
}

int TestImageDLAAPatterns(int, char*[])
{
  StraightEdgesAreUnchanged();
  OnePixelStep();
  LongEdgeRamp();
  NoColourBleeding();
  FlatAndFaintNoise();
  GreenLuminosity();
  ShortStepsOfAThinLine();
  return Result();
}
