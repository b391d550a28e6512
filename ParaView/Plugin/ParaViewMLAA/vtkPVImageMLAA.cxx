// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVImageMLAA.h"

#include "vtkInformationVector.h"
#include "vtkMLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkPVChosenArray.h"

vtkStandardNewMacro(vtkPVImageMLAA);

//------------------------------------------------------------------------------
int vtkPVImageMLAA::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
  {
    return 0;
  }
  // A debug output is 8-bit RGBA whatever the input.
  if (this->GetOptions()->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    vtkPVChosenArray::AnnounceScalars(this, inputVector, outputVector);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImageMLAA::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkPVChosenArray::RequestData(
    this, inputVector, outputVector, [&](vtkInformationVector** inputs) {
      return this->Superclass::RequestData(request, inputs, outputVector);
    });
}

//------------------------------------------------------------------------------
void vtkPVImageMLAA::SetUseValueRange(bool use)
{
  this->UseValueRange = use;
  vtkPVChosenArray::ApplyValueRange(this, this->UseValueRange, this->ValueRangeSetting);
}

//------------------------------------------------------------------------------
void vtkPVImageMLAA::SetValueRangeSetting(double lo, double hi)
{
  this->ValueRangeSetting[0] = lo;
  this->ValueRangeSetting[1] = hi;
  vtkPVChosenArray::ApplyValueRange(this, this->UseValueRange, this->ValueRangeSetting);
}

//------------------------------------------------------------------------------
void vtkPVImageMLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseValueRange: " << (this->UseValueRange ? "On" : "Off") << "\n";
  os << indent << "ValueRangeSetting: " << this->ValueRangeSetting[0] << " "
     << this->ValueRangeSetting[1] << "\n";
}
