// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageDLAA
 * @brief   Directionally localized antialiasing (DLAA) of images, on the CPU.
 *
 * vtkImageDLAA hides staircase aliasing by blurring each edge along its own direction
 * (Andreev, "Anti-Aliasing From a Different Perspective", GDC 2011, slides 19 to 47): a short
 * 5-pixel blur along x where a high-pass filter across it finds a horizontal edge and along y
 * for a vertical one (slides 21 to 24), and on long edges, found as runs of such responses
 * (slides 26 to 29), an interpolation with the neighbour across the edge that gives the pixel
 * the luminosity of the mean along it over the step the pixel is on (at most 17 pixels), so
 * that no distant colour bleeds in (slides 30, 31, 45 to 47). Where both directions respond strongly (noise, texture) only the short-edge
 * blur is applied (slide 32). Unlike MLAA it recognises no patterns, so a staircase that moves
 * by a fraction of a pixel changes the result by a fraction: steadier in motion, softer on still
 * images. The method is written down, for this filter and the GPU pass vtkOpenGLDLAAPass alike,
 * in vtkDLAAOptions; the two compute the same image within 2/255.
 *
 * Settings are those of a vtkDLAAOptions object (GetOptions; SetOptions to share one with a
 * vtkOpenGLDLAAPass): Epsilon, Lambda, LumaFunction, LongEdges.
 *
 * Input: vtkImageData of any numeric scalar type with 1 to 4 components (grey, grey + alpha,
 * RGB, RGBA). 2D images and 3D volumes; each z slice is antialiased on its own. Values are
 * normalised by ValueRange (vtkImageAntialiasingAlgorithm): by default the range of the type
 * for integers and [0, 1] for floating point. Every channel, alpha included, is filtered alike;
 * the luminosity reads RGB (or the grey value). Reads beyond the image are clamped to its
 * border. Pixels that read NaN or infinity (see vtkDLAAOptions), or a value too large to blend
 * without overflow (beyond 1/4096 of the largest float or double, normalised), are left as they
 * are.
 *
 * Output: an image of the input's extent, scalar type and components; integer results are
 * rounded to nearest. Pixels the method does not change (flat regions, faint noise) are copied
 * bit for bit. The filter is streaming-safe: it asks for its input padded by 10 pixels (2
 * without LongEdges), so processing an image in pieces gives the same pixels as processing it
 * whole. It is multithreaded with vtkSMPTools over bands of rows, each task reading its rows
 * into small buffers of its own (vtkDLAAStages.h), and deterministic. Progress is reported
 * (ProgressEvent) and AbortExecute honoured between bands: an aborted update gives an empty
 * output.
 *
 * Bad input (no scalars, too few tuples, an empty image, more than 4 components, a non-numeric
 * scalar type, an empty or non-finite ValueRange) is reported with vtkErrorMacro and gives an
 * empty output; an empty requested extent gives an empty output without error.
 *
 * @sa vtkDLAAOptions vtkOpenGLDLAAPass vtkImageMLAA vtkImageAntialiasingAlgorithm
 */

#ifndef vtkImageDLAA_h
#define vtkImageDLAA_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkImageAntialiasingAlgorithm.h"

class vtkDLAAOptions;

class VTKFILTERSMLAA_EXPORT vtkImageDLAA : public vtkImageAntialiasingAlgorithm
{
public:
  static vtkImageDLAA* New();
  vtkTypeMacro(vtkImageDLAA, vtkImageAntialiasingAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The DLAA settings. Never null: a filter starts with its own default options; setting
   * nullptr restores a fresh default object. Changing the options re-executes the filter.
   */
  vtkGetObjectMacro(Options, vtkDLAAOptions);
  virtual void SetOptions(vtkDLAAOptions* options);
  ///@}

  /**
   * The modification time also covers the options.
   */
  vtkMTimeType GetMTime() override;

  /**
   * How far, in pixels, an output pixel's value reaches into the input in x and y: 2 for the
   * short-edge kernels, and 8 more with LongEdges (the 17-pixel means).
   */
  int GetInputPadding() override;

protected:
  vtkImageDLAA();
  ~vtkImageDLAA() override;

  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkDLAAOptions* Options = nullptr;

private:
  vtkImageDLAA(const vtkImageDLAA&) = delete;
  void operator=(const vtkImageDLAA&) = delete;
};

#endif
