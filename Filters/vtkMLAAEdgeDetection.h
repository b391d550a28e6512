// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAAEdgeDetection.h
 * @brief  MLAA stage 2, edge detection (GPU Pro 2 chapter, section 4.2); the twin of
 *         Rendering/glsl/vtkMLAAEdgeDetectionFS.glsl.
 *
 * DetectEdges reads the features of each row (vtkAntialiasingKit.h: FeatureReader), compares
 * every pixel with its left and top neighbours and keeps the edgels that local contrast
 * adaptation allows, into an EdgesBuffer laid out as the pass's RG8 edges texture.
 *
 * Internal to MLAA::FiltersMLAA (tests and benchmarks include it); not installed.
 */

#ifndef vtkMLAAEdgeDetection_h
#define vtkMLAAEdgeDetection_h

#include "vtkAntialiasingKit.h"
#include "vtkFiltersMLAAModule.h" // For export macro

#include <cstdint>
#include <cstring>
#include <functional>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

//------------------------------------------------------------------------------
// Stage 2: edges (section 4.2).

/**
 * The edges of a rectangle of pixels, laid out as the pass's RG8 edges texture: two bytes per
 * pixel, [0] = 255 where the pixel has an edgel at its left boundary, [1] = 255 at its top
 * boundary (towards the next row); 0 elsewhere.
 */
struct EdgesBuffer
{
  Rect Extent;
  ByteBuffer Data;

  void Allocate(const Rect& extent);
  const unsigned char* At(int x, int y) const
  {
    return this->Data.Get() +
      2 * (static_cast<size_t>(y - this->Extent.Y0) * this->Extent.Width() + (x - this->Extent.X0));
  }
  unsigned char* At(int x, int y)
  {
    return const_cast<unsigned char*>(static_cast<const EdgesBuffer*>(this)->At(x, y));
  }
  bool Left(int x, int y) const { return this->At(x, y)[0] != 0; }
  bool Top(int x, int y) const { return this->At(x, y)[1] != 0; }
  bool Any(int x, int y) const { return (this->At(x, y)[0] | this->At(x, y)[1]) != 0; }
};

/** Settings of edge detection, from vtkMLAAOptions. */
struct EdgeSettings
{
  double Threshold = 0.1;
  double LocalContrastFactor = 2.0; // 0: off
  // How many leading features are compared together, by their Euclidean distance: 3 in LAB
  // mode (Delta E / 100 from L, a, b, Biri et al. section 3.2), 1 otherwise (a plain
  // difference); no other value is used.
  int EuclideanFeatures = 1;
};

/**
 * The edgels of every pixel of edges.Extent (already allocated), from the features that
 * `readRow(y, features)` gives for each row y of it (layout.Count planes of
 * edges.Extent.Width() values, FeatureReader::Row). The contrast across a boundary is the
 * largest of the Euclidean distance of the first settings.EuclideanFeatures features and the
 * differences of the others; the boundary is an edge where it is at least the threshold (and
 * more than 0); with local contrast adaptation, only if factor
 * times that contrast is at least the contrast of every other boundary of its two pixels.
 * Boundaries outside the extent are not edges. Acc is float or double (AccumulatorType).
 */
template <typename Acc>
VTKFILTERSMLAA_EXPORT void DetectEdges(const std::function<void(int, Acc*)>& readRow, int features,
  const EdgeSettings& settings, EdgesBuffer& edges, Progress& progress);


// Whether any of the 32 bytes at p (the edgels of 16 pixels) is set: four 8-byte words, read
// into registers.
inline bool AnyByte32(const unsigned char* p)
{
  std::uint64_t a, b, c, d;
  std::memcpy(&a, p, 8);
  std::memcpy(&b, p + 8, 8);
  std::memcpy(&c, p + 16, 8);
  std::memcpy(&d, p + 24, 8);
  return (a | b | c | d) != 0;
}

// Whether any of the n pixels of an edges row at e has a left edgel (Which = 0) or a top one
// (Which = 1), eight bytes (four pixels) at a time. The masks select each pixel's first or
// second byte on little-endian machines (as BlendRow's skip assumes); elsewhere every byte
// counts, which only costs the skip.
template <int Which>
inline bool AnyEdgel(const unsigned char* e, int n)
{
  static const std::uint64_t mask = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first != 1 ? ~0ull : Which == 0 ? 0x00FF00FF00FF00FFull : 0xFF00FF00FF00FF00ull;
  }();
  int k = 0;
  std::uint64_t any = 0;
  for (; k + 4 <= n; k += 4)
  {
    std::uint64_t four;
    std::memcpy(&four, e + 2 * k, sizeof(four));
    any |= four;
  }
  bool found = (any & mask) != 0;
  for (; k < n && !found; ++k)
  {
    found = e[2 * k + Which] != 0;
  }
  return found;
}

}

#endif
