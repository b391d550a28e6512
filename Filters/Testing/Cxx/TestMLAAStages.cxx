// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The stages of the CPU MLAA (vtkMLAAStages.h), each on its own: the halo derived from the
// options, the features (normalisation, luma, planes, NaN), edge detection (threshold, image
// border, local contrast adaptation, edges inside ramps), blending weights (an L shape against
// the area texture's generator), neighbourhood blending (equation 4.1, dominant direction,
// straight and premultiplied alpha), the whole slice on the smallest extents, and the buffers
// that every filter of the process shares.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAStages.h"

#include <cmath>
#include <limits>
#include <vector>

using namespace vtkMLAATest;
using namespace vtkMLAAStages;

namespace
{
void HaloFromOptions()
{
  vtkNew<vtkMLAAOptions> options;
  vtkNew<vtkImageMLAA> filter;
  filter->SetOptions(options);
  struct Case
  {
    int Steps;
    bool Diagonals;
    double Factor;
    int Search, Edges;
    bool Corners = false;
  };
  for (const Case& c : { Case{ 8, true, 2.0, 19, 2 }, Case{ 8, false, 2.0, 17, 2 },
         Case{ 8, true, 0.0, 19, 0 }, Case{ 3, true, 1.0, 9, 2 }, Case{ 64, false, 0.0, 129, 0 },
         Case{ 8, true, 2.0, 36, 2, true }, Case{ 64, false, 0.0, 258, 0, true } })
  {
    options->SetMaxSearchSteps(c.Steps);
    options->SetDiagonalDetection(c.Diagonals);
    options->SetCornerExtrapolation(c.Corners);
    options->SetLocalContrastFactor(c.Factor);
    const Halo halo = ComputeHalo(options);
    MLAA_CHECK(halo.Blending == 1);
    MLAA_CHECK(halo.Search == c.Search);
    MLAA_CHECK(halo.Edges == c.Edges);
    MLAA_CHECK(filter->GetInputPadding() == halo.Total());
  }
}

void Features()
{
  // RGB bytes: luma with Rec. 709 weights, the same floats as the arithmetic.
  {
    const unsigned char rgb[] = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30 };
    const FeatureReader<unsigned char, float> reader(
      MakeFeatureLayout(vtkMLAAOptions::LUMA, 3), 0.0f, 1.0f / 255.0f);
    // Room for four planes (Lab and alpha): GCC cannot see which planes a layout writes and
    // warns otherwise.
    float f[16];
    reader.Row(rgb, 4, nullptr, f);
    for (int x = 0; x < 4; ++x)
    {
      const unsigned char* p = rgb + 3 * x;
      const float expected = 0.2126f * (p[0] * (1.0f / 255.0f)) +
        0.7152f * (p[1] * (1.0f / 255.0f)) + 0.0722f * (p[2] * (1.0f / 255.0f));
      MLAA_CHECK(f[x] == expected);
    }
  }
  // Signed bytes, every channel of grey + alpha: one plane per channel, normalised by the
  // type's range.
  {
    const signed char ga[] = { -128, 127, 0, -128, 127, 0 };
    const FeatureLayout layout = MakeFeatureLayout(vtkMLAAOptions::COLOR, 2);
    MLAA_CHECK(layout.Count == 2 && layout.HasAlpha);
    const FeatureReader<signed char, float> reader(layout, -128.0f, 1.0f / 255.0f);
    float f[16];
    reader.Row(ga, 3, nullptr, f);
    const float expected[6] = { 0.0f, 128.0f / 255.0f, 1.0f, 1.0f, 0.0f, 128.0f / 255.0f };
    for (int i = 0; i < 6; ++i)
    {
      MLAA_CHECK(std::abs(f[i] - expected[i]) < 1e-6f);
    }
  }
  // Float RGBA: luma then alpha; a pixel with NaN or infinity in any channel gets NaN features.
  {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const float rgba[] = { 1, 1, 1, 0.5f, nan, 0, 0, 1, 0, 0, 0, inf };
    const FeatureLayout layout = MakeFeatureLayout(vtkMLAAOptions::LUMA, 4);
    MLAA_CHECK(layout.Count == 2);
    const FeatureReader<float, float> reader(layout, 0.0f, 1.0f);
    float f[16];
    reader.Row(rgba, 3, nullptr, f);
    MLAA_CHECK(std::abs(f[0] - 1.0f) < 1e-6f && f[3] == 0.5f);
    MLAA_CHECK(std::isnan(f[1]) && std::isnan(f[4]));
    MLAA_CHECK(std::isnan(f[2]) && std::isnan(f[5]));
  }
  // Depth: the normalised depth, then alpha.
  {
    const unsigned short ga[] = { 0, 65535, 65535, 0 };
    const double depth[] = { 0.25, 0.75 };
    const FeatureReader<unsigned short, float> reader(
      MakeFeatureLayout(vtkMLAAOptions::DEPTH, 2), 0.0f, 1.0f / 65535.0f);
    float f[16];
    reader.Row(ga, 2, depth, f);
    MLAA_CHECK(f[0] == 0.25f && f[1] == 0.75f && f[2] == 1.0f && f[3] == 0.0f);
  }
}

