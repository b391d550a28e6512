// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAAEdgeDetection.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkMLAAStages
{
//------------------------------------------------------------------------------
void EdgesBuffer::Allocate(const Rect& extent)
{
  this->Extent = extent;
  // Every entry is written by DetectEdges.
  this->Data.Reserve(extent.Empty() ? 0 : 2 * static_cast<size_t>(extent.Width()) * extent.Height());
}

//------------------------------------------------------------------------------
namespace
{
// A difference d kept as a contrast: d where it is at least the threshold and more than nothing
// (so that a zero threshold means "any difference"), else 0. NaN differences are never kept.
template <typename Acc>
inline Acc KeptContrast(Acc d, Acc threshold)
{
  return (d >= threshold && d > Acc(0)) ? d : Acc(0);
}

// The Euclidean distances of n pixels' first three features (planes a0, a1, a2) from those of n
// other pixels (b0, b1, b2), each kept as a contrast (KeptContrast). The square roots are most of
// the cost of LAB edges; an AVX2 clone (no fused multiply-add, so the same results) takes eight at
// a time where the processor has it.
template <typename Acc>
void KeptDistances(const Acc* a0, const Acc* a1, const Acc* a2, const Acc* b0, const Acc* b1,
  const Acc* b2, Acc threshold, Acc* out, int n)
{
  for (int x = 0; x < n; ++x)
  {
    const Acc d0 = a0[x] - b0[x];
    const Acc d1 = a1[x] - b1[x];
    const Acc d2 = a2[x] - b2[x];
    const Acc d = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2);
    out[x] = KeptContrast(d, threshold);
  }
}

VTKMLAA_TARGET_CLONES void KeptDistances3(const float* a0, const float* a1, const float* a2,
  const float* b0, const float* b1, const float* b2, float threshold, float* out, int n)
{
  KeptDistances(a0, a1, a2, b0, b1, b2, threshold, out, n);
}
VTKMLAA_TARGET_CLONES void KeptDistances3(const double* a0, const double* a1, const double* a2,
  const double* b0, const double* b1, const double* b2, double threshold, double* out, int n)
{
  KeptDistances(a0, a1, a2, b0, b1, b2, threshold, out, n);
}

// The contrasts across the left and the top boundaries of the pixels of one row (0: not an
// edge), each with a zero entry before the first and after the last pixel ([-1] and [w]).
template <typename Acc>
struct ContrastRow
{
  Acc* Left;
  Acc* Top;
};

// The features of four rows around a row r of the extent: r - 1, r, r + 1 and r + 2, each null
// where outside the extent.
template <typename Acc>
struct FeatureRows
{
  const Acc* Below;
  const Acc* Row;
  const Acc* Above;
  const Acc* Above2;
};

// The contrasts of rows and the edgels that local contrast adaptation keeps.
template <typename Acc>
class EdgeDetector
{
public:
  EdgeDetector(int features, const EdgeSettings& settings)
    : F(features)
    , E(settings.EuclideanFeatures == 3 && features >= 3 ? 3 : 1)
    , Threshold(static_cast<Acc>(settings.Threshold))
    , Factor(static_cast<Acc>(settings.LocalContrastFactor))
  {
  }

  // The contrast across a boundary of one feature (KeptContrast of the difference).
  Acc Contrast(Acc a, Acc b) const { return this->Kept(std::abs(a - b)); }
  Acc Kept(Acc d) const { return KeptContrast(d, this->Threshold); }

  // The contrasts of one row of w pixels with features f, and the row above with features g
  // (null where there is no row above: no top edges); features in planes of w values. The
  // largest over the features is taken plane by plane, which vectorises.
  void Contrasts(const Acc* f, const Acc* g, ContrastRow<Acc> b, int w) const
  {
    b.Left[-1] = b.Left[w] = b.Top[-1] = b.Top[w] = Acc(0);
    b.Left[0] = Acc(0);
    if (this->E == 3)
    {
      // LAB: Delta E / 100, the Euclidean distance of (L, a, b) / 100 (Biri et al., 3.2).
      const Acc* f1 = f + w;
      const Acc* f2 = f + 2 * w;
      KeptDistances3(f + 1, f1 + 1, f2 + 1, f, f1, f2, this->Threshold, b.Left + 1, w - 1);
    }
    else
    {
      for (int x = 1; x < w; ++x)
      {
        b.Left[x] = this->Contrast(f[x], f[x - 1]);
      }
    }
    for (int k = this->E; k < this->F; ++k)
    {
      const Acc* plane = f + k * w;
      for (int x = 1; x < w; ++x)
      {
        const Acc c = this->Contrast(plane[x], plane[x - 1]);
        b.Left[x] = c > b.Left[x] ? c : b.Left[x];
      }
    }
    if (!g)
    {
      std::fill(b.Top, b.Top + w, Acc(0));
      return;
    }
    if (this->E == 3)
    {
      const Acc* f1 = f + w;
      const Acc* f2 = f + 2 * w;
      const Acc* g1 = g + w;
      const Acc* g2 = g + 2 * w;
      KeptDistances3(f, f1, f2, g, g1, g2, this->Threshold, b.Top, w);
    }
    else
    {
      for (int x = 0; x < w; ++x)
      {
        b.Top[x] = this->Contrast(f[x], g[x]);
      }
    }
    for (int k = this->E; k < this->F; ++k)
    {
      const Acc* plane = f + k * w;
      const Acc* planeAbove = g + k * w;
      for (int x = 0; x < w; ++x)
      {
        const Acc c = this->Contrast(plane[x], planeAbove[x]);
        b.Top[x] = c > b.Top[x] ? c : b.Top[x];
      }
    }
  }

  // Whether a boundary lies inside a ramp rather than at a step: the boundaries before and after
  // it along the same axis change the features the same way as it does, by at least half as
  // much (the projections of their changes on its change d are at least |d| / 2). Sampled
  // shading, a colour map's gradient or an already antialiased edge, which a step's blend would
  // only damage. The four pixels in a row across it are x0 and x of rows a0 and a, xb and x1 of
  // rows b and b1 (planes of `stride` values). a0 or b1 is null where that pixel is outside the
  // extent: at its border the side that is seen decides alone (the ramp goes on out of sight as
  // it does inside). A pixel holding NaN has NaN features: no ramp.
  bool InsideRamp(const Acc* a0, const Acc* a, const Acc* b, const Acc* b1, size_t stride,
    int x0, int x, int xb, int x1) const
  {
    if (!a0 && !b1)
    {
      return false;
    }
    Acc dd = 0, before = 0, after = 0;
    for (int k = 0; k < this->F; ++k)
    {
      const size_t o = k * stride;
      const Acc d = b[o + xb] - a[o + x];
      dd += d * d;
      before += a0 ? d * (a[o + x] - a0[o + x0]) : Acc(0);
      after += b1 ? d * (b1[o + x1] - b[o + xb]) : Acc(0);
    }
    return (!a0 || Acc(2) * before >= dd) && (!b1 || Acc(2) * after >= dd);
  }

  // The edgels of one row that local contrast adaptation (vtkMLAAOptions::LocalContrastFactor)
  // keeps, from the contrasts of the row (b) and of the rows below and above it: an edge whose
  // contrast, times the factor, is below the contrast of one of the six other boundaries of the
  // two pixels it separates is dropped, and so is an edge inside a ramp (InsideRamp, from the
  // features f around the row).
  void KeepEdgels(ContrastRow<Acc> below, ContrastRow<Acc> b, ContrastRow<Acc> above,
    const FeatureRows<Acc>& f, unsigned char* edges, int w) const
  {
    const Acc factor = this->Factor;
    const size_t stride = static_cast<size_t>(w);
    // Most boundaries are not edges: clear the row, and skip runs of pixels whose contrasts are
    // all +0 (contrasts are never negative or NaN), 16 bytes of each at a time.
    std::fill(edges, edges + 2 * static_cast<size_t>(w), 0);
    constexpr int chunk = static_cast<int>(16 / sizeof(Acc));
    for (int x = 0; x < w; ++x)
    {
      if (x % chunk == 0 && x + chunk <= w)
      {
        std::uint64_t bits[4];
        std::memcpy(bits, b.Left + x, 16);
        std::memcpy(bits + 2, b.Top + x, 16);
        if ((bits[0] | bits[1] | bits[2] | bits[3]) == 0)
        {
          x += chunk - 1;
          continue;
        }
      }
      const Acc left = b.Left[x];
      const Acc top = b.Top[x];
      if (!(left > Acc(0)) && !(top > Acc(0)))
      {
        continue;
      }
      unsigned char* edge = edges + 2 * x;
      // The ramp test last: most edges that reach it are kept.
      edge[0] = (left > Acc(0) &&
                   (factor == Acc(0) ||
                     (factor * left >= std::max({ b.Left[x - 1], b.Left[x + 1], b.Top[x - 1],
                                         top, below.Top[x - 1], below.Top[x] }) &&
                       !this->InsideRamp(x >= 2 ? f.Row : nullptr, f.Row, f.Row,
                         x + 1 < w ? f.Row : nullptr, stride, x - 2, x - 1, x, x + 1))))
        ? 255
        : 0;
      edge[1] = (top > Acc(0) &&
                   (factor == Acc(0) ||
                     (factor * top >= std::max({ below.Top[x], above.Top[x], left,
                                        b.Left[x + 1], above.Left[x], above.Left[x + 1] }) &&
                       !this->InsideRamp(
                         f.Below, f.Row, f.Above, f.Above2, stride, x, x, x, x))))
        ? 255
        : 0;
    }
  }

private:
  int F;
  int E; // leading features compared by Euclidean distance (1 or 3)
  Acc Threshold;
  Acc Factor;
};
}

