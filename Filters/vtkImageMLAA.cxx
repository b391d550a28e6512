// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageMLAA.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMLAAOptions.h"
#include "vtkMLAAStages.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkImageMLAA);

//------------------------------------------------------------------------------
vtkImageMLAA::vtkImageMLAA()
{
  this->SetNumberOfInputPorts(2);
  this->Options = vtkMLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkImageMLAA::~vtkImageMLAA()
{
  this->Options->Delete();
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetOptions(vtkMLAAOptions* options)
{
  if (vtkMLAAOptions::Assign(this, this->Options, options))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkImageMLAA::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Options->GetMTime());
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetDepthInputData(vtkDataObject* depth)
{
  this->SetInputData(1, depth);
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetDepthInputConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkImageMLAA::GetInputPadding()
{
  // How far each stage reads is derived in one place: vtkMLAAStages::ComputeHalo.
  return vtkMLAAStages::ComputeHalo(this->Options).Total();
}

//------------------------------------------------------------------------------
int vtkImageMLAA::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (this->Options->GetEdgeDetection() == vtkMLAAOptions::DEPTH)
  {
    // Checked here, for the whole image, rather than piece by piece: a piece that fails in the
    // middle of a streamed update makes vtkImageDataStreamer request it again and again.
    vtkInformation* colorInfo = inputVector[0]->GetInformationObject(0);
    vtkInformation* depthInfo = inputVector[1]->GetInformationObject(0);
    if (!depthInfo)
    {
      vtkErrorMacro("EdgeDetection is Depth but no depth image is connected to input port 1 "
                    "(SetDepthInputData / SetDepthInputConnection).");
      return 0;
    }
    int color[6], depth[6];
    colorInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), color);
    depthInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), depth);
    if (depth[0] > color[0] || depth[1] < color[1] || depth[2] > color[2] ||
      depth[3] < color[3] || depth[4] > color[4] || depth[5] < color[5])
    {
      vtkErrorMacro("The depth image does not cover the colour image's extent (depth "
        << depth[0] << " " << depth[1] << " " << depth[2] << " " << depth[3] << " " << depth[4]
        << " " << depth[5] << ", colour " << color[0] << " " << color[1] << " " << color[2] << " "
        << color[3] << " " << color[4] << " " << color[5] << ").");
      return 0;
    }
  }
  if (this->Options->GetDebugOutput() != vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 4);
  }
  else
  {
    CopyInputScalarInfo(inputVector, outInfo);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Request request;
  if (!this->PrepareRequest(inputVector, outputVector, request))
  {
    return 0;
  }
  vtkImageData* output = request.Output;
  vtkImageData* input = request.Input;
  vtkDataArray* scalars = request.Scalars;
  const int components = request.Components;
  const int scalarType = request.ScalarType;
  int* outExt = request.OutputExtent;
  const int* inExt = request.InputExtent;
  const int* whole = request.WholeExtent;
  auto fail = [output]() {
    output->Initialize();
    return 0;
  };
  // The output: the input's type and components, or 8-bit RGBA for a debug image.
  const int debugOutput = this->Options->GetDebugOutput();
  auto allocateOutput = [&]() {
    output->SetExtent(outExt);
    if (debugOutput != vtkMLAAOptions::NO_DEBUG_OUTPUT)
    {
      output->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
      output->GetPointData()->GetScalars()->SetName(
        debugOutput == vtkMLAAOptions::EDGES ? "Edges" : "BlendingWeights");
    }
    else
    {
      output->AllocateScalars(scalarType, components);
      output->GetPointData()->GetScalars()->SetName(scalars->GetName());
      vtkAntialiasingKit::PreferHugePages(output->GetPointData()->GetScalars());
    }
  };
  if (request.EmptyRequest)
  {
    allocateOutput();
    return 1;
  }

  const int mode = this->Options->GetEdgeDetection();
  const int pad = this->GetInputPadding();

  vtkMLAAStages::SliceSetup setup;
  setup.Whole = { whole[0], whole[1], whole[2], whole[3] };
  setup.Output = { outExt[0], outExt[1], outExt[2], outExt[3] };
  // The pixels the stages may read: the output padded by the halo, within the image and within
  // what the input holds (which may be less than asked for; every read stays inside it).
  setup.Input = setup.Output.Grown(pad)
                  .Intersect(setup.Whole)
                  .Intersect({ inExt[0], inExt[1], inExt[2], inExt[3] });
  vtkMLAAStages::ConfigureSlice(
    this->Options, components, request.Range[0], request.Range[1], setup);

  // The depth image, for depth edges.
  vtkImageData* depth = nullptr;
  vtkDataArray* depthScalars = nullptr;
  if (mode == vtkMLAAOptions::DEPTH)
  {
    depth = vtkImageData::GetData(inputVector[1]);
    depthScalars = depth ? depth->GetPointData()->GetScalars() : nullptr;
    if (!depthScalars)
    {
      vtkErrorMacro("EdgeDetection is Depth but no depth image with scalars is connected to "
                    "input port 1 (SetDepthInputData / SetDepthInputConnection).");
      return fail();
    }
    int depthExt[6];
    depth->GetExtent(depthExt);
    if (depthExt[0] > setup.Input.X0 || depthExt[1] < setup.Input.X1 ||
      depthExt[2] > setup.Input.Y0 || depthExt[3] < setup.Input.Y1 || depthExt[4] > outExt[4] ||
      depthExt[5] < outExt[5])
    {
      vtkErrorMacro("The depth image does not cover the colour image's extent.");
      return fail();
    }
    switch (depthScalars->GetDataType())
    {
      vtkTemplateMacro(break);
      default:
        vtkErrorMacro("The depth scalars are of type " << depthScalars->GetDataTypeAsString()
                                                       << ", which is not supported.");
        return fail();
    }
  }

  allocateOutput();

  vtkIdType inIncrements[3];
  input->GetIncrements(scalars, inIncrements);
  const vtkIdType outSliceSize =
    static_cast<vtkIdType>(setup.Output.Width()) * setup.Output.Height() *
    output->GetPointData()->GetScalars()->GetNumberOfComponents();

  // The stages' full-size buffers, shared with every other filter of the process (a new filter
  // per image costs what a reused one does) and reused from slice to slice.
  const vtkMLAAStages::SliceBuffersLease lease = vtkMLAAStages::AcquireSliceBuffers();
  vtkMLAAStages::SliceBuffers& buffers = *lease;
  this->ForEachSlice(request, setup.RowsOfWork(), [&](int z, vtkAntialiasingKit::Progress& progress) {
    vtkMLAAStages::DepthRows depthRows;
    if (depth)
    {
      vtkIdType depthIncrements[3];
      depth->GetIncrements(depthScalars, depthIncrements);
      depthRows.Origin =
        static_cast<const char*>(depth->GetScalarPointer(setup.Input.X0, setup.Input.Y0, z));
      depthRows.RowBytes = depthIncrements[1] * depthScalars->GetDataTypeSize();
      depthRows.PixelStride = depthIncrements[0];
      switch (depthScalars->GetDataType())
      {
        vtkTemplateMacro(depthRows.Normalise = &vtkMLAAStages::NormaliseDepthRow<VTK_TT>);
      }
    }
    void* inPtr = input->GetScalarPointer(setup.Input.X0, setup.Input.Y0, z);
    void* outPtr = static_cast<char*>(output->GetScalarPointer()) +
      (z - outExt[4]) * outSliceSize * output->GetScalarSize();
    unsigned char* debug = debugOutput != vtkMLAAOptions::NO_DEBUG_OUTPUT
      ? static_cast<unsigned char*>(outPtr)
      : nullptr;
    switch (scalarType)
    {
      vtkTemplateMacro(vtkMLAAStages::RunSlice(setup, static_cast<const VTK_TT*>(inPtr),
        inIncrements[1], depthRows, debug ? nullptr : static_cast<VTK_TT*>(outPtr), debug, buffers,
        progress));
    }
  });
  return 1;
}

//------------------------------------------------------------------------------
void vtkImageMLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
