// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Streaming and threading invariance of a vtkImageAntialiasingAlgorithm (every method and every
// configuration of FilterMethods()): the filter pads its input request by its reach
// (GetInputPadding), so processing an image in pieces (vtkImageDataStreamer, or explicit update
// extents) gives exactly the pixels of processing it whole; an empty request gives an empty
// output and no error; and the result does not depend on the number of threads. Also on lines
// longer than a piece and its padding (with each method's farthest-reaching configuration), and
// for requests by piece (piece p of n, as ParaView asks each MPI rank) from a source that
// splits them itself.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkExtentTranslator.h"
#include "vtkImageDataStreamer.h"
#include "vtkImageThreshold.h"
#include "vtkMath.h"
#include "vtkRTAnalyticSource.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <array>
#include <cmath>

using namespace vtkMLAATest;

namespace
{
// An odd-sized colour image full of edges of every slope: three overlapping discs and
// half-planes in different colours, plus long nearly-horizontal and nearly-vertical lines that
// exceed the search distance. Faint shading bands (steps of 30, about 0.12) run across
// everything, so that local contrast adaptation drops edges next to stronger ones everywhere,
// piece borders included.
vtkSmartPointer<vtkImageData> Discs()
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

// An odd-sized colour image with edges of every slope, long shallow lines and a textured band.
vtkSmartPointer<vtkImageData> Band(int width = 197, int height = 151)
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

// A 700 x 600 image crossed by lines of 1, 0.2 and 0.13 degrees and a nearly vertical one
// (steps of 57 to 440 pixels): wider and taller than a piece's padded request at 128 search
// steps (256 pixels each way), so that lines leave pieces and pieces see only part of the image.
vtkSmartPointer<vtkImageData> LongLines()
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

using Extent = std::array<int, 6>;

// `image` processed whole, then piece by piece: each of the explicit `pieces` (a fresh filter
// per piece: an up-to-date output that covers a request satisfies it without executing), and
// through vtkImageDataStreamer with each of `divisions` in each split mode.
void CheckPieces(const FilterMethod& method, const FilterConfiguration& configuration,
  vtkImageData* image, const std::vector<Extent>& pieces, const std::vector<int>& divisions,
  vtkIdType minChanged)
{
  const std::string what = std::string(method.Name) + ", " + configuration.Name;
  auto whole = RunConfigured(method, image, &configuration);
  if (!MLAA_CHECK(Compare(image, whole).Count > minChanged))
  {
    std::cerr << what << ": too few values changed" << std::endl;
  }
  for (const Extent& ext : pieces)
  {
    auto filter = NewConfigured(method, configuration);
    filter->SetInputData(image);
    filter->UpdateExtent(ext.data());
    int got[6];
    filter->GetOutput()->GetExtent(got);
    MLAA_CHECK(got[0] == ext[0] && got[1] == ext[1] && got[2] == ext[2] && got[3] == ext[3]);
    if (!MLAA_CHECK(SameOnExtent(whole, filter->GetOutput(), ext.data())))
    {
      std::cerr << what << ": extent " << ext[0] << " " << ext[1] << " " << ext[2] << " "
                << ext[3] << " differs from the whole result" << std::endl;
    }
  }
  for (int n : divisions)
  {
    for (int mode = 0; mode < 3; ++mode)
    {
      auto streamed = NewConfigured(method, configuration);
      streamed->SetInputData(image);
      vtkNew<vtkImageDataStreamer> streamer;
      streamer->SetInputConnection(streamed->GetOutputPort());
      streamer->SetNumberOfStreamDivisions(n);
      SetSplitMode(streamer->GetExtentTranslator(), mode);
      streamer->Update();
      const Difference d = Compare(whole, streamer->GetOutput());
      if (!MLAA_CHECK(d.Count == 0))
      {
        std::cerr << what << ": " << n << " pieces, split mode " << mode << ": " << d.Pixels
                  << " pixels differ" << std::endl;
      }
    }
  }
}

// Requests by piece: a distributed pipeline asks for piece p of n and leaves the whole extent
// as the update extent. vtkRTAnalyticSource splits such a request itself; the filter must take
// the piece's extent (as vtkExtentTranslator splits the whole extent), pad it, and ask for the
// padded extent as one piece, or it gets the source's piece without padding.
void CheckRequestsByPiece(const FilterMethod& method, const FilterConfiguration& configuration)
{
  vtkNew<vtkRTAnalyticSource> source;
  source->SetWholeExtent(-60, 59, -45, 44, 0, 0);
  vtkNew<vtkImageThreshold> shapes; // curved shapes with aliased edges, 0 or 255
  shapes->SetInputConnection(source->GetOutputPort());
  shapes->ThresholdByUpper(150.0);
  shapes->SetInValue(255.0);
  shapes->SetOutValue(0.0);
  shapes->SetOutputScalarTypeToUnsignedChar();
  auto reference = NewConfigured(method, configuration);
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
      auto filter = NewConfigured(method, configuration);
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
        std::cerr << method.Name << ", " << configuration.Name << ": piece " << piece << " of "
                  << pieces << " differs from the whole result" << std::endl;
      }
    }
  }
}