// Edge detection on a grid of luma values, rows listed bottom first.
EdgesBuffer Edges(const std::vector<std::vector<float>>& rows, double factor, double threshold = 0.1)
{
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows[0].size());
  EdgesBuffer edges;
  edges.Allocate({ 10, 10 + w - 1, 20, 20 + h - 1 }); // any extent, not only from 0
  const std::function<void(int, float*)> readRow = [&](int y, float* f) {
    std::copy(rows[y - 20].begin(), rows[y - 20].end(), f);
  };
  EdgeSettings settings;
  settings.Threshold = threshold;
  settings.LocalContrastFactor = factor;
  Progress progress;
  DetectEdges<float>(readRow, 1, settings, edges, progress);
  return edges;
}

void EdgeDetection()
{
  // A vertical step between columns 1 and 2 and a horizontal one between rows 1 and 2 (of
  // columns 3 and 4): left edgels on column 2, top edgels on row 1; the extent's own border is
  // not an edge; a difference below the threshold is not one either.
  const std::vector<std::vector<float>> rows = { { 0.00f, 0.05f, 1, 1, 1 },
    { 0.00f, 0.05f, 1, 0.3f, 0.3f }, { 0.00f, 0.05f, 1, 1, 1 }, { 0.00f, 0.05f, 1, 1, 1 } };
  const EdgesBuffer e = Edges(rows, 0.0);
  for (int y = 20; y < 24; ++y)
  {
    for (int x = 10; x < 15; ++x)
    {
      const bool left = x == 12 || (y == 21 && x == 13);
      const bool top = (y == 20 || y == 21) && x >= 13;
      MLAA_CHECK(e.Left(x, y) == left);
      MLAA_CHECK(e.Top(x, y) == top);
      MLAA_CHECK(e.At(x, y)[0] == (left ? 255 : 0) && e.At(x, y)[1] == (top ? 255 : 0));
    }
  }

  // Local contrast adaptation: a faint step (0.2) meets a strong one (0.9) at a pixel. With the
  // factor 2 the faint edgel is dropped (2 x 0.2 < 0.9), with 5 it is kept, with 0 always.
  const std::vector<std::vector<float>> meet = { { 0.0f, 0.0f, 0.9f }, { 0.2f, 0.2f, 0.9f } };
  // The faint boundary is the top of (0, 0) and (1, 0); the strong ones are left of column 2.
  MLAA_CHECK(!Edges(meet, 2.0).Top(11, 20));
  MLAA_CHECK(Edges(meet, 2.0).Top(10, 20)); // no stronger boundary beside (0, 0)
  MLAA_CHECK(Edges(meet, 5.0).Top(11, 20));
  MLAA_CHECK(Edges(meet, 0.0).Top(11, 20));
  MLAA_CHECK(Edges(meet, 2.0).Left(12, 20) && Edges(meet, 2.0).Left(12, 21));

  // One row and one column: nothing to compare across the missing direction.
  const EdgesBuffer row = Edges({ { 0, 1, 0 } }, 2.0);
  MLAA_CHECK(row.Left(11, 20) && row.Left(12, 20) && !row.Top(11, 20));
  const EdgesBuffer column = Edges({ { 0 }, { 1 } }, 2.0);
  MLAA_CHECK(column.Top(10, 20) && !column.Left(10, 20) && !column.Top(10, 21));
}

