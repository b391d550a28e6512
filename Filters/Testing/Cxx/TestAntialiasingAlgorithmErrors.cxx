// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input to a vtkImageAntialiasingAlgorithm (every method: vtkImageMLAA, vtkImageDLAA): a
// clear error message and an empty output, never a crash or a partial result. Then the same
// filter works again on good input. The checks are the base class's (RequestData's input
// validation), so each runs for every entry of FilterMethods().
#include "vtkAntialiasingTestUtilities.h"

#include "vtkBitArray.h"
#include "vtkExecutive.h"
#include "vtkUnsignedCharArray.h"

#include <limits>

using namespace vtkMLAATest;

namespace
{
// Runs a new filter of `method` on `input` and checks that it reports an error containing
// `expected` and leaves an empty output.
void ExpectError(const FilterMethod& method, vtkImageData* input, const std::string& expected,
  const double* valueRange = nullptr)
{
  auto filter = method.New();
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  if (valueRange)
  {
    filter->SetValueRange(valueRange[0], valueRange[1]);
  }
  filter->SetInputData(input);
  filter->Update();
  if (!MLAA_CHECK(messages->HasError(expected)))
  {
    std::cerr << method.Name << ": expected an error containing \"" << expected << "\"; got:";
    for (const auto& e : messages->Errors)
    {
      std::cerr << "\n  " << e;
    }
    std::cerr << std::endl;
  }
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  MLAA_CHECK(filter->GetOutput()->GetPointData()->GetScalars() == nullptr);
}

void BadInput(const FilterMethod& method)
{
  // No scalars at all.
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(8, 8, 1);
  ExpectError(method, noScalars, "no point scalars");

  // An empty extent.
  vtkNew<vtkImageData> empty;
  empty->SetExtent(0, -1, 0, -1, 0, -1);
  vtkNew<vtkUnsignedCharArray> emptyScalars;
  emptyScalars->SetNumberOfComponents(3);
  empty->GetPointData()->SetScalars(emptyScalars);
  ExpectError(method, empty, "empty");

  // More than four components: the message names the count and the filter's class.
  ExpectError(method, MakeImage(8, 8, 5), "5 components");
  ExpectError(method, MakeImage(8, 8, 5), std::string(method.Name) + " takes 1 to 4");
  ExpectError(method, MakeImage(8, 8, 9, VTK_FLOAT), "9 components");

  // Bit scalars are not a numeric type the filter supports.
  vtkNew<vtkImageData> bits;
  bits->SetDimensions(8, 8, 1);
  vtkNew<vtkBitArray> bitScalars;
  bitScalars->SetNumberOfTuples(64);
  bits->GetPointData()->SetScalars(bitScalars);
  ExpectError(method, bits, "does not support");

  // Fewer scalar tuples than the image has points.
  vtkNew<vtkImageData> short_;
  short_->SetDimensions(8, 8, 1);
  vtkNew<vtkUnsignedCharArray> fewTuples;
  fewTuples->SetNumberOfComponents(3);
  fewTuples->SetNumberOfTuples(10);
  short_->GetPointData()->SetScalars(fewTuples);
  ExpectError(method, short_, "fewer than the 64 points");

  // A floating-point value range that is empty, reversed or not finite.
  const double emptyRange[2] = { 1.0, 1.0 };
  ExpectError(method, MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", emptyRange);
  const double reversed[2] = { 1.0, 0.0 };
  ExpectError(method, MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", reversed);
  const double infinite[2] = { 0.0, std::numeric_limits<double>::infinity() };
  ExpectError(method, MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", infinite);

  // After an error, the same filter object works on good input.
  auto filter = method.New();
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  filter->SetInputData(MakeImage(8, 8, 7));
  filter->Update();
  MLAA_CHECK(!messages->Errors.empty());
  messages->Clear();
  auto good = MakeImage(8, 8, 3);
  FillImage(good, [](int x, int y, int, int) { return y < 2 + x / 3 ? 255.0 : 0.0; });
  filter->SetInputData(good);
  filter->Update();
  MLAA_CHECK(messages->Errors.empty());
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 64);
  MLAA_CHECK(Compare(good, filter->GetOutput()).Count > 0);
}
}

int TestAntialiasingAlgorithmErrors(int, char*[])
{
  for (const auto& method : FilterMethods())
  {
    BadInput(method);
  }
  return Result();
}
