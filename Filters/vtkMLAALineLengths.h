// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAALineLengths.h
 * @brief  MLAA line lengths counted as run lengths (second paper, section 3.3); the twin of
 *         Rendering/glsl/vtkMLAALineLengthsInitFS.glsl and vtkMLAALineLengthsFS.glsl.
 *
 * The distances the blending weights' search (section 4.3.1) would find from every pixel, counted
 * in one scan per row and per column from the far end of each line: the CPU's counterpart of the
 * pass's recursive doubling. vtkMLAABlendingWeights.h uses them from
 * vtkMLAAOptions::ExactLineLengthsSteps search steps on.
 *
 * Internal to MLAA::FiltersMLAA (tests and benchmarks include it); not installed.
 */

#ifndef vtkMLAALineLengths_h
#define vtkMLAALineLengths_h

#include "vtkAntialiasingKit.h"
#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAAEdgeDetection.h"

#include <cstdint>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

/**
 * Line lengths (section 4.3.1's distance search, done as run lengths): for a pixel p, the number
 * of further pixels along its row (left or right) or its column (down or up) that continue its
 * line, at most maxDistance (vtkMLAAOptions::GetMaxDistance()). Pixel q continues the line from
 * its neighbour p towards q when q has the line's edgel (a top edgel for a row, a left edgel for
 * a column) and no crossing edgel lies at the boundary between p and q: no left edgel there on
 * p's row or the row above (rows), no top edgel there in p's column or the column to the left
 * (columns). Edgels are read clamped to edges.Extent, as a GPU reads with clamp-to-edge, so a
 * line that reaches the border of the extent and continues across it (by that rule applied to
 * the clamped edgels) runs on to maxDistance.
 *
 * These equal, for every pixel, the distances of a search that steps pixel by pixel up to
 * maxDistance (the chapter's loop, vtkOpenGLMLAAPass's SEARCH_LOOP), but cost one linear scan
 * per row and per column instead of up to maxDistance reads per pixel and direction: each length
 * is 0 where the next pixel does not continue the line, else 1 plus the next pixel's length,
 * capped (the recursion that the GPU's recursive doubling, Rendering/glsl/
 * vtkMLAALineLengthsFS.glsl, evaluates in log4(maxDistance) passes instead; Biri et al., section
 * 3.3). 16-bit lengths hold maxDistance up to 256.
 */
using LineLength = std::uint16_t;

/**
 * The left and right lengths of the pixels of row y of edges.Extent that have a top edgel (one
 * entry per column of the extent, from edges.Extent.X0; the entries of pixels without a top
 * edgel are not all written: they are never needed).
 */
VTKFILTERSMLAA_EXPORT void ComputeRowLineLengths(
  const EdgesBuffer& edges, int y, int maxDistance, LineLength* left, LineLength* right);

/**
 * The down and up lengths of the pixels of `extent` (within edges.Extent) that have a left
 * edgel, row by row, one entry per pixel of `extent` in each array (those of pixels without a
 * left edgel are not all written). Each column is scanned from the border of edges.Extent or
 * from maxDistance rows beyond `extent`, whichever is nearer, so `extent` may be a band of rows
 * of a larger image. Threaded over strips of columns unless `threaded` is false (when the
 * caller's tasks are the bands).
 */
VTKFILTERSMLAA_EXPORT void ComputeColumnLineLengths(const EdgesBuffer& edges, const Rect& extent,
  int maxDistance, LineLength* down, LineLength* up, bool threaded = true);

}

#endif
