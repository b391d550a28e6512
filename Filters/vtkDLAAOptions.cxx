// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkDLAAOptions.h"

#include "vtkAntialiasingOptionsHelpers.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkDLAAOptions);

namespace
{
const char* const LumaFunctionNames[] = { "rec709", "green" };
}

//------------------------------------------------------------------------------
const char* vtkDLAAOptions::GetLumaFunctionAsString(int function)
{
  return (function >= REC709 && function <= GREEN) ? LumaFunctionNames[function] : "unknown";
}

//------------------------------------------------------------------------------
int vtkDLAAOptions::GetLumaFunctionFromString(const char* name)
{
  return vtkAntialiasingInternal::IndexOfName(LumaFunctionNames, name);
}

//------------------------------------------------------------------------------
void vtkDLAAOptions::DeepCopy(vtkDLAAOptions* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->SetEpsilon(other->Epsilon);
  this->SetLambda(other->Lambda);
  this->SetLumaFunction(other->LumaFunction);
  this->SetLongEdges(other->LongEdges);
}

//------------------------------------------------------------------------------
bool vtkDLAAOptions::Assign(vtkObject* owner, vtkDLAAOptions*& member, vtkDLAAOptions* options)
{
  return vtkAntialiasingInternal::AssignOwned(owner, member, options);
}

//------------------------------------------------------------------------------
void vtkDLAAOptions::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Lambda: " << this->Lambda << "\n";
  os << indent << "LumaFunction: " << GetLumaFunctionAsString(this->LumaFunction) << "\n";
  os << indent << "LongEdges: " << (this->LongEdges ? "On" : "Off") << "\n";
}
