// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkDLAAOptions
 * @brief   The settings of directionally localized antialiasing (DLAA), shared by the CPU filter
 *          and the GPU pass.
 *
 * DLAA (Andreev, "Anti-Aliasing From a Different Perspective", GDC 2011; the method of The
 * Force Unleashed 2) blurs each edge along its own direction instead of recognising the
 * patterns of its staircase as MLAA does. It is a fixed, small set of filters per pixel, so a
 * staircase that moves by a fraction of a pixel changes the result by a fraction too: it trades
 * some of MLAA's sharpness on still images for temporal stability. vtkImageDLAA (CPU) and
 * vtkOpenGLDLAAPass (GPU) read their settings from an instance of this class and compute the
 * same image within the rounding of the GPU's arithmetic.
 *
 * The method, as both back ends implement it. Colours are normalised as vtkImageMLAA normalises
 * them (its value range: the whole range is 1), reads beyond the image are clamped to its border
 * (as GPU texture reads are), l(c) is the luminosity function (LumaFunction) of a colour c, and
 * every channel, alpha included, is filtered alike. For pixel p with colour c:
 * 1. Short edges (slides 21 to 24, 43). Along x, the four neighbours at distance 1 and 2 give the
 *    5-pixel high-pass Hx = |sum - 4 c| / 4 (per channel) and the 5-pixel blur
 *    Bx = (sum + 2 c) / 6; along y the same give Hy and By. The blend masks turn the high-pass
 *    responses into weights with the contrast curve saturate(lambda * response - epsilon),
 *    divided by the luminosity of the blur they are used with, which makes them independent of
 *    the image's intensity:
 *      mx = saturate((Lambda * l(Hy) - Epsilon) / l(Bx))   (a horizontal edge: blur along x),
 *      my = saturate((Lambda * l(Hx) - Epsilon) / l(By))   (a vertical edge: blur along y),
 *    with 0 where the numerator is not positive and 1 where it is positive and the divisor is 0.
 *    The short-edge result is s = lerp(lerp(c, Bx, mx), By, my / 2).
 *    Corners (an addition of ours, issue 50): a blur reads no pixel past the side of a corner
 *    (below); a read beyond such a side, 1 or 2 pixels from p, reads the last pixel before it.
 *    Without this, the blur along a side that lies on pixel borders brought the next shape's
 *    colour into the pixels at its ends (bars, rectangles, voxels seen straight on).
 * 2. Long edges (slides 25 to 31, 44 to 47; LongEdges on). A long horizontal edge is a run of
 *    horizontal-edge responses along x: the long mask Mx = saturate(2 * a - 1), where a is the
 *    mean of mx over the 17 pixels p - 8 .. p + 8 along x; My likewise along y with my. Near
 *    the border, the masks of the positions beyond it are computed by the formulas of step 1
 *    at those positions, from clamped colour reads (not the border pixel's masks). Where
 *    both Mx and My are positive (noise, texture: slide 32) nothing more is done. Otherwise, for
 *    Mx > 0: the mean colour along x over the step the pixel is on (p - h .. p + h, below) is
 *    only a target luminosity t, never a colour (a distant colour would bleed); the pixel is
 *    moved towards the neighbour above (u) or below (d) until its luminosity is t: with
 *    k = (t - l(c)) / (l(n) - l(c)) for
 *    n = u and n = d, the first of u, d whose k lies in (0, 1] (the smaller k if both do) gives
 *    q = lerp(c, n, k), else q = c; and the result is lerp(s, q, Mx). For My > 0 the same along
 *    y with the left and right neighbours.
 *    The window's half-length h (1 to 8) is how far the step reaches, the shorter of its two
 *    reaches from p along the edge (for Mx, along x, with u and d the neighbours across): it goes
 *    on while both u and d keep their luminosity within half of |l(u) - l(d)| (the tolerance),
 *    and, where exactly one of u, d is within the tolerance of c, it may go on once through a
 *    place where the pixel's row and the other neighbour swap luminosities (a line one pixel
 *    wide moving into the pixel's row); h = max(1, shorter reach). The talk's 17-pixel mean is
 *    this window for steps of 17 pixels and more; on shorter steps (edges a few pixels off
 *    horizontal or vertical) a longer window would spread each step's transition across more
 *    than the pixels it covers, and make it flicker in motion (docs/measurements.md).
 *    The reach also stops before the first place along the edge where the pixel's row changes
 *    luminosity across the side of a corner (3, below). Where that side is next to the pixel,
 *    h = 0 (the mean of the pixel alone: q = c).
 * 3. The side of a corner (issue 50). A boundary between two pixels a and b next to each other
 *    along a direction (the blur's, or the edge's) separates luminosities l(a) and l(b); with
 *    tolerance half their difference, the pair goes on across that direction as far as the
 *    pixels beside a and b keep l(a) and l(b) within the tolerance (followed up to
 *    CornerSearch = 8 pixels each way). The boundary is the side of a corner when l(a) and l(b)
 *    differ; the colours of a and b differ by more than 2 Epsilon / Lambda in some channel that
 *    l reads (the contrast at which the masks see an edge: a step of that height gives the pixel
 *    beside it a high-pass of half of it; in colour, since voxels of different colours may have
 *    nearly the same luminosity; fainter boundaries, such as the bands of flat shading along a
 *    silhouette, are none); the pair goes on for CornerRun = 4 pixels or more in all (a and b
 *    included); and
 *    at each end where it stops within the 8 pixels: the pair does not go on one pixel over
 *    along the direction (one pixel further or back: a staircase's run goes on so at each of
 *    its steps); on a's side or on
 *    b's, the two pixels at the end (the last of the run and the first past it) differ, and the
 *    3 pairs next to them further from the boundary keep their luminosities within half that
 *    difference (a side crossing the boundary's line that goes on for 4 pixels: a shorter
 *    crossing, such as the end of a line one pixel wide, is a step as well); and both of the
 *    end's luminosities are finite. MLAA's "sides without steps" (docs/methods.md) reads the
 *    same kind of picture from its edges.
 * Flat regions (every response 0) and faint noise (Lambda * response <= Epsilon) are left
 * exactly as they are. Pixels whose neighbourhood holds NaN or infinity are left as they are.
 * Details both back ends follow: "above" is the next row (y + 1, up on screen in VTK images and
 * GL textures), and u is tried before d, left before right (on equal k the first wins); a
 * neighbour with l(n) = l(c) is never used (no k). A pixel's neighbourhood is every pixel its
 * result reads: the 5-pixel crosses (x +- 2, y +- 2) of the pixel and, with LongEdges, of every
 * pixel up to 8 away along x or y.
 *
 * The settings:
 * - Epsilon (default 0.1, range [0, 1]) and Lambda (default 3, range [0, 100]): the contrast
 *   curve of the blend masks (the talk's effectiveness controls, slide 43, with its values).
 *   Responses below Epsilon / Lambda are ignored; higher Lambda blends more.
 * - LumaFunction (default REC709): the luminosity l. REC709: 0.2126 R + 0.7152 G + 0.0722 B, as
 *   MLAA's luma edges; GREEN: the green channel alone (the talk's choice for speed). One- and
 *   two-component images use their first component.
 * - LongEdges (default on): the long-edge step; off gives the short-edge result alone.
 *
 * @sa vtkImageDLAA vtkOpenGLDLAAPass vtkMLAAOptions
 */

#ifndef vtkDLAAOptions_h
#define vtkDLAAOptions_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkObject.h"

#include <cfloat> // For FLT_MAX

class VTKFILTERSMLAA_EXPORT vtkDLAAOptions : public vtkObject
{
public:
  static vtkDLAAOptions* New();
  vtkTypeMacro(vtkDLAAOptions, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The luminosity functions. */
  enum LumaFunctions
  {
    REC709 = 0,
    GREEN = 1
  };

  /** Pixels each way of the long-edge masks and blurs (a 17-pixel window). */
  static constexpr int LongEdgeRadius = 8;
  /** Pixels each way over which the side of a corner is followed (method step 3). */
  static constexpr int CornerSearch = 8;
  /** Pixels, the first included, for which a side crossing a corner's side must go on (step 3). */
  static constexpr int CornerCrossing = 4;
  /** Pixels, both of the boundary's included, for which a corner's side must go on (step 3). */
  static constexpr int CornerRun = 4;

  /**
   * 2 epsilon / lambda as a float, the largest float where lambda is 0: the contrast at which the
   * blend masks see an edge, above which a boundary may be the side of a corner (method step 3).
   * Both back ends take it from here.
   */
  static float SideContrast(double epsilon, double lambda)
  {
    return lambda > 0.0 ? static_cast<float>(2.0 * epsilon / lambda) : FLT_MAX;
  }

  ///@{
  /** Offset of the contrast curve of the blend masks. Default 0.1, range [0, 1]. */
  vtkSetClampMacro(Epsilon, double, 0.0, 1.0);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /** Gain of the contrast curve of the blend masks. Default 3, range [0, 100]. */
  vtkSetClampMacro(Lambda, double, 0.0, 100.0);
  vtkGetMacro(Lambda, double);
  ///@}

  ///@{
  /** The luminosity function: REC709 (default) or GREEN. */
  vtkSetClampMacro(LumaFunction, int, REC709, GREEN);
  vtkGetMacro(LumaFunction, int);
  void SetLumaFunctionToRec709() { this->SetLumaFunction(REC709); }
  void SetLumaFunctionToGreen() { this->SetLumaFunction(GREEN); }
  ///@}

  ///@{
  /** Whether long edges get the long-edge step. Default on. */
  vtkSetMacro(LongEdges, bool);
  vtkGetMacro(LongEdges, bool);
  vtkBooleanMacro(LongEdges, bool);
  ///@}

  ///@{
  /**
   * Names of the luminosity functions, as the `mlaa` tool spells them: "rec709", "green". The
   * parsing function returns -1 for an unknown name.
   */
  static const char* GetLumaFunctionAsString(int function);
  static int GetLumaFunctionFromString(const char* name);
  ///@}

  /** Copy every setting of another instance. */
  void DeepCopy(vtkDLAAOptions* other);

  /**
   * For the classes that own options (vtkImageDLAA, vtkOpenGLDLAAPass), whose options are never
   * null: make `member` refer to `options` (registered to `owner`), or to a fresh default object
   * when `options` is null, releasing the previous one. Returns true when `member` changed.
   */
  static bool Assign(vtkObject* owner, vtkDLAAOptions*& member, vtkDLAAOptions* options);

protected:
  vtkDLAAOptions() = default;
  ~vtkDLAAOptions() override = default;

  double Epsilon = 0.1;
  double Lambda = 3.0;
  int LumaFunction = REC709;
  bool LongEdges = true;

private:
  vtkDLAAOptions(const vtkDLAAOptions&) = delete;
  void operator=(const vtkDLAAOptions&) = delete;
};

#endif
