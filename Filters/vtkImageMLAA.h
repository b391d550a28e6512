/**
 * @class   vtkImageMLAA
 * @brief   Morphological antialiasing (MLAA) of images, on the CPU.
 *
 * vtkImageMLAA removes staircase aliasing from an image by finding its edges, recognising the
 * L, U and Z patterns that the edges form, and blending each pixel next to an edge with the pixel
 * across it by the area that the revectorised (smooth) line would cover. It implements the three
 * passes of Jimenez et al., "Practical Morphological Antialiasing" (GPU Pro 2, chapter 4):
 * 1. edge detection (section 4.2): each pixel boundary whose difference exceeds the threshold,
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
 * DiagonalDetection, DominantDirectionBlending, DebugOutput.
 *
 * Input: vtkImageData of any numeric scalar type with 1 to 4 components (grey, grey + alpha,
 * RGB, RGBA). 2D images and 3D volumes; each z slice is antialiased on its own. Integer values are
 * normalised by the range of their type for edge detection; floating-point values by ValueRange
 * (default [0, 1]). All components, alpha included, are blended with the same weights, so an
 * opaque silhouette over a transparent background gets a soft alpha edge. Pixels holding NaN or
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
 * Bad input (no scalars, an empty extent, more than 4 components, a non-numeric scalar type, a
 * missing or mismatched depth image) is reported with vtkErrorMacro and gives an empty output.
 *
 * @sa vtkMLAAOptions vtkMLAAAreaTexture vtkOpenGLMLAAPass
 */

#ifndef vtkImageMLAA_h
#define vtkImageMLAA_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class vtkMLAAOptions;

class VTKFILTERSMLAA_EXPORT vtkImageMLAA : public vtkImageAlgorithm
{
public:
  static vtkImageMLAA* New();
  vtkTypeMacro(vtkImageMLAA, vtkImageAlgorithm);
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
   * The values that map to 0 and 1 when floating-point images are normalised for edge
   * detection (integer images use the range of their type). Default [0, 1].
   */
  vtkSetVector2Macro(ValueRange, double);
  vtkGetVector2Macro(ValueRange, double);
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
   * distance plus the pixels the edges and the blending look at. RequestUpdateExtent pads the
   * requested extent by this much.
   */
  int GetInputPadding();

protected:
  vtkImageMLAA();
  ~vtkImageMLAA() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  vtkMLAAOptions* Options = nullptr;
  double ValueRange[2] = { 0.0, 1.0 };

private:
  vtkImageMLAA(const vtkImageMLAA&) = delete;
  void operator=(const vtkImageMLAA&) = delete;
};

#endif