// Edges inside ramps (issue 20): a boundary whose neighbours along the same axis, before and
// after it, change the values the same way by at least half as much is sampled shading, not a
// step: local contrast adaptation drops it; its factor 0 (off) keeps it.
void Ramps()
{
  // A ramp of 0.2 a pixel from 0 to 1 along x, three rows high: the edgels at its two ends (x =
  // 2 and 6: a flat pixel on one side) are kept, the three inside it dropped. The same along y.
  const std::vector<float> ramp = { 0.0f, 0.0f, 0.2f, 0.4f, 0.6f, 0.8f, 1.0f, 1.0f };
  const EdgesBuffer along = Edges({ ramp, ramp, ramp }, 2.0);
  const EdgesBuffer off = Edges({ ramp, ramp, ramp }, 0.0);
  std::vector<std::vector<float>> column;
  for (const float v : ramp)
  {
    column.push_back({ v, v });
  }
  const EdgesBuffer across = Edges(column, 2.0);
  for (int i = 0; i < 8; ++i)
  {
    const bool end = i == 2 || i == 6;
    const bool inside = i >= 3 && i <= 5;
    for (int j = 0; j < 2; ++j)
    {
      MLAA_CHECK(along.Left(10 + i, 20 + j) == end);
      MLAA_CHECK(off.Left(10 + i, 20 + j) == (end || inside));
      MLAA_CHECK(!along.Top(10 + i, 20 + j));
      // A top edgel is on the row below its boundary: the rise from row 1 to 2, from 5 to 6.
      MLAA_CHECK(across.Top(10 + j, 20 + i) == (i == 1 || i == 5));
      MLAA_CHECK(!across.Left(10 + j, 20 + i));
    }
  }
  // At least half as much: before the edgel at x = 2 the values rise by 0.12 (more than half of
  // its 0.2: a ramp) or by 0.08 (less: a step).
  MLAA_CHECK(!Edges({ { 0.0f, 0.12f, 0.32f, 0.52f, 0.52f } }, 2.0).Left(12, 20));
  MLAA_CHECK(Edges({ { 0.0f, 0.08f, 0.28f, 0.48f, 0.48f } }, 2.0).Left(12, 20));
  // The same way: a zigzag has no ramp; every boundary is an edge.
  const EdgesBuffer zigzag = Edges({ { 0.0f, 0.3f, 0.1f, 0.3f, 0.1f, 0.3f } }, 2.0);
  for (int x = 11; x <= 15; ++x)
  {
    MLAA_CHECK(zigzag.Left(x, 20));
  }
  // A NaN pixel before the edge: no ramp (x = 2). At the extent's border the side seen decides
  // alone: the last boundary (x = 3) goes on from the one before it, a ramp; the last of
  // { 0, 0, 0.2 } follows a flat pair, a step; a two-pixel extent sees neither side, a step.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const EdgesBuffer open = Edges({ { nan, 0.2f, 0.4f, 0.6f } }, 2.0);
  MLAA_CHECK(!open.Left(11, 20) && open.Left(12, 20) && !open.Left(13, 20));
  MLAA_CHECK(Edges({ { 0.0f, 0.0f, 0.2f } }, 2.0).Left(12, 20));
  MLAA_CHECK(Edges({ { 0.0f, 0.5f } }, 2.0).Left(11, 20));
  const EdgesBuffer bottom = Edges({ { 0.0f }, { 0.2f }, { 0.4f } }, 2.0);
  MLAA_CHECK(!bottom.Top(10, 20) && !bottom.Top(10, 21)); // each boundary sees one side rise
}

