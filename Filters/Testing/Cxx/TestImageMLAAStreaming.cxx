// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Streaming and threading invariance: vtkImageMLAA pads its input request by the search
// distance, so processing an image in pieces (vtkImageDataStreamer, or explicit update extents)
// gives exactly the pixels of processing it whole; and the result does not depend on the number
// of threads. Also at 128 steps, on lines longer than a piece and its padding, and for requests
// by piece (piece p of n, as ParaView asks each MPI rank) from a source that splits them itself.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkExtentTranslator.h"
#include "vtkImageDataStreamer.h"
#include "vtkImageThreshold.h"
#include "vtkMath.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTrivialProducer.h"

#include <algorithm>
#include <cmath>

using namespace vtkMLAATest;

namespace
{
// An odd-sized colour image full of edges of every slope: three overlapping discs and
// half-planes in different colours, plus long nearly-horizontal and nearly-vertical lines that
// exceed the search distance. Faint shading bands (steps of 30, about 0.12) run across
// everything, so that local contrast adaptation drops edges next to stronger ones everywhere,
// piece borders included.
vtkSmartPointer<vtkImageData> Picture()
{
  auto image = MakeImage(97, 83, 3);
  FillImage(image, [](int x, int y, int, int k) {
    double v = 40.0 + 10.0 * k;
    if ((x - 30.3) * (x - 30.3) + (y - 40.7) * (y - 40.7) < 22.0 * 22.0)
    {
      v = 220.0 - 60.0 * k;
    }
    if ((x - 70.1) * (x - 70.1) + 0.5 * (y - 20.2) * (y - 20.2) < 18.0 * 18.0)
    {
      v = 90.0 + 70.0 * k;
    }
    if (y > 0.07 * x + 60.0)
    {
      v = 250.0 - 20.0 * k;
    }
    if (x > 85.0 - 0.05 * y)
    {
      v = 10.0 + 100.0 * (k == 1);
    }
    return std::min(255.0, v + 30.0 * ((x / 3 + y / 4) % 3 == 0));
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
}

int TestImageMLAAStreaming(int, char*[])
{
  auto picture = Picture();
  for (int steps : { 1, 4, 8, 32 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(steps);
    auto whole = RunMLAA(picture, options);
    MLAA_CHECK(Compare(picture, whole).Count > 100);

    // Explicit pieces: each requested extent gets the pixels of the whole result. (A fresh filter
    // per piece: an up-to-date output that covers a request satisfies it without executing.)
    const int pieces[][6] = { { 0, 96, 0, 82, 0, 0 }, { 0, 10, 0, 82, 0, 0 },
      { 40, 60, 30, 50, 0, 0 }, { 50, 50, 41, 41, 0, 0 }, { 90, 96, 0, 5, 0, 0 },
      { 0, 96, 81, 82, 0, 0 }, { 17, 79, 3, 9, 0, 0 } };
    for (const auto& ext : pieces)
    {
      vtkNew<vtkImageMLAA> filter;
      filter->SetOptions(options);
      filter->SetInputData(picture);
      filter->UpdateExtent(ext);
      int got[6];
      filter->GetOutput()->GetExtent(got);
      MLAA_CHECK(got[0] == ext[0] && got[1] == ext[1] && got[2] == ext[2] && got[3] == ext[3]);
      MLAA_CHECK(SameOnExtent(whole, filter->GetOutput(), ext));
    }

    // vtkImageDataStreamer with several piece counts and split modes.
    for (int divisions : { 2, 7, 23 })
    {
      for (int mode = 0; mode < 3; ++mode)
      {
        vtkNew<vtkImageMLAA> streamed;
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
          std::cerr << "steps " << steps << ", " << divisions << " pieces, split mode " << mode
                    << ": " << d.Pixels << " pixels differ" << std::endl;
        }
      }
    }
  }

  // Long lines at 128 steps (256 pixels each way): an image wider and taller than a piece's
  // padded request, crossed by lines of 1, 0.2 and 0.13 degrees and a nearly vertical one (steps of
  // 57 to 440 pixels), so that lines leave pieces and pieces see only part of the image.
  {
    auto image = MakeImage(700, 600, 3);
    const double s1 = std::tan(vtkMath::RadiansFromDegrees(1.0));
    const double s2 = std::tan(vtkMath::RadiansFromDegrees(0.2));
    const double s3 = std::tan(vtkMath::RadiansFromDegrees(0.13));
    FillImage(image, [s1, s2, s3](int x, int y, int, int k) {
      double v = 30.0 + 20.0 * k;
      if (y + 0.5 > 100.0 + s1 * (x + 0.5))
      {
        v = 200.0 - 50.0 * k;
      }
      if (y + 0.5 > 420.0 + s2 * (x + 0.5))
      {
        v = 90.0 + 60.0 * k;
      }
      if (y + 0.5 > 250.0 + s3 * (x + 0.5))
      {
        v = 140.0 + 40.0 * k;
      }
      if (x + 0.5 > 350.0 + 0.0035 * (y + 0.5))
      {
        v = std::min(255.0, v + 50.0);
      }
      return v;
    });
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(128);
    auto whole = RunMLAA(image, options);
    MLAA_CHECK(Compare(image, whole).Count > 1000);
    const int pieces[][6] = { { 0, 40, 0, 599, 0, 0 }, { 300, 360, 90, 110, 0, 0 },
      { 650, 699, 0, 599, 0, 0 }, { 0, 699, 590, 599, 0, 0 }, { 340, 345, 0, 599, 0, 0 } };
    for (const auto& ext : pieces)
    {
      vtkNew<vtkImageMLAA> filter;
      filter->SetOptions(options);
      filter->SetInputData(image);
      filter->UpdateExtent(ext);
      MLAA_CHECK(SameOnExtent(whole, filter->GetOutput(), ext));
    }
    for (int mode = 0; mode < 3; ++mode)
    {
      vtkNew<vtkImageMLAA> streamed;
      streamed->SetOptions(options);
      streamed->SetInputData(image);
      vtkNew<vtkImageDataStreamer> streamer;
      streamer->SetInputConnection(streamed->GetOutputPort());
      streamer->SetNumberOfStreamDivisions(13);
      SetSplitMode(streamer->GetExtentTranslator(), mode);
      streamer->Update();
      MLAA_CHECK(Compare(whole, streamer->GetOutput()).Count == 0);
    }
  }

  // Requests by piece: a distributed pipeline asks for piece p of n and leaves the whole extent
  // as the update extent. vtkRTAnalyticSource splits such a request itself; the filter must
  // take the piece's extent (as vtkExtentTranslator splits the whole extent), pad it, and ask
  // for the padded extent as one piece, or it gets the source's piece without padding.
  {
    vtkNew<vtkRTAnalyticSource> source;
    source->SetWholeExtent(-60, 59, -45, 44, 0, 0);
    vtkNew<vtkImageThreshold> shapes; // curved shapes with aliased edges, 0 or 255
    shapes->SetInputConnection(source->GetOutputPort());
    shapes->ThresholdByUpper(150.0);
    shapes->SetInValue(255.0);
    shapes->SetOutValue(0.0);
    shapes->SetOutputScalarTypeToUnsignedChar();
    vtkNew<vtkImageMLAA> reference;
    reference->SetInputConnection(shapes->GetOutputPort());
    reference->Update();
    vtkNew<vtkImageData> whole;
    whole->DeepCopy(reference->GetOutput());
    shapes->Update();
    MLAA_CHECK(Compare(shapes->GetOutput(), whole).Count > 50);
    int wholeExtent[6];
    whole->GetExtent(wholeExtent);
    for (int pieces : { 2, 3, 7 })
    {
      for (int piece = 0; piece < pieces; ++piece)
      {
        vtkNew<vtkImageMLAA> filter;
        filter->SetInputConnection(shapes->GetOutputPort());
        filter->UpdatePiece(piece, pieces, 0);
        vtkNew<vtkExtentTranslator> translator;
        int expected[6], got[6];
        translator->PieceToExtentThreadSafe(
          piece, pieces, 0, wholeExtent, expected, translator->GetSplitMode(), 0);
        filter->GetOutput()->GetExtent(got);
        bool same = std::equal(expected, expected + 6, got);
        for (int y = expected[2]; same && y <= expected[3]; ++y)
        {
          for (int x = expected[0]; same && x <= expected[1]; ++x)
          {
            same = whole->GetScalarComponentAsDouble(x, y, 0, 0) ==
              filter->GetOutput()->GetScalarComponentAsDouble(x, y, 0, 0);
          }
        }
        if (!MLAA_CHECK(same))
        {
          std::cerr << "piece " << piece << " of " << pieces << " differs from the whole result"
                    << std::endl;
        }
      }
    }
  }

  // The number of threads does not change the result.
  auto defaultThreads = RunMLAA(picture);
  vtkSMPTools::Initialize(1);
  auto oneThread = RunMLAA(picture);
  vtkSMPTools::Initialize(2);
  auto twoThreads = RunMLAA(picture);
  MLAA_CHECK(Compare(defaultThreads, oneThread).Count == 0);
  MLAA_CHECK(Compare(defaultThreads, twoThreads).Count == 0);
  return Result();
}
