// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Streaming, threading, progress and pipeline behaviour of vtkImageDLAA: it pads its input
// request by its reach (10 pixels, 2 without long edges), so processing an image in pieces
// (explicit update extents, vtkImageDataStreamer) gives exactly the pixels of processing it
// whole; the result does not depend on the number of threads; ProgressEvent rises to 1 from
// the calling thread and AbortExecute gives an empty output; the options are never null and
// changing them re-executes the filter.
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkAntialiasingTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkExtentTranslator.h"
#include "vtkImageDataStreamer.h"
#include "vtkSMPTools.h"

#include <thread>

using namespace vtkMLAATest;

namespace
{
// An odd-sized colour image with edges of every slope, long shallow lines and a textured band.
vtkSmartPointer<vtkImageData> Picture(int width = 197, int height = 151)
{
  auto image = MakeImage(width, height, 3);
  FillImage(image, [](int x, int y, int, int k) {
    double v = 40.0 + 10.0 * k;
    if ((x - 60.3) * (x - 60.3) + (y - 70.7) * (y - 70.7) < 40.0 * 40.0)
    {
      v = 220.0 - 60.0 * k;
    }
    if (y > 0.04 * x + 110.0)
    {
      v = 250.0 - 20.0 * k;
    }
    if (x > 170.0 - 0.03 * y)
    {
      v = 10.0 + 100.0 * (k == 1);
    }
    if (y > 20 && y < 30)
    {
      v += 25.0 * (((x * 7) ^ (y * 3)) % 3);
    }
    return std::min(255.0, v);
  });
  return image;
}

bool SameOnExtent(vtkImageData* whole, vtkImageData* piece, const int ext[6])
{
  for (int y = ext[2]; y <= ext[3]; ++y)
  {
    for (int x = ext[0]; x <= ext[1]; ++x)
    {
      for (int k = 0; k < 3; ++k)
      {
        if (whole->GetScalarComponentAsDouble(x, y, 0, k) !=
          piece->GetScalarComponentAsDouble(x, y, 0, k))
        {
          std::cerr << "pixel (" << x << ", " << y << ") differs" << std::endl;
          return false;
        }
      }
    }
  }
  return true;
}

void Streaming()
{
  auto picture = Picture();
  for (bool longEdges : { true, false })
  {
    vtkNew<vtkDLAAOptions> options;
    options->SetLongEdges(longEdges);
    auto whole = RunDLAA(picture, options);
    MLAA_CHECK(Compare(picture, whole).Count > 100);
    const int pieces[][6] = { { 0, 196, 0, 150, 0, 0 }, { 0, 10, 0, 150, 0, 0 },
      { 40, 60, 30, 50, 0, 0 }, { 50, 50, 41, 41, 0, 0 }, { 190, 196, 0, 5, 0, 0 },
      { 0, 196, 149, 150, 0, 0 }, { 17, 79, 105, 115, 0, 0 } };
    for (const auto& ext : pieces)
    {
      vtkNew<vtkImageDLAA> filter;
      filter->SetOptions(options);
      filter->SetInputData(picture);
      filter->UpdateExtent(ext);
      int got[6];
      filter->GetOutput()->GetExtent(got);
      MLAA_CHECK(got[0] == ext[0] && got[1] == ext[1] && got[2] == ext[2] && got[3] == ext[3]);
      MLAA_CHECK(SameOnExtent(whole, filter->GetOutput(), ext));
    }
    for (int divisions : { 2, 7, 23 })
    {
      for (int mode = 0; mode < 3; ++mode)
      {
        vtkNew<vtkImageDLAA> streamed;
        streamed->SetOptions(options);
        streamed->SetInputData(picture);
        vtkNew<vtkImageDataStreamer> streamer;
        streamer->SetInputConnection(streamed->GetOutputPort());
        streamer->SetNumberOfStreamDivisions(divisions);
        SetSplitMode(streamer->GetExtentTranslator(), mode);
        streamer->Update();
        const Difference d = Compare(whole, streamer->GetOutput());
        if (!MLAA_CHECK(d.Count == 0))
        {
          std::cerr << "long edges " << longEdges << ", " << divisions << " pieces, split mode "
                    << mode << ": " << d.Pixels << " pixels differ" << std::endl;
        }
      }
    }
  }
  MLAA_CHECK(vtkNew<vtkImageDLAA>()->GetInputPadding() == 10);
}

void Threads()
{
  // Taller than several tasks, so that bands meet inside the image.
  auto picture = Picture(131, 301);
  auto defaultThreads = RunDLAA(picture);
  vtkSMPTools::Initialize(1);
  auto oneThread = RunDLAA(picture);
  vtkSMPTools::Initialize(2);
  auto twoThreads = RunDLAA(picture);
  MLAA_CHECK(Compare(defaultThreads, oneThread).Count == 0);
  MLAA_CHECK(Compare(defaultThreads, twoThreads).Count == 0);
}

struct ProgressRecord
{
  std::vector<double> Values;
  bool OtherThread = false;
  std::thread::id Caller = std::this_thread::get_id();
  double AbortAt = 2.0; // never
};

void OnProgress(vtkObject* caller, unsigned long, void* clientData, void* callData)
{
  auto* record = static_cast<ProgressRecord*>(clientData);
  const double value = *static_cast<double*>(callData);
  record->Values.push_back(value);
  record->OtherThread = record->OtherThread || std::this_thread::get_id() != record->Caller;
  if (value >= record->AbortAt)
  {
    static_cast<vtkImageDLAA*>(caller)->SetAbortExecute(1);
  }
}

void ProgressAndAbort()
{
  auto volume = MakeImage(120, 700, 3, VTK_UNSIGNED_CHAR, 0.0, 3);
  FillImage(volume, [](int x, int y, int z, int) { return y < 5 + (x + z) / 9 ? 255.0 : 0.0; });
  for (double abortAt : { 2.0, 0.3 })
  {
    ProgressRecord record;
    record.AbortAt = abortAt;
    vtkNew<vtkCallbackCommand> callback;
    callback->SetCallback(OnProgress);
    callback->SetClientData(&record);
    vtkNew<vtkImageDLAA> filter;
    filter->AddObserver(vtkCommand::ProgressEvent, callback);
    filter->SetInputData(volume);
    filter->Update();
    MLAA_CHECK(!record.OtherThread);
    MLAA_CHECK(std::is_sorted(record.Values.begin(), record.Values.end()));
    if (abortAt > 1.0)
    {
      MLAA_CHECK(record.Values.size() > 3 && record.Values.back() == 1.0);
      MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 120 * 700 * 3);
    }
    else
    {
      MLAA_CHECK(!record.Values.empty() && record.Values.back() < 1.0);
      MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
    }
  }
}