void BlendingWeights()
{
  // A horizontal line of top edgels on row 2 from x = 3 to x = 12, with a crossing edge (a left
  // edgel on the line's own row) at its left end only: an L. Each pixel of the line takes the
  // area of the L for its distances to both ends (section 4.3.3), from the shared generator.
  // (Only pixels with edgels get weights; the others are never written.)
  vtkNew<vtkMLAAOptions> options;
  options->SetDiagonalDetection(false);
  WeightSettings settings;
  MakeWeightSettings(options, settings);
  const Rect whole = { 0, 19, 0, 5 };
  EdgesBuffer edges;
  edges.Allocate(whole);
  std::fill(edges.Data.Get(), edges.Data.Get() + edges.Data.GetSize(), 0);
  for (int x = 3; x <= 12; ++x)
  {
    edges.At(x, 2)[1] = 255;
  }
  edges.At(3, 2)[0] = 255;
  WeightsBuffer weights;
  weights.Allocate(whole);
  Progress progress;
  ComputeBlendingWeights(edges, whole, settings, weights, progress);
  for (int y = whole.Y0; y <= whole.Y1; ++y)
  {
    for (int x = whole.X0; x <= whole.X1; ++x)
    {
      const unsigned char* w = weights.At(x, y);
      if (y == 2 && x >= 4 && x <= 12)
      {
        double areas[2];
        vtkMLAAAreaTexture::ComputeAreas(3, 0, x - 3, 12 - x, areas);
        MLAA_CHECK(w[0] == std::nearbyint(255.0 * areas[0]));
        MLAA_CHECK(w[1] == std::nearbyint(255.0 * areas[1]));
        MLAA_CHECK(w[2] == 0 && w[3] == 0);
      }

    }
  }
  // The L is not flat: the pixels near its corner blend.
  MLAA_CHECK(weights.At(4, 2)[0] > 0);
}

// BlendRow on a 3 x 3 image whose centre pixel has the given weights (bytes, as stored) and the
// edgels that go with them.
template <typename T>
std::vector<T> BlendCentre(const std::vector<T>& pixels, int components, const unsigned char own[4],
  const BlendSettings& settings)
{
  const Rect all = { 0, 2, 0, 2 };
  EdgesBuffer edges;
  edges.Allocate(all);
  std::fill(edges.Data.Get(), edges.Data.Get() + edges.Data.GetSize(), 0);
  edges.At(1, 1)[0] = (own[2] || own[3]) ? 255 : 0;
  edges.At(1, 1)[1] = (own[0] || own[1]) ? 255 : 0;
  WeightsBuffer weights;
  weights.Allocate(all);
  std::fill(weights.Data.Get(), weights.Data.Get() + weights.Data.GetSize(), 77); // never read
  std::copy(own, own + 4, weights.At(1, 1));
  auto pixel = [&](int x, int y) { return pixels.data() + (3 * y + x) * components; };
  std::vector<T> out(3 * components);
  BlendRow<T, float>(1, all, components, edges, weights, settings, pixel, out.data());
  // The other pixels of the row have no weights: copied.
  MLAA_CHECK(std::equal(out.begin(), out.begin() + components, pixel(0, 1)));
  MLAA_CHECK(std::equal(out.begin() + 2 * components, out.end(), pixel(2, 1)));
  return std::vector<T>(out.begin() + components, out.begin() + 2 * components);
}

