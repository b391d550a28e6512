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
 *   normalisation by the blur's luminosity (slides 21 to 23, 43);
 * - per output pixel, the short-edge result (slide 23), the long-edge masks (the 17-pixel means
 *   of mx and my, slides 26 to 29), the noise rejection (slide 32) and the luminosity-matching
 *   interpolation with the neighbours across the edge (slides 31, 45 to 47).
 * Nothing full-size is allocated besides the output; each thread keeps its buffers (about
 * 5 x (64 + 20) rows of floats) for its next task and update.
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
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace vtkDLAAStages
{
using vtkAntialiasingKit::Progress;
using vtkAntialiasingKit::Rect;

/** Pixels each way of the short-edge high-pass filters and blurs (5-pixel kernels). */
constexpr int ShortEdgeRadius = 2;
/** Pixels each way of the long-edge means (17 pixels). */
constexpr int LongEdgeRadius = vtkDLAAOptions::LongEdgeRadius;
/** Output rows per task: each task also reads Halo() rows each side. */
constexpr int RowsPerTask = 64;

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
   * with LongEdges the 17-pixel means of masks that themselves read 2 pixels further (8 + 2).
   */
  int Halo() const { return ShortEdgeRadius + (this->LongEdges ? LongEdgeRadius : 0); }
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
    // written before they are read.
    const size_t myRowsSize = static_cast<size_t>(bandRows + 2 * longRadius) * width;
    const size_t mxSize = static_cast<size_t>(bandRows) * (width + 2 * longRadius);
    static thread_local std::vector<Acc> scratch;
    const size_t sizes[] = { rowSize * rows, static_cast<size_t>(readWidth) * c, myRowsSize,
      mxSize, 2 * static_cast<size_t>(width) };
    size_t needed = 0;
    for (size_t size : sizes)
    {
      needed += size;
    }
    if (scratch.size() < needed)
    {
      scratch.resize(needed);
    }
    Acc* next = scratch.data();
    auto take = [&next](size_t size) {
      Acc* p = next;
      next += size;
      return p;
    };
    Acc* const band = take(sizes[0]);
    Acc* const readBuffer = take(sizes[1]);
    Acc* const my = take(sizes[2]);
    Acc* const mx = take(sizes[3]);
    Acc* const sums = take(sizes[4]);
    auto plane = [&](int j, int k) { return band + rowSize * j + pw * k; };
    auto luma = [&](int j) { return band + rowSize * j + pw * c; };

    // The rows, clamped to the available pixels, normalised and padded by clamping.
    bool anyNonFinite = false;
    for (int j = 0; j < rows; ++j)
    {
      const int y = std::min(std::max(y0 + j, in.Y0), in.Y1);
      const T* p = input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
        static_cast<vtkIdType>(readX0 - in.X0) * c;
      reader.Row(p, readWidth, nullptr, readBuffer);
      for (int k = 0; k < c; ++k)
      {
        Acc* dst = plane(j, k);
        const Acc* src = readBuffer + static_cast<size_t>(readWidth) * k;
        std::fill(dst, dst + readOffset, src[0]);
        std::copy(src, src + readWidth, dst + readOffset);
        std::fill(dst + readOffset + readWidth, dst + paddedWidth, src[readWidth - 1]);
      }
      Acc* l = luma(j);
      std::fill(l, l + paddedWidth, Acc(0));
      for (int n = 0; n < lumaCount; ++n)
      {
        const Acc* ck = plane(j, lumaChannels[n]);
        const Acc w = lumaWeights[n];
        for (int i = 0; i < paddedWidth; ++i)
        {
          l[i] += w * ck[i];
        }
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
    const int mxWidth = width + 2 * longRadius; // mx column m is padded column i = m + halo - longRadius
    for (int m = 0; m < myRows; ++m)
    {
      const int j = m + halo - longRadius;
      const Acc* l2 = luma(j - 2) + halo;
      const Acc* l1 = luma(j - 1) + halo;
      const Acc* l0 = luma(j) + halo;
      const Acc* u1 = luma(j + 1) + halo;
      const Acc* u2 = luma(j + 2) + halo;
      Acc* row = my + static_cast<size_t>(m) * width;
      std::fill(row, row + width, Acc(0)); // l(Hx), then the mask
      for (int n = 0; n < lumaCount; ++n)
      {
        const Acc* ck = plane(j, lumaChannels[n]) + halo;
        const Acc w = lumaWeights[n] * Acc(0.25);
        for (int i = 0; i < width; ++i)
        {
          row[i] += w * std::abs(ck[i - 2] + ck[i - 1] + ck[i + 1] + ck[i + 2] - Acc(4) * ck[i]);
        }
      }
      for (int i = 0; i < width; ++i)
      {
        const Acc blur = (l2[i] + l1[i] + u1[i] + u2[i] + Acc(2) * l0[i]) * sixth;
        row[i] = BlendMask(lambda * row[i] - epsilon, blur);
      }
    }
    for (int r = 0; r < bandRows; ++r)
    {
      const int j = r + halo;
      const int first = halo - longRadius; // padded column of mx column 0
      Acc* row = mx + static_cast<size_t>(r) * mxWidth;
      std::fill(row, row + mxWidth, Acc(0)); // l(Hy), then the mask
      for (int n = 0; n < lumaCount; ++n)
      {
        const int k = lumaChannels[n];
        const Acc* d2 = plane(j - 2, k) + first;
        const Acc* d1 = plane(j - 1, k) + first;
        const Acc* c0 = plane(j, k) + first;
        const Acc* u1 = plane(j + 1, k) + first;
        const Acc* u2 = plane(j + 2, k) + first;
        const Acc w = lumaWeights[n] * Acc(0.25);
        for (int i = 0; i < mxWidth; ++i)
        {
          row[i] += w * std::abs(d2[i] + d1[i] + u1[i] + u2[i] - Acc(4) * c0[i]);
        }
      }
      const Acc* l0 = luma(j) + first;
      for (int i = 0; i < mxWidth; ++i)
      {
        const Acc blur = (l0[i - 2] + l0[i - 1] + l0[i + 1] + l0[i + 2] + Acc(2) * l0[i]) * sixth;
        row[i] = BlendMask(lambda * row[i] - epsilon, blur);
      }
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
    // written.
    std::vector<Acc> result(c);
    Acc* ax = sums;         // sums of mx over the 17 pixels along x
    Acc* ay = sums + width; // sums of my over the 17 pixels along y
    for (int r = 0; r < bandRows; ++r)
    {
      const int j = r + halo;
      const int y = y0 + j;
      const T* source = input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
        static_cast<vtkIdType>(out.X0 - in.X0) * c;
      T* target = output + (static_cast<size_t>(begin) + r) * width * c;
      std::copy(source, source + static_cast<size_t>(width) * c, target);
      const Acc* mxRow = mx + static_cast<size_t>(r) * mxWidth + longRadius;
      const Acc* myColumn = my + static_cast<size_t>(r + longRadius) * width;
      const Acc* l0 = luma(j) + halo;
      if (s.LongEdges)
      {
        // Summed in the same order for every pixel, whatever the band or piece.
        std::fill(ax, ax + 2 * width, Acc(0));
        for (int d = -LongEdgeRadius; d <= LongEdgeRadius; ++d)
        {
          const Acc* m = mxRow + d;
          for (int x = 0; x < width; ++x)
          {
            ax[x] += m[x];
          }
        }
        for (int d = -LongEdgeRadius; d <= LongEdgeRadius; ++d)
        {
          const Acc* m = myColumn + static_cast<ptrdiff_t>(d) * width;
          for (int x = 0; x < width; ++x)
          {
            ay[x] += m[x];
          }
        }
      }
      for (int x = 0; x < width; ++x)
      {
        const Acc mxp = mxRow[x];
        const Acc myp = myColumn[x];
        // The long-edge masks and the noise rejection.
        Acc longMask = 0;
        bool alongX = false;
        if (s.LongEdges)
        {
          const Acc mX = LongEdgeMask(ax[x] * mean);
          const Acc mY = LongEdgeMask(ay[x] * mean);
          if ((mX > Acc(0)) != (mY > Acc(0)))
          {
            alongX = mX > Acc(0);
            longMask = alongX ? mX : mY;
          }
        }
        const bool isFrozen = !frozen.empty() && frozen[static_cast<size_t>(r) * width + x];
        if (isFrozen || (mxp == Acc(0) && myp == Acc(0) && longMask == Acc(0)))
        {
          continue; // copied
        }
        // The short-edge result: s = lerp(lerp(c, Bx, mx), By, my / 2).
        const int i = x + halo;
        for (int k = 0; k < c; ++k)
        {
          const Acc* row = plane(j, k) + i;
          const Acc cv = row[0];
          const Acc bx = (row[-2] + row[-1] + row[1] + row[2] + Acc(2) * cv) * sixth;
          const Acc by = (plane(j - 2, k)[i] + plane(j - 1, k)[i] + plane(j + 1, k)[i] +
                           plane(j + 2, k)[i] + Acc(2) * cv) *
            sixth;
          const Acc h = cv + (bx - cv) * mxp;
          result[k] = h + (by - h) * (myp * Acc(0.5));
        }
        // The long-edge step: the neighbour across the edge whose interpolation with the pixel
        // reaches the luminosity of the 17-pixel mean along the edge.
        if (longMask > Acc(0))
        {
          Acc t = 0;
          const Acc* across[2];
          Acc acrossLuma[2];
          if (alongX)
          {
            for (int d = -LongEdgeRadius; d <= LongEdgeRadius; ++d)
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
            for (int d = -LongEdgeRadius; d <= LongEdgeRadius; ++d)
            {
              t += luma(j + d)[i];
            }
            across[0] = plane(j, 0) + i - 1; // left
            across[1] = plane(j, 0) + i + 1; // right
            acrossLuma[0] = l0[x - 1];
            acrossLuma[1] = l0[x + 1];
          }
          t *= mean;
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
    }
    progress.RowsDone(end - begin);
  });
}
}

#endif
