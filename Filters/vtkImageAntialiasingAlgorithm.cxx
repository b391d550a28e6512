// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageAntialiasingAlgorithm.h"

#include "vtkDataArray.h"
#include "vtkExtentTranslator.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkAntialiasingKit.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVersionMacros.h"

#include <algorithm>
#include <cmath>
#include <limits>

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::SetValueRange(double lo, double hi)
{
  if (this->ValueRangeIsTypeDefault || this->ValueRange[0] != lo || this->ValueRange[1] != hi)
  {
    this->ValueRange[0] = lo;
    this->ValueRange[1] = hi;
    this->ValueRangeIsTypeDefault = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::SetValueRangeToTypeDefault()
{
  if (!this->ValueRangeIsTypeDefault)
  {
    this->ValueRange[0] = 0.0;
    this->ValueRange[1] = 1.0;
    this->ValueRangeIsTypeDefault = true;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::GetEffectiveValueRange(int scalarType, double range[2])
{
  range[0] = this->ValueRange[0];
  range[1] = this->ValueRange[1];
  if (this->ValueRangeIsTypeDefault && scalarType != VTK_FLOAT && scalarType != VTK_DOUBLE)
  {
    switch (scalarType)
    {
      vtkTemplateMacro(range[0] = static_cast<double>(std::numeric_limits<VTK_TT>::lowest());
                       range[1] = static_cast<double>(std::numeric_limits<VTK_TT>::max()));
    }
  }
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::GetRequestedOutputExtent(vtkInformation* outInfo, int extent[6])
{
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  if (pieces <= 1 || !outInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    return;
  }
  // A request by piece: distributed pipelines (ParaView's, vtkXMLPImageDataWriter) ask each
  // process for piece p of n and leave the whole extent as the update extent. Structured sources
  // split such requests themselves, so the filter must too, or it would get the source's piece
  // without the padding (and seams at the pieces' borders): it takes the piece's extent as VTK's
  // extent translator splits the whole extent, within the requested one.
  int whole[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int ghosts =
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS())
    : 0;
  vtkNew<vtkExtentTranslator> translator;
  int pieceExtent[6];
  if (!translator->PieceToExtentThreadSafe(
        piece, pieces, ghosts, whole, pieceExtent, translator->GetSplitMode(), 0))
  {
    // More pieces than the image has cells to split: this one is empty.
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    std::copy(empty, empty + 6, extent);
    return;
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    extent[2 * axis] = std::max(extent[2 * axis], pieceExtent[2 * axis]);
    extent[2 * axis + 1] = std::min(extent[2 * axis + 1], pieceExtent[2 * axis + 1]);
  }
}

//------------------------------------------------------------------------------
int vtkImageAntialiasingAlgorithm::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  GetRequestedOutputExtent(outInfo, extent);
  const int pad = this->GetInputPadding();

  for (int port = 0; port < this->GetNumberOfInputPorts(); ++port)
  {
    vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
    if (!inInfo)
    {
      continue;
    }
    int whole[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    int padded[6];
    for (int axis = 0; axis < 3; ++axis)
    {
      const int p = axis < 2 ? pad : 0; // z slices are independent
      padded[2 * axis] = std::max(extent[2 * axis] - p, whole[2 * axis]);
      padded[2 * axis + 1] = std::min(extent[2 * axis + 1] + p, whole[2 * axis + 1]);
      if (extent[2 * axis] > extent[2 * axis + 1])
      {
        // An empty request stays empty.
        padded[2 * axis] = extent[2 * axis];
        padded[2 * axis + 1] = extent[2 * axis + 1];
      }
    }
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), padded, 6);
    // The padded extent is the whole request: upstream must not split it into pieces again.
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
bool vtkImageAntialiasingAlgorithm::PrepareRequest(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector, Request& r)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  r.Output = vtkImageData::GetData(outInfo);
  r.Input = vtkImageData::GetData(inInfo);
  if (!r.Output)
  {
    vtkErrorMacro("No output image.");
    return false;
  }
  vtkImageData* output = r.Output;
  auto fail = [output]() {
    output->Initialize();
    return false;
  };
  vtkImageData* input = r.Input;
  if (!input)
  {
    vtkErrorMacro("No input image.");
    return fail();
  }

  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (!scalars)
  {
    vtkErrorMacro("The input image has no point scalars to antialias.");
    return fail();
  }
  if (scalars->GetNumberOfTuples() < input->GetNumberOfPoints())
  {
    vtkErrorMacro("The input scalars '" << (scalars->GetName() ? scalars->GetName() : "")
                                        << "' hold " << scalars->GetNumberOfTuples()
                                        << " tuples, fewer than the " << input->GetNumberOfPoints()
                                        << " points of the input's extent.");
    return fail();
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > 4)
  {
    vtkErrorMacro("The input image has " << components << " components; " << this->GetClassName()
                                         << " takes 1 to 4 (grey, grey + alpha, RGB, RGBA).");
    return fail();
  }
  const int scalarType = scalars->GetDataType();
  switch (scalarType)
  {
    vtkTemplateMacro(break);
    default:
      vtkErrorMacro("The input scalars are of type "
        << scalars->GetDataTypeAsString() << ", which " << this->GetClassName()
        << " does not support (it takes integer and floating-point types).");
      return fail();
  }
  if (this->ValueRange[1] <= this->ValueRange[0] || !std::isfinite(this->ValueRange[0]) ||
    !std::isfinite(this->ValueRange[1]))
  {
    vtkErrorMacro("ValueRange must be finite with ValueRange[0] < ValueRange[1]; it is ["
      << this->ValueRange[0] << ", " << this->ValueRange[1] << "].");
    return fail();
  }
  r.Scalars = scalars;
  r.Components = components;
  r.ScalarType = scalarType;
  this->GetEffectiveValueRange(scalarType, r.Range);

  int* outExt = r.OutputExtent;
  int* inExt = r.InputExtent;
  int* whole = r.WholeExtent;
  GetRequestedOutputExtent(outInfo, outExt);
  input->GetExtent(inExt);
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  const bool emptyWhole = whole[0] > whole[1] || whole[2] > whole[3] || whole[4] > whole[5];
  if (!emptyWhole && (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5]))
  {
    // An empty request (a streamer's piece of an image smaller than its piece count): nothing
    // to produce, and nothing wrong.
    r.EmptyRequest = true;
    return true;
  }
  if (emptyWhole || inExt[0] > inExt[1] || inExt[2] > inExt[3] || inExt[4] > inExt[5])
  {
    vtkErrorMacro("The input image is empty (extent " << inExt[0] << " " << inExt[1] << " "
                                                      << inExt[2] << " " << inExt[3] << " "
                                                      << inExt[4] << " " << inExt[5] << ").");
    return fail();
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (outExt[2 * axis] < inExt[2 * axis] || outExt[2 * axis + 1] > inExt[2 * axis + 1])
    {
      vtkErrorMacro("The input extent does not cover the requested output extent.");
      return fail();
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::ForEachSlice(const Request& r, vtkIdType rowsPerSlice,
  const std::function<void(int, vtkAntialiasingKit::Progress&)>& slice)
{
  // Progress counts the rows of every slice; it is reported and AbortExecute is polled between
  // tasks, from this thread.
  const int* outExt = r.OutputExtent;
  const int slices = outExt[5] - outExt[4] + 1;
  vtkAntialiasingKit::Progress progress([this](double fraction) { this->UpdateProgress(fraction); },
    [this]() { return this->AbortRequested(); }, slices * rowsPerSlice);
  for (int z = outExt[4]; z <= outExt[5] && !progress.CheckAbort(); ++z)
  {
    slice(z, progress);
  }
  if (progress.Aborted())
  {
    // Cancelled (AbortExecute): nothing half-computed goes downstream.
    r.Output->Initialize();
  }
}

//------------------------------------------------------------------------------
bool vtkImageAntialiasingAlgorithm::AbortRequested()
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 3, 0)
  // VTK 9.3 and later: CheckAbort() also sees an abort of an upstream algorithm, and marks the
  // output aborted (AbortOutput), which the executive passes downstream. (The executive still
  // reports a progress of 1 at the end.) AbortExecute stays set until the application clears it.
  return this->CheckAbort();
#else
  // VTK 9.1 and 9.2: the executive clears AbortExecute before each execution.
  return this->GetAbortExecute() != 0;
#endif
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ValueRange: ";
  if (this->ValueRangeIsTypeDefault)
  {
    os << "type default ([0, 1] for floating point, the type's range for integers)\n";
  }
  else
  {
    os << this->ValueRange[0] << " " << this->ValueRange[1] << "\n";
  }
}

//------------------------------------------------------------------------------
void vtkImageAntialiasingAlgorithm::CopyInputScalarInfo(
  vtkInformationVector** inputVector, vtkInformation* outInfo)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
    inInfo, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
  if (scalarInfo)
  {
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo,
      scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE()),
      scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()));
  }
}