void NeighbourhoodBlending()
{
  // Grey: the centre (0) takes 64/255 of the pixel above it (255): equation 4.1 gives 64.
  std::vector<unsigned char> grey = { 9, 9, 9, 9, 0, 200, 9, 255, 9 };
  const unsigned char up[4] = { 64, 0, 0, 0 };
  BlendSettings plain;
  MLAA_CHECK(BlendCentre(grey, 1, up, plain)[0] == 64);
  // A corner with a vertical (64) and a horizontal (32) weight: with dominant-direction
  // blending only the vertical one counts; without, the blends with the pixel above (255) and
  // the one on the left (9) are averaged by their weights a and b: (a a 255 + b b 9) / (a + b)
  // = 43.04 -> 43, with a = 64 / 255 and b = 32 / 255.
  const unsigned char corner[4] = { 64, 0, 32, 0 };
  MLAA_CHECK(BlendCentre(grey, 1, corner, plain)[0] == 64);
  BlendSettings average;
  average.Dominant = false;
  {
    const float a = 64.0f / 255.0f, b = 32.0f / 255.0f;
    const float blended = (a * (a * 255.0f) + b * (b * 9.0f)) / (a + b);
    MLAA_CHECK(BlendCentre(grey, 1, corner, average)[0] == std::floor(blended + 0.5f));
  }

  // Grey + alpha: a transparent black pixel takes 128/255 of an opaque white one above it. With
  // straight alpha the colour stays white (transparent pixels have no colour to give) and only
  // alpha is blended; with premultiplied alpha the values blend as they are.
  std::vector<unsigned char> ga = { 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 255, 255, 0, 0 };
  const unsigned char half[4] = { 128, 0, 0, 0 };
  BlendSettings straight;
  straight.StraightAlpha = true;
  straight.AlphaInverseRange = 1.0 / 255.0;
  const std::vector<unsigned char> s = BlendCentre(ga, 2, half, straight);
  MLAA_CHECK(s[0] == 255 && s[1] == 128);
  const std::vector<unsigned char> p = BlendCentre(ga, 2, half, plain);
  MLAA_CHECK(p[0] == 128 && p[1] == 128);
  // Equal alphas: straight alpha changes nothing.
  std::vector<unsigned char> opaque = ga;
  for (size_t i = 1; i < opaque.size(); i += 2)
  {
    opaque[i] = 255;
  }
  MLAA_CHECK(BlendCentre(opaque, 2, half, straight) == BlendCentre(opaque, 2, half, plain));
}

// The filter on the smallest extents, every scalar type and component count: no error, the
// same size and type, and values within the input's range (an output pixel is a mix of input
// pixels).
void SmallestExtents()
{
  const int types[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
    VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG,
    VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE };
  const int sizes[][3] = { { 1, 1, 1 }, { 1, 7, 1 }, { 7, 1, 1 }, { 2, 2, 1 }, { 1, 1, 5 },
    { 1, 4, 3 }, { 3, 2, 2 } };
  for (int type : types)
  {
    for (int components = 1; components <= 4; ++components)
    {
      for (const auto& size : sizes)
      {
        auto image = MakeImage(size[0], size[1], components, type, 0.0, size[2]);
        const bool real = type == VTK_FLOAT || type == VTK_DOUBLE;
        FillImage(image, [&](int x, int y, int z, int k) {
          const bool on = (x + 2 * y + z + k) % 3 == 0;
          return real ? (on ? 1.0 : 0.0) : (on ? 100.0 : 3.0);
        });
        for (bool diagonals : { true, false })
        {
          vtkNew<vtkMLAAOptions> options;
          options->SetDiagonalDetection(diagonals);
          options->SetEdgeDetection(components % 2 ? vtkMLAAOptions::LUMA : vtkMLAAOptions::COLOR);
          vtkNew<vtkImageMLAA> filter;
          vtkNew<MessageObserver> messages;
          messages->Watch(filter);
          filter->SetOptions(options);
          filter->SetInputData(image);
          filter->Update();
          vtkImageData* out = filter->GetOutput();
          int dims[3];
          out->GetDimensions(dims);
          MLAA_CHECK(messages->Errors.empty());
          MLAA_CHECK(dims[0] == size[0] && dims[1] == size[1] && dims[2] == size[2]);
          MLAA_CHECK(out->GetScalarType() == type);
          MLAA_CHECK(out->GetNumberOfScalarComponents() == components);
          bool inRange = true;
          for (int z = 0; z < size[2]; ++z)
          {
            for (int y = 0; y < size[1]; ++y)
            {
              for (int x = 0; x < size[0]; ++x)
              {
                for (int k = 0; k < components; ++k)
                {
                  const double v = GetValue(out, x, y, k, z);
                  inRange = inRange && v >= (real ? 0.0 : 3.0) && v <= (real ? 1.0 : 100.0);
                }
              }
            }
          }
          MLAA_CHECK(inRange);
          if (size[0] * size[1] == 1)
          {
            MLAA_CHECK(Compare(image, out).Count == 0); // nothing to blend with
          }
        }
      }
    }
  }
}

