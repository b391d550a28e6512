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
void vtkPVImageDLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
