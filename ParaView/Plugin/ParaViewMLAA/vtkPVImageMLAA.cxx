#include "vtkPVImageMLAA.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"

#include <vector>

vtkStandardNewMacro(vtkPVImageMLAA);

//------------------------------------------------------------------------------
int vtkPVImageMLAA::RequestInformation(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestInformation(request, inputVector, outputVector))
  {
    return 0;
  }
  // The superclass announced the input's active scalars; a chosen array by name replaces them.
  vtkInformation* arrayInfo = this->GetInputArrayInformation(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (arrayInfo && arrayInfo->Has(vtkDataObject::FIELD_NAME()) &&
    this->GetOptions()->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    vtkInformation* field = vtkDataObject::GetNamedFieldInformation(
      inputVector[0]->GetInformationObject(0), vtkDataObject::FIELD_ASSOCIATION_POINTS,
      arrayInfo->Get(vtkDataObject::FIELD_NAME()));
    if (field && field->Has(vtkDataObject::FIELD_ARRAY_TYPE()))
    {
      vtkDataObject::SetPointDataActiveScalarInfo(outInfo,
        field->Get(vtkDataObject::FIELD_ARRAY_TYPE()),
        field->Has(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
          ? field->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS())
          : 1);
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkPVImageMLAA::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* chosen = input ? this->GetInputArrayToProcess(0, input, association) : nullptr;
  if (!input || !chosen || input->GetPointData()->GetScalars() == chosen)
  {
    // The active scalars, or nothing to choose from: the superclass reports what is wrong.
    return this->Superclass::RequestData(request, inputVector, outputVector);
  }
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    vtkErrorMacro("The array '" << (chosen->GetName() ? chosen->GetName() : "")
                                << "' is not a point array; only point arrays are antialiased.");
    vtkImageData::GetData(outputVector)->Initialize();
    return 0;
  }

  // The same image, with the chosen array as its active scalars, in the same information (the
  // requested and whole extents the superclass checks).
  vtkNew<vtkImageData> substitute;
  substitute->ShallowCopy(input);
  substitute->GetPointData()->SetScalars(chosen);
  vtkNew<vtkInformationVector> substituteVector;
  substituteVector->Copy(inputVector[0], 1);
  substituteVector->GetInformationObject(0)->Set(vtkDataObject::DATA_OBJECT(), substitute);

  std::vector<vtkInformationVector*> inputs(inputVector, inputVector + this->GetNumberOfInputPorts());
  inputs[0] = substituteVector;
  return this->Superclass::RequestData(request, inputs.data(), outputVector);
}

//------------------------------------------------------------------------------
void vtkPVImageMLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