// The stages' buffers come from one pool for the process: a new filter per image runs on the
// buffers the last one gave back, with the same result as a reused filter; buffers in use at
// once are distinct; the pool keeps at most RetainedBytes, the most recently returned first.
void SharedBuffers()
{
  auto image = MakeImage(67, 45, 3);
  FillImage(image, [](int x, int y, int, int k) {
    // A tilted square and a circle: edges in every direction.
    const bool square = std::abs((x - 20) + 0.3 * (y - 22)) < 12 && std::abs((y - 22) - 0.3 * (x - 20)) < 12;
    const bool circle = (x - 50) * (x - 50) + (y - 20) * (y - 20) < 100;
    return square ? 200.0 + 10 * k : circle ? 40.0 : 120.0;
  });
  vtkNew<vtkImageMLAA> reused;
  reused->SetInputData(image);
  reused->Update();
  vtkNew<vtkImageData> first;
  first->DeepCopy(reused->GetOutput());
  const size_t retained = GetRetainedSliceBufferBytes();
  MLAA_CHECK(retained > 0 && retained <= RetainedBytes);
  for (int i = 0; i < 3; ++i)
  {
    // A new filter per image: the buffers the last update gave back, the same output.
    vtkNew<vtkImageMLAA> filter;
    filter->SetInputData(image);
    filter->Update();
    MLAA_CHECK(Compare(first, filter->GetOutput()).Count == 0);
    MLAA_CHECK(GetRetainedSliceBufferBytes() == retained);
  }
  reused->Modified();
  reused->Update();
  MLAA_CHECK(Compare(first, reused->GetOutput()).Count == 0);
  {
    SliceBuffersLease a = AcquireSliceBuffers();
    MLAA_CHECK(a->GetCapacity() == retained); // the set the filters used
    MLAA_CHECK(GetRetainedSliceBufferBytes() == 0);
    SliceBuffersLease b = AcquireSliceBuffers();
    MLAA_CHECK(b.get() != a.get() && b->GetCapacity() == 0);
    // Both are kept: a, destroyed last, is the first taken next time.
  }
  MLAA_CHECK(GetRetainedSliceBufferBytes() == retained);
  {
    // Buffers larger than the limit are freed, not kept.
    SliceBuffersLease filters = AcquireSliceBuffers();
    MLAA_CHECK(filters->GetCapacity() == retained);
    SliceBuffersLease big = AcquireSliceBuffers();
    big->Reconstructed.Reserve(RetainedBytes + 1);
  }
  MLAA_CHECK(GetRetainedSliceBufferBytes() == retained);
  {
    // Two sets of more than half the limit each: only the one returned last is kept.
    SliceBuffersLease a = AcquireSliceBuffers();
    SliceBuffersLease b = AcquireSliceBuffers();
    SliceBuffersLease c = AcquireSliceBuffers();
    a->Reconstructed.Reserve(RetainedBytes / 2 + 1);
    b->Reconstructed.Reserve(RetainedBytes / 2 + 2);
    SliceBuffers* kept = c.get();
    c->Reconstructed.Reserve(1);
    c.reset();
    a.reset();
    b.reset();
    MLAA_CHECK(GetRetainedSliceBufferBytes() == RetainedBytes / 2 + 2);
    SliceBuffersLease again = AcquireSliceBuffers();
    MLAA_CHECK(again->GetCapacity() == RetainedBytes / 2 + 2 && again.get() != kept);
  }
}
}

int TestMLAAStages(int, char*[])
{
  HaloFromOptions();
  Features();
  EdgeDetection();
  Ramps();
  BlendingWeights();
  NeighbourhoodBlending();
  SmallestExtents();
  SharedBuffers();
  return Result();
}
