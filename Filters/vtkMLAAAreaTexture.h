// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMLAAAreaTexture
 * @brief   The precomputed area texture of morphological antialiasing (the one generator).
 *
 * The blending-weights pass of MLAA (Jimenez et al., "Practical Morphological Antialiasing",
 * GPU Pro 2, section 4.3.3 and Figure 4.2) needs, for each edgel, the area that the revectorised
 * line cuts from the pixel on each side of the edge. That area depends on four numbers only:
 * the crossing-edge codes e1 and e2 at the two ends of the line and the distances `left` and
 * `right` from the pixel to those ends. This class tabulates it.
 *
 * Layout (Figure 4.2): a square of 5 x 5 cells of D x D texels, D = MaxDistance + 1. The cell is
 * chosen by the codes e1, e2 in {0, 1, 3, 4} (code 2 cannot occur; its row and column of cells
 * are zero), and the texel (s, t) = (D * e1 + left, D * e2 + right) holds two areas:
 * - channel 0 (red): the area of the pixel that owns the edgel (the pixel below a horizontal
 *   edge, right of a vertical one), i.e. how much it takes of the colour across the edge;
 * - channel 1 (green): the same for the pixel on the other side of the edge.
 *
 * Crossing-edge codes (section 4.3.2): the crossing edge at an end of the line is read between
 * the pixel's own row (or column) and the opposite one, weighted 3:1, and multiplied by 4:
 * 0 = no crossing edge, 1 = crossing edge on the opposite pixel's side only, 3 = on the owning
 * pixel's side only, 4 = on both sides.
 *
 * The revectorised line (section 4.1): an end with a crossing edge on one side only starts half a
 * pixel into that side, in the middle of the crossing edge, and the line reaches the edge itself
 * at the middle of its length, L / 2 with L = left + right + 1. Two such ends give a U shape
 * (same side) or a Z shape (opposite sides, a straight line through the middle); one gives an
 * L shape. An end with no crossing edge adds nothing. An end with crossing edges on both sides
 * (code 4) is where a one-pixel-wide line (or gap) steps on diagonally: with a one-sided
 * crossing edge at the other end, it acts as a crossing edge on the side opposite to that one,
 * which makes the pattern the Z that the outline of such a line is; with nothing at the other end
 * (the end of a thin line) no slope can be told and it adds nothing. Code 4 at both ends is the
 * run of a thin feature between two of its diagonal steps (thin lines and gaps side by side, the
 * apex of a thin curve), or a side between two junctions of wider shapes (a checkerboard's
 * corners): the weights stages use this cell only where one of the two pixels is one pixel thin
 * across the edge, and since the pixels cannot tell which of the two features steps on at
 * either end, both take the area of the U shape (heights 1/2 at both ends) that would be its.
 * The chapter leaves code 4's areas to its web material; this reading is the project's. The areas
 * are exact integrals of this piecewise-linear line over the pixel, evaluated in double
 * precision; an L shape gives the trapeze area 1/2 (1 - (2p + 1) / L) of "Morphological
 * antialiasing and topological reconstruction" (section 3.4) for the p-th pixel from its crossing
 * edge.
 *
 * Tables are computed once per D and shared by all instances (thread-safe). The CPU filter
 * vtkImageMLAA reads GetTable(); the GPU pass vtkOpenGLMLAAPass uploads the same table.
 *
 * @sa vtkMLAAOptions vtkImageMLAA vtkOpenGLMLAAPass
 */

#ifndef vtkMLAAAreaTexture_h
#define vtkMLAAAreaTexture_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::shared_ptr
#include <vector> // For std::vector

class vtkImageData;

