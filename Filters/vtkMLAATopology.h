// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMLAATopology
 * @brief   Connexity numbers and the pixel selection rule of topological reconstruction.
 *
 * Topological reconstruction ("Morphological antialiasing and topological reconstruction",
 * Biri, Herubel and Deverly, GRAPP 2011, section 4) looks at the 3 x 3 neighbourhood of every
 * pixel A. Each of A's eight neighbours is classed as unlike A (it belongs to the shape X) or
 * like it (the complement X'). The neighbours are named by the bits of an 8-bit mask,
 * counter-clockwise from the right, with y growing towards the next row (VTK's image rows):
 *
 *     bit 0  E  (x + 1, y)      bit 4  W  (x - 1, y)
 *     bit 1  NE (x + 1, y + 1)  bit 5  SW (x - 1, y - 1)
 *     bit 2  N  (x,     y + 1)  bit 6  S  (x,     y - 1)
 *     bit 3  NW (x - 1, y + 1)  bit 7  SE (x + 1, y - 1)
 *
 * ConnexityNumber(m) is T8 of section 4.1 for the set m: the number of 8-connected components
 * formed by the neighbour positions in m, adjacency being taken among those eight positions
 * (A itself is left out; every neighbour is 8-adjacent to A, so these are the components
 * adjacent to A). The paper selects a pixel for reconstruction (section 4.2) when its unlike
 * neighbours make exactly two components and its like neighbours exactly one:
 * T8(X) == 2 and T8(X') == 1: it then joins two pieces of a thin shape that point sampling cut
 * apart (a diagonal line missing one pixel is closed).
 *
 * Our additions. The paper's rule as it stands (8-adjacency among the neighbours) also selects
 * the background pixels between two lines that pass within a pixel of each other (a dense
 * wireframe, converging iso-lines) and fills them, which undoes most of what MLAA gains on a
 * dense wireframe. It selects the corner pixel of a one-pixel-wide
 * L (which then takes the background's colour and cuts the corner), and the two pixels beside a
 * gap in a horizontal or vertical one-pixel line (which take the line's colour), while the gap
 * itself stays open (its like neighbours are two pieces). So a pixel is selected when:
 * - its unlike neighbours X make exactly two pieces (T8(X) == 2, the paper's rule);
 * - neither piece holds more than MaximumPieceSize (two) neighbours: all a one-pixel line
 *   crossing the 3 x 3 neighbourhood holds (pieces of lines passing by, and the background
 *   around a thin L's corner, are larger);
 * - the two pieces lie on opposite sides of the pixel: the angle between their mean offsets is
 *   at least 135 degrees (cosine at most OppositeCosine), as the two ends of a line through the
 *   pixel are (the pixels beside a straight gap see them at 90 degrees);
 * - its like neighbours make one piece (T8(X') == 1, the paper's rule), or two where the shape
 *   is a straight line through the pixel (two single, exactly opposite neighbours): the gap in
 *   a horizontal, vertical or 45-degree line is closed.
 * A diagonal or knight's-move gap, and a straight one, are closed; a line end, an isolated dot,
 * a corner (of a filled shape or of a thin L), a crossing of lines and lines passing by are left
 * alone.

 * This class is the one generator of that rule: vtkImageMLAA reads GetSelectionTable() and
 * vtkOpenGLMLAAPass uploads GetSelectionBits() to its reconstruction shader. What "unlike"
 * means (the CIELAB difference of vtkMLAAOptions::Reconstruction) and the further condition that
 * the X pixels are all of one colour are left to the back ends.
 *
 * @sa vtkMLAAOptions vtkImageMLAA vtkOpenGLMLAAPass
 */

#ifndef vtkMLAATopology_h
#define vtkMLAATopology_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkObject.h"

#include <vector> // For std::vector

class VTKFILTERSMLAA_EXPORT vtkMLAATopology : public vtkObject
{
public:
  static vtkMLAATopology* New();
  vtkTypeMacro(vtkMLAATopology, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The offset (dx, dy) of neighbour `bit` (0 to 7, see the class description).
   */
  static void GetNeighborOffset(int bit, int& dx, int& dy);

  /**
   * T8 of the neighbour positions in `mask` (its low 8 bits): the number of their 8-connected
   * components, 0 to 4.
   */
  static int ConnexityNumber(int mask);

  /**
   * The number of positions in the largest 8-connected component of `mask` (0 for none).
   */
  static int LargestComponent(int mask);

  /**
   * The most neighbours that one piece of the shape may hold for a pixel to be selected: two,
   * the cross-section of a one-pixel line as the 3 x 3 neighbourhood sees it.
   */
  static constexpr int MaximumPieceSize = 2;

  /**
   * The largest cosine of the angle between the two pieces' mean offsets for a pixel to be
   * selected: -0.7, about 135 degrees (a knight's-move gap is exactly 135 degrees).
   */
  static constexpr double OppositeCosine = -0.7;

  /**
   * The coverage rule: a selected pixel does not take the shape's full colour, but the share of
   * it that the thin shape would cover there. Point sampling keeps a shape's mean coverage: a
   * line of width w < 1 pixel lights about a fraction w of the pixels along it (at most one per
   * column, or per row where it is steep) and leaves the rest as gaps, so the density of the
   * shape's pixels around a gap measures w. Let n be the number of pixels alike the shape
   * (not unlike its pixels, by the test of the selection) among the (2 R + 1)^2 - 1 others of
   * the square window of radius R = CoverageRadius around the selected pixel:
   * - n > 2 R + 1 is more than one thin line crossing the window can light: two lines passing
   *   within a pixel of each other, or a shape that is not thin. The pixel is no gap and keeps
   *   its colour (coverage 0).
   * - Otherwise the line's density is w = n / (2 R + 1), and the gap, which the line crosses
   *   without covering the pixel's centre, is covered by w / 2 on average (a band of width w
   *   that misses the centre covers between 0 and w of the pixel). The pixel moves that share
   *   of the way to the mean colour of its unlike neighbours: n / (2 (2 R + 1)).
   * Filling gaps with the full colour (the paper's rule) made restored lines too bright and
   * too thick, and filled the space between lines passing close by.
   * The pixels of the line beside a gap follow the thin line rule (GetLineShare).
   */
  static constexpr int CoverageRadius = 3;

  /**
   * The share of the shape's colour (0 to 1/2) that a selected pixel takes when `shapePixels`
   * pixels of its window are alike the shape (the coverage rule above).
   */
  static double GetCoverage(int shapePixels);

  /**
   * The thin line rule: the share of its colour (0 to 1) that a pixel of the shape of a gap
   * keeps, when the gap's window holds `shapePixels` pixels alike the shape (n, as for
   * GetCoverage). Point sampling lights a pixel of a line w < 1 pixel wide with the line's full
   * colour where the reference shows the share of the pixel that the line covers. For
   * w <= 1/2 the line's band, which passes within w / 2 of the lit pixel's centre, lies inside
   * the pixel, which it covers by exactly w: the share is the line's density
   * w = n / (2 R + 1) for 2 n <= 2 R + 1, and the pixel moves the rest of the way to the gap's
   * colour. Wider lines spill into the next row or column, which MLAA's blending already
   * models: there (and for n = 0) the share is 1, the pixel keeps its colour. The back ends
   * apply it to a pixel unlike a gap among its neighbours (it is a pixel of the gap's shape)
   * when the gap's n is more than the gap's unlike neighbours (the line goes on beyond them:
   * two dots side by side are left alone); among several gaps, the one with the largest n, the
   * first in neighbour order among equals.
   */
  static double GetLineShare(int shapePixels);

  /**
   * The number of rows and columns beyond a pixel that reconstruction reads for it: its
   * neighbours, which may be gaps (the thin line rule), and their coverage windows,
   * CoverageRadius + 1.
   */
  static constexpr int ReconstructionReach = CoverageRadius + 1;

  /**
   * GetCoverage for 0 to (2 CoverageRadius + 1)^2 - 1 shape pixels, as floats for a shader;
   * the pointer stays valid for the life of the program.
   */
  static const float* GetCoverageTable();

  /**
   * GetLineShare for 0 to (2 CoverageRadius + 1)^2 - 1 shape pixels, as floats for a shader;
   * the pointer stays valid for the life of the program.
   */
  static const float* GetLineShareTable();

  /** The number of entries of GetCoverageTable() and GetLineShareTable(): (2 CoverageRadius + 1)^2. */
  static constexpr int CoverageTableSize = (2 * CoverageRadius + 1) * (2 * CoverageRadius + 1);

  /**
   * Whether a pixel whose unlike neighbours are `unlikeMask` is selected for reconstruction
   * (the rule of the class description).
   */
  static bool IsSelected(int unlikeMask) { return GetSelectionTable()[unlikeMask & 255] != 0; }

  /**
   * The selection rule for the 256 masks: entry m is 1 where IsSelected(m), else 0. Computed
   * once (thread-safe); the pointer stays valid for the life of the program.
   */
  static const unsigned char* GetSelectionTable();

  /**
   * The selection table packed as 256 bits, for a shader: bit (m & 31) of bits[m >> 5] is
   * entry m.
   */
  static void GetSelectionBits(unsigned int bits[8]);

protected:
  vtkMLAATopology() = default;
  ~vtkMLAATopology() override = default;

private:
  // A piece (8-connected component) of a neighbourhood mask: its size and the sums of its
  // neighbours' offsets.
  struct Piece
  {
    int Size = 0;
    int X = 0;
    int Y = 0;
  };
  static std::vector<Piece> FindPieces(int mask);
  static double PiecesCosine(const Piece& a, const Piece& b);
  static bool ComputeSelection(int mask);
  vtkMLAATopology(const vtkMLAATopology&) = delete;
  void operator=(const vtkMLAATopology&) = delete;
};

#endif