//------------------------------------------------------------------------------
// Section 4.2: the contrast across every boundary (0 where it is not an edge), then the edgels
// that local contrast adaptation keeps. Each task takes a band of rows and computes the
// contrasts of its rows and of the rows just below and above it (which adaptation reads) from
// the features of those rows, so no full-size buffer but the edges is needed.
template <typename Acc>
void DetectEdges(const std::function<void(int, Acc*)>& readRow, int features,
  const EdgeSettings& settings, EdgesBuffer& edges, Progress& progress)
{
  const Rect r = edges.Extent;
  if (r.Empty())
  {
    return;
  }
  const int w = r.Width();
  const int h = r.Height();
  const EdgeDetector<Acc> detector(features, settings);
  // Each task also reads the features of two rows and computes the contrasts of one row on each
  // side of its own.
  vtkSMPTools::For(0, h, BandRowsPerTask(h), [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    // Keeping the edgels of a row reads the contrasts of the rows beside it: the contrasts of
    // four consecutive rows are kept, row i in slot i % 4, and rows outside the extent (no
    // boundaries) read a fifth slot of zeros. A few rows, which stay in the cache.
    const size_t stride = static_cast<size_t>(w) + 2;
    std::vector<Acc> contrasts(2 * stride * 5);
    Acc* outside = contrasts.data() + 2 * stride * 4;
    std::fill(outside, outside + 2 * stride, Acc(0));
    auto contrastRow = [&](int i) {
      Acc* left = (i < 0 || i >= h) ? outside : contrasts.data() + 2 * stride * (i % 4);
      return ContrastRow<Acc>{ left + 1, left + stride + 1 };
    };
    const int first = std::max(0, static_cast<int>(begin) - 1);
    const int last = std::min(h - 1, static_cast<int>(end));
    // The features of four consecutive rows, row i in slot i % 4: the contrasts of row i read
    // rows i and i + 1, the edgels of row i - 1 then keep read rows i - 2 to i + 1.
    const size_t rowSize = static_cast<size_t>(w) * features;
    std::vector<Acc> ring(4 * rowSize);
    int loaded = first - 1; // the last row read
    auto featuresOf = [&](int i) -> const Acc* {
      if (i < 0 || i >= h)
      {
        return nullptr; // outside the extent
      }
      for (; loaded < i; ++loaded)
      {
        readRow(r.Y0 + loaded + 1, ring.data() + rowSize * ((loaded + 1) % 4));
      }
      return ring.data() + rowSize * (i % 4);
    };
    for (int i = first; i <= last + 1; ++i)
    {
      if (i <= last)
      {
        // The top row of the extent has no top edge (no row above: null).
        const Acc* row = featuresOf(i);
        detector.Contrasts(row, featuresOf(i + 1), contrastRow(i), w);
      }
      const int kept = i - 1; // its contrasts and those of the rows beside it are known
      if (kept >= begin && kept < end)
      {
        const FeatureRows<Acc> around{ featuresOf(kept - 1), featuresOf(kept), featuresOf(kept + 1),
          featuresOf(kept + 2) };
        detector.KeepEdgels(contrastRow(kept - 1), contrastRow(kept), contrastRow(kept + 1),
          around, edges.At(r.X0, r.Y0 + kept), w);
      }
    }
    progress.RowsDone(end - begin);
  });
}

template VTKFILTERSMLAA_EXPORT void DetectEdges<float>(const std::function<void(int, float*)>&,
  int, const EdgeSettings&, EdgesBuffer&, Progress&);
template VTKFILTERSMLAA_EXPORT void DetectEdges<double>(const std::function<void(int, double*)>&,
  int, const EdgeSettings&, EdgesBuffer&, Progress&);
}
