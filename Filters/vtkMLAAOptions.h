// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMLAAOptions
 * @brief   The settings of morphological antialiasing, shared by the CPU filter and the GPU pass.
 *
 * vtkMLAAOptions holds every setting of the MLAA algorithm of Jimenez et al., "Practical
 * Morphological Antialiasing" (GPU Pro 2, chapter 4). The CPU filter vtkImageMLAA and the GPU
 * render pass vtkOpenGLMLAAPass both read their settings from an instance of this class, so the
 * names, defaults, ranges and meanings are defined once, here. One instance may be shared by a
 * filter and a pass (SetOptions on both): they then produce the same image, within the rounding
 * of the GPU's arithmetic.
 *
 * The settings:
 * - Threshold (default 0.1, range [0, 1]): the smallest difference between two neighbouring
 *   pixels that is an edge, in normalised units (the whole value range of the image is 1).
 *   The chapter (section 4.2.1) found 0.1 adequate for luma. Lower values find more, fainter
 *   edges (and more noise); higher values leave faint edges aliased.
 * - LocalContrastFactor (default 2, range [0, 100]; 0 turns it off): local contrast
 *   adaptation, an idea of SMAA (Jimenez et al., "SMAA: Enhanced Subpixel Morphological
 *   Antialiasing", 2012) that the chapter does not have. An edge is kept only if this factor
 *   times its contrast is at least the contrast of every other boundary of the two pixels it
 *   separates. Shading inside an object next to a strong silhouette (the dark rim of a lit
 *   cylinder, say) otherwise makes faint edges that cut the silhouette's staircase into short
 *   pieces with the wrong shapes; with the default factor, only edges at least half as
 *   strong as the strongest edge beside them count. A faint edge with no stronger edge beside
 *   it is kept. Adaptation also drops an edge that lies inside a ramp: where the boundaries
 *   before and after it, along the same axis, change what is compared the same way, by at least
 *   half as much (sampled shading, a smooth colour map, an edge that is already antialiased);
 *   MLAA's blend assumes a step between two regions, and would only damage a ramp.
 * - EdgeDetection (default Lab): what is compared across each pixel boundary.
 *   - Luma: the Rec. 709 luminance 0.2126 R + 0.7152 G + 0.0722 B (the chapter's section 4.2.1;
 *     one- and two-component images use their first component). Cheapest and perceptual.
 *   - Color: the largest difference of any colour channel. Finds edges between colours of equal
 *     luma (pure red against pure green, say) at a small extra cost.
 *   - Depth: the difference of depth values (section 4.2): the filter's second input or the
 *     pass's depth buffer. Shading edges are then left alone. Depth buffers are non-linear,
 *     so this mode usually wants a far smaller threshold (1e-3 to 1e-2).
 *   - Lab: the CIELAB colour difference of "Morphological antialiasing and topological
 *     reconstruction" (Biri et al., section 3.2). The normalised colours are taken as sRGB,
 *     linearised, converted to CIE XYZ (D65) and to L*a*b*; the contrast is the Euclidean
 *     distance Delta E (CIE 1976) divided by 100, so the threshold is Delta E / 100: the default
 *     0.1 is Delta E 10, and 0.023 is one just-noticeable difference. Finds edges between
 *     colours of equal luma (red against blue) and weighs differences as a person sees them,
 *     at the highest cost of the four modes. Grey images are grey sRGB (a* = b* = 0).
 *   With an alpha channel (2 or 4 components), a change in alpha alone is also an edge, in
 *   every mode.
 * - MaxSearchSteps (default 16, range [1, 128]): the distance search of section 4.3.1 reads two
 *   edgels per step, so lines are followed for up to 2 * MaxSearchSteps pixels on each side of
 *   a pixel (32 by default; 16 with the chapter's 8 steps; 256 at most, the 255-pixel lines of Biri et al.,
 *   section 3.3). The area texture then has cells of 2 * MaxSearchSteps + 1 texels
 *   (vtkMLAAAreaTexture). Longer searches smooth longer, flatter staircases (a nearly
 *   horizontal horizon gets one ramp per step of its staircase instead of one every 16 pixels).
 *   The CPU filter finds the distances from run lengths and the GPU pass by recursive doubling,
 *   so their cost grows slowly with the number of steps.
 * - DiagonalDetection (default on): also recognise staircases of one-pixel steps as lines at
 *   45 degrees and revectorise them along the diagonal (vtkMLAAAreaTexture::ComputeDiagonalAreas).
 *   The chapter's method only follows horizontal and vertical lines, and gives every pixel of
 *   such a staircase the same 1/8 weight however the real line drifts across it; near-45-degree
 *   silhouettes and wireframe lines are where MLAA otherwise does worst. Staircases shorter
 *   than MinimumDiagonalLength units (a box's corner, say) keep the orthogonal treatment. The
 *   diagonal search follows up to GetMaxDistance() units each way. Off follows only horizontal
 *   and vertical lines, as the chapter does.
 * - CornerExtrapolation (default off, and off in every preset): where a horizontal or vertical
 *   line ends at a corner of a shape (its crossing edge is a side of the shape, two pixels long
 *   or more, and the line does not go on one row or column over past it) or at the image
 *   border, its height there is extrapolated from the staircase seen at its other end (the
 *   length of the next run past that step gives the slope): the line is ramped as the whole run
 *   of that staircase it is part of. The chapter reads every crossing edge as a one-pixel step,
 *   so a long line's ramp rounds the corner over half the line's length, the more the longer
 *   the search, also where the side lies on a pixel boundary. Where that step is the side's
 *   only one (the next run past it ends at a corner or the border too), the run is not seen
 *   whole: it is at least as long as the longer of the two runs, and the line is ramped as a
 *   run twice that long, the expected run when no run length is more likely than another at
 *   its scale. Where the other end is seen but gives no slope (no next run, or one that ends at
 *   a step but is too short to belong to one straight staircase with the line), the corner's
 *   height is unknown and it takes half the chapter's ramp, the mean of a step and a flat end.
 *   Where nothing is seen at all (corners at both ends, the other end beyond the search's
 *   reach), no step is seen either, and the side is left alone, with this option or without
 *   (see "Sides without steps" below). Raises AAR and lowers damage on
 *   long lines (docs/measurements.md), but not on every scene, hence off by default.
 * - Sides without steps (always, in every preset; issue 50, not a setting): the chapter reads every
 *   crossing edge at the end of a line as a one-pixel step of a staircase, and ramps the line
 *   from it. Where the crossing edge is instead a side of a shape (it goes on for two pixels or
 *   more, the line does not go on one row or column over past it, and the side does not end in
 *   a step of a steeper staircase within the search's reach), and the line's other end is no
 *   step either (such a corner, a junction of wider shapes, the image border, no crossing edge,
 *   or beyond the reach), nothing tells that the side leaves the pixel boundary, and the line
 *   (four pixels or longer) gets no blending: the sides of axis-aligned rectangles, of voxels
 *   seen straight on, of bars, legends and viewport borders stay exactly as they are. A side
 *   that is really a fraction of a pixel off the boundary looks the same in one sample per
 *   pixel and is not antialiased either; MultiSamples measures where it lies.
 * - DominantDirectionBlending (default on): in the neighbourhood blending, a pixel that lies on
 *   both a horizontal and a vertical line (the corner of a staircase) is blended along the one
 *   with the larger weight only, as SMAA (Jimenez et al., 2012) does; on a tie it keeps both.
 *   The chapter (section 4.4) averages the blends with all four neighbours, which at every corner
 *   mixes in a second, cross-wise share of the other colour that no revectorised line covers.
 *   Off gives the chapter's blending.
 * - Reconstruction (default off): topological reconstruction (Biri et al., section 4) before
 *   edge detection. Each pixel's eight neighbours are classed as unlike it (the CIELAB
 *   difference of the Lab mode reaches the threshold, or alpha differs by as much) or like it;
 *   where the unlike neighbours form exactly two 8-connected pieces of at most two pixels each,
 *   all of one colour, on opposite sides of the pixel, and the like ones a single piece (two
 *   for a straight line), the pixel is where point sampling dropped a piece of a thin shape (a
 *   wire, a streamline, an iso-line). It moves towards the mean of the unlike neighbours by the
 *   share of the shape that covers it, which the density of the shape's pixels around it
 *   measures (the coverage rule: about half the line's density; none where the window holds
 *   more than one thin line, so the space between lines passing close by is left alone);
 *   on lines at most half a pixel wide the lit pixels beside it keep the line's density of
 *   their colour (the thin line rule). vtkMLAATopology has the rules and where they depart from the paper's, which restored
 *   the full colour. MLAA alone cannot restore such pixels. A line end, an isolated dot, a
 *   corner or a thin line crossing the pixel's own thin line are left alone. On the project's
 *   scenes it raises AAR where sub-pixel lines break into dashes and changes no other scene's
 *   by more than 0.001, but costs about as much as the rest of the filter: off by default and
 *   in every preset but Max; turn it on for images of sub-pixel wires, curves and points.
 * - PremultipliedAlpha (default off): how the colour of an image with alpha (2 or 4 components)
 *   relates to its alpha. Off: straight (unassociated) alpha, as image files hold it (PNG always)
 *   and as VTK images usually do: the colour is that of the surface, whatever its coverage. The
 *   blending then mixes premultiplied colours and divides by the blended alpha again, so the
 *   colour stored in fully transparent pixels (a black or white background, say) never leaks
 *   into an antialiased silhouette as a dark or bright fringe. On: the colour is already
 *   premultiplied (associated alpha, as EXR and compositing pipelines hold it), and is blended
 *   as it is. Images without alpha are not affected.
 * - DebugOutput (default None): instead of the antialiased image, output one of the
 *   intermediate textures of Figure 4.1, as 8-bit RGBA:
 *   - Edges: red = 255 where the pixel has an edge at its left boundary, green = 255 where it
 *     has one at its top boundary (so both is yellow); blue = 0, alpha = 255.
 *   - BlendingWeights: the blending-weights texture of section 4.3 scaled to 0..255. Red: weight
 *     with which this pixel takes the colour of the pixel above it; green: weight with which the
 *     pixel above takes this pixel's colour; blue: weight with which this pixel takes the colour
 *     of its left neighbour; alpha: weight with which the left neighbour takes this pixel's.
 *     Weights are at most 0.5, so values are at most 128.
 *
 * Presets set every quality setting at once (Threshold, LocalContrastFactor, EdgeDetection,
 * MaxSearchSteps, DiagonalDetection, CornerExtrapolation, DominantDirectionBlending,
 * Reconstruction), as SMAA's quality presets do; PremultipliedAlpha and DebugOutput describe the
 * data and the output and are left as they are. Settings changed after a preset override it.
 * docs/measurements.md lists what each preset costs and gains, as measured by the project's
 * benchmarks.
 * - Low: luma, threshold 0.15, 4 steps, no diagonals.
 * - Medium: luma, threshold 0.1, 8 steps, diagonals (the chapter's edges and search length).
 * - High: Lab, threshold 0.1, 16 steps, diagonals: the defaults, which measured best for their
 *   cost.
 * - Ultra: Lab, threshold 0.05, 32 steps, diagonals.
 * - Max: Ultra with Reconstruction, for pictures with lines or points under a pixel wide
 *   (wires, streamlines, point clouds), which point sampling breaks into dashes; elsewhere it
 *   gives Ultra's result (within 0.001 AAR on the project's scenes) at about twice its cost.
 * The other presets leave Reconstruction off.
 *
 * "Top" and "above" mean towards the top of the displayed image: higher row index in a
 * vtkImageData and in an OpenGL texture.
 *
 * @sa vtkImageMLAA vtkOpenGLMLAAPass vtkMLAAAreaTexture
 */

#ifndef vtkMLAAOptions_h
#define vtkMLAAOptions_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkObject.h"

class VTKFILTERSMLAA_EXPORT vtkMLAAOptions : public vtkObject
{
public:
  static vtkMLAAOptions* New();
  vtkTypeMacro(vtkMLAAOptions, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** What edge detection compares across each pixel boundary. */
  enum EdgeDetectionModes
  {
    LUMA = 0,
    COLOR = 1,
    DEPTH = 2,
    LAB = 3
  };

  /** The quality presets (SetPreset). */
  enum Presets
  {
    LOW = 0,
    MEDIUM = 1,
    HIGH = 2,
    ULTRA = 3,
    MAX = 4
  };

  /** Which image the filter or pass outputs. */
  enum DebugOutputs
  {
    NO_DEBUG_OUTPUT = 0,
    EDGES = 1,
    BLENDING_WEIGHTS = 2
  };

  ///@{
  /**
   * Smallest normalised difference that is an edge. Default 0.1, range [0, 1].
   */
  vtkSetClampMacro(Threshold, double, 0.0, 1.0);
  vtkGetMacro(Threshold, double);
  ///@}

  ///@{
  /**
   * Local contrast adaptation: an edge survives only if LocalContrastFactor times its contrast
   * is at least the contrast of each other boundary of the two pixels it separates, and if it
   * does not lie inside a ramp (the boundaries before and after it along the same axis change the
   * values the same way, by at least half as much). Default 2, range [0, 100]; 0 keeps every edge
   * above the threshold (the chapter's detection).
   */
  vtkSetClampMacro(LocalContrastFactor, double, 0.0, 100.0);
  vtkGetMacro(LocalContrastFactor, double);
  ///@}

  ///@{
  /**
   * What edge detection compares: LUMA, COLOR, DEPTH or LAB (default).
   */
  vtkSetClampMacro(EdgeDetection, int, LUMA, LAB);
  vtkGetMacro(EdgeDetection, int);
  void SetEdgeDetectionToLuma() { this->SetEdgeDetection(LUMA); }
  void SetEdgeDetectionToColor() { this->SetEdgeDetection(COLOR); }
  void SetEdgeDetectionToDepth() { this->SetEdgeDetection(DEPTH); }
  void SetEdgeDetectionToLab() { this->SetEdgeDetection(LAB); }
  ///@}

  ///@{
  /**
   * Number of steps of the distance search, two pixels per step. Default 16 (lines followed for
   * up to 32 pixels each way), range [1, 128].
   */
  vtkSetClampMacro(MaxSearchSteps, int, 1, 128);
  vtkGetMacro(MaxSearchSteps, int);
  ///@}

  /**
   * Longest distance, in pixels, from a pixel to either end of its line that the search
   * reports: 2 * MaxSearchSteps.
   */
  int GetMaxDistance() const { return 2 * this->MaxSearchSteps; }

  /**
   * How far, in pixels, the search reads from a pixel along its line: the MaxDistance pixels of
   * the line and the crossing edge one further (section 4.3.2), 2 * MaxSearchSteps + 1. It is
   * also D, the side in texels of one cell of the area texture for this distance
   * (vtkMLAAAreaTexture::GetCellSize), and the reach of the filter's halo along a line. This is
   * the one place that computes it.
   */
  int GetSearchReach() const { return this->GetMaxDistance() + 1; }

  /**
   * The search length from which both back ends count line lengths exactly over the whole image
   * beforehand instead of searching from every pixel with an edge: vtkImageMLAA by run lengths
   * (one scan per row and per column), vtkOpenGLMLAAPass by recursive doubling (with its
   * LineLengths AUTOMATIC). Either way the distances, and so the images, are the same; only the
   * cost differs. A search stops at the end of each line, so it costs little where lines are
   * short, but its cost grows with the length of the lines up to MaxSearchSteps reads each way;
   * counting costs a few reads of every pixel (and, on the CPU, a buffer of line lengths the
   * size of the image) whatever the lines, and bounds the cost that long lines add. Below this
   * length the search's reach is short enough that searching wins on both back ends.
   */
  static constexpr int ExactLineLengthsSteps = 32;

  /** Whether MaxSearchSteps is long enough to count line lengths exactly (above). */
  bool GetCountsExactLineLengths() const
  {
    return this->MaxSearchSteps >= ExactLineLengthsSteps;
  }

  ///@{
  /**
   * Whether staircases of one-pixel steps are treated as 45-degree lines. Default on.
   */
  vtkSetMacro(DiagonalDetection, bool);
  vtkGetMacro(DiagonalDetection, bool);
  vtkBooleanMacro(DiagonalDetection, bool);
  ///@}

  ///@{
  /**
   * Whether the ends of lines at corners of shapes and at the image border take the height
   * extrapolated from the staircase (see the class description). Default off.
   */
  vtkSetMacro(CornerExtrapolation, bool);
  vtkGetMacro(CornerExtrapolation, bool);
  vtkBooleanMacro(CornerExtrapolation, bool);
  ///@}

  ///@{
  /**
   * Whether a pixel on both a horizontal and a vertical line is blended along the dominant one
   * only (the larger weight; both on a tie). Default on; off averages all four neighbours'
   * blends, as in the chapter.
   */
  vtkSetMacro(DominantDirectionBlending, bool);
  vtkGetMacro(DominantDirectionBlending, bool);
  vtkBooleanMacro(DominantDirectionBlending, bool);
  ///@}

  ///@{
  /**
   * Whether the colour channels of an image with alpha are premultiplied by alpha (associated
   * alpha). Default off: straight alpha.
   */
  vtkSetMacro(PremultipliedAlpha, bool);
  vtkGetMacro(PremultipliedAlpha, bool);
  vtkBooleanMacro(PremultipliedAlpha, bool);
  ///@}

  ///@{
  /**
   * Whether topological reconstruction restores the pixels that point sampling dropped from
   * thin shapes (by the share of the shape that covers them), before edge detection. Default
   * off.
   */
  vtkSetMacro(Reconstruction, bool);
  vtkGetMacro(Reconstruction, bool);
  vtkBooleanMacro(Reconstruction, bool);
  ///@}

  ///@{
  /**
   * Set every quality setting to those of a preset: LOW, MEDIUM, HIGH, ULTRA or MAX (see the class
   * description). Out-of-range values are ignored with an error. GetPreset() returns the
   * preset whose settings the current ones equal, or -1 when they equal none.
   */
  void SetPreset(int preset);
  int GetPreset();
  void SetPresetToLow() { this->SetPreset(LOW); }
  void SetPresetToMedium() { this->SetPreset(MEDIUM); }
  void SetPresetToHigh() { this->SetPreset(HIGH); }
  void SetPresetToUltra() { this->SetPreset(ULTRA); }
  void SetPresetToMax() { this->SetPreset(MAX); }
  ///@}

  /**
   * Fewest units (turns of the staircase) that DiagonalDetection treats as a diagonal line.
   */
  static constexpr int MinimumDiagonalLength = 2;

  ///@{
  /**
   * The image to output: NO_DEBUG_OUTPUT (default: the antialiased image), EDGES or
   * BLENDING_WEIGHTS.
   */
  vtkSetClampMacro(DebugOutput, int, NO_DEBUG_OUTPUT, BLENDING_WEIGHTS);
  vtkGetMacro(DebugOutput, int);
  void SetDebugOutputToNone() { this->SetDebugOutput(NO_DEBUG_OUTPUT); }
  void SetDebugOutputToEdges() { this->SetDebugOutput(EDGES); }
  void SetDebugOutputToBlendingWeights() { this->SetDebugOutput(BLENDING_WEIGHTS); }
  ///@}

  ///@{
  /**
   * Names of the modes, as the `mlaa` tool spells them: "luma", "color", "depth", "lab";
   * "none", "edges", "weights"; "low", "medium", "high", "ultra", "max" (GetPresetAsString(-1) is
   * "custom"). The parsing functions return -1 for an unknown name.
   */
  static const char* GetEdgeDetectionAsString(int mode);
  static int GetEdgeDetectionFromString(const char* name);
  static const char* GetPresetAsString(int preset);
  static int GetPresetFromString(const char* name);
  static const char* GetDebugOutputAsString(int output);
  static int GetDebugOutputFromString(const char* name);
  ///@}

  /**
   * Copy every setting of another instance.
   */
  void DeepCopy(vtkMLAAOptions* other);

  /**
   * Copy the quality settings of another instance, the ones a preset sets (Threshold,
   * LocalContrastFactor, EdgeDetection, MaxSearchSteps, DiagonalDetection,
   * CornerExtrapolation, DominantDirectionBlending, Reconstruction), and leave
   * PremultipliedAlpha and DebugOutput.
   */
  void CopyQualitySettings(vtkMLAAOptions* other);

  /**
   * For the classes that own options (vtkImageMLAA, vtkOpenGLMLAAPass), whose options are never
   * null: make `member` refer to `options` (registered to `owner`), or to a fresh default object
   * when `options` is null, releasing the previous one. Returns true when `member` changed.
   */
  static bool Assign(vtkObject* owner, vtkMLAAOptions*& member, vtkMLAAOptions* options);

protected:
  vtkMLAAOptions() = default;
  ~vtkMLAAOptions() override = default;

  double Threshold = 0.1;
  double LocalContrastFactor = 2.0;
  int EdgeDetection = LAB;
  int MaxSearchSteps = 16;
  int DebugOutput = NO_DEBUG_OUTPUT;
  bool DiagonalDetection = true;
  bool CornerExtrapolation = false;
  bool DominantDirectionBlending = true;
  bool PremultipliedAlpha = false;
  bool Reconstruction = false;

private:
  vtkMLAAOptions(const vtkMLAAOptions&) = delete;
  void operator=(const vtkMLAAOptions&) = delete;
};

#endif
