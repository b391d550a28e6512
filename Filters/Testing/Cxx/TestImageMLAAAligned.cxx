// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Pictures whose every side lies on a pixel boundary come out of vtkImageMLAA exactly as they
// went in (issue 50): there is no staircase in them, and the sides end at corners of shapes, at
// junctions of wider shapes and at the image's border, never at a one-pixel step. vtkImageDLAA,
// whose blurs and long-edge windows stop at the sides of corners, changes none of their pixels by
// more than 4/255 (with and without long edges). Seeded pictures of four kinds, in grey, RGB and
// RGBA:
// - voxels: square cells 4 to 24 pixels a side with random values, at a random offset that cuts
//   no cell to one pixel at the borders (a zoomed image with nearest-neighbour interpolation,
//   seen straight on);
// - four-colour voxels: the same with four values only, so that neighbouring cells often match
//   and sides end at L corners and T junctions;
// - rectangles: up to eight rectangles 4 to 60 pixels a side, apart from each other by at least
//   two pixels (a bar chart, boxes in parallel projection);
// - hanging bars: bars of a chart hanging from a line one pixel high across the picture (the
//   line's edge stops at each bar, and its far edge, running on past the bars one row over, is
//   no step: CrossingEndsInStep in vtkMLAABlendingWeights.cxx);
// at every preset, at 1 to 128 search steps, and with corner extrapolation. Rotated by a few
// degrees, the same voxels are antialiased by both (their sides are staircases).
// Not covered, and still ramped: the ends of one-pixel lines (axes, ticks: a crossing edge one
// pixel long is a step), two shapes whose sides are one row apart (a step, as a staircase's),
// and where one-pixel lines cross or meet (mlaa-aligned measures them); DLAA on one-pixel lines.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMath.h"

#include <cmath>
#include <iostream>
#include <random>

using namespace vtkMLAATest;

namespace
{
const int Width = 97, Height = 71;

// One picture: value(x, y) in [0, 1] per component, from `seed`.
vtkSmartPointer<vtkImageData> Picture(int kind, int components, unsigned seed, double degrees)
{
  std::mt19937 engine(seed);
  auto uniform = [&engine](int lo, int hi) { return lo + static_cast<int>(engine() % (hi - lo + 1)); };
  const int cell = uniform(4, 24);
  // Offsets that leave no partial cell one pixel wide at the borders (a one-pixel line).
  auto offset = [&](int size) {
    int o = uniform(0, cell - 2);
    while ((size + o) % cell == 1)
    {
      o = uniform(0, cell - 2);
    }
    return o;
  };
  const int ox = offset(Width), oy = offset(Height);
  std::vector<double> values(4 * 64 * 64);
  for (double& v : values)
  {
    v = kind == 1 ? uniform(0, 3) / 3.0 : uniform(0, 255) / 255.0;
  }
  struct Box
  {
    int X0, Y0, X1, Y1;
    double Value;
  };
  std::vector<Box> boxes;
  if (kind == 2)
  {
    for (int tries = 0; tries < 200 && boxes.size() < 8; ++tries)
    {
      Box b;
      b.X0 = uniform(0, Width - 5);
      b.Y0 = uniform(0, Height - 5);
      b.X1 = std::min(Width - 1, b.X0 + uniform(3, 59));
      b.Y1 = std::min(Height - 1, b.Y0 + uniform(3, 59));
      b.Value = uniform(0, 255) / 255.0;
      bool apart = b.X1 - b.X0 >= 3 && b.Y1 - b.Y0 >= 3;
      for (const Box& o : boxes)
      {
        apart = apart &&
          (b.X0 > o.X1 + 2 || o.X0 > b.X1 + 2 || b.Y0 > o.Y1 + 2 || o.Y0 > b.Y1 + 2);
      }
      if (apart)
      {
        boxes.push_back(b);
      }
    }
  }
  // Bars hanging from a line one pixel high (kind 3), across the whole picture at row `top`:
  // 4 to 6 pixels wide, 6 to 30 high, 4 or more apart. The line's edge stops at each bar, and its
  // far edge runs on one row over.
  const int top = uniform(Height / 2, Height - 8), width = uniform(4, 6);
  const int step = width + uniform(4, 8), shift = uniform(3, 9);
  auto onLine = [&](int x, int y) {
    const int b = (x - shift) / step;
    const bool bar = x >= shift && (x - shift) % step < width &&
      shift + b * step + width + 4 <= Width && y < top && y >= top - 6 - (7 * b + shift) % 25;
    return y == top || bar;
  };
  const double c = std::cos(degrees * vtkMath::Pi() / 180.0);
  const double s = std::sin(degrees * vtkMath::Pi() / 180.0);
  auto image = MakeImage(Width, Height, components);
  FillImage(image, [&](int x, int y, int, int k) {
    if (kind == 3)
    {
      return k == 3 ? 255.0 : (onLine(x, y) ? 230.0 - 60.0 * k : 40.0 + 20.0 * k);
    }
    if (kind == 2)
    {
      for (const Box& b : boxes)
      {
        if (x >= b.X0 && x <= b.X1 && y >= b.Y0 && y <= b.Y1)
        {
          return 255.0 * (k == 3 ? 1.0 : std::fmod(b.Value + 0.37 * k, 1.0));
        }
      }
      return k == 3 ? 255.0 : 40.0;
    }
    // The cell of the pixel's centre, rotated by `degrees` about the image's centre.
    const double px = x + 0.5 - 0.5 * Width, py = y + 0.5 - 0.5 * Height;
    const double rx = c * px - s * py + 0.5 * Width, ry = s * px + c * py + 0.5 * Height;
    const int i = static_cast<int>(std::floor((rx + ox) / cell)) + 8;
    const int j = static_cast<int>(std::floor((ry + oy) / cell)) + 8;
    const double v = values[(4 * (j * 64 + i) + (k == 3 ? 0 : k)) % values.size()];
    return k == 3 ? 255.0 * (0.5 + 0.5 * v) : 255.0 * v;
  });
  return image;
}
}

