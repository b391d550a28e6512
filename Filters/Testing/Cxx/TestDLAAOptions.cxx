// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkDLAAOptions: defaults (the talk's), clamping, names, copying, ownership.
#include "vtkDLAAOptions.h"
#include "vtkAntialiasingTestUtilities.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cstring>

int TestDLAAOptions(int, char*[])
{
  vtkNew<vtkDLAAOptions> options;
  MLAA_CHECK(options->GetEpsilon() == 0.1);
  MLAA_CHECK(options->GetLambda() == 3.0);
  MLAA_CHECK(options->GetLumaFunction() == vtkDLAAOptions::REC709);
  MLAA_CHECK(options->GetLongEdges());

  options->SetEpsilon(-1.0);
  MLAA_CHECK(options->GetEpsilon() == 0.0);
  options->SetEpsilon(2.0);
  MLAA_CHECK(options->GetEpsilon() == 1.0);
  options->SetLambda(-3.0);
  MLAA_CHECK(options->GetLambda() == 0.0);
  options->SetLambda(1e6);
  MLAA_CHECK(options->GetLambda() == 100.0);
  options->SetLumaFunction(9);
  MLAA_CHECK(options->GetLumaFunction() == vtkDLAAOptions::GREEN);

  for (int f = vtkDLAAOptions::REC709; f <= vtkDLAAOptions::GREEN; ++f)
  {
    MLAA_CHECK(vtkDLAAOptions::GetLumaFunctionFromString(
                 vtkDLAAOptions::GetLumaFunctionAsString(f)) == f);
  }
  MLAA_CHECK(std::strcmp(vtkDLAAOptions::GetLumaFunctionAsString(0), "rec709") == 0);
  MLAA_CHECK(vtkDLAAOptions::GetLumaFunctionFromString("Green") == -1);
  MLAA_CHECK(vtkDLAAOptions::GetLumaFunctionFromString(nullptr) == -1);
  MLAA_CHECK(std::strcmp(vtkDLAAOptions::GetLumaFunctionAsString(5), "unknown") == 0);

  vtkNew<vtkDLAAOptions> copy;
  options->LongEdgesOff();
  options->SetEpsilon(0.25);
  copy->DeepCopy(options);
  MLAA_CHECK(copy->GetEpsilon() == 0.25);
  MLAA_CHECK(copy->GetLambda() == 100.0);
  MLAA_CHECK(copy->GetLumaFunction() == vtkDLAAOptions::GREEN);
  MLAA_CHECK(!copy->GetLongEdges());

  // Ownership: a member is never null, takes a shared object, and a fresh default for null.
  vtkNew<vtkDLAAOptions> owner; // any vtkObject can own
  vtkDLAAOptions* member = nullptr;
  MLAA_CHECK(vtkDLAAOptions::Assign(owner, member, nullptr));
  MLAA_CHECK(member != nullptr && member->GetEpsilon() == 0.1);
  MLAA_CHECK(vtkDLAAOptions::Assign(owner, member, options));
  MLAA_CHECK(member == options.GetPointer() && options->GetReferenceCount() == 2);
  MLAA_CHECK(!vtkDLAAOptions::Assign(owner, member, options));
  MLAA_CHECK(vtkDLAAOptions::Assign(owner, member, nullptr));
  MLAA_CHECK(options->GetReferenceCount() == 1 && member != options.GetPointer());
  member->UnRegister(owner);
  return vtkMLAATest::Result();
}
