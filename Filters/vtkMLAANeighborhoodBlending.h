// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAANeighborhoodBlending.h
 * @brief  MLAA stage 4, neighbourhood blending (GPU Pro 2 chapter, section 4.4); the twin of
 *         Rendering/glsl/vtkMLAANeighborhoodBlendingFS.glsl.
 *
 * BlendRow, the only typed step on the way out, blends each pixel with its four neighbours by
 * the blending weights; WriteDebugImage writes the edges or the weights instead (the pass's
 * debug outputs).
 *
 * Internal to MLAA::FiltersMLAA (tests and benchmarks include it); not installed.
 */

#ifndef vtkMLAANeighborhoodBlending_h
#define vtkMLAANeighborhoodBlending_h

#include "vtkAntialiasingKit.h"
#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAABlendingWeights.h"
#include "vtkMLAAEdgeDetection.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

//------------------------------------------------------------------------------
// Stage 4: neighbourhood blending (section 4.4, typed).

/** The 8-bit weights as the blending reads them: value / 255 in float. */
VTKFILTERSMLAA_EXPORT const float* WeightValues();

/** Settings of the blending, from vtkMLAAOptions and the image. */
struct BlendSettings
{
  bool Dominant = true;          // vtkMLAAOptions::DominantDirectionBlending
  bool StraightAlpha = false;    // alpha present and not premultiplied
  double AlphaLo = 0.0;          // normalisation of the alpha channel
  double AlphaInverseRange = 1.0;
};

/**
 * Channel k of a blend: `blend(scale)` computes it from the values taking part (the pixel's
 * `own` and its neighbours with a weight `a`) times `scale`. It is called with 1; for a
 * floating-point type, a result that came out infinite or NaN although every value taking part
 * is finite (values near the type's limit overflow the weighted sums) is computed again with
 * 1/4, where the sums cannot overflow (the weights add up to at most 4), scaled back and kept
 * within the type's range (a weighted mean of finite values is finite). Non-finite values taking
 * part give what the plain formula gives.
 */
template <typename T, typename Acc, typename Blend>
Acc BlendChannel(Blend blend, T own, const T* const neighbours[4], const Acc a[4], int k)
{
  const Acc r = blend(Acc(1));
  if (!std::is_floating_point<T>::value || std::isfinite(r))
  {
    return r;
  }
  bool finite = std::isfinite(static_cast<double>(own));
  for (int n = 0; n < 4; ++n)
  {
    finite = finite && (!(a[n] > Acc(0)) || std::isfinite(static_cast<double>(neighbours[n][k])));
  }
  if (!finite)
  {
    return r;
  }
  const Acc limit = static_cast<Acc>(std::numeric_limits<T>::max());
  return std::max(-limit, std::min(limit, Acc(4) * blend(Acc(0.25))));
}

/**
 * Row y of the output: each pixel of `out` (columns out.X0..X1) mixed with its four neighbours
 * by the weights, c' = sum_k a_k ((1 - a_k) c + a_k c_k) / sum_k a_k, which for a single edge is
 * equation 4.1; pixels without weights are copied. `pixel(x, y)` gives the input pixel (all
 * components); only neighbours with a weight are read, and those lie within the weights' extent.
 * With DominantDirectionBlending, a pixel on both a horizontal and a vertical line blends along
 * the one with the larger weight only. With straight alpha, the colour channels are averaged
 * weighted by alpha as well (premultiply, blend, divide by the blended alpha), so the colour of
 * transparent pixels never leaks into their neighbours; where the alphas that take part are all
 * equal, that changes nothing and the plain formula is used.
 */
