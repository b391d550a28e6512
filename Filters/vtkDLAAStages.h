// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkDLAAStages.h
 * @brief  The CPU DLAA of vtkImageDLAA (internal header).
 *
 * Directionally localized antialiasing as vtkDLAAOptions describes it, on one z slice, in
 * bands of rows run by vtkSMPTools. Each task reads the rows it needs (its band and a halo of
 * Halo() rows each side, clamped to the image) once, with MLAA's typed row reader
 * (vtkAntialiasingKit::FeatureReader in COLOR mode: normalised channels, NaN for non-finite
 * pixels), into per-task planes padded by Halo() columns each side, so that no inner loop
 * clamps. On those rows it computes, as the talk's slides do in Photoshop layers:
 * - the luminosity of every pixel (slide 43: REC709 or the green channel);
 * - the blend masks mx (horizontal edges, on the band's rows and 8 columns each side) and my
 *   (vertical edges, on the band's columns and 8 rows each side): high-pass, contrast curve,
 *   normalisation by the blur's luminosity (slides 21 to 23, 43), in chunks of 8 pixels, set
 *   to 0 without the filters where every pixel a chunk reads has one colour (a flat region);
 * - per output pixel, the short-edge result (slide 23), the long-edge masks (the 17-pixel means
 *   of mx and my, slides 26 to 29), the noise rejection (slide 32) and the luminosity-matching
 *   interpolation with the neighbours across the edge (slides 31, 45 to 47) towards the mean
 *   luminosity along the edge over the step the pixel is on (StepHalfLength), for the pixels
 *   that have a mask or may have a long edge (counts of the masks other than 0 in their
 *   windows), eight pixels without either passed over at a time.
 * The result is the same, bit for bit, as computing every mask and window everywhere.
 * Nothing full-size is allocated besides the output; each thread keeps its buffers (about
 * (components + 3) x (128 + 20) rows of floats and a few rows of bytes) for its next task and
 * update.
 *
 * Rows and columns follow VTK's image layout: y grows towards the top of the displayed image,
 * so the neighbour "above" a pixel is the next row (y + 1).
 *
 * This header is internal to MLAA::FiltersMLAA (the tests include it); it is not installed.
 */

#ifndef vtkDLAAStages_h
#define vtkDLAAStages_h

#include "vtkDLAAOptions.h"
#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkAntialiasingKit.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace vtkDLAAStages
{
using vtkAntialiasingKit::Progress;
using vtkAntialiasingKit::Rect;

/** Pixels each way of the short-edge high-pass filters and blurs (5-pixel kernels). */
constexpr int ShortEdgeRadius = 2;
/** Pixels each way of the long-edge means (17 pixels). */
constexpr int LongEdgeRadius = vtkDLAAOptions::LongEdgeRadius;
/** Pixels each way across a boundary over which CornerSide follows the side. */
constexpr int CornerSearch = vtkDLAAOptions::CornerSearch;
/** Pixels, the first included, for which a side crossing a corner's side at its end must go on. */
constexpr int CornerCrossing = vtkDLAAOptions::CornerCrossing;
/** Pixels, the boundary's included, for which a corner's side must go on. */
constexpr int CornerRun = vtkDLAAOptions::CornerRun;
/**
 * Output rows per task: each task also reads Halo() rows each side and computes my on
 * LongEdgeRadius rows each side (64 rows: 12 % slower at 1080p, one thread).
 */
constexpr int RowsPerTask = 128;

/** The settings of one slice, from the options, the components and the value range. */
struct Settings
{
  double Epsilon = 0.1;
  double Lambda = 3.0;
  bool LongEdges = true;
  int Components = 3;
  double Lo = 0.0; // normalisation: value -> (value - Lo) / (Hi - Lo)
  double Hi = 1.0;
  // The luminosity function: l(c) = sum over k of LumaWeights[k] c[k] (alpha weighs 0).
  double LumaWeights[4] = { 0.2126, 0.7152, 0.0722, 0.0 };

  /**
   * How far, in pixels along x and y, an output pixel reads: the short-edge kernels (2), and
   * with LongEdges the 17-pixel means of masks that themselves read 2 pixels further (8 + 2);
   * the tests of corners' sides (CornerSide) of boundaries up to 2 pixels away (8 with LongEdges)
   * read CornerCrossing - 1 pixels past them, and CornerSearch + 1 across.
   */
  int Halo() const
  {
    const int reach = this->LongEdges ? LongEdgeRadius : ShortEdgeRadius;
    return std::max({ ShortEdgeRadius + (this->LongEdges ? LongEdgeRadius : 0),
      reach + CornerCrossing - 1, CornerSearch + 1 });
  }

  /** vtkDLAAOptions::SideContrast of these settings. */
  float SideContrast() const { return vtkDLAAOptions::SideContrast(this->Epsilon, this->Lambda); }
};
VTKFILTERSMLAA_EXPORT Settings MakeSettings(
  vtkDLAAOptions* options, int components, double lo, double hi);

/** Everything one z slice needs. */
struct SliceSetup
{
  Rect Whole;  // the image
  Rect Input;  // the pixels available: reads beyond them are clamped to them
  Rect Output; // the pixels to produce
  Settings DLAA;
};

/**
 * Whether a normalised value takes part in the blending: finite, and small enough that the
 * masks (sums of up to 8 values times Lambda, at most 100) and blurs cannot overflow. Larger
 * values are treated as NaN is: pixels that read one are left as they are (found by the fuzz
 * target mlaa_filter_fuzzer: -1.7e38 in a float image, normalised by [0, 1], gave NaN).
 */
template <typename Acc>
inline bool IsBlendable(Acc v)
{
  return std::abs(v) <= std::numeric_limits<Acc>::max() / Acc(4096);
}

/**
 * The contrast curve of a blend mask, divided by the blur's luminosity:
 * saturate(numerator / divisor), 0 where the numerator is not positive, 1 where it is positive
 * and the divisor is 0.
 */
template <typename Acc>
inline Acc BlendMask(Acc numerator, Acc divisor)
{
  // Without branches, so that the loops over rows vectorise: a positive numerator over a zero
  // divisor is +infinity, which saturates to 1; a negative divisor gives 0.
  const Acc q = numerator / divisor;
  const Acc m = std::min(std::max(q, Acc(0)), Acc(1));
  return numerator > Acc(0) ? m : Acc(0);
}

/** saturate(2 a - 1): the long-edge mask from the mean a of a blend mask. */
template <typename Acc>
inline Acc LongEdgeMask(Acc a)
{
  const Acc m = Acc(2) * a - Acc(1);
  return m > Acc(1) ? Acc(1) : (m > Acc(0) ? m : Acc(0));
}

/**
 * The interpolation parameter that gives a colour of luminosity t between c (luminosity lc)
 * and a neighbour n (luminosity ln) (slide 45): k = (t - lc) / (ln - lc), or -1 when no such
 * colour lies in (c, n] (k outside (0, 1], or ln = lc).
 */
template <typename Acc>
inline Acc LuminosityMatch(Acc t, Acc lc, Acc ln)
{
  const Acc d = ln - lc;
  if (d == Acc(0))
  {
    return Acc(-1);
  }
  const Acc k = (t - lc) / d;
  return k > Acc(0) && k <= Acc(1) ? k : Acc(-1);
}

/**
 * Corners of sides that lie on pixel borders (issue 50). The short-edge blur along an edge reads
 * two pixels each way, and the long-edge step takes the mean over up to 8; where those reads
 * cross a side that meets the edge at a corner (the end of a bar, a junction of voxels), they
 * bring the next shape's colour into a side that was exact. The accessor `at(d, i)` gives the
 * luminosity d pixels from the pixel along the blur (or the edge; d < 0 behind it) and i pixels
 * across. The pass's vtkDLAACornersFS.glsl computes the same, once a boundary.
 *
 * CrossingGoesOn: whether, d pixels along, the pixels i0 and i1 across differ and the pixels 1 to
 * CornerCrossing - 1 further along in the direction `away` (1 or -1) differ alike (each within
 * half the difference of its own at d): a side crossing the line between i0 and i1 that goes on
 * for CornerCrossing pixels.
 */
template <typename Acc, typename Luma>
inline bool CrossingGoesOn(const Luma& at, int d, int i0, int i1, int away)
{
  const Acc l0 = at(d, i0);
  const Acc l1 = at(d, i1);
  const Acc difference = std::abs(l0 - l1);
  if (!(difference > Acc(0)))
  {
    return false;
  }
  const Acc tolerance = Acc(0.5) * difference;
  for (int m = 1; m < CornerCrossing; ++m)
  {
    if (!(std::abs(at(d + m * away, i0) - l0) <= tolerance &&
          std::abs(at(d + m * away, i1) - l1) <= tolerance))
    {
      return false;
    }
  }
  return true;
}

/**
 * Whether the boundary between the pixels k - 1 and k along the blur (or the edge) is the side
 * of a corner: the two luminosities it separates, lP and lQ, differ, their colours differ by more
 * than `minimum` (Settings::SideContrast) in some channel that the luminosity reads
 * (`contrast(d0, d1)`: the largest difference of those channels between the pixels d0 and d1
 * along), and
 * the pair goes on across (each within half their difference; followed up to CornerSearch pixels
 * each way) for CornerRun pixels or more, and at each end where it stops, it neither goes on one
 * pixel over along the blur (as a staircase's run goes on at its steps) nor meets a crossing side
 * shorter than CornerCrossing pixels (a crossing one pixel long is the end of a line one pixel
 * wide, a step as well). A luminosity that is not finite at an end makes it a step.
 */
template <typename Acc, typename Luma, typename Contrast>
inline bool CornerSide(const Luma& at, const Contrast& contrast, int k, Acc minimum)
{
  const Acc lP = at(k - 1, 0);
  const Acc lQ = at(k, 0);
  const Acc difference = std::abs(lP - lQ);
  if (!(difference > Acc(0)) || !(contrast(k - 1, k) > minimum))
  {
    return false; // no side the masks would see (or a value that is not finite)
  }
  const Acc tolerance = Acc(0.5) * difference;
  auto pairAt = [&](int d, int i) {
    return std::abs(at(d - 1, i) - lP) <= tolerance && std::abs(at(d, i) - lQ) <= tolerance;
  };
  int run = 1;
  for (int side = -1; side <= 1; side += 2)
  {
    int end = 1;
    for (; end <= CornerSearch; ++end)
    {
      if (!pairAt(k, side * end))
      {
        break;
      }
    }
    run += end - 1;
    if (end <= CornerSearch)
    {
      const int i = side * end;
      if (!std::isfinite(at(k - 1, i)) || !std::isfinite(at(k, i)) || pairAt(k - 1, i) ||
        pairAt(k + 1, i))
      {
        return false;
      }
      if (!(CrossingGoesOn<Acc>(at, k - 1, i - side, i, -1) ||
            CrossingGoesOn<Acc>(at, k, i - side, i, 1)))
      {
        return false;
      }
    }
  }
  return run >= CornerRun;
}

/**
 * How many pixels, 0 to 2, the short-edge blur of a pixel reads in the direction of `at` before
 * a corner's side (CornerSide): reads beyond it read the last pixel before it.
 */
template <typename Acc, typename Luma, typename Contrast>
inline int BlurReach(const Luma& at, const Contrast& contrast, Acc sideContrast)
{
  return CornerSide<Acc>(at, contrast, 1, sideContrast)
    ? 0
    : (CornerSide<Acc>(at, contrast, 2, sideContrast) ? 1 : 2);
}

/**
 * How far the step of a long edge that a pixel is on reaches from it in the direction `sign`
 * (1 or -1) along the edge, at most `limit` pixels. `at(d, k)` is the luminosity d pixels along
 * the edge from the pixel and k (-1, 0 or 1) across it: below or left for -1, the pixel's own row
 * or column for 0. The step goes on as far as both neighbours across the edge keep their
 * luminosity, within half their difference; where the pixel has one of them on its side of the
 * edge (within that tolerance) and the other not, it may also go on once through the place where
 * the pixel's row (or column) and the other neighbour swap luminosities, which is where a line
 * one pixel wide moves into the pixel's row: without it, the pixels beside such a line would see
 * its step end at the very place where the line reaches them. The pass's vtkDLAAFS.glsl
 * computes the same.
 */
template <typename Acc, typename Luma, typename Contrast>
inline int StepReach(
  const Luma& at, const Contrast& contrast, int sign, int limit, Acc sideContrast, bool& corner)
{
  corner = false;
  Acc e0 = at(0, -1);
  Acc e1 = at(0, 0);
  Acc e2 = at(0, 1);
  const Acc tolerance = Acc(0.5) * std::abs(e0 - e2);
  auto near = [tolerance](Acc x, Acc y) { return std::abs(x - y) <= tolerance; };
  bool swap = near(e0, e1) != near(e2, e1);
  Acc row = e1; // the luminosity of the pixel's row (or column) d - 1 pixels along
  auto ahead = [&at, sign](int d, int i) { return at(sign * d, i); };
  auto aheadContrast = [&contrast, sign](int d0, int d1) {
    return contrast(sign * d0, sign * d1);
  };
  for (int d = 1; d <= limit; ++d)
  {
    const Acc m0 = at(sign * d, -1);
    const Acc m1 = at(sign * d, 0);
    const Acc m2 = at(sign * d, 1);
    if (m1 != row && CornerSide<Acc>(ahead, aheadContrast, d, sideContrast))
    {
      corner = true;
      return d - 1; // the window stops before a corner's side
    }
    row = m1;
    if (near(m0, e0) && near(m2, e2))
    {
      continue;
    }
    // The neighbour on one side and the pixel's row swapped, the other side's kept.
    auto swapped = [&](Acc& side, Acc other, Acc mSide, Acc mOther) {
      if (near(mSide, e1) && near(m1, side) && near(mOther, other))
      {
        std::swap(side, e1);
        return true;
      }
      return false;
    };
    if (swap && (swapped(e0, e2, m0, m2) || swapped(e2, e0, m2, m0)))
    {
      swap = false;
      continue;
    }
    return d - 1;
  }
  return limit;
}

/**
 * Half the length, from 1 to LongEdgeRadius pixels, of the window along the edge over which the
 * long-edge step takes its mean luminosity: the shorter of the two reaches of the step the pixel
 * is on (StepReach). A window longer than the step spreads the step's transition over the whole
 * window, which on an edge a few pixels from vertical or horizontal (steps of 2 to 16 pixels)
 * blurs it across more than the pixels it covers and makes it flicker as the edge moves
 * (docs/measurements.md). 0 where a corner's side lies next to the pixel (StepReach stopped
 * there): the window would cross it, and the mean of the pixel alone leaves it as it is.
 */
template <typename Acc, typename Luma, typename Contrast>
inline int StepHalfLength(const Luma& at, const Contrast& contrast, Acc sideContrast)
{
  bool cornerAhead = false;
  bool cornerBehind = false;
  const int ahead = StepReach<Acc>(at, contrast, 1, LongEdgeRadius, sideContrast, cornerAhead);
  // (At least 1 pixel behind: a corner's side there sets 0 whatever the reach ahead.)
  const int behind =
    StepReach<Acc>(at, contrast, -1, std::max(ahead, 1), sideContrast, cornerBehind);
  return (cornerAhead && ahead == 0) || (cornerBehind && behind == 0)
    ? 0
    : std::max(1, std::min(ahead, behind));
}

/**
 * row[i] += term(i) for i in [0, n), or with `first`, row[i] = 0 + term(i): the sums
 * 0 + t0 + t1 + ... that the luminosity and the high-pass filters add up, in that order, without
 * clearing the row first.
 */
template <typename Acc, typename Term>
inline void AddTerms(Acc* row, int n, bool first, Term term)
{
  if (first)
  {
    for (int i = 0; i < n; ++i)
    {
      row[i] = Acc(0) + term(i);
    }
  }
  else
  {
    for (int i = 0; i < n; ++i)
    {
      row[i] += term(i);
    }
  }
}

/**
 * For the N planes of one row (here) and of the row above it (above), whether each pixel
 * i in [0, n) equals bit for bit the pixel right of it (right[i], i < n - 1) and the pixel above it
 * (up[i]) in every plane.
 */
template <int N, typename Acc>
inline void SameNeighbours(
  const Acc* const* here, const Acc* const* above, int n, unsigned char* __restrict right,
  unsigned char* __restrict up)
{
  using Bits = typename std::conditional<sizeof(Acc) == 4, std::uint32_t, std::uint64_t>::type;
  auto bits = [](const Acc* p) {
    Bits u;
    std::memcpy(&u, p, sizeof(Acc));
    return u;
  };
  const Acc* h[N];
  const Acc* a[N];
  for (int k = 0; k < N; ++k)
  {
    h[k] = here[k];
    a[k] = above[k];
  }
  for (int i = 0; i < n - 1; ++i)
  {
    unsigned char sameRight = 1;
    unsigned char sameUp = 1;
    for (int k = 0; k < N; ++k)
    {
      const Bits v = bits(h[k] + i);
      sameRight &= v == bits(h[k] + i + 1) ? 1 : 0;
      sameUp &= v == bits(a[k] + i) ? 1 : 0;
    }
    right[i] = sameRight;
    up[i] = sameUp;
  }
  unsigned char sameUp = 1;
  for (int k = 0; k < N; ++k)
  {
    sameUp &= bits(h[k] + n - 1) == bits(a[k] + n - 1) ? 1 : 0;
  }
  up[n - 1] = sameUp;
  right[n - 1] = 0;
}

/** SameNeighbours<N> for N = planes (1 to 3). */
template <typename Acc>
inline void SameNeighbours(int planes, const Acc* const* here, const Acc* const* above, int n,
  unsigned char* right, unsigned char* up)
{
  switch (planes)
  {
    case 1:
      SameNeighbours<1>(here, above, n, right, up);
      break;
    case 2:
      SameNeighbours<2>(here, above, n, right, up);
      break;
    default:
      SameNeighbours<3>(here, above, n, right, up);
      break;
  }
}

/**
 * SameNeighbours<N> for float planes (N = 1 to 3), with an AVX2 clone (VTKMLAA_TARGET_CLONES).
 */
VTKFILTERSMLAA_EXPORT void SameNeighbours(int planes, const float* const* here,
  const float* const* above, int n, unsigned char* right, unsigned char* up);

/** Whether the 8 bytes at p are all 1. */
inline bool AllSet8(const unsigned char* p)
{
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v == 0x0101010101010101ull;
}

/**
 * DLAA on one slice of an image of type T: `input` points at the first pixel of setup.Input
 * (rows `inputRowStride` values apart), `output` at the first pixel of setup.Output (rows
 * packed). Pixels that the method leaves as they are (no blend, or a non-finite value among
 * the pixels they read) are copied bit for bit.
 */
template <typename T>
void RunSlice(const SliceSetup& setup, const T* input, vtkIdType inputRowStride, T* output,
  Progress& progress)
{
  using Acc = vtkAntialiasingKit::AccumulatorType<T>;
  const Rect& in = setup.Input;
  const Rect& out = setup.Output;
  if (out.Empty() || in.Empty())
  {
    return;
  }
  const Settings& s = setup.DLAA;
  const int c = s.Components;
  const int halo = s.Halo();
  const int longRadius = s.LongEdges ? LongEdgeRadius : 0;
  const int width = out.Width();
  const int paddedWidth = width + 2 * halo; // column i is x = out.X0 - halo + i
  const Acc lambda = static_cast<Acc>(s.Lambda);
  const Acc epsilon = static_cast<Acc>(s.Epsilon);
  const Acc sideContrast = static_cast<Acc>(s.SideContrast());
  const Acc lo = static_cast<Acc>(s.Lo);
  const Acc range = static_cast<Acc>(s.Hi - s.Lo);
  // The channels that the luminosity reads, with their weights.
  int lumaChannels[4];
  Acc lumaWeights[4];
  int lumaCount = 0;
  for (int k = 0; k < c; ++k)
  {
    if (s.LumaWeights[k] != 0.0)
    {
      lumaChannels[lumaCount] = k;
      lumaWeights[lumaCount++] = static_cast<Acc>(s.LumaWeights[k]);
    }
  }
  const vtkAntialiasingKit::FeatureReader<T, Acc> reader(
    vtkAntialiasingKit::MakeFeatureLayout(vtkMLAAOptions::COLOR, c), lo,
    static_cast<Acc>(1.0 / (s.Hi - s.Lo)));
  // The columns of the input that the padded rows hold (the rest are clamped copies).
  const int readX0 = std::max(out.X0 - halo, in.X0);
  const int readX1 = std::min(out.X1 + halo, in.X1);
  const int readWidth = readX1 - readX0 + 1;
  const int readOffset = readX0 - (out.X0 - halo);
  // Integer images hold no NaN, but a narrow ValueRange may normalise their values beyond what
  // can be blended (found by mlaa_filter_fuzzer: a signed char image gave NaN, converted back
  // to signed char, which is undefined).
  const Acc inverseRange = static_cast<Acc>(1.0 / (s.Hi - s.Lo));
  const bool mayHoldNonFinite = std::is_floating_point<T>::value ||
    !IsBlendable((static_cast<Acc>(std::numeric_limits<T>::lowest()) - lo) * inverseRange) ||
    !IsBlendable((static_cast<Acc>(std::numeric_limits<T>::max()) - lo) * inverseRange);
  constexpr Acc sixth = Acc(1) / Acc(6);
  constexpr Acc mean = Acc(1) / Acc(2 * LongEdgeRadius + 1);

  vtkSMPTools::For(0, out.Height(), RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    const int bandRows = static_cast<int>(end - begin);
    const int rows = bandRows + 2 * halo; // row j is y = out.Y0 + begin - halo + j
    const int y0 = out.Y0 + static_cast<int>(begin) - halo;
    const size_t pw = static_cast<size_t>(paddedWidth);
    const size_t rowSize = pw * (c + 1); // c planes of channels, then the luminosity
    // Per-thread buffers, kept from task to task and update to update (pool threads live on),
    // written before they are read; sized for the largest band at once (a thread's first band
    // may be the slice's last, shorter one).
    // Values of the band's planes, my rows and mx rows for a band of n rows.
    auto bandSizes = [&](int n) {
      const size_t r = static_cast<size_t>(n);
      return std::array<size_t, 3>{ rowSize * (r + 2 * halo), (r + 2 * longRadius) * width,
        r * (width + 2 * longRadius) };
    };
    auto total = [](const std::array<size_t, 3>& a) { return a[0] + a[1] + a[2]; };
    static thread_local vtkAntialiasingKit::ScratchBuffer<Acc> scratch;
    const std::array<size_t, 3> sizes = bandSizes(bandRows);
    const int largestBand = std::max(bandRows, std::min(RowsPerTask, out.Height()));
    scratch.Reserve(total(bandSizes(largestBand))); // (largestBand >= bandRows)
    Acc* next = scratch.Get();
    auto take = [&next](size_t size) {
      Acc* p = next;
      next += size;
      return p;
    };
    Acc* const band = take(sizes[0]);
    Acc* const my = take(sizes[1]);
    Acc* const mx = take(sizes[2]);
    auto plane = [&](int j, int k) { return band + rowSize * j + pw * k; };
    auto luma = [&](int j) { return band + rowSize * j + pw * c; };

    // The rows, clamped to the available pixels, normalised and padded by clamping.
    bool anyNonFinite = false;
    for (int j = 0; j < rows; ++j)
    {
      const int y = std::min(std::max(y0 + j, in.Y0), in.Y1);
      const T* p = input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
        static_cast<vtkIdType>(readX0 - in.X0) * c;
      reader.Row(p, readWidth, nullptr, plane(j, 0) + readOffset, paddedWidth);
      for (int k = 0; k < c; ++k)
      {
        Acc* dst = plane(j, k);
        std::fill(dst, dst + readOffset, dst[readOffset]);
        std::fill(dst + readOffset + readWidth, dst + paddedWidth, dst[readOffset + readWidth - 1]);
      }
      Acc* l = luma(j);
      for (int n = 0; n < lumaCount; ++n)
      {
        const Acc* ck = plane(j, lumaChannels[n]);
        const Acc w = lumaWeights[n];
        AddTerms(l, paddedWidth, n == 0, [&](int i) { return w * ck[i]; });
      }
      if (mayHoldNonFinite)
      {
        // (NaN fails every comparison; infinity is beyond the largest finite value.)
        bool finite = true;
        for (int k = 0; k < c; ++k)
        {
          const Acc* ck = plane(j, k);
          for (int i = 0; i < paddedWidth; ++i)
          {
            finite &= IsBlendable(ck[i]);
          }
        }
        anyNonFinite = anyNonFinite || !finite;
      }
    }

    // The blend masks. my (a vertical edge: blur along y) on the band's columns and on
    // longRadius rows each side of the band; mx (a horizontal edge: blur along x) on the band's
    // rows and longRadius columns each side of the output.
    const int myRows = bandRows + 2 * longRadius; // my row m is band row j = m + halo - longRadius
    // mx column m is padded column i = m + halo - longRadius
    const int mxWidth = width + 2 * longRadius;
    // The numerators of the masks at padded column i of row j: Lambda l(Hx) - Epsilon and
    // Lambda l(Hy) - Epsilon, l(H) summed as 0 + t0 + t1 + ... (AddTerms).
    auto xTerm = [](const Acc* ck, int i, Acc w) {
      return w * std::abs(ck[i - 2] + ck[i - 1] + ck[i + 1] + ck[i + 2] - Acc(4) * ck[i]);
    };
    auto yTerm = [](const Acc* d2, const Acc* d1, const Acc* c0, const Acc* u1, const Acc* u2,
                   int i, Acc w) {
      return w * std::abs(d2[i] + d1[i] + u1[i] + u2[i] - Acc(4) * c0[i]);
    };
    auto myNumerator = [&](int j, int i) {
      Acc sum = 0;
      for (int n = 0; n < lumaCount; ++n)
      {
        const Acc term = xTerm(plane(j, lumaChannels[n]), i, lumaWeights[n] * Acc(0.25));
        sum = n == 0 ? Acc(0) + term : sum + term;
      }
      return lambda * sum - epsilon;
    };
    auto mxNumerator = [&](int j, int i) {
      Acc sum = 0;
      for (int n = 0; n < lumaCount; ++n)
      {
        const int k = lumaChannels[n];
        const Acc term = yTerm(plane(j - 2, k), plane(j - 1, k), plane(j, k), plane(j + 1, k),
          plane(j + 2, k), i, lumaWeights[n] * Acc(0.25));
        sum = n == 0 ? Acc(0) + term : sum + term;
      }
      return lambda * sum - epsilon;
    };
    // Columns [a, b) of my row m, and of mx row r.
    auto myRange = [&](int m, int a, int b) {
      const int j = m + halo - longRadius;
      const Acc* l2 = luma(j - 2) + halo;
      const Acc* l1 = luma(j - 1) + halo;
      const Acc* l0 = luma(j) + halo;
      const Acc* u1 = luma(j + 1) + halo;
      const Acc* u2 = luma(j + 2) + halo;
      Acc* row = my + static_cast<size_t>(m) * width; // l(Hx), then the mask
      for (int n = 0; n < lumaCount; ++n)
      {
        const Acc* ck = plane(j, lumaChannels[n]) + halo + a;
        const Acc w = lumaWeights[n] * Acc(0.25);
        AddTerms(row + a, b - a, n == 0, [&](int i) { return xTerm(ck, i, w); });
      }
      for (int i = a; i < b; ++i)
      {
        const Acc blur = (l2[i] + l1[i] + u1[i] + u2[i] + Acc(2) * l0[i]) * sixth;
        row[i] = BlendMask(lambda * row[i] - epsilon, blur);
      }
    };
    auto mxRange = [&](int r, int a, int b) {
      const int j = r + halo;
      const int first = halo - longRadius + a; // padded column of mx column a
      Acc* row = mx + static_cast<size_t>(r) * mxWidth + a; // l(Hy), then the mask
      for (int n = 0; n < lumaCount; ++n)
      {
        const int k = lumaChannels[n];
        const Acc* d2 = plane(j - 2, k) + first;
        const Acc* d1 = plane(j - 1, k) + first;
        const Acc* c0 = plane(j, k) + first;
        const Acc* u1 = plane(j + 1, k) + first;
        const Acc* u2 = plane(j + 2, k) + first;
        const Acc w = lumaWeights[n] * Acc(0.25);
        AddTerms(row, b - a, n == 0, [&](int i) { return yTerm(d2, d1, c0, u1, u2, i, w); });
      }
      const Acc* l0 = luma(j) + first;
      for (int i = 0; i < b - a; ++i)
      {
        const Acc blur = (l0[i - 2] + l0[i - 1] + l0[i + 1] + l0[i + 2] + Acc(2) * l0[i]) * sixth;
        row[i] = BlendMask(lambda * row[i] - epsilon, blur);
      }
    };

    // Flat pixels. Most of a rendered image is regions of one colour, where the high-pass
    // filters read equal values: the numerator is then the same for every pixel of the region,
    // and where it is not above 0 (Epsilon > 0 and the usual Lambda: always), the mask is 0
    // whatever the blur. Pixels equal bit for bit in the channels the luminosity reads give the
    // same floats, so the masks are computed in chunks of 8 columns, skipped (set to 0) where
    // every value the chunk's filters read is one colour and its numerator, computed once per
    // run of such chunks, is not above 0. sameRight[j][i]: pixel i of band row j equals pixel
    // i + 1; sameAbove[j][i]: it equals pixel i of row j + 1. (Tests of 8 bytes at a time may
    // read a few bytes past what a chunk needs: they then ask more, never less.)
    static thread_local vtkAntialiasingKit::ByteBuffer sameStorage;
    sameStorage.Reserve(2 * pw * static_cast<size_t>(largestBand + 2 * halo) + 16);
    unsigned char* const sameRight = sameStorage.Get();
    unsigned char* const sameAbove = sameRight + pw * rows;
    // (The last row of sameAbove and the bytes past the rows may be read, never used.)
    std::fill(sameAbove + pw * rows, sameAbove + pw * rows + 16, static_cast<unsigned char>(0));
    for (int j = 0; j < rows; ++j)
    {
      const Acc* here[3];
      const Acc* above[3];
      for (int n = 0; n < lumaCount; ++n)
      {
        here[n] = plane(j, lumaChannels[n]);
        above[n] = plane(std::min(j + 1, rows - 1), lumaChannels[n]);
      }
      unsigned char* right = sameRight + pw * j;
      unsigned char* up = sameAbove + pw * j;
      SameNeighbours(lumaCount, here, above, paddedWidth, right, up);
    }
    constexpr int chunk = 8;
    // Runs the chunks of one row of a mask: compute(a, b) the columns [a, b) (a < b), flat(x0)
    // whether chunk x0 is one colour (and one colour with the chunk before when that was flat
    // too), numerator(x0) its numerator.
    auto maskRow = [&](Acc* row, int count, auto compute, auto flat, auto numerator) {
      int pending = 0; // the columns from here to the chunk are still to compute
      bool zeroRun = false; // the chunk before was flat with a numerator not above 0
      for (int x0 = 0; x0 < count; x0 += chunk)
      {
        const int x1 = std::min(x0 + chunk, count);
        bool zero = false;
        if (flat(x0))
        {
          zero = zeroRun || !(numerator(x0) > Acc(0));
        }
        if (zero)
        {
          if (pending < x0)
          {
            compute(pending, x0);
          }
          std::fill(row + x0, row + x1, Acc(0));
          pending = x1;
        }
        zeroRun = zero;
      }
      if (pending < count)
      {
        compute(pending, count);
      }
    };
    for (int m = 0; m < myRows; ++m)
    {
      const int j = m + halo - longRadius;
      const unsigned char* right = sameRight + pw * j + halo;
      maskRow(
        my + static_cast<size_t>(m) * width, width,
        [&](int a, int b) { myRange(m, a, b); },
        // pixels x0 - 2 .. x0 + 9 (x0 - 2 .. x0 + 8 equal to the next)
        [&](int x0) { return AllSet8(right + x0 - 2) && AllSet8(right + x0 + 1); },
        [&](int x0) { return myNumerator(j, halo + x0); });
    }
    for (int r = 0; r < bandRows; ++r)
    {
      const int j = r + halo;
      const int first = halo - longRadius;
      const unsigned char* right = sameRight + pw * j + first;
      maskRow(
        mx + static_cast<size_t>(r) * mxWidth, mxWidth,
        [&](int a, int b) { mxRange(r, a, b); },
        // pixels x0 - 1 .. x0 + 8 of rows j - 2 .. j + 2 (x0 - 1 joins the chunk before)
        [&](int x0) {
          const unsigned char* below = sameAbove + pw * (j - 2) + first + x0;
          return AllSet8(right + x0 - 1) && right[x0 + 7] && AllSet8(below) &&
            AllSet8(below + pw) && AllSet8(below + 2 * pw) && AllSet8(below + 3 * pw);
        },
        [&](int x0) { return mxNumerator(j, first + x0); });
    }

    // Pixels that read a non-finite value: those within the cross of radius 2 of one, and with
    // long edges, of one within longRadius along x or y.
    std::vector<unsigned char> frozen;
    if (anyNonFinite)
    {
      std::vector<unsigned char> bad(pw * rows, 0);
      for (int j = 0; j < rows; ++j)
      {
        for (int k = 0; k < c; ++k)
        {
          const Acc* ck = plane(j, k);
          for (int i = 0; i < paddedWidth; ++i)
          {
            bad[j * pw + i] |= IsBlendable(ck[i]) ? 0 : 1;
          }
        }
      }
      // The short-edge cross of every pixel whose masks the band reads.
      std::vector<unsigned char> cross(pw * rows, 0);
      for (int j = ShortEdgeRadius; j < rows - ShortEdgeRadius; ++j)
      {
        for (int i = ShortEdgeRadius; i < paddedWidth - ShortEdgeRadius; ++i)
        {
          unsigned char b = 0;
          for (int d = -ShortEdgeRadius; d <= ShortEdgeRadius; ++d)
          {
            b |= bad[j * pw + i + d] | bad[(j + d) * pw + i];
          }
          cross[j * pw + i] = b;
        }
      }
      frozen.assign(static_cast<size_t>(bandRows) * width, 0);
      for (int r = 0; r < bandRows; ++r)
      {
        for (int x = 0; x < width; ++x)
        {
          const int j = r + halo;
          const int i = x + halo;
          unsigned char b = 0;
          for (int d = -longRadius; d <= longRadius; ++d)
          {
            b |= cross[j * pw + i + d] | cross[(j + d) * pw + i];
          }
          frozen[static_cast<size_t>(r) * width + x] = b;
        }
      }
    }

    // The output pixels: a copy of the input row, where the pixels that change are then
    // written. A long-edge mask is above 0 only where the mean of its 17 blend masks is above
    // 1/2: since no blend mask exceeds 1, only where at least 9 of them are not 0. Those counts
    // (integers, exact in any order) are kept along the row (x) and down the columns (y, from
    // row to row), and the sums, where a count allows a mask, are added up as the GPU pass's
    // windows are, in the same order for every pixel whatever the band or piece. (A NaN mask
    // counts as not 0; its sum is NaN and gives no long edge, as before.)
    // (columns: the width in a local, which the byte stores below cannot alias, so that their
    // loops vectorise.)
    const int columns = width;
    std::vector<Acc> result(c);
    static thread_local vtkAntialiasingKit::ByteBuffer countStorage;
    countStorage.Reserve(5 * static_cast<size_t>(columns) + 4 * LongEdgeRadius + 8);
    unsigned char* countY = countStorage.Get(); // masks of my not 0 in each column's window
    unsigned char* countX = countY + columns;      // masks of mx not 0 in each row window
    unsigned char* active = countX + columns;      // 8 more: read 8 at a time
    unsigned char* nonZeroX = active + columns + 8; // mx not 0, from column -LongEdgeRadius
    unsigned char* pairSums = nonZeroX + columns + 2 * LongEdgeRadius; // for countX
    if (s.LongEdges)
    {
      std::fill(countY, countY + columns, static_cast<unsigned char>(0));
      for (int m = 0; m < 2 * LongEdgeRadius; ++m) // the first window but its last row
      {
        const Acc* row = my + static_cast<size_t>(m) * columns;
        for (int x = 0; x < columns; ++x)
        {
          countY[x] += row[x] != Acc(0) ? 1 : 0;
        }
      }
    }
    auto windowSum = [](const Acc* center, ptrdiff_t stride) {
      Acc sum = 0;
      for (int d = -LongEdgeRadius; d <= LongEdgeRadius; ++d)
      {
        sum += center[d * stride];
      }
      return sum;
    };
    constexpr int fewestForLongEdge = LongEdgeRadius + 1;
    for (int r = 0; r < bandRows; ++r)
    {
      const int j = r + halo;
      const int y = y0 + j;
      const T* source = input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
        static_cast<vtkIdType>(out.X0 - in.X0) * c;
      T* target = output + (static_cast<size_t>(begin) + r) * columns * c;
      std::copy(source, source + static_cast<size_t>(columns) * c, target);
      const Acc* mxRow = mx + static_cast<size_t>(r) * mxWidth + longRadius;
      const Acc* myColumn = my + static_cast<size_t>(r + longRadius) * columns;
      const Acc* l0 = luma(j) + halo;
      if (s.LongEdges)
      {
        // Column windows: rows r .. r + 2 LongEdgeRadius of my; the one before left out below.
        const Acc* enter = my + static_cast<size_t>(r + 2 * LongEdgeRadius) * columns;
        for (int x = 0; x < columns; ++x)
        {
          countY[x] += enter[x] != Acc(0) ? 1 : 0;
        }
        for (int i = 0; i < columns + 2 * LongEdgeRadius; ++i)
        {
          nonZeroX[i] = mxRow[i - LongEdgeRadius] != Acc(0) ? 1 : 0;
        }
        // The windows' counts by doubling: sums of 2, 4, 8 and 16 flags, then the 17th.
        static_assert(2 * LongEdgeRadius == 16, "a window is 16 + 1 pixels");
        unsigned char* sums = pairSums;
        for (int i = 0; i < columns + 15; ++i)
        {
          sums[i] = static_cast<unsigned char>(nonZeroX[i] + nonZeroX[i + 1]);
        }
        for (int step = 2, last = columns + 13; step <= 8; last -= 2 * step, step *= 2)
        {
          for (int i = 0; i < last; ++i) // (sums[i + step] is read before it is written)
          {
            sums[i] = static_cast<unsigned char>(sums[i] + sums[i + step]);
          }
        }
        for (int x = 0; x < columns; ++x)
        {
          countX[x] = static_cast<unsigned char>(sums[x] + nonZeroX[x + 16]);
        }
        for (int x = 0; x < columns; ++x)
        {
          active[x] = (mxRow[x] != Acc(0)) | (myColumn[x] != Acc(0)) |
            (countX[x] >= fewestForLongEdge) | (countY[x] >= fewestForLongEdge);
        }
      }
      else
      {
        for (int x = 0; x < columns; ++x)
        {
          active[x] = (mxRow[x] != Acc(0)) | (myColumn[x] != Acc(0));
        }
      }
      std::fill(active + columns, active + columns + 8, static_cast<unsigned char>(0));
      for (int x = 0; x < columns; ++x)
      {
        std::uint64_t eight;
        std::memcpy(&eight, active + x, 8);
        if (eight == 0)
        {
          x += 7; // none of the 8 pixels changes
          continue;
        }
        if (!active[x])
        {
          continue;
        }
        const Acc mxp = mxRow[x];
        const Acc myp = myColumn[x];
        // The long-edge masks and the noise rejection.
        Acc longMask = 0;
        bool alongX = false;
        if (s.LongEdges)
        {
          const bool maybeX = countX[x] >= fewestForLongEdge;
          const bool maybeY = countY[x] >= fewestForLongEdge;
          if (maybeX || maybeY)
          {
            const Acc mX = maybeX ? LongEdgeMask(windowSum(mxRow + x, 1) * mean) : Acc(0);
            const Acc mY = maybeY ? LongEdgeMask(windowSum(myColumn + x, columns) * mean) : Acc(0);
            if ((mX > Acc(0)) != (mY > Acc(0)))
            {
              alongX = mX > Acc(0);
              longMask = alongX ? mX : mY;
            }
          }
        }
        const bool isFrozen = !frozen.empty() && frozen[static_cast<size_t>(r) * columns + x];
        if (isFrozen || (mxp == Acc(0) && myp == Acc(0) && longMask == Acc(0)))
        {
          continue; // copied
        }
        // The short-edge result: s = lerp(lerp(c, Bx, mx), By, my / 2), each blur reading no
        // farther than the corners' sides it meets (BlurReach; only where its mask is not 0).
        const int i = x + halo;
        // The largest difference, in the channels the luminosity reads, between the pixels
        // (padded column, band row) (i0, j0) and (i1, j1).
        auto colourContrast = [&](int i0, int j0, int i1, int j1) {
          Acc largest = 0;
          for (int n = 0; n < lumaCount; ++n)
          {
            const int k = lumaChannels[n];
            largest = std::max(largest, std::abs(plane(j0, k)[i0] - plane(j1, k)[i1]));
          }
          return largest;
        };
        int right = 2, left = 2, up = 2, down = 2;
        if (mxp != Acc(0))
        {
          right = BlurReach<Acc>([&](int d, int k) { return luma(j + k)[i + d]; },
            [&](int d0, int d1) { return colourContrast(i + d0, j, i + d1, j); }, sideContrast);
          left = BlurReach<Acc>([&](int d, int k) { return luma(j + k)[i - d]; },
            [&](int d0, int d1) { return colourContrast(i - d0, j, i - d1, j); }, sideContrast);
        }
        if (myp != Acc(0))
        {
          up = BlurReach<Acc>([&](int d, int k) { return luma(j + d)[i + k]; },
            [&](int d0, int d1) { return colourContrast(i, j + d0, i, j + d1); }, sideContrast);
          down = BlurReach<Acc>([&](int d, int k) { return luma(j - d)[i + k]; },
            [&](int d0, int d1) { return colourContrast(i, j - d0, i, j - d1); }, sideContrast);
        }
        for (int k = 0; k < c; ++k)
        {
          const Acc* row = plane(j, k) + i;
          const Acc cv = row[0];
          const Acc bx = (row[-std::min(2, left)] + row[-std::min(1, left)] +
                           row[std::min(1, right)] + row[std::min(2, right)] + Acc(2) * cv) *
            sixth;
          const Acc by = (plane(j - std::min(2, down), k)[i] + plane(j - std::min(1, down), k)[i] +
                           plane(j + std::min(1, up), k)[i] + plane(j + std::min(2, up), k)[i] +
                           Acc(2) * cv) *
            sixth;
          const Acc h = cv + (bx - cv) * mxp;
          result[k] = h + (by - h) * (myp * Acc(0.5));
        }
        // The long-edge step: the neighbour across the edge whose interpolation with the pixel
        // reaches the luminosity of the mean along the edge over the step the pixel is on.
        if (longMask > Acc(0))
        {
          Acc t = 0;
          const Acc* across[2];
          Acc acrossLuma[2];
          int half = 0;
          if (alongX)
          {
            half = StepHalfLength<Acc>([&](int d, int k) { return luma(j + k)[i + d]; },
              [&](int d0, int d1) { return colourContrast(i + d0, j, i + d1, j); }, sideContrast);
            for (int d = -half; d <= half; ++d)
            {
              t += l0[x + d];
            }
            across[0] = plane(j + 1, 0) + i; // above
            across[1] = plane(j - 1, 0) + i; // below
            acrossLuma[0] = luma(j + 1)[i];
            acrossLuma[1] = luma(j - 1)[i];
          }
          else
          {
            half = StepHalfLength<Acc>([&](int d, int k) { return luma(j + d)[i + k]; },
              [&](int d0, int d1) { return colourContrast(i, j + d0, i, j + d1); }, sideContrast);
            for (int d = -half; d <= half; ++d)
            {
              t += luma(j + d)[i];
            }
            across[0] = plane(j, 0) + i - 1; // left
            across[1] = plane(j, 0) + i + 1; // right
            acrossLuma[0] = l0[x - 1];
            acrossLuma[1] = l0[x + 1];
          }
          t /= static_cast<Acc>(2 * half + 1);
          const Acc k0 = LuminosityMatch(t, l0[x], acrossLuma[0]);
          const Acc k1 = LuminosityMatch(t, l0[x], acrossLuma[1]);
          const int pick = k0 > Acc(0) && (k1 <= Acc(0) || k0 <= k1) ? 0 : (k1 > Acc(0) ? 1 : -1);
          for (int k = 0; k < c; ++k)
          {
            const Acc cv = plane(j, k)[i];
            const Acc q = pick < 0 ? cv : cv + (across[pick][pw * k] - cv) * (pick ? k1 : k0);
            result[k] += (q - result[k]) * longMask;
          }
        }
        for (int k = 0; k < c; ++k)
        {
          target[x * c + k] = vtkAntialiasingKit::ConvertBlended<T>(lo + result[k] * range);
        }
      }
      if (s.LongEdges)
      {
        const Acc* leave = my + static_cast<size_t>(r) * columns; // the window's first row
        for (int x = 0; x < columns; ++x)
        {
          countY[x] -= leave[x] != Acc(0) ? 1 : 0;
        }
      }
    }
    progress.RowsDone(end - begin);
  });
}
}

#endif
