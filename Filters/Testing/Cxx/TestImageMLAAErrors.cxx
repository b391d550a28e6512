// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input to vtkImageMLAA: a clear error message and an empty output, never a crash or a
// partial result. Then the same filter works again on good input.
#include "vtkMLAATestUtilities.h"

#include "vtkBitArray.h"
#include "vtkExecutive.h"
#include "vtkExtentTranslator.h"
#include "vtkFloatArray.h"
#include "vtkImageDataStreamer.h"
#include "vtkUnsignedCharArray.h"

using namespace vtkMLAATest;

namespace
{
// Runs the filter on `input` (and `depth`) and checks that it reports an error containing
// `expected` and leaves an empty output.
void ExpectError(vtkImageData* input, const std::string& expected, vtkMLAAOptions* options = nullptr,
  vtkImageData* depth = nullptr, const double* valueRange = nullptr)
{
  vtkNew<vtkImageMLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  if (options)
  {
    filter->SetOptions(options);
  }
  if (valueRange)
  {
    filter->SetValueRange(valueRange[0], valueRange[1]);
  }
  filter->SetInputData(input);
  if (depth)
  {
    filter->SetDepthInputData(depth);
  }
  filter->Update();
  if (!MLAA_CHECK(messages->HasError(expected)))
  {
    std::cerr << "expected an error containing \"" << expected << "\"; got:";
    for (const auto& e : messages->Errors)
    {
      std::cerr << "\n  " << e;
    }
    std::cerr << std::endl;
  }
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  MLAA_CHECK(filter->GetOutput()->GetPointData()->GetScalars() == nullptr);
}
}

// A streamed update whose later pieces cannot be produced (the depth image covers only the
// bottom of the colour image) ends with one error, instead of vtkImageDataStreamer requesting
// the failing piece forever.
void StreamedFailureEnds()
{
  auto colour = MakeImage(40, 130, 3);
  auto depth = MakeImage(40, 60, 1, VTK_FLOAT, 0.5);
  vtkNew<vtkMLAAOptions> options;
  options->SetEdgeDetectionToDepth();
  vtkNew<vtkImageMLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  filter->SetOptions(options);
  filter->SetInputData(colour);
  filter->SetDepthInputData(depth);
  vtkNew<vtkImageDataStreamer> streamer;
  streamer->SetInputConnection(filter->GetOutputPort());
  streamer->SetNumberOfStreamDivisions(4);
  streamer->GetExtentTranslator()->SetSplitModeToYSlab();
  streamer->Update(); // returns
  MLAA_CHECK(messages->HasError("does not cover"));
}

int TestImageMLAAErrors(int, char*[])
{
  StreamedFailureEnds();

  // No scalars at all.
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(8, 8, 1);
  ExpectError(noScalars, "no point scalars");

  // An empty extent.
  vtkNew<vtkImageData> empty;
  empty->SetExtent(0, -1, 0, -1, 0, -1);
  vtkNew<vtkUnsignedCharArray> emptyScalars;
  emptyScalars->SetNumberOfComponents(3);
  empty->GetPointData()->SetScalars(emptyScalars);
  ExpectError(empty, "empty");

  // More than four components.
  ExpectError(MakeImage(8, 8, 5), "5 components");
  ExpectError(MakeImage(8, 8, 9, VTK_FLOAT), "9 components");

  // Bit scalars are not a numeric type the filter supports.
  vtkNew<vtkImageData> bits;
  bits->SetDimensions(8, 8, 1);
  vtkNew<vtkBitArray> bitScalars;
  bitScalars->SetNumberOfTuples(64);
  bits->GetPointData()->SetScalars(bitScalars);
  ExpectError(bits, "does not support");

  // Depth edges without a depth image, or with one that does not cover the colour image.
  vtkNew<vtkMLAAOptions> depthOptions;
  depthOptions->SetEdgeDetectionToDepth();
  ExpectError(MakeImage(8, 8, 3), "no depth image", depthOptions);
  ExpectError(MakeImage(8, 8, 3), "does not cover", depthOptions, MakeImage(4, 8, 1, VTK_FLOAT));
  vtkNew<vtkImageData> depthWithoutScalars;
  depthWithoutScalars->SetDimensions(8, 8, 1);
  ExpectError(MakeImage(8, 8, 3), "no depth image", depthOptions, depthWithoutScalars);

  // A floating-point value range that is empty or not finite.
  const double emptyRange[2] = { 1.0, 1.0 };
  ExpectError(MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", nullptr, nullptr, emptyRange);
  const double reversed[2] = { 1.0, 0.0 };
  ExpectError(MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", nullptr, nullptr, reversed);

  // After an error, the same filter object works on good input.
  vtkNew<vtkImageMLAA> filter;
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
  return Result();
}
