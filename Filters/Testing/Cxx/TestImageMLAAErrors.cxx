// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input that only vtkImageMLAA has (depth edges need a depth image that covers the colour
// image): a clear error message and an empty output, never a crash or a partial result, nor a
// streamed update that never ends. The errors every method shares (scalars, components, types,
// ValueRange, working again after an error) are in TestAntialiasingAlgorithmErrors.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkExecutive.h"
#include "vtkExtentTranslator.h"
#include "vtkImageDataStreamer.h"

using namespace vtkMLAATest;

namespace
{
// Runs the filter on `input` (and `depth`) and checks that it reports an error containing
// `expected` and leaves an empty output.
void ExpectError(vtkImageData* input, const std::string& expected, vtkMLAAOptions* options,
  vtkImageData* depth = nullptr)
{
  vtkNew<vtkImageMLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  if (options)
  {
    filter->SetOptions(options);
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

  // Depth edges without a depth image, or with one that does not cover the colour image.
  vtkNew<vtkMLAAOptions> depthOptions;
  depthOptions->SetEdgeDetectionToDepth();
  ExpectError(MakeImage(8, 8, 3), "no depth image", depthOptions);
  ExpectError(MakeImage(8, 8, 3), "does not cover", depthOptions, MakeImage(4, 8, 1, VTK_FLOAT));
  vtkNew<vtkImageData> depthWithoutScalars;
  depthWithoutScalars->SetDimensions(8, 8, 1);
  ExpectError(MakeImage(8, 8, 3), "no depth image", depthOptions, depthWithoutScalars);
  return Result();
}
