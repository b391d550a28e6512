// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkDLAAOptions: defaults (the talk's), clamping, names, copying, ownership; and the
// options of vtkImageDLAA: never null, shared, and a change re-executes the filter and sets its
// reach (the input padding: 11 pixels, 9 without long edges, which the tests of corners' sides
// set).
#include "vtkDLAAOptions.h"
#include "vtkAntialiasingTestUtilities.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <cstring>

namespace
{
using namespace vtkMLAATest;

// vtkImageDLAA's options: never null, shared, and a change of the shared object alone
// re-executes the filter (with the same result as a new filter with those options) and changes
// its padding. (Moved from TestImageDLAAStreaming, whose shared checks now run for every method
// in TestAntialiasingAlgorithmStreaming.)
void FilterOptions()
{
  MLAA_CHECK(vtkNew<vtkImageDLAA>()->GetInputPadding() == 11);
  vtkNew<vtkImageDLAA> filter;
  MLAA_CHECK(filter->GetOptions() != nullptr);
  filter->SetOptions(nullptr);
  MLAA_CHECK(filter->GetOptions() != nullptr);
  vtkNew<vtkDLAAOptions> shared;
  filter->SetOptions(shared);
  MLAA_CHECK(filter->GetOptions() == shared.GetPointer());

  // An odd-sized colour image with a disc, shallow lines and a textured band.
  auto picture = MakeImage(60, 40, 3);
  FillImage(picture, [](int x, int y, int, int k) {
    double v = 40.0 + 10.0 * k;
    if ((x - 60.3) * (x - 60.3) + (y - 70.7) * (y - 70.7) < 40.0 * 40.0)
    {
      v = 220.0 - 60.0 * k;
    }
    if (y > 20 && y < 30)
    {
      v += 25.0 * (((x * 7) ^ (y * 3)) % 3);
    }
    return std::min(255.0, v);
  });
  filter->SetInputData(picture);
  filter->Update();
  auto withLong = vtkSmartPointer<vtkImageData>::New();
  withLong->DeepCopy(filter->GetOutput());
  const vtkMTimeType before = filter->GetMTime();
  shared->LongEdgesOff(); // only the options change
  MLAA_CHECK(filter->GetMTime() > before);
  MLAA_CHECK(filter->GetInputPadding() == 9);
  filter->Update();
  MLAA_CHECK(Compare(withLong, filter->GetOutput()).Count > 0);
  MLAA_CHECK(Compare(RunDLAA(picture, shared), filter->GetOutput()).Count == 0);
}
}

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
  FilterOptions();
  return vtkMLAATest::Result();
}
