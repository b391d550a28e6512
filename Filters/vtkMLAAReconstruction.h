// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAAReconstruction.h
 * @brief  MLAA stage 0 (optional), topological reconstruction (second paper, section 4); the twin
 *         of Rendering/glsl/vtkMLAAReconstructionFS.glsl.
 *
 * Reconstruct, typed, runs before the features when vtkMLAAOptions::Reconstruction is on; its
 * output replaces the input of every later stage. The selection rule is vtkMLAATopology's.
 *
 * Internal to MLAA::FiltersMLAA (tests and benchmarks include it); not installed.
 */

#ifndef vtkMLAAReconstruction_h
#define vtkMLAAReconstruction_h

#include "vtkAntialiasingKit.h"
#include "vtkMLAATopology.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

//------------------------------------------------------------------------------
// Stage 0 (optional): topological reconstruction (Biri et al., section 4), typed; runs before
// the features when vtkMLAAOptions::Reconstruction is on, and its output replaces the input of
// every later stage.

/**
 * Whether two pixels with LAB features (FeatureReader in LAB mode, `count` planes `plane`
 * values apart) are unlike for reconstruction: Delta E / 100 at least the threshold (and more
 * than 0), or, with alpha (count 4), the alpha difference likewise: the boundary between them
 * would be a LAB edge before local contrast adaptation. NaN features (non-finite pixels) are
 * never unlike anything. Distances are compared squared, which is the same test.
 * Must match unlike() in Rendering/glsl/vtkMLAAReconstructionFS.glsl.
 */
template <typename Acc>
bool Unlike(const Acc* p, const Acc* q, size_t plane, int count, Acc threshold2)
{
  const Acc d0 = p[0] - q[0];
  const Acc d1 = p[plane] - q[plane];
  const Acc d2 = p[2 * plane] - q[2 * plane];
  const Acc e2 = d0 * d0 + d1 * d1 + d2 * d2;
  if (e2 >= threshold2 && e2 > Acc(0))
  {
    return true;
  }
  if (count > 3)
  {
    const Acc da = p[3 * plane] - q[3 * plane];
    const Acc a2 = da * da;
    return a2 >= threshold2 && a2 > Acc(0);
  }
  return false;
}

/**
 * Unlike for pixels first..last - 1 of a row of features `a` against `b` (the same row, or the
 * one below or above, offset to the neighbour): `value` is or-ed into mask[x] where they are
 * unlike. One branch-free loop per direction.
 */
template <typename Acc, bool Alpha>
void UnlikeMasks(const Acc* a, const Acc* b, size_t plane, Acc threshold2, unsigned char value,
  int first, int last, unsigned char* mask)
{
  const Acc* a1 = a + plane;
  const Acc* a2 = a + 2 * plane;
  const Acc* a3 = a + 3 * plane;
  const Acc* b1 = b + plane;
  const Acc* b2 = b + 2 * plane;
  const Acc* b3 = b + 3 * plane;
  for (int x = first; x < last; ++x)
  {
    const Acc d0 = a[x] - b[x];
    const Acc d1 = a1[x] - b1[x];
    const Acc d2 = a2[x] - b2[x];
    const Acc e2 = d0 * d0 + d1 * d1 + d2 * d2;
    bool unlike = (e2 >= threshold2) & (e2 > Acc(0));
    if (Alpha)
    {
      const Acc da = a3[x] - b3[x];
      const Acc a2d = da * da;
      unlike = unlike | ((a2d >= threshold2) & (a2d > Acc(0)));
    }
    mask[x] |= unlike ? value : static_cast<unsigned char>(0);
  }
}

/**
 * The neighbour masks (bits as vtkMLAATopology) of pixels first..last - 1 of a row from the
 * comparisons of Reconstruct (1 where unlike): toE[x] with the pixel right of x, toN, toNE and
 * toNW[x] with the pixels above, and those of the row below, whose entries at x, x - 1 and
 * x + 1 are the comparisons of pixel x with its S, SW and SE neighbours.
 */
