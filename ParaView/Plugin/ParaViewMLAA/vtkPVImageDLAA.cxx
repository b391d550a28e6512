// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVImageDLAA.h"

#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPVChosenArray.h"

vtkStandardNewMacro(vtkPVImageDLAA);

//------------------------------------------------------------------------------
int vtkPVImageDLAA::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkPVChosenArray::AnnounceScalars(this, inputVector, outputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImageDLAA::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return vtkPVChosenArray::RequestData(
    this, inputVector, outputVector, [&](vtkInformationVector** inputs) {
      return this->Superclass::RequestData(request, inputs, outputVector);
    });
}

//------------------------------------------------------------------------------
void vtkPVImageDLAA::SetUseValueRange(bool use)
{
  this->UseValueRange = use;
  vtkPVChosenArray::ApplyValueRange(this, this->UseValueRange, this->ValueRangeSetting);
}

//------------------------------------------------------------------------------
void vtkPVImageDLAA::SetValueRangeSetting(double lo, double hi)
{
  this->ValueRangeSetting[0] = lo;
  this->ValueRangeSetting[1] = hi;
  vtkPVChosenArray::ApplyValueRange(this, this->UseValueRange, this->ValueRangeSetting);
}

//------------------------------------------------------------------------------
void vtkPVImageDLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseValueRange: " << (this->UseValueRange ? "On" : "Off") << "\n";
  os << indent << "ValueRangeSetting: " << this->ValueRangeSetting[0] << " "
     << this->ValueRangeSetting[1] << "\n";
}
