// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Inputs smaller than the halo the filter asks for: clipped images (vtkImageClip with and without
// ClipData), 1-pixel-wide slabs and the smallest extents, streamed in pieces
// (vtkImageDataStreamer), for every scalar type; and an upstream that delivers less than the
// padded request (only the requested extent). Run under AddressSanitizer by the test command,
// this shows that no stage reads outside the input it was given; the results must equal the
// unstreamed filter on the same clipped image.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkExtentTranslator.h"
#include "vtkImageClip.h"
#include "vtkImageDataStreamer.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"

#include <string>

using namespace vtkMLAATest;

namespace
{
// A 13 x 11 image of the given type and components with edges in every direction.
vtkSmartPointer<vtkImageData> Picture(int type, int components)
{
  auto image = MakeImage(13, 11, components, type);
  const bool real = type == VTK_FLOAT || type == VTK_DOUBLE;
  FillImage(image, [&](int x, int y, int, int k) {
    const bool on = (x - 6.3) * (x - 6.3) + (y - 5.1) * (y - 5.1) < 16.0 || y > 0.4 * x + 8.0;
    const double v = on ? 0.9 - 0.2 * k : 0.1 + 0.1 * k;
    return real ? v : std::floor(v * 100.0);
  });
  return image;
}

// The filter on the clip of `image` to `clip`, whole and streamed in `pieces` pieces along
// each split mode; every result must equal the one of the clipped image given as data.
void ClippedAndStreamed(vtkImageData* image, const int clip[6], bool clipData, vtkMLAAOptions* options,
  const std::string& what)
{
  vtkNew<vtkImageClip> clipper;
  clipper->SetInputData(image);
  clipper->SetOutputWholeExtent(clip[0], clip[1], clip[2], clip[3], clip[4], clip[5]);
  clipper->SetClipData(clipData);
  clipper->Update();
  // The reference: the clipped pixels as an image of their own.
  vtkNew<vtkImageClip> exact;
  exact->SetInputData(image);
  exact->SetOutputWholeExtent(clip[0], clip[1], clip[2], clip[3], clip[4], clip[5]);
  exact->ClipDataOn();
  exact->Update();
  vtkNew<vtkImageData> clipped;
  clipped->DeepCopy(exact->GetOutput());
  auto expected = RunMLAA(clipped, options);

  // (More pieces than rows or columns give empty pieces, which vtkImageDataStreamer of VTK 9.1
  // cannot assemble; the filter's answer to an empty request is tested below.)
  const int pixels = (clip[1] - clip[0] + 1) * (clip[3] - clip[2] + 1);
  for (int divisions : { 1, 3, 8 })
  {
    if (divisions > 1 && 2 * divisions > pixels)
    {
      continue;
    }
    for (int mode = 0; mode < 3; ++mode)
    {
      vtkNew<vtkImageMLAA> filter;
      vtkNew<MessageObserver> messages;
      messages->Watch(filter);
      filter->SetOptions(options);
      filter->SetInputConnection(clipper->GetOutputPort());
      vtkNew<vtkImageDataStreamer> streamer;
      streamer->SetInputConnection(filter->GetOutputPort());
      streamer->SetNumberOfStreamDivisions(divisions);
      SetSplitMode(streamer->GetExtentTranslator(), mode);
      streamer->Update();
      const Difference d = Compare(expected, streamer->GetOutput());
      if (!MLAA_CHECK(messages->Errors.empty() && d.Count == 0))
      {
        std::cerr << what << ", clip " << clip[0] << " " << clip[1] << " " << clip[2] << " "
                  << clip[3] << (clipData ? " (ClipData)" : "") << ", " << divisions
                  << " pieces, split mode " << mode << ": " << d.Count << " values differ"
                  << (messages->Errors.empty() ? "" : "; error: " + messages->Errors[0])
                  << std::endl;
      }
    }
  }
}

// An upstream that gives exactly the extent it is asked for, never the halo: a trivial
// producer whose data is only the requested piece while its whole extent is the full image.
// The filter must antialias with what it has (clamping at the piece's border) and read
// nothing outside it.
void LessThanRequested(vtkImageData* image, vtkMLAAOptions* options, const std::string& what)
{
  int whole[6];
  image->GetExtent(whole);
  const int piece[6] = { 3, 8, 2, 6, 0, 0 };
  vtkNew<vtkImageClip> cut;
  cut->SetInputData(image);
  cut->SetOutputWholeExtent(const_cast<int*>(piece));
  cut->ClipDataOn();
  cut->Update();
  vtkNew<vtkImageData> data;
  data->DeepCopy(cut->GetOutput());

  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(data);
  producer->SetWholeExtent(whole);
  vtkNew<vtkImageMLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  filter->SetOptions(options);
  filter->SetInputConnection(producer->GetOutputPort());
  filter->UpdateExtent(piece);
  int got[6];
  filter->GetOutput()->GetExtent(got);
  // The piece is produced from the piece alone, as if it were the whole image, except that
  // the piece's border is not the image's border (no crossing edges are assumed there).
  if (!MLAA_CHECK(messages->Errors.empty() && got[0] == piece[0] && got[1] == piece[1] &&
        got[2] == piece[2] && got[3] == piece[3]))
  {
    std::cerr << what << ": the short input was not antialiased" << std::endl;
  }
}
}

