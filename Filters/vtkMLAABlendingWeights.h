// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAABlendingWeights.h
 * @brief  MLAA stage 3, blending weights (GPU Pro 2 chapter, section 4.3); the twin of
 *         Rendering/glsl/vtkMLAABlendingWeightsFS.glsl.
 *
 * ComputeBlendingWeights finds, for every pixel with an edgel, the distances to the ends of its
 * line (searched, or from vtkMLAALineLengths.h), the crossing edges there (section 4.3.2) and,
 * with DiagonalDetection, the staircases through it, and looks up the areas in the tables of
 * vtkMLAAAreaTexture quantised to 8 bits, into a WeightsBuffer laid out as the pass's RGBA8
 * blending-weights texture.
 *
 * Internal to MLAA::FiltersMLAA (tests and benchmarks include it); not installed.
 */

#ifndef vtkMLAABlendingWeights_h
#define vtkMLAABlendingWeights_h

#include "vtkAntialiasingKit.h"
#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAAEdgeDetection.h"
#include "vtkMLAALineLengths.h"

#include <memory>
#include <mutex>
#include <vector>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

//------------------------------------------------------------------------------
// Stage 3: blending weights (section 4.3).

/**
 * The blending weights of a rectangle of pixels, laid out as the pass's RGBA8 blending-weights
 * texture (8-bit, value / 255): [0] the weight with which the pixel takes the colour above it,
 * [1] the pixel above takes this one's, [2] the pixel takes its left neighbour's, [3] the left
 * neighbour takes this one's. Only the pixels with an edgel are written ([0] and [1] are 0
 * unless the pixel has a top edgel, [2] and [3] unless it has a left one); the others are left
 * as they were and never read, which spares clearing the whole buffer.
 */
struct WeightsBuffer
{
  Rect Extent;
  ByteBuffer Data;
  /**
   * Scratch of ComputeBlendingWeights with run lengths: the line lengths of one band of rows
   * (see there), one buffer per task running at once, kept with the weights so that they are
   * not allocated (nor their pages faulted in) afresh on every run.
   */
  class BandScratch
  {
  public:
    VTKFILTERSMLAA_EXPORT ByteBuffer* Acquire();
    VTKFILTERSMLAA_EXPORT void Release(ByteBuffer* buffer);
    VTKFILTERSMLAA_EXPORT size_t GetCapacity() const;

  private:
    mutable std::mutex Mutex;
    std::vector<std::unique_ptr<ByteBuffer>> Buffers;
    std::vector<ByteBuffer*> Free;
  };
  BandScratch Scratch;

  void Allocate(const Rect& extent);
  const unsigned char* At(int x, int y) const
  {
    return this->Data.Get() +
      4 * (static_cast<size_t>(y - this->Extent.Y0) * this->Extent.Width() + (x - this->Extent.X0));
  }
  unsigned char* At(int x, int y)
  {
    return const_cast<unsigned char*>(static_cast<const WeightsBuffer*>(this)->At(x, y));
  }
};


/**
 * The area tables of vtkMLAAAreaTexture for one maximum distance, quantised to 8 bits as the
 * blending weights are stored (the pass's RGBA8 texture), and the search settings: all set from
 * the options by MakeWeightSettings.
 */
struct WeightSettings
{
  int SearchSteps = 0;     // vtkMLAAOptions::MaxSearchSteps
  bool Diagonals = true;   // vtkMLAAOptions::DiagonalDetection
  bool Corners = false;    // vtkMLAAOptions::CornerExtrapolation
  // How lines and staircases are measured: true, by run lengths counted over the extent
  // beforehand (ComputeRowLineLengths, ComputeColumnLineLengths, and the staircases' likewise);
  // false, by searching from every pixel with an edgel, step by step, as the GPU's SEARCH_LOOP.
  // The same numbers either way; MakeWeightSettings follows the rule both back ends share,
  // vtkMLAAOptions::GetCountsExactLineLengths().
  bool RunLengths = false;
  int CellSize = 0;         // D = vtkMLAAOptions::GetSearchReach()
  int AreaSize = 0;         // 5 D
  int DiagonalAreaSize = 0; // 3 D
  // Quantised once per maximum distance and shared (quantising the tables of 128 steps, 5 million
  // texels, costs more than the rest of the weights stage).
  std::shared_ptr<const std::vector<unsigned char>> Area;         // 2 per texel
  std::shared_ptr<const std::vector<unsigned char>> DiagonalArea; // 3 per texel; null without diagonals
  // With Corners: the float table of vtkMLAAAreaTexture, for the ends of half height (an end whose
  // height is unknown takes half the ramp of a step), whose areas are combined from two texels
  // and then quantised, as the pass combines them before it stores the weights; null without.
  std::shared_ptr<const std::vector<float>> FloatArea;
};
VTKFILTERSMLAA_EXPORT void MakeWeightSettings(vtkMLAAOptions* options, WeightSettings& settings);

/**
 * The blending weights of the pixels of weights.Extent (already allocated, within edges.Extent)
 * that have an edgel, from the edges; the entries of the others are not written. `whole` is
 * the image: edgels are read clamped to edges.Extent, as a GPU clamps texture reads, and the
 * image border is not a crossing edge.
 *
 * From vtkMLAAOptions::ExactLineLengthsSteps search steps on (WeightSettings::RunLengths), the
 * distances to the ends of orthogonal lines are line lengths, and with DiagonalDetection those
 * of staircases are counted the same way. Each task takes a band of rows, at least as high as
 * the maximum distance, and counts the lengths of its band only (ComputeRowLineLengths per row,
 * ComputeColumnLineLengths over the band, the staircases likewise) into a buffer of
 * weights.Scratch: 2 16-bit values per pixel of the band, 6 with DiagonalDetection, so the
 * scratch grows with the width and the number of threads, not with the image. Below that
 * number of steps they are searched from each pixel instead, which needs no scratch.
 */
VTKFILTERSMLAA_EXPORT void ComputeBlendingWeights(const EdgesBuffer& edges, const Rect& whole,
  const WeightSettings& settings, WeightsBuffer& weights, Progress& progress);

}

#endif
