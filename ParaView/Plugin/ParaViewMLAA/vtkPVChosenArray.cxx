// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVChosenArray.h"

#include "vtkImageAntialiasingAlgorithm.h"

#include "vtkAlgorithm.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <vector>

//------------------------------------------------------------------------------
void vtkPVChosenArray::AnnounceScalars(vtkAlgorithm* algorithm,
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* arrayInfo = algorithm->GetInputArrayInformation(0);
  if (!arrayInfo || !arrayInfo->Has(vtkDataObject::FIELD_NAME()) ||
    !*arrayInfo->Get(vtkDataObject::FIELD_NAME()))
  {
    return; // the active scalars, which the filter announced itself
  }
  vtkInformation* field =
    vtkDataObject::GetNamedFieldInformation(inputVector[0]->GetInformationObject(0),
      vtkDataObject::FIELD_ASSOCIATION_POINTS, arrayInfo->Get(vtkDataObject::FIELD_NAME()));
  if (field && field->Has(vtkDataObject::FIELD_ARRAY_TYPE()))
  {
    vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0),
      field->Get(vtkDataObject::FIELD_ARRAY_TYPE()),
      field->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        ? field->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
        : 1);
  }
}

//------------------------------------------------------------------------------
int vtkPVChosenArray::RequestData(vtkAlgorithm* algorithm, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector,
  const std::function<int(vtkInformationVector**)>& requestData)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkInformation* arrayInfo = algorithm->GetInputArrayInformation(0);
  const char* name = arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME())
    ? arrayInfo->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  if (!input || !name || !*name)
  {
    // The active scalars (the default, or no array chosen), or no input: the filter reports
    // what is wrong.
    return requestData(inputVector);
  }
  const int association = arrayInfo->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? arrayInfo->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* chosen = input->GetPointData()->GetArray(name);
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS || !chosen)
  {
    vtkErrorWithObjectMacro(algorithm,
      "The input image has no point array '"
        << name << "' to antialias (only point arrays of numbers are antialiased).");
    if (vtkImageData* output = vtkImageData::GetData(outputVector))
    {
      output->Initialize();
    }
    return 0;
  }

  if (input->GetPointData()->GetScalars() == chosen)
  {
    return requestData(inputVector);
  }

  // The same image, with the chosen array as its active scalars, in the same information (the
  // requested and whole extents the filter checks).
  vtkNew<vtkImageData> substitute;
  substitute->ShallowCopy(input);
  substitute->GetPointData()->SetScalars(chosen);
  vtkNew<vtkInformationVector> substituteVector;
  substituteVector->Copy(inputVector[0], 1);
  substituteVector->GetInformationObject(0)->Set(vtkDataObject::DATA_OBJECT(), substitute);

  std::vector<vtkInformationVector*> inputs(
    inputVector, inputVector + algorithm->GetNumberOfInputPorts());
  inputs[0] = substituteVector;
  return requestData(inputs.data());
}

//------------------------------------------------------------------------------
void vtkPVChosenArray::ApplyValueRange(
  vtkImageAntialiasingAlgorithm* filter, bool use, const double range[2])
{
  if (use)
  {
    filter->SetValueRange(range);
  }
  else
  {
    filter->SetValueRangeToTypeDefault();
  }
}