void OptionsAndMTime()
{
  vtkNew<vtkImageDLAA> filter;
  MLAA_CHECK(filter->GetOptions() != nullptr);
  filter->SetOptions(nullptr);
  MLAA_CHECK(filter->GetOptions() != nullptr);
  vtkNew<vtkDLAAOptions> shared;
  filter->SetOptions(shared);
  MLAA_CHECK(filter->GetOptions() == shared.GetPointer());

  auto picture = Picture(60, 40);
  filter->SetInputData(picture);
  filter->Update();
  auto withLong = vtkSmartPointer<vtkImageData>::New();
  withLong->DeepCopy(filter->GetOutput());
  const vtkMTimeType before = filter->GetMTime();
  shared->LongEdgesOff(); // only the options change
  MLAA_CHECK(filter->GetMTime() > before);
  MLAA_CHECK(filter->GetInputPadding() == 2);
  filter->Update();
  MLAA_CHECK(Compare(withLong, filter->GetOutput()).Count > 0);
  MLAA_CHECK(Compare(RunDLAA(picture, shared), filter->GetOutput()).Count == 0);

  // An empty request (a streamed piece with nothing in it) gives an empty output, no error.
  // (vtkImageDataStreamer of VTK 9.1 cannot assemble empty pieces, so it is asked directly.)
  vtkNew<MessageObserver> messages;
  vtkNew<vtkImageDLAA> small;
  messages->Watch(small);
  small->SetInputData(picture);
  const int nothing[6] = { 5, 4, 0, 10, 0, 0 };
  small->UpdateExtent(nothing);
  MLAA_CHECK(messages->Errors.empty());
  MLAA_CHECK(small->GetOutput()->GetNumberOfPoints() == 0);
}
}

int TestImageDLAAStreaming(int, char*[])
{
  Streaming();
  Threads();
  ProgressAndAbort();
  OptionsAndMTime();
  return Result();
}