template <typename T, typename Acc, typename PixelAt>
void BlendRow(int y, const Rect& out, int components, const EdgesBuffer& edges,
  const WeightsBuffer& weights, const BlendSettings& settings, PixelAt pixel, T* output)
{
  const float* value = WeightValues();
  const Rect& wr = weights.Extent;
  const int c = components;
  std::copy(pixel(out.X0, y), pixel(out.X0, y) + static_cast<size_t>(out.Width()) * c, output);
  if (y < wr.Y0 || y > wr.Y1)
  {
    return;
  }
  const bool hasBelow = y - 1 >= wr.Y0;
  const int x0 = std::max(out.X0, wr.X0);
  const int x1 = std::min(out.X1, wr.X1);
  const unsigned char* e = edges.At(x0, y);
  const unsigned char* eBelow = hasBelow ? edges.At(x0, y - 1) : nullptr;
  const unsigned char* w = weights.At(x0, y);
  const unsigned char* wBelow = hasBelow ? weights.At(x0, y - 1) : nullptr;
  // A pixel is blended where it has an edgel of its own, where the pixel below has a top edgel
  // or where the pixel on its right has a left edgel; only then are the weights read (the
  // weights of pixels without edgels are never written). Most pixels have none: sixteen or
  // four pixels at a time are skipped with tests on the edges.
  constexpr std::uint64_t topMask = 0xFF00FF00FF00FF00ull;
  constexpr std::uint64_t leftMask = 0x00FF00FF00FF00FFull;
  const bool littleEndian = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }();
  // Whether pixels x to x + 3 (edgels from `own`, those below from `below`) need no blending:
  // their edgels, the top edgels below them and the left edgels of the pixels right of them
  // (x + 1 to x + 4, all within the weights) are all zero.
  auto quietQuad = [](const unsigned char* own, const unsigned char* below) {
    std::uint64_t o, r, b = 0;
    std::memcpy(&o, own, 8);
    std::memcpy(&r, own + 2, 8);
    if (below)
    {
      std::memcpy(&b, below, 8);
    }
    return (o | (b & topMask) | (r & leftMask)) == 0;
  };
  for (int x = x0; x <= x1; ++x, e += 2, w += 4, eBelow = eBelow ? eBelow + 2 : nullptr,
           wBelow = wBelow ? wBelow + 4 : nullptr)
  {
    // Runs of sixteen quiet pixels at a time, then four.
    while (littleEndian && x + 15 <= x1 && x + 16 <= wr.X1 && quietQuad(e, eBelow) &&
      quietQuad(e + 8, eBelow ? eBelow + 8 : nullptr) &&
      quietQuad(e + 16, eBelow ? eBelow + 16 : nullptr) &&
      quietQuad(e + 24, eBelow ? eBelow + 24 : nullptr))
    {
      x += 16;
      e += 32;
      w += 64;
      eBelow = eBelow ? eBelow + 32 : nullptr;
      wBelow = wBelow ? wBelow + 64 : nullptr;
    }
    if (x > x1)
    {
      break;
    }
    if (littleEndian && x + 3 <= x1 && x + 4 <= wr.X1 && quietQuad(e, eBelow))
    {
      x += 3;
      e += 6;
      w += 12;
      eBelow = eBelow ? eBelow + 6 : nullptr;
      wBelow = wBelow ? wBelow + 12 : nullptr;
      continue;
    }
    const bool top = e[1] != 0;
    const bool left = e[0] != 0;
    const bool fromBelow = eBelow && eBelow[1];
    const bool fromRight = x < wr.X1 && e[2];
    if (!top && !left && !fromBelow && !fromRight)
    {
      continue;
    }
    Acc a[4] = { top ? static_cast<Acc>(value[w[0]]) : Acc(0),
      fromBelow ? static_cast<Acc>(value[wBelow[1]]) : Acc(0),
      left ? static_cast<Acc>(value[w[2]]) : Acc(0),
      fromRight ? static_cast<Acc>(value[w[4 + 3]]) : Acc(0) };
    if (settings.Dominant)
    {
      // DominantDirectionBlending: on a corner, only the line with the larger weight counts.
      const Acc vertical = std::max(a[0], a[1]);
      const Acc horizontal = std::max(a[2], a[3]);
      if (vertical > horizontal)
      {
        a[2] = a[3] = Acc(0);
      }
      else if (horizontal > vertical)
      {
        a[0] = a[1] = Acc(0);
      }
    }
    const Acc sum = a[0] + a[1] + a[2] + a[3];
    if (!(sum > Acc(0)))
    {
      continue;
    }
    const T* p = pixel(x, y);
    // Neighbours that are not blended in are never read (they may lie outside the input).
    const T* neighbours[4] = { a[0] > Acc(0) ? pixel(x, y + 1) : p,
      a[1] > Acc(0) ? pixel(x, y - 1) : p, a[2] > Acc(0) ? pixel(x - 1, y) : p,
      a[3] > Acc(0) ? pixel(x + 1, y) : p };
    T* q = output + static_cast<size_t>(x - out.X0) * c;
    int first = 0; // the first channel blended by the plain formula
    if (settings.StraightAlpha)
    {
      // Straight alpha: blend the colours premultiplied, unless all alphas taking part agree.
      const Acc alpha = static_cast<Acc>(p[c - 1]);
      bool equal = true;
      for (int n = 0; n < 4; ++n)
      {
        equal = equal && (!(a[n] > Acc(0)) || static_cast<Acc>(neighbours[n][c - 1]) == alpha);
      }
      if (!equal)
      {
        first = c - 1;
        auto coverage = [&settings, c](const T* px) {
          const double v =
            (static_cast<double>(px[c - 1]) - settings.AlphaLo) * settings.AlphaInverseRange;
          return static_cast<Acc>(std::min(1.0, std::max(0.0, v)));
        };
        const Acc ownCoverage = coverage(p);
        Acc mixedAlpha = 0;
        Acc selfShare[4] = { 0, 0, 0, 0 };
        Acc otherShare[4] = { 0, 0, 0, 0 };
        for (int n = 0; n < 4; ++n)
        {
          if (a[n] > Acc(0))
          {
            selfShare[n] = a[n] * (Acc(1) - a[n]) * ownCoverage;
            otherShare[n] = a[n] * a[n] * coverage(neighbours[n]);
            mixedAlpha += selfShare[n] + otherShare[n];
          }
        }
        if (mixedAlpha > Acc(0))
        {
          for (int k = 0; k < c - 1; ++k)
          {
            auto mix = [&](Acc scale) {
              Acc m = 0;
              for (int n = 0; n < 4; ++n)
              {
                if (a[n] > Acc(0))
                {
                  m += selfShare[n] * (scale * static_cast<Acc>(p[k])) +
                    otherShare[n] * (scale * static_cast<Acc>(neighbours[n][k]));
                }
              }
              return m / mixedAlpha;
            };
            q[k] = ConvertBlended<T>(BlendChannel<T, Acc>(mix, p[k], neighbours, a, k));
          }
        }
        // else: everything that takes part is fully transparent; the colour stays.
      }
    }
    for (int k = first; k < c; ++k)
    {
      auto blend = [&](Acc scale) {
        const Acc v = scale * static_cast<Acc>(p[k]);
        Acc b = 0;
        for (int n = 0; n < 4; ++n)
        {
          if (a[n] > Acc(0))
          {
            b += a[n] * ((Acc(1) - a[n]) * v + a[n] * (scale * static_cast<Acc>(neighbours[n][k])));
          }
        }
        return b / sum;
      };
      q[k] = ConvertBlended<T>(BlendChannel<T, Acc>(blend, p[k], neighbours, a, k));
    }
  }
}

/**
 * One of the debug images of vtkMLAAOptions (8-bit RGBA, rows of out.Width() pixels) for the
 * pixels of `out`: the edges or the blending weights.
 */
VTKFILTERSMLAA_EXPORT void WriteDebugImage(int debugOutput, const EdgesBuffer& edges,
  const WeightsBuffer& weights, const Rect& out, unsigned char* rgba);

}

#endif