// An empty request (a streamed piece with nothing in it) gives an empty output, no error.
// (vtkImageDataStreamer of VTK 9.1 cannot assemble empty pieces, so it is asked directly.)
void CheckEmptyRequest(const FilterMethod& method, vtkImageData* image)
{
  vtkNew<MessageObserver> messages;
  auto filter = method.New();
  messages->Watch(filter);
  filter->SetInputData(image);
  const int nothing[6] = { 5, 4, 0, 10, 0, 0 };
  filter->UpdateExtent(nothing);
  MLAA_CHECK(messages->Errors.empty());
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
}

// The number of threads does not change the result (the band picture is taller than several
// tasks, so that bands meet inside the image). Every method's results with the default number of
// threads come first, before vtkSMPTools is initialised with 1 and then 2.
void CheckThreads()
{
  const std::vector<vtkSmartPointer<vtkImageData>> pictures = { Discs(), Band(131, 301) };
  std::vector<vtkSmartPointer<vtkImageData>> defaultThreads;
  for (const auto& method : FilterMethods())
  {
    for (const auto& picture : pictures)
    {
      defaultThreads.push_back(RunConfigured(method, picture));
    }
  }
  for (int threads : { 1, 2 })
  {
    vtkSMPTools::Initialize(threads);
    size_t i = 0;
    for (const auto& method : FilterMethods())
    {
      for (const auto& picture : pictures)
      {
        if (!MLAA_CHECK(Compare(defaultThreads[i++], RunConfigured(method, picture)).Count == 0))
        {
          std::cerr << method.Name << ": " << threads << " threads differ" << std::endl;
        }
      }
    }
  }
}
}

int TestAntialiasingAlgorithmStreaming(int, char*[])
{
  auto discs = Discs();
  auto band = Band();
  auto longLines = LongLines();
  const std::vector<Extent> discPieces = { { 0, 96, 0, 82, 0, 0 }, { 0, 10, 0, 82, 0, 0 },
    { 40, 60, 30, 50, 0, 0 }, { 50, 50, 41, 41, 0, 0 }, { 90, 96, 0, 5, 0, 0 },
    { 0, 96, 81, 82, 0, 0 }, { 17, 79, 3, 9, 0, 0 } };
  const std::vector<Extent> bandPieces = { { 0, 196, 0, 150, 0, 0 }, { 0, 10, 0, 150, 0, 0 },
    { 40, 60, 30, 50, 0, 0 }, { 50, 50, 41, 41, 0, 0 }, { 190, 196, 0, 5, 0, 0 },
    { 0, 196, 149, 150, 0, 0 }, { 17, 79, 105, 115, 0, 0 } };
  const std::vector<Extent> longLinePieces = { { 0, 40, 0, 599, 0, 0 },
    { 300, 360, 90, 110, 0, 0 }, { 650, 699, 0, 599, 0, 0 }, { 0, 699, 590, 599, 0, 0 },
    { 340, 345, 0, 599, 0, 0 } };
  for (const auto& method : FilterMethods())
  {
    const FilterConfiguration* farthest = nullptr;
    int farthestPadding = -1;
    for (const auto& configuration : method.Configurations)
    {
      CheckPieces(method, configuration, discs, discPieces, { 2, 7, 23 }, 100);
      CheckPieces(method, configuration, band, bandPieces, { 2, 7, 23 }, 100);
      CheckRequestsByPiece(method, configuration);
      const int padding = NewConfigured(method, configuration)->GetInputPadding();
      if (padding > farthestPadding)
      {
        farthest = &configuration;
        farthestPadding = padding;
      }
    }
    std::cout << method.Name << ": long lines with " << farthest->Name << " (padding "
              << farthestPadding << ")" << std::endl;
    // DLAA leaves most of these very shallow lines as they are (754 values change).
    const vtkIdType longLinesChanged = std::string(method.Name) == "vtkImageDLAA" ? 500 : 1000;
    CheckPieces(method, *farthest, longLines, longLinePieces, { 13 }, longLinesChanged);
    CheckEmptyRequest(method, band);
  }
  CheckThreads();
  return Result();
}