class VTKFILTERSMLAA_EXPORT vtkMLAAAreaTexture : public vtkObject
{
public:
  static vtkMLAAAreaTexture* New();
  vtkTypeMacro(vtkMLAAAreaTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Number of crossing-edge codes, and so of cells along each side of the texture. */
  static constexpr int NumberOfCodes = 5;

  ///@{
  /**
   * Longest distance to an end of a line that the table covers, in pixels: D - 1. Default 16
   * (the distance of the chapter's 8 search steps), range [1, 1023]. The filter and the pass use
   * vtkMLAAOptions::GetMaxDistance() of their options.
   */
  vtkSetClampMacro(MaxDistance, int, 1, 1023);
  vtkGetMacro(MaxDistance, int);
  ///@}

  /** D, the side of one cell in texels: MaxDistance + 1. */
  int GetCellSize() const { return this->MaxDistance + 1; }

  /** Side of the whole texture in texels: 5 * D. */
  int GetTextureSize() const { return NumberOfCodes * this->GetCellSize(); }

  /**
   * The table for the current MaxDistance: GetTextureSize()^2 texels of two floats, texel (s, t)
   * at index 2 * (t * GetTextureSize() + s). Owned by a shared cache; valid while this object
   * lives and its MaxDistance is unchanged.
   */
  const float* GetTable();

  /**
   * The areas of texel (D * e1 + left, D * e2 + right) of the table: channel 0 or 1 (see the
   * class description). Out-of-range arguments give 0.
   */
  float GetArea(int e1, int e2, int left, int right, int channel);

  /**
   * The table as an 8-bit image, GetTextureSize() square, 3 components: red and green are the
   * two areas times 255, rounded; blue is 0. Rows are stored so that the image reads as
   * Figure 4.2 when written by an image writer (the texel row t = 0 is the top row of the file,
   * i.e. the vtkImageData row GetTextureSize() - 1). The returned object belongs to this one.
   */
  vtkImageData* GetImage();

  /**
   * The analytical areas, in double precision, without a table: areas[0] for the pixel that
   * owns the edgel, areas[1] for the pixel opposite. Codes other than 1 and 3 add no slope.
   * Distances must be non-negative.
   *
   * `across` and `along` (default 0, in pixels) move the whole revectorised line relative to
   * the pixel before the areas are taken: `across` towards the opposite pixel, `along` along
   * the line (towards its second end); past its ends the line continues with the slope it
   * has there. They serve images that are one sample set of a multisampled render
   * (vtkOpenGLAntialiasingPass::SetMultiSamples): such an image holds the scene at each
   * pixel's sample position, not at its centre, so the line found in it lies where the edge
   * is as seen from the samples; moved by the sample's offset from the pixel centre, the areas
   * are those of the whole pixel, and averaging the sample images gives the pixel's coverage
   * rather than the coverages of shifted pixels. A straight line (codes 0) moved across gives
   * |across| to one of the pixels. The areas are exact integrals, the line's height clamped to
   * one pixel on either side.
   */
  static void ComputeAreas(int e1, int e2, int left, int right, double areas[2],
    double across = 0.0, double along = 0.0);

  ///@{
  /**
   * The shared table for cells of side D = maxDistance + 1; with `across` and `along`, the table
   * of the line moved by them (ComputeAreas; each clamped to [-1/2, 1/2]). Every caller that
   * holds the table of the same arguments holds the same one. It is computed where no one holds
   * it (the last one asked for is also kept while it takes at most 1 MB): a process that uses many
   * search lengths in turn keeps only the tables in use. Keep the returned pointer for as long
   * as the table is read: `const auto& t = *GetSharedTable(n);` dangles once the statement ends.
   */
  static std::shared_ptr<const std::vector<float>> GetSharedTable(int maxDistance);
  static std::shared_ptr<const std::vector<float>> GetSharedTable(
    int maxDistance, double across, double along);
  ///@}

  ///@{
  /**
   * Diagonal lines (vtkMLAAOptions::DiagonalDetection). A staircase of one-pixel steps is a line
   * at 45 degrees; its "units" are the pixels where the staircase turns (both edgels of one pixel
   * for a rising line, a top edgel and the next pixel's left edgel for a falling one). Across one
   * unit the staircase reads as the 45-degree line through the middles of its two edgels, which
   * cuts 1/8 of a pixel from each side, as the orthogonal search already does. Where the
   * staircase ends, in a run of two pixels along x or y, the real line is half a pixel to one
   * side of that 45-degree line; the line is revectorised as in section 4.1, but along the
   * diagonal: it starts at the shift of the first end, reaches the 45-degree line in the middle
   * of the staircase and ends at the shift of the second end (U and Z shapes, along 45 degrees).
   *
   * End codes: 0 = nothing to tell (no run, a junction, or beyond the search), 1 = the line
   * leaves the unit's pixel (shift -1/2), 2 = it enters the pixel (shift +1/2). The unit's pixel
   * is the one whose corner the line cuts (its "outside" is up-left for a rising line, up-right
   * for a falling one). For a unit at distance d1 from the first end and d2 from the second
   * (length L = d1 + d2 + 1 units), the shift s(t) is evaluated at points t along the diagonal,
   * t = 0 the first end), areas[0] = (1/2 + s)^2 / 2 at t = d1 + 1/2 (how much the unit's pixel
   * takes of the colour on the other side), areas[1] = (1/2 - s)^2 / 2 at t = d1 (how much the
   * other-side pixel before the unit takes of the unit's colour), areas[2] = the same at
   * t = d1 + 1 (the other-side pixel after the unit). Shifts are clamped to [-1/2, 1/2].
   */
  static constexpr int NumberOfDiagonalCodes = 3;
  static void ComputeDiagonalAreas(int e1, int e2, int d1, int d2, double areas[3]);
  ///@}

  /**
   * The shared table of diagonal areas for cells of side D = maxDistance + 1: 3 x 3 cells (end
   * codes e1, e2) of D x D texels, three floats per texel (ComputeDiagonalAreas), texel
   * (D * e1 + d1, D * e2 + d2) at index 3 * (t * 3 D + s). Shared and kept as GetSharedTable's.
   */
  static std::shared_ptr<const std::vector<float>> GetSharedDiagonalTable(int maxDistance);

protected:
  vtkMLAAAreaTexture();
  ~vtkMLAAAreaTexture() override;

  int MaxDistance = 16;

private:
  vtkMLAAAreaTexture(const vtkMLAAAreaTexture&) = delete;
  void operator=(const vtkMLAAAreaTexture&) = delete;

  std::shared_ptr<const std::vector<float>> Table;
  int TableMaxDistance = 0;
  vtkImageData* Image = nullptr;
  int ImageMaxDistance = 0;
};

#endif