int TestImageMLAAClippedInputs(int, char*[])
{
  const int types[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
    VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG,
    VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE };
  // Clips: a 1-pixel-wide column, a 1-pixel-high row, a single pixel, a 2 x 2 corner, an
  // odd inner rectangle.
  const int clips[][6] = { { 6, 6, 0, 10, 0, 0 }, { 0, 12, 5, 5, 0, 0 }, { 12, 12, 10, 10, 0, 0 },
    { 0, 1, 0, 1, 0, 0 }, { 2, 10, 1, 8, 0, 0 } };
  vtkNew<vtkMLAAOptions> options;
  vtkNew<vtkMLAAOptions> small;
  small->SetMaxSearchSteps(1);
  small->SetDiagonalDetection(false);
  small->SetEdgeDetectionToColor();
  for (int type : types)
  {
    for (int components : { 1, 2, 3, 4 })
    {
      auto image = Picture(type, components);
      const std::string name =
        std::string(vtkImageScalarTypeNameMacro(type)) + " x " + std::to_string(components);
      for (const auto& clip : clips)
      {
        for (bool clipData : { false, true })
        {
          ClippedAndStreamed(image, clip, clipData, options, name);
        }
      }
      ClippedAndStreamed(image, clips[0], true, small, name + " (1 search step)");
      LessThanRequested(image, options, name);
    }
  }

  // An empty request (a streamed piece with nothing in it) gives an empty output, no error.
  {
    vtkNew<vtkImageMLAA> filter;
    vtkNew<MessageObserver> messages;
    messages->Watch(filter);
    filter->SetInputData(Picture(VTK_UNSIGNED_CHAR, 3));
    const int nothing[6] = { 5, 4, 0, 10, 0, 0 };
    filter->UpdateExtent(nothing);
    MLAA_CHECK(messages->Errors.empty());
    MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  }

  // A volume of 1-pixel slices, clipped and streamed along z.
  auto column = MakeImage(1, 1, 3, VTK_UNSIGNED_CHAR, 0.0, 9);
  FillImage(column, [](int, int, int z, int k) { return (z * 40 + k * 10) % 256; });
  vtkNew<vtkImageMLAA> filter;
  filter->SetInputData(column);
  vtkNew<vtkImageDataStreamer> streamer;
  streamer->SetInputConnection(filter->GetOutputPort());
  streamer->SetNumberOfStreamDivisions(4);
  streamer->Update();
  MLAA_CHECK(Compare(column, streamer->GetOutput()).Count == 0);
  return Result();
}
