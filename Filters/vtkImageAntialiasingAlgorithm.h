// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkImageAntialiasingAlgorithm
 * @brief   What the CPU antialiasing filters (vtkImageMLAA, vtkImageDLAA) share: the value
 *          range that normalises an image, the input checks, the padding of the input request
 *          and the slice-by-slice driver with progress.
 *
 * An abstract vtkImageAlgorithm. A subclass says how far an output pixel reaches into its input
 * (GetInputPadding); this class then asks every connected input for the requested extent padded
 * by that much in x and y (z slices are independent), so that a streamed image gives the same
 * pixels as a whole one. A request by piece (piece p of n, as ParaView and other distributed
 * pipelines make) is first turned into that piece's extent (GetRequestedOutputExtent), and the
 * padded extent is asked for as one piece, so distributed images get the same pixels too.
 * In RequestData a subclass calls PrepareRequest, which checks the input
 * (point scalars of a numeric type with 1 to 4 components, as many tuples as points, a finite
 * value range, a non-empty image that covers the request), reports what is wrong with
 * vtkErrorMacro and empties the output; an empty request is not an error. ForEachSlice then runs
 * the subclass's work on each z slice, reports progress (ProgressEvent) and honours
 * AbortExecute: an aborted update gives an empty output. On VTK 9.3 and later (vtkAlgorithm's
 * CheckAbort) an abort of an upstream algorithm stops it too, and AbortExecute stays set until
 * the application clears it, as for VTK's own filters; before 9.3 each update clears it.
 *
 * Values are normalised as (value - lo) / (hi - lo) with [lo, hi] the ValueRange: by default
 * [0, 1] for floating-point images and the range of the type for integer ones.
 *
 * @sa vtkImageMLAA vtkImageDLAA
 */

#ifndef vtkImageAntialiasingAlgorithm_h
#define vtkImageAntialiasingAlgorithm_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <functional> // For ForEachSlice

class vtkDataArray;
namespace vtkAntialiasingKit
{
class Progress;
}

class VTKFILTERSMLAA_EXPORT vtkImageAntialiasingAlgorithm : public vtkImageAlgorithm
{
public:
  vtkTypeMacro(vtkImageAntialiasingAlgorithm, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The values that map to 0 and 1 when the image is normalised. By default floating-point
   * images use [0, 1] and integer images the range of their type (0 to 255 for unsigned char,
   * 0 to 65535 for unsigned short). SetValueRange sets one range for every scalar type: 10-, 12-
   * or 14-bit data stored in 16-bit integers needs it (SetValueRange(0, 4095) for 12 bits), or
   * its edges look 16 times fainter than they are. SetValueRangeToTypeDefault() restores the
   * defaults; GetValueRange() then holds [0, 1]. There is no automatic (data min/max) mode: it
   * would make a streamed piece's result depend on the piece; the `mlaa` tool's
   * `--value-range auto` measures the whole image and sets the range.
   */
  virtual void SetValueRange(double lo, double hi);
  void SetValueRange(const double range[2]) { this->SetValueRange(range[0], range[1]); }
  vtkGetVector2Macro(ValueRange, double);
  void SetValueRangeToTypeDefault();
  vtkGetMacro(ValueRangeIsTypeDefault, bool);
  ///@}

  /**
   * The range that normalises an image of the given VTK scalar type with the current settings.
   */
  void GetEffectiveValueRange(int scalarType, double range[2]);

  /**
   * How far, in pixels, an output pixel's value reaches into the input in x and y.
   * RequestUpdateExtent pads the requested extent by this much.
   */
  virtual int GetInputPadding() = 0;

protected:
  vtkImageAntialiasingAlgorithm() = default;
  ~vtkImageAntialiasingAlgorithm() override = default;

  int RequestUpdateExtent(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /**
   * The extent the output is asked for: the update extent or, for a request by piece (piece p
   * of n, as distributed pipelines ask), that piece's part of it, split as vtkExtentTranslator
   * splits the whole extent. RequestUpdateExtent pads it and asks for it as one piece.
   */
  static void GetRequestedOutputExtent(vtkInformation* outInfo, int extent[6]);

  /**
   * For RequestInformation: give the output the scalar type and component count of the
   * input's active point scalars (when the input has them).
   */
  static void CopyInputScalarInfo(vtkInformationVector** inputVector, vtkInformation* outInfo);

  /** What PrepareRequest found out about an update. */
  struct Request
  {
    vtkImageData* Input = nullptr;
    vtkImageData* Output = nullptr;
    vtkDataArray* Scalars = nullptr; // the input's point scalars
    int Components = 0;
    int ScalarType = 0;
    int OutputExtent[6];
    int InputExtent[6];
    int WholeExtent[6];
    bool EmptyRequest = false; // nothing to produce, and nothing wrong
    double Range[2];           // the effective value range
  };

  /**
   * Checks the input of port 0 against the request (see the class description). Returns false
   * after reporting an error (the output, if any, is then empty); true otherwise, with
   * request.EmptyRequest set when the requested extent is empty (the caller allocates an empty
   * output and returns).
   */
  bool PrepareRequest(
    vtkInformationVector** inputVector, vtkInformationVector* outputVector, Request& request);

  /**
   * Calls `slice(z, progress)` for each z of the output extent, in order, until the progress
   * reports an abort; `rowsPerSlice` rows of work are counted for each slice. After an abort
   * the output is emptied. `slice` counts its rows with progress.RowsDone.
   */
  void ForEachSlice(const Request& request, vtkIdType rowsPerSlice,
    const std::function<void(int, vtkAntialiasingKit::Progress&)>& slice);

  double ValueRange[2] = { 0.0, 1.0 };
  bool ValueRangeIsTypeDefault = true;

private:
  // AbortExecute, and on VTK 9.3 and later an upstream abort (CheckAbort).
  bool AbortRequested();

  vtkImageAntialiasingAlgorithm(const vtkImageAntialiasingAlgorithm&) = delete;
  void operator=(const vtkImageAntialiasingAlgorithm&) = delete;
};

#endif
