// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkImageDLAA.h"

#include "vtkAntialiasingKit.h"
#include "vtkDLAAOptions.h"
#include "vtkDLAAStages.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <algorithm>

vtkStandardNewMacro(vtkImageDLAA);

//------------------------------------------------------------------------------
vtkImageDLAA::vtkImageDLAA()
{
  this->Options = vtkDLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkImageDLAA::~vtkImageDLAA()
{
  this->Options->Delete();
}

//------------------------------------------------------------------------------
void vtkImageDLAA::SetOptions(vtkDLAAOptions* options)
{
  if (vtkDLAAOptions::Assign(this, this->Options, options))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkImageDLAA::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Options->GetMTime());
}

//------------------------------------------------------------------------------
int vtkImageDLAA::GetInputPadding()
{
  return vtkDLAAStages::MakeSettings(this->Options, 3, 0.0, 1.0).Halo();
}

//------------------------------------------------------------------------------
int vtkImageDLAA::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  CopyInputScalarInfo(inputVector, outputVector->GetInformationObject(0));
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageDLAA::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  Request request;
  if (!this->PrepareRequest(inputVector, outputVector, request))
  {
    return 0;
  }
  vtkImageData* output = request.Output;
  const int* outExt = request.OutputExtent;
  const int* inExt = request.InputExtent;
  const int* whole = request.WholeExtent;
  output->SetExtent(request.OutputExtent);
  output->AllocateScalars(request.ScalarType, request.Components);
  vtkAntialiasingKit::PreferHugePages(output->GetPointData()->GetScalars()); // (not yet written)
  output->GetPointData()->GetScalars()->SetName(request.Scalars->GetName());
  if (request.EmptyRequest)
  {
    return 1;
  }

  vtkDLAAStages::SliceSetup setup;
  setup.DLAA = vtkDLAAStages::MakeSettings(
    this->Options, request.Components, request.Range[0], request.Range[1]);
  setup.Whole = { whole[0], whole[1], whole[2], whole[3] };
  setup.Output = { outExt[0], outExt[1], outExt[2], outExt[3] };
  // The pixels the filter may read: the output padded by the halo, within the image and within
  // what the input holds (which may be less than asked for; every read stays inside it, and
  // reads beyond it are clamped to it).
  setup.Input = setup.Output.Grown(setup.DLAA.Halo())
                  .Intersect(setup.Whole)
                  .Intersect({ inExt[0], inExt[1], inExt[2], inExt[3] });

  vtkImageData* input = request.Input;
  vtkIdType inIncrements[3];
  input->GetIncrements(request.Scalars, inIncrements);
  const vtkIdType outSliceValues = static_cast<vtkIdType>(setup.Output.Width()) *
    setup.Output.Height() * request.Components;
  this->ForEachSlice(
    request, setup.Output.Height(), [&](int z, vtkAntialiasingKit::Progress& progress) {
      void* inPtr = input->GetScalarPointer(setup.Input.X0, setup.Input.Y0, z);
      void* outPtr = static_cast<char*>(output->GetScalarPointer()) +
        (z - outExt[4]) * outSliceValues * output->GetScalarSize();
      switch (request.ScalarType)
      {
        vtkTemplateMacro(vtkDLAAStages::RunSlice(setup, static_cast<const VTK_TT*>(inPtr),
          inIncrements[1], static_cast<VTK_TT*>(outPtr), progress));
      }
    });
  return 1;
}

//------------------------------------------------------------------------------
void vtkImageDLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