inline void CombineUnlike(const unsigned char* __restrict toE,
  const unsigned char* __restrict toNE, const unsigned char* __restrict toN,
  const unsigned char* __restrict toNW, const unsigned char* __restrict belowNE,
  const unsigned char* __restrict belowN, const unsigned char* __restrict belowNW, int first,
  int last, unsigned char* __restrict mask)
{
  for (int x = first; x < last; ++x)
  {
    mask[x] = static_cast<unsigned char>(toE[x] | (toNE[x] << 1) | (toN[x] << 2) |
      (toNW[x] << 3) | (toE[x - 1] << 4) | (belowNE[x - 1] << 5) | (belowN[x] << 6) |
      (belowNW[x + 1] << 7));
  }
}

/** The number of bits set in an 8-bit mask. */
// Where x is a multiple of 8 with eight mask bytes left in the row (w wide) and all eight are
// zero, moves x to the last of them and returns true, so that the caller's loop goes past them.
inline bool SkipClearEight(const unsigned char* mask, int& x, int w)
{
  if ((x & 7) == 0 && x + 8 <= w)
  {
    std::uint64_t eight;
    std::memcpy(&eight, mask + x, sizeof(eight));
    if (eight == 0)
    {
      x += 7;
      return true;
    }
  }
  return false;
}

inline int Popcount8(unsigned int m)
{
  m = (m & 0x55u) + ((m >> 1) & 0x55u);
  m = (m & 0x33u) + ((m >> 2) & 0x33u);
  return static_cast<int>((m & 0x0Fu) + (m >> 4));
}

// `value` moved by the share `t` (in [0, 1]) of the way to `target`. For floating-point images
// whose values are so large that their difference is not finite (the filters take any finite
// value), the same as a weighted mean, which stays within the two values.
inline double MoveTowards(double value, double target, double t)
{
  const double difference = target - value;
  return std::isfinite(difference) ? value + t * difference : (1.0 - t) * value + t * target;
}

/** What reconstruction needs of a slice (vtkMLAAStages.h: SliceSetup::GetReconstruction). */
struct ReconstructionSettings
{
  Rect Input;            // the pixels available, which are reconstructed
  int Components = 3;    // of the image
  double Threshold = 0.1; // vtkMLAAOptions::Threshold, as Delta E / 100 (LAB edges)
  double Lo = 0.0;       // normalisation: value -> (value - Lo) / (Hi - Lo)
  double Hi = 1.0;
};

/**
 * Section 4.3: the reconstructed pixels of setup.Input into `output` (rows of
 * setup.Input.Width() pixels, packed). `input` points at the first pixel of setup.Input (rows
 * `inputRowStride` values apart); reads beyond setup.Input are clamped to it (the halo keeps
 * those reads away from the output, and at the image border they are clamped as a GPU clamps
 * texture reads). For each pixel A, X is the mask of its neighbours unlike A (Unlike, threshold
 * setup.Threshold; bits as vtkMLAATopology). A is selected when
 * vtkMLAATopology::GetSelectionTable() says so and the X pixels are pairwise not unlike (one
 * colour: the shape), and the coverage rule (vtkMLAATopology::GetCoverage of the pixels of its
 * window of radius vtkMLAATopology::CoverageRadius not unlike the shape's first pixel) gives it
 * a share above 0; it then moves by that share towards the mean of its X pixels, every
 * component, rounded to nearest for integer types (a gap). A pixel that is not a gap but is
 * unlike one of its neighbours that is, whose n exceeds its number of unlike neighbours, keeps
 * vtkMLAATopology::GetLineShare(n) of its colour and takes the rest from that gap (the thin
 * line rule; the largest n, the first in neighbour order among equals). Every other pixel is
 * copied. All decisions read the original pixels; reads reach
 * vtkMLAATopology::ReconstructionReach beyond a pixel.
 * Must match Rendering/glsl/vtkMLAAReconstructionFS.glsl.
 */
