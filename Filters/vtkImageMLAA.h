// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageMLAA
 * @brief   Morphological antialiasing (MLAA) of images, on the CPU.
 *
 * vtkImageMLAA removes staircase aliasing from an image by finding its edges, recognising the
 * L, U and Z patterns that the edges form, and blending each pixel next to an edge with the pixel
 * across it by the area that the revectorised (smooth) line would cover. It implements the three
 * passes of Jimenez et al., "Practical Morphological Antialiasing" (GPU Pro 2, chapter 4):
 * 0. with Reconstruction only: topological reconstruction (Biri et al., "Morphological
 *    antialiasing and topological reconstruction", section 4): a pixel whose unlike neighbours
 *    (CIELAB difference at least the threshold) form two 8-connected pieces of one colour, and
 *    whose like neighbours one piece (vtkMLAATopology), moves towards the mean colour of the
 *    unlike ones by the share of the thin shape that covers it (the coverage rule);
 *    the result replaces the input of the stages below, and is in the output;
 * 1. edge detection (section 4.2): each pixel boundary whose difference (luma, colour, depth or
 *    the CIELAB Delta E of Biri et al., section 3.2) reaches the threshold,
 *    unless local contrast adaptation (LocalContrastFactor, an addition after SMAA) finds it
 *    much fainter than another boundary of its two pixels;
 * 2. blending weights (section 4.3): for every edgel, the distance to both ends of its line
 *    (two edgels read per step, section 4.3.1; unlike the chapter's search, it stops at crossing
 *    edges, which keeps the two outlines of one-pixel-wide lines apart), the crossing edges at
 *    those ends (4.3.2) and the precomputed area (4.3.3, vtkMLAAAreaTexture); with
 *    DiagonalDetection (default), edgels on a staircase of one-pixel steps take their weights
 *    from the 45-degree line through it instead (vtkMLAAAreaTexture::ComputeDiagonalAreas);
 * 3. neighbourhood blending (section 4.4): each pixel mixed with its four neighbours by those
 *    weights; with DominantDirectionBlending (default), a pixel on both a horizontal and a
 *    vertical line only along the one with the larger weight, as in SMAA.
 * It follows the GPU pass vtkOpenGLMLAAPass step for step: the same search (clamped at the image
 * border the way a GPU clamps texture reads), the same area texture and 8-bit blending weights,
 * so the two produce the same image within 1/255 on the same input.
 *
 * Settings are those of a vtkMLAAOptions object (GetOptions; SetOptions to share one with a
 * vtkOpenGLMLAAPass): Threshold, LocalContrastFactor, EdgeDetection, MaxSearchSteps,
 * DiagonalDetection, DominantDirectionBlending, Reconstruction, PremultipliedAlpha, DebugOutput.
 *
 * Input: vtkImageData of any numeric scalar type with 1 to 4 components (grey, grey + alpha,
 * RGB, RGBA). 2D images and 3D volumes; each z slice is antialiased on its own. Values are
 * normalised for edge detection by ValueRange (vtkImageAntialiasingAlgorithm): by default the
 * range of the type for integers and [0, 1] for floating point; SetValueRange for data that uses part of its type (12-bit data in
 * 16-bit integers). All components, alpha included, are blended with the same weights, so an
 * opaque silhouette over a transparent background gets a soft alpha edge; with straight alpha
 * (vtkMLAAOptions::PremultipliedAlpha off, the default) the colours are blended premultiplied
 * and divided by the blended alpha again, so the colour of transparent pixels does not leak
 * into the edge as a dark or bright fringe. Pixels holding NaN or
 * infinity are never part of an edge: they are neither changed nor mixed into their neighbours.
 * For EdgeDetection = Depth, the depth image goes to the second input (SetDepthInputData or
 * SetDepthInputConnection): one component, same extent; floating-point depths are used as they
 * are (a z-buffer in [0, 1]), integer ones normalised by their type range.
 *
 * Output: an image of the input's extent, scalar type and components (8-bit RGBA for the debug
 * outputs, see vtkMLAAOptions). The filter is streaming-safe: it asks for its input padded by the
 * search distance, so processing an image in pieces gives the same pixels as processing it whole.
 * It is multithreaded with vtkSMPTools and deterministic.
 *
 * Stages (vtkMLAAStages.h lists their files): the work mirrors the GPU pass's shaders: with Reconstruction, a
 * typed reconstruction of the slice's pixels into a copy (one more full-size buffer, in the
 * input's type; none without it), features (the only other typed step on the way in: each row
 * read into a few rows of normalised luma, colour, CIELAB, depth and alpha), edges (a buffer laid out as the pass's RG8 edges texture), blending weights (as its
 * RGBA8 weights texture, with the same 8-bit quantisation) and neighbourhood blending (the only
 * typed step on the way out). Besides the output, the edges and weights buffers (6 bytes per
 * pixel of a slice and its halo) are the only full-size buffers; they are kept between updates
 * so that a filter run frame after frame does not allocate them again, and freed with the
 * filter. Progress is reported (ProgressEvent) from the calling thread between groups of rows of
 * every stage, and AbortExecute is honoured there: an aborted update gives an empty output.
 *
 * Bad input (no scalars, scalars with fewer tuples than the extent has points, an empty image,
 * more than 4 components, a non-numeric scalar type, a missing depth image or one that does not
 * cover the colour image) is reported with vtkErrorMacro and gives an empty output; the depth
 * image's coverage is checked in RequestInformation, so a streamed update fails at once instead
 * of piece by piece. An empty requested extent (a piece of a streamed image smaller than the
 * piece count) gives an empty output without error. All reads stay within the input the filter
 * is given, even when an upstream delivers less than the padded extent it asked for.
 *
 * @sa vtkMLAAOptions vtkMLAAAreaTexture vtkOpenGLMLAAPass vtkImageAntialiasingAlgorithm vtkImageDLAA
 */

#ifndef vtkImageMLAA_h
#define vtkImageMLAA_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkImageAntialiasingAlgorithm.h"

class vtkMLAAOptions;

class VTKFILTERSMLAA_EXPORT vtkImageMLAA : public vtkImageAntialiasingAlgorithm
{
public:
  static vtkImageMLAA* New();
  vtkTypeMacro(vtkImageMLAA, vtkImageAntialiasingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The MLAA settings. Never null: a filter starts with its own default options; setting
   * nullptr restores a fresh default object. Changing the options re-executes the filter.
   */
  vtkGetObjectMacro(Options, vtkMLAAOptions);
  virtual void SetOptions(vtkMLAAOptions* options);
  ///@}

  ///@{
  /**
   * The depth image for EdgeDetection = Depth (input port 1, optional otherwise).
   */
  void SetDepthInputData(vtkDataObject* depth);
  void SetDepthInputConnection(vtkAlgorithmOutput* output);
  ///@}

  /**
   * The modification time also covers the options.
   */
  vtkMTimeType GetMTime() override;

  /**
   * How far, in pixels, an output pixel's value reaches into the input in x and y: the search
   * distance plus the pixels the edges and the blending look at (and one more with
   * Reconstruction). RequestUpdateExtent pads the
   * requested extent by this much.
   */
  int GetInputPadding() override;

protected:
  vtkImageMLAA();
  ~vtkImageMLAA() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkMLAAOptions* Options = nullptr;

private:
  vtkImageMLAA(const vtkImageMLAA&) = delete;
  void operator=(const vtkImageMLAA&) = delete;
};

#endif