int TestImageMLAAAligned(int, char*[])
{
  using Configure = std::function<void(vtkMLAAOptions*)>;
  std::vector<std::pair<std::string, Configure>> configurations;
  for (int preset = vtkMLAAOptions::LOW; preset <= vtkMLAAOptions::MAX; ++preset)
  {
    configurations.emplace_back("preset " + std::to_string(preset),
      [preset](vtkMLAAOptions* o) { o->SetPreset(preset); });
  }
  for (int steps : { 1, 2, 3, 8, 32, 64, 128 })
  {
    for (bool corners : { false, true })
    {
      configurations.emplace_back(
        std::to_string(steps) + " steps" + (corners ? ", corners" : ""),
        [steps, corners](vtkMLAAOptions* o) {
          o->SetPresetToHigh();
          o->SetMaxSearchSteps(steps);
          o->SetCornerExtrapolation(corners);
        });
    }
  }
  int pictures = 0;
  for (unsigned seed = 1; seed <= 6; ++seed)
  {
    for (int kind = 0; kind < 4; ++kind)
    {
      const int components = 1 + static_cast<int>((seed + kind) % 4);
      auto picture = Picture(kind, components == 2 ? 3 : components, seed, 0.0);
      ++pictures;
      // DLAA, with and without long edges: no pixel changed by more than 4/255 (a long-edge
      // window may still cross a junction whose sides differ by less than 2 Epsilon / Lambda,
      // which the masks do not see: 1/255 to 4/255 on grey voxels).
      // (Not on the line the bars hang from, which DLAA's short-edge blur spreads as any feature
      // one pixel thin.)
      for (bool longEdges : { true, false })
      {
        if (kind == 3)
        {
          break;
        }
        vtkNew<vtkDLAAOptions> options;
        options->SetLongEdges(longEdges);
        const Difference d = Compare(picture, RunDLAA(picture, options), 4.0);
        if (!MLAA_CHECK(d.Pixels == 0))
        {
          std::cerr << "kind " << kind << ", seed " << seed << ", DLAA"
                    << (longEdges ? "" : " without long edges") << ": " << d.Pixels
                    << " pixels changed by more than 4/255 (largest difference " << d.Max << ")"
                    << std::endl;
        }
      }
      for (const auto& configuration : configurations)
      {
        vtkNew<vtkMLAAOptions> options;
        configuration.second(options);
        const Difference d = Compare(picture, RunMLAA(picture, options), 0.0);
        if (!MLAA_CHECK(d.Count == 0))
        {
          std::cerr << "kind " << kind << ", seed " << seed << ", " << configuration.first
                    << ": " << d.Pixels << " pixels changed (largest difference " << d.Max
                    << ")" << std::endl;
        }
      }
    }
    // Rotated voxels are staircases: antialiased as any other edge.
    auto rotated = Picture(0, 3, seed, 4.0);
    MLAA_CHECK(Compare(rotated, RunMLAA(rotated), 4.0).Pixels > 50);
    MLAA_CHECK(Compare(rotated, RunDLAA(rotated), 4.0).Pixels > 50);
  }
  std::cout << pictures << " pictures, " << configurations.size()
            << " configurations: unchanged" << std::endl;
  return Result();
}
