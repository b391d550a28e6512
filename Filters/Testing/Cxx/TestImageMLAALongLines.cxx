// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Long lines (up to 256 pixels each way, MaxSearchSteps up to 128) in the CPU filter:
// - the line lengths of vtkMLAAStages (one scan per row and per column) equal, on random edge
//   patterns, those of a plain search that steps pixel by pixel (the loop vtkImageMLAA used
//   before, and the SEARCH_LOOP of the GPU pass) for 1, 8, 37 and 128 steps, with the extent's
//   clamped borders, and for pixels near and far from them;
// - a 1-degree slope across a 512-pixel-wide image (staircase steps of about 57 pixels) gets one
//   smooth ramp along each whole step with 32 steps or more, and the weights of every step are
//   the area texture's for the step's full length; with 8 steps (16 pixels each way) they are
//   not, which shows what the check catches;
// - with DiagonalDetection, the line and staircase lengths counted beforehand give the weights
//   of the search on random 45-degree patterns.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMLAAAreaTexture.h"
#include "vtkMLAABlendingWeights.h"
#include "vtkMath.h"

#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace vtkMLAATest;
using namespace vtkMLAAStages;

namespace
{
// The plain search: from (x, y), step pixel by pixel in direction (dx, dy) while the next pixel
// has the line's edgel and no crossing edgel lies between the two, at most maxDistance pixels,
// reading edgels clamped to the extent (as the filter and the GPU's clamp-to-edge do).
int ReferenceLength(const EdgesBuffer& e, int x, int y, int dx, int dy, int maxDistance)
{
  const Rect& r = e.Extent;
  auto at = [&](int u, int v) {
    return e.At(std::min(std::max(u, r.X0), r.X1), std::min(std::max(v, r.Y0), r.Y1));
  };
  for (int k = 1; k <= maxDistance; ++k)
  {
    const int px = x + dx * (k - 1), py = y + dy * (k - 1); // the previous pixel
    const int qx = x + dx * k, qy = y + dy * k;             // the next pixel
    bool continues;
    if (dy == 0)
    {
      // A row of top edgels; the crossing edgels are left edgels of the boundary's right pixel,
      // on this row and the row above.
      const int owner = std::max(px, qx);
      continues = at(qx, qy)[1] && !at(owner, y)[0] && !at(owner, y + 1)[0];
    }
    else
    {
      // A column of left edgels; the crossing edgels are top edgels of the boundary's lower
      // pixel, in this column and the column to the left.
      const int owner = std::min(py, qy);
      continues = at(qx, qy)[0] && !at(x, owner)[1] && !at(x - 1, owner)[1];
    }
    if (!continues)
    {
      return k - 1;
    }
  }
  return maxDistance;
}

void RunLengthsMatchSearch()
{
  std::mt19937 random(1234);
  int compared = 0;
  int atCap = 0;
  for (int steps : { 1, 8, 37, 128 })
  {
    const int maxDistance = 2 * steps;
    for (int trial = 0; trial < 6; ++trial)
    {
      // Extents of various sizes (some narrower than a line can be long) and offsets; edgel
      // densities from sparse to nearly full, with few crossing edgels so that long lines occur.
      const int w = std::uniform_int_distribution<int>(1, 300)(random);
      const int h = std::uniform_int_distribution<int>(1, 300)(random);
      const int x0 = std::uniform_int_distribution<int>(-20, 20)(random);
      const int y0 = std::uniform_int_distribution<int>(-20, 20)(random);
      const double alongDensity = trial % 2 ? 0.97 : 0.6;
      const double crossDensity = trial % 3 == 0 ? 0.002 : 0.03;
      EdgesBuffer edges;
      edges.Allocate(Rect{ x0, x0 + w - 1, y0, y0 + h - 1 });
      std::uniform_real_distribution<double> u(0.0, 1.0);
      // Rows of top edgels and columns of left edgels, in alternating bands so that both cross.
      for (int y = y0; y < y0 + h; ++y)
      {
        for (int x = x0; x < x0 + w; ++x)
        {
          const bool rowBand = ((y - y0) / 5) % 2 == 0;
          const bool columnBand = ((x - x0) / 7) % 2 == 0;
          unsigned char* e = edges.At(x, y);
          e[1] = u(random) < (rowBand ? alongDensity : crossDensity) ? 255 : 0;
          e[0] = u(random) < (columnBand ? alongDensity : crossDensity) ? 255 : 0;
        }
      }
      // Rows: every pixel of the extent with a top edgel (the others' lengths are not needed).
      std::vector<LineLength> left(w), right(w);
      for (int y = y0; y < y0 + h; ++y)
      {
        ComputeRowLineLengths(edges, y, maxDistance, left.data(), right.data());
        for (int x = x0; x < x0 + w; ++x)
        {
          if (!edges.Top(x, y))
          {
            continue;
          }
          const int l = ReferenceLength(edges, x, y, -1, 0, maxDistance);
          const int r = ReferenceLength(edges, x, y, +1, 0, maxDistance);
          atCap += (l == maxDistance) + (r == maxDistance);
          compared += 2;
          if (!MLAA_CHECK(left[x - x0] == l && right[x - x0] == r))
          {
            std::cerr << "steps " << steps << " row " << y << " x " << x << ": " << left[x - x0]
                      << "/" << right[x - x0] << " instead of " << l << "/" << r << std::endl;
            return;
          }
        }
      }
      // Columns (pixels with a left edgel): the whole extent, and a sub-extent (as the weights extent lies within the
      // edges extent) whose scan starts from rows far from the extent's border.
      for (int sub = 0; sub < 2; ++sub)
      {
        Rect part = edges.Extent;
        if (sub == 1)
        {
          part.X0 += std::min(w - 1, 3);
          part.Y0 += std::min(h - 1, 2 + h / 3);
          part.Y1 = std::max(part.Y0, part.Y1 - h / 3);
        }
        const size_t n = static_cast<size_t>(part.Width()) * part.Height();
        std::vector<LineLength> down(n), up(n);
        ComputeColumnLineLengths(edges, part, maxDistance, down.data(), up.data());
        for (int y = part.Y0; y <= part.Y1; ++y)
        {
          for (int x = part.X0; x <= part.X1; ++x)
          {
            if (!edges.Left(x, y))
            {
              continue;
            }
            const size_t i = static_cast<size_t>(y - part.Y0) * part.Width() + (x - part.X0);
            const int d = ReferenceLength(edges, x, y, 0, -1, maxDistance);
            const int v = ReferenceLength(edges, x, y, 0, +1, maxDistance);
            atCap += (d == maxDistance) + (v == maxDistance);
            compared += 2;
            if (!MLAA_CHECK(down[i] == d && up[i] == v))
            {
              std::cerr << "steps " << steps << " column " << x << " y " << y << ": " << down[i]
                        << "/" << up[i] << " instead of " << d << "/" << v << std::endl;
              return;
            }
          }
        }
      }
    }
  }
  // The patterns do exercise long lines and the cap.
  MLAA_CHECK(atCap > compared / 50);
}

// Staircases (DiagonalDetection) and lines: the blending weights with line and staircase lengths
// counted beforehand (WeightSettings::RunLengths) equal those of searching from every pixel, on
// random
// images of 45-degree stripes both ways with noise, for weights extents within the edges extent
// (so that the counts meet the borders of the extent and of the weights stage's bands of rows), for 1, 8, 37 and 128 steps.
void DiagonalRunsMatchSearch()
{
  std::mt19937 random(99);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int units = 0;
  for (int steps : { 1, 8, 37, 128 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(steps);
    WeightSettings settings;
    MakeWeightSettings(options, settings);
    for (int trial = 0; trial < 4; ++trial)
    {
      const int w = std::uniform_int_distribution<int>(20, 600)(random);
      const int h = std::uniform_int_distribution<int>(20, 300)(random);
      const Rect whole{ 0, w - 1, 0, h - 1 };
      // Pixels of two classes: stripes along one diagonal (period 2 to 40), some flipped.
      const int period = std::uniform_int_distribution<int>(2, 40)(random);
      const bool rising = trial % 2 == 0;
      const double noise = trial < 2 ? 0.002 : 0.05;
      std::vector<int> v(static_cast<size_t>(w) * h);
      for (int y = 0; y < h; ++y)
      {
        for (int x = 0; x < w; ++x)
        {
          const int along = rising ? x - y + 10000 : x + y;
          v[static_cast<size_t>(y) * w + x] = ((along / period) % 2) ^ (u(random) < noise ? 1 : 0);
        }
      }
      // The edges extent: the image or a part of it, with edges where the classes change.
      Rect extent = whole;
      if (trial == 3)
      {
        extent = Rect{ w / 5, w - 1 - w / 7, h / 6, h - 1 - h / 9 };
      }
      EdgesBuffer edges;
      edges.Allocate(extent);
      for (int y = extent.Y0; y <= extent.Y1; ++y)
      {
        for (int x = extent.X0; x <= extent.X1; ++x)
        {
          const int c = v[static_cast<size_t>(y) * w + x];
          unsigned char* e = edges.At(x, y);
          e[0] = (x > extent.X0 && v[static_cast<size_t>(y) * w + x - 1] != c) ? 255 : 0;
          e[1] = (y < extent.Y1 && v[static_cast<size_t>(y + 1) * w + x] != c) ? 255 : 0;
          units += (e[0] && e[1]) ? 1 : 0;
        }
      }
      // Weights extents: the edges extent, and one well inside it.
      for (int inner = 0; inner < 2; ++inner)
      {
        const Rect weightsExtent = inner ? extent.Grown(-std::min(extent.Width(), extent.Height()) / 4)
                                         : extent;
        if (weightsExtent.Empty())
        {
          continue;
        }
        WeightsBuffer runs, search;
        runs.Allocate(weightsExtent);
        search.Allocate(weightsExtent);
        Progress progress;
        settings.RunLengths = true;
        ComputeBlendingWeights(edges, whole, settings, runs, progress);
        settings.RunLengths = false;
        ComputeBlendingWeights(edges, whole, settings, search, progress);
        int differ = 0;
        for (int y = weightsExtent.Y0; y <= weightsExtent.Y1; ++y)
        {
          for (int x = weightsExtent.X0; x <= weightsExtent.X1; ++x)
          {
            if (edges.Any(x, y) && std::memcmp(runs.At(x, y), search.At(x, y), 4) != 0)
            {
              ++differ;
            }
          }
        }
        if (!MLAA_CHECK(differ == 0))
        {
          std::cerr << "steps " << steps << ", trial " << trial << ", inner " << inner << ": "
                    << differ << " pixels with other weights" << std::endl;
        }
      }
    }
  }
  MLAA_CHECK(units > 10000);
}

// A dark half-plane under a line rising by 1 degree, across a 512 x 64 grey image: staircase
// steps of 1 / tan(1 degree), about 57 pixels.
vtkSmartPointer<vtkImageData> OneDegreeSlope()
{
  auto image = MakeImage(512, 64, 1);
  const double slope = std::tan(vtkMath::RadiansFromDegrees(1.0));
  FillImage(image, [slope](int x, int y, int, int) {
    return (y + 0.5) > 20.0 + slope * (x + 0.5) ? 255.0 : 0.0;
  });
  return image;
}

// The staircase of the slope: for each step, its row (the dark row under the edge) and columns.
struct Step
{
  int Row, X0, X1;
};
std::vector<Step> Steps(vtkImageData* image)
{
  std::vector<Step> steps;
  int dims[3];
  image->GetDimensions(dims);
  int current = -1;
  for (int x = 0; x < dims[0]; ++x)
  {
    int row = 0;
    while (row + 1 < dims[1] && GetValue(image, x, row + 1) == 0.0)
    {
      ++row;
    }
    if (row != current)
    {
      steps.push_back(Step{ row, x, x });
      current = row;
    }
    steps.back().X1 = x;
  }
  return steps;
}

void OneDegreeRamps()
{
  auto image = OneDegreeSlope();
  const std::vector<Step> steps = Steps(image);
  MLAA_CHECK(steps.size() >= 8);
  for (int searchSteps : { 8, 32, 64, 128 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(searchSteps);
    options->SetDiagonalDetection(false);
    options->SetLocalContrastFactor(0.0);
    auto out = RunMLAA(image, options);
    options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
    auto weights = RunMLAA(image, options);
    // Held for the whole check: a table over 1 MB that no one holds is freed at once.
    const auto held = vtkMLAAAreaTexture::GetSharedTable(options->GetMaxDistance());
    const std::vector<float>& table = *held;
    const int cell = options->GetMaxDistance() + 1;
    const int size = vtkMLAAAreaTexture::NumberOfCodes * cell;
    bool allExact = true;
    bool allRamps = true;
    // The inner steps (both ends inside the image): a Z shape of two half-steps.
    for (size_t s = 1; s + 1 < steps.size(); ++s)
    {
      const Step& step = steps[s];
      const int length = step.X1 - step.X0 + 1;
      MLAA_CHECK(length >= 56 && length <= 59);
      // Weights: the area of the step's whole line at each pixel (crossing edges: at the left
      // end the line continues one row down, on the owning side (code 3); at the right end one
      // row up, on the opposite side (code 1)).
      for (int x = step.X0; x <= step.X1; ++x)
      {
        const int d1 = x - step.X0, d2 = step.X1 - x;
        const size_t texel = static_cast<size_t>(cell * 1 + d2) * size + (cell * 3 + d1);
        const bool fits = d1 <= 2 * searchSteps && d2 <= 2 * searchSteps;
        for (int k = 0; k < 2; ++k)
        {
          const double expected = std::nearbyint(table[2 * texel + k] * 255.0);
          const double got = GetValue(weights, x, step.Row, k);
          if (fits && got != expected)
          {
            allExact = false;
          }
        }
      }
      // The blended values: one monotonic ramp over the whole step, from bright (where the true
      // edge lies a row below the staircase's, the dark pixels of the left half lighten) to dark
      // (the bright pixels above the right half darken): the sum of the two rows never grows
      // from one pixel to the next, and is not flat over more than a quarter of the step.
      std::vector<double> ramp;
      for (int x = step.X0; x <= step.X1; ++x)
      {
        ramp.push_back(GetValue(out, x, step.Row) + GetValue(out, x, step.Row + 1));
      }
      int flat = 0, longestFlat = 0;
      for (size_t i = 1; i < ramp.size(); ++i)
      {
        if (ramp[i] > ramp[i - 1])
        {
          allRamps = false;
        }
        flat = ramp[i] == ramp[i - 1] ? flat + 1 : 0;
        longestFlat = std::max(longestFlat, flat);
      }
      if (longestFlat > length / 4 || ramp.front() < 255.0 * 1.4 || ramp.back() > 255.0 * 0.6)
      {
        allRamps = false;
      }
    }
    if (searchSteps >= 32)
    {
      if (!MLAA_CHECK(allExact && allRamps))
      {
        std::cerr << searchSteps << " steps: exact weights " << allExact << ", ramps "
                  << allRamps << std::endl;
      }
    }
    else
    {
      // 16 pixels each way cannot see both ends of a 57-pixel step: its middle is left flat.
      MLAA_CHECK(!allRamps);
    }
  }
}
}

int TestImageMLAALongLines(int, char*[])
{
  RunLengthsMatchSearch();
  DiagonalRunsMatchSearch();
  OneDegreeRamps();
  return Result();
}
