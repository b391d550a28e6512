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

// The buffers of the stages, reused from slice to slice and from update to update.
struct vtkImageMLAABuffers : public vtkMLAAStages::SliceBuffers
{
};

//------------------------------------------------------------------------------
vtkImageMLAA::vtkImageMLAA()
{
  this->SetNumberOfInputPorts(2);
  this->Options = vtkMLAAOptions::New();
  this->Buffers = new vtkImageMLAABuffers;
}

//------------------------------------------------------------------------------
vtkImageMLAA::~vtkImageMLAA()
{
  this->Options->Delete();
  delete this->Buffers;
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
void vtkImageMLAA::SetValueRange(double lo, double hi)
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
void vtkImageMLAA::SetValueRangeToTypeDefault()
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
void vtkImageMLAA::GetEffectiveValueRange(int scalarType, double range[2])
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
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const int pad = this->GetInputPadding();

  for (int port = 0; port < 2; ++port)
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
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  if (!output)
  {
    vtkErrorMacro("No output image.");
    return 0;
  }
  auto fail = [output]() {
    output->Initialize();
    return 0;
  };
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
    vtkErrorMacro("The input image has " << components
                                         << " components; vtkImageMLAA takes 1 to 4 (grey, grey "
                                            "+ alpha, RGB, RGBA).");
    return fail();
  }
  const int scalarType = scalars->GetDataType();
  switch (scalarType)
  {
    vtkTemplateMacro(break);
    default:
      vtkErrorMacro("The input scalars are of type " << scalars->GetDataTypeAsString()
                                                     << ", which vtkImageMLAA does not support "
                                                        "(it takes integer and floating-point "
                                                        "types).");
      return fail();
  }
  if (this->ValueRange[1] <= this->ValueRange[0] || !std::isfinite(this->ValueRange[0]) ||
    !std::isfinite(this->ValueRange[1]))
  {
    vtkErrorMacro("ValueRange must be finite with ValueRange[0] < ValueRange[1]; it is ["
      << this->ValueRange[0] << ", " << this->ValueRange[1] << "].");
    return fail();
  }

  int outExt[6], inExt[6], whole[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  input->GetExtent(inExt);
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
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
    }
  };
  const bool emptyWhole = whole[0] > whole[1] || whole[2] > whole[3] || whole[4] > whole[5];
  if (!emptyWhole && (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5]))
  {
    // An empty request (a streamer's piece of an image smaller than its piece count): nothing
    // to produce, and nothing wrong.
    allocateOutput();
    return 1;
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
  double range[2];
  this->GetEffectiveValueRange(scalarType, range);
  vtkMLAAStages::ConfigureSlice(this->Options, components, range[0], range[1], setup);

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

  // Progress counts the rows of every stage of every slice; it is reported and AbortExecute is
  // polled between tasks, from this thread.
  const int slices = outExt[5] - outExt[4] + 1;
  vtkMLAAStages::Progress progress([this](double fraction) { this->UpdateProgress(fraction); },
    [this]() { return this->GetAbortExecute() != 0; }, slices * setup.RowsOfWork());
  vtkMLAAStages::SliceBuffers& buffers = *this->Buffers;
  for (int z = outExt[4]; z <= outExt[5] && !progress.CheckAbort(); ++z)
  {
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
      vtkTemplateMacro(vtkMLAAStages::RunSlice(setup, static_cast<const VTK_TT*>(inPtr), inIncrements[1],
        depthRows, debug ? nullptr : static_cast<VTK_TT*>(outPtr), debug, buffers, progress));
    }
  }
  if (progress.Aborted())
  {
    // Cancelled (AbortExecute): nothing half-computed goes downstream.
    output->Initialize();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkImageMLAA::PrintSelf(ostream& os, vtkIndent indent)
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
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