template <typename T>
void Reconstruct(const ReconstructionSettings& setup, const T* input, vtkIdType inputRowStride, T* output,
  Progress& progress)
{
  using Acc = AccumulatorType<T>;
  const Rect& in = setup.Input;
  if (in.Empty())
  {
    return;
  }
  const int w = in.Width();
  const int h = in.Height();
  const int c = setup.Components;
  const FeatureLayout layout = MakeFeatureLayout(vtkMLAAOptions::LAB, c);
  const int count = layout.Count;
  const size_t plane = static_cast<size_t>(w);
  const FeatureReader<T, Acc> reader(
    layout, static_cast<Acc>(setup.Lo), static_cast<Acc>(1.0 / (setup.Hi - setup.Lo)));
  const Acc threshold = static_cast<Acc>(setup.Threshold);
  const Acc threshold2 = threshold * threshold;
  const unsigned char* selected = vtkMLAATopology::GetSelectionTable();
  int offsets[8][2];
  for (int bit = 0; bit < 8; ++bit)
  {
    vtkMLAATopology::GetNeighborOffset(bit, offsets[bit][0], offsets[bit][1]);
  }
  auto pixel = [&](int x, int y) { return input + y * inputRowStride + static_cast<vtkIdType>(x) * c; };

  vtkSMPTools::For(0, h, RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    // A pixel's output depends on whether its neighbours are gaps (the thin line rule), and a
    // gap on its coverage window: the selection is made for the task's rows and one more each
    // way ("selection rows"), whose windows reach R = vtkMLAATopology::CoverageRadius further.
    // The LAB features of rows begin - radius .. end - 1 + radius (clamped; radius = R + 1), row
    // i at index i - first.
    const int radius = vtkMLAATopology::CoverageRadius + 1;
    const int first = static_cast<int>(begin) - radius;
    const int rows = static_cast<int>(end - begin) + 2 * radius;
    const size_t rowSize = plane * count;
    std::unique_ptr<Acc[]> band(new Acc[rowSize * rows]);
    auto readBandRows = [&](int from, int to) {
      for (int i = from; i < to; ++i)
      {
        const int y = std::min(std::max(first + i, 0), h - 1);
        reader.Row(pixel(0, y), w, nullptr, band.get() + rowSize * i);
      }
    };
    // The rows the neighbour masks of the selection rows read (one past them each way) now; the
    // outer rows, which only the coverage windows of selected pixels read, when the first one
    // is.
    readBandRows(radius - 2, rows - radius + 2);
    bool windowRowsRead = false;
    // Whether pixels are unlike their neighbours, each pair compared once (Unlike is
    // symmetric): along each band row (x, x + 1), and between band rows i and i + 1 (x with x,
    // x + 1 and x - 1 above it), over the columns where both pixels exist. Branch-free loops
    // that vectorise. (Only the rows that the neighbour masks of the selection rows read.)
    const size_t uw = static_cast<size_t>(w);
    std::vector<unsigned char> along(rows * uw, 0);
    std::vector<unsigned char> up((rows - 1) * uw, 0);
    std::vector<unsigned char> upRight((rows - 1) * uw, 0);
    std::vector<unsigned char> upLeft((rows - 1) * uw, 0);
    auto compare = [&](const Acc* a, const Acc* b, int from, int to, unsigned char* out) {
      if (count > 3)
      {
        UnlikeMasks<Acc, true>(a, b, plane, threshold2, 1, from, to, out);
      }
      else
      {
        UnlikeMasks<Acc, false>(a, b, plane, threshold2, 1, from, to, out);
      }
    };
    for (int i = radius - 2; i <= rows - radius; ++i)
    {
      const Acc* here = band.get() + rowSize * i;
      if (i >= radius - 1)
      {
        compare(here, here + 1, 0, w - 1, along.data() + i * uw);
      }
      const Acc* above = here + rowSize;
      compare(here, above, 0, w, up.data() + i * uw);
      compare(here, above + 1, 0, w - 1, upRight.data() + i * uw);
      compare(here, above - 1, 1, w, upLeft.data() + i * uw);
    }
    // The selection rows: image rows begin - 1 .. end (those outside the image are never
    // read), selection row s at image row begin - 1 + s. Their neighbour masks, and for each
    // selected pixel the number of its window's pixels alike the shape (0 for the others).
    const int selectionRows = static_cast<int>(end - begin) + 2;
    std::vector<unsigned char> masks(selectionRows * uw, 0);
    std::vector<unsigned char> shapeCounts(selectionRows * uw, 0);
    auto neighbourFeatures = [&](int j, int x, int bit) {
      const int nx = std::min(std::max(x + offsets[bit][0], 0), w - 1);
      return band.get() + rowSize * (j + offsets[bit][1]) + nx;
    };
    for (int s = 0; s < selectionRows; ++s)
    {
      const int y = static_cast<int>(begin) - 1 + s;
      if (y < 0 || y >= h)
      {
        continue;
      }
      const int j = y - first; // band row of y
      // The masks of the unlike neighbours of the inner columns from the comparisons above
      // (bits as vtkMLAATopology: E, NE, N, NW, W, SW, S, SE), then those of the first and
      // last columns, whose reads are clamped.
      unsigned char* mask = masks.data() + s * uw;
      const unsigned char* toE = along.data() + j * uw;
      const unsigned char* toN = up.data() + j * uw;
      const unsigned char* toNE = upRight.data() + j * uw;
      const unsigned char* toNW = upLeft.data() + j * uw;
      const unsigned char* toS = up.data() + (j - 1) * uw;
      const unsigned char* toSW = upRight.data() + (j - 1) * uw; // from (x - 1, y - 1)
      const unsigned char* toSE = upLeft.data() + (j - 1) * uw;  // from (x + 1, y - 1)
      CombineUnlike(toE, toNE, toN, toNW, toSW, toS, toSE, 1, w - 1, mask);
      const Acc* centre = band.get() + rowSize * j;
      for (int x : { 0, w - 1 })
      {
        mask[x] = 0; // (a single column is done twice, to the same result)
        for (int bit = 0; bit < 8; ++bit)
        {
          mask[x] |= Unlike(centre + x, neighbourFeatures(j, x, bit), plane, count, threshold2)
            ? static_cast<unsigned char>(1 << bit)
            : 0;
        }
      }
      unsigned char* shapeCount = shapeCounts.data() + s * uw;
      for (int x = 0; x < w; ++x)
      {
        if (SkipClearEight(mask, x, w))
        {
          continue; // most pixels have no unlike neighbour
        }
        if (!selected[mask[x]])
        {
          continue;
        }
        const Acc* features[8];
        for (int bit = 0; bit < 8; ++bit)
        {
          features[bit] = neighbourFeatures(j, x, bit);
        }
        const int unlike = mask[x];
        // The shape is one colour: its pixels are pairwise alike.
        bool oneColour = true;
        for (int a = 0; a < 8 && oneColour; ++a)
        {
          for (int b = a + 1; b < 8 && oneColour; ++b)
          {
            if (((unlike >> a) & (unlike >> b) & 1) &&
              Unlike(features[a], features[b], plane, count, threshold2))
            {
              oneColour = false;
            }
          }
        }
        if (!oneColour)
        {
          continue;
        }
        // The coverage rule (vtkMLAATopology): the pixels of the window alike the shape (its
        // first pixel stands for it) measure the thin shape's density.
        const Acc* shape = nullptr;
        for (int bit = 0; bit < 8 && !shape; ++bit)
        {
          shape = ((unlike >> bit) & 1) ? features[bit] : nullptr;
        }
        if (!windowRowsRead)
        {
          readBandRows(0, radius - 2);
          readBandRows(rows - radius + 2, rows);
          windowRowsRead = true;
        }
        const int reach = vtkMLAATopology::CoverageRadius;
        int shapePixels = 0;
        for (int dy = -reach; dy <= reach; ++dy)
        {
          const Acc* windowRow = band.get() + rowSize * (j + dy);
          for (int dx = -reach; dx <= reach; ++dx)
          {
            const int wx = std::min(std::max(x + dx, 0), w - 1);
            shapePixels += ((dx != 0 || dy != 0) &&
                             !Unlike(windowRow + wx, shape, plane, count, threshold2))
              ? 1
              : 0;
          }
        }
        shapeCount[x] =
          vtkMLAATopology::GetCoverage(shapePixels) > 0.0 ? static_cast<unsigned char>(shapePixels) : 0;
      }
    }
    for (vtkIdType row = begin; row < end; ++row)
    {
      const int y = static_cast<int>(row);
      const int s = y - static_cast<int>(begin) + 1; // selection row of y
      T* out = output + static_cast<size_t>(y) * w * c;
      std::copy(pixel(0, y), pixel(0, y) + static_cast<size_t>(w) * c, out);
      const unsigned char* mask = masks.data() + s * uw;
      for (int x = 0; x < w; ++x)
      {
        if (SkipClearEight(mask, x, w))
        {
          continue;
        }
        const int unlike = mask[x];
        if (!unlike)
        {
          continue;
        }
        const T* self = pixel(x, y);
        const int shapePixels = shapeCounts[s * uw + x];
        if (shapePixels > 0)
        {
          // A gap: the pixel plus the coverage's share of the difference to the mean of the
          // shape's pixels, every component.
          const double coverage = vtkMLAATopology::GetCoverage(shapePixels);
          double sum[4] = { 0, 0, 0, 0 };
          int n = 0;
          for (int bit = 0; bit < 8; ++bit)
          {
            if ((unlike >> bit) & 1)
            {
              const int nx = std::min(std::max(x + offsets[bit][0], 0), w - 1);
              const int ny = std::min(std::max(y + offsets[bit][1], 0), h - 1);
              const T* q = pixel(nx, ny);
              for (int k = 0; k < c; ++k)
              {
                sum[k] += static_cast<double>(q[k]);
              }
              ++n;
            }
          }
          for (int k = 0; k < c; ++k)
          {
            double mean = sum[k] / n;
            if (!std::isfinite(mean)) // huge floating-point values: their sum overflowed
            {
              mean = 0.0;
              for (int bit = 0; bit < 8; ++bit)
              {
                if ((unlike >> bit) & 1)
                {
                  const int nx = std::min(std::max(x + offsets[bit][0], 0), w - 1);
                  const int ny = std::min(std::max(y + offsets[bit][1], 0), h - 1);
                  mean += static_cast<double>(pixel(nx, ny)[k]) / n;
                }
              }
            }
            out[static_cast<size_t>(x) * c + k] =
              ConvertBlended<T>(MoveTowards(static_cast<double>(self[k]), mean, coverage));
          }
          continue;
        }
        // The thin line rule (vtkMLAATopology::GetLineShare): a pixel of the shape of a gap
        // among its unlike neighbours, whose window holds more shape pixels than its eight
        // neighbours (the line goes on beyond them), keeps the line's share of its colour, the
        // rest going to the gap's colour (the gap with the most shape pixels in its window, the
        // first in bit order among equals).
        int best = 0;
        int bestX = 0, bestY = 0;
        for (int bit = 0; bit < 8; ++bit)
        {
          if ((unlike >> bit) & 1)
          {
            const int nx = std::min(std::max(x + offsets[bit][0], 0), w - 1);
            const int ny = std::min(std::max(y + offsets[bit][1], 0), h - 1);
            const size_t g = (ny - static_cast<int>(begin) + 1) * uw + nx;
            const int count8 = shapeCounts[g];
            if (count8 > best && count8 > Popcount8(masks[g]))
            {
              best = count8;
              bestX = nx;
              bestY = ny;
            }
          }
        }
        const double share = best > 0 ? vtkMLAATopology::GetLineShare(best) : 1.0;
        if (share >= 1.0)
        {
          continue;
        }
        const T* gap = pixel(bestX, bestY);
        for (int k = 0; k < c; ++k)
        {
          out[static_cast<size_t>(x) * c + k] = ConvertBlended<T>(MoveTowards(
            static_cast<double>(self[k]), static_cast<double>(gap[k]), 1.0 - share));
        }
      }
    }
    progress.RowsDone(end - begin);
  });
}

}

#endif
