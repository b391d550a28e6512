// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * mlaa: morphological antialiasing of image files.
 *
 *   mlaa [options] INPUT OUTPUT
 *   mlaa [options] --format NAME INPUT|- -      (- : standard input / standard output)
 *   mlaa [options] --output-dir DIR INPUT...
 *   mlaa --area-texture D OUTPUT
 *
 * Reads INPUT with OpenImageIO, antialiases it with vtkImageMLAA (Jimenez et al., "Practical
 * Morphological Antialiasing", GPU Pro 2, chapter 4), or with vtkImageDLAA (directionally
 * localized antialiasing) with --method dlaa, and writes OUTPUT in the format of its extension
 * and INPUT's pixel type. The options are those of vtkMLAAOptions and vtkDLAAOptions, under the
 * names those classes give them (GetEdgeDetectionFromString, GetDebugOutputFromString,
 * GetLumaFunctionFromString), with their defaults and ranges. `mlaa --help` says everything.
 *
 * Errors are reported as one line on stderr starting with "mlaa: ", with exit status 1 (2 for a
 * bad command line); OUTPUT is then left as it was (see WriteImageFile). With --output-dir, each
 * INPUT is processed as if alone, in a process of its own (mlaaBatch.h).
 */

#include "mlaaBatch.h"
#include "mlaaCrashReport.h"
#include "mlaaImageFile.h"
#include "mlaaOptionTable.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDLAAOptions.h"
#include "vtkExecutive.h"
#include "vtkImageDLAA.h"
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkLogger.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
constexpr int ExitFailure = 1;
constexpr int ExitUsage = 2;

/** A bad command line: reported like any error, with exit status 2. */
using UsageError = mlaa::UsageError;

// The command line (mlaaOptionTable.h).
using mlaa::AlphaAuto;
using mlaa::AlphaPremultiplied;
using mlaa::CommandLine;
using mlaa::MethodDLAA;
using mlaa::MethodMLAA;
using mlaa::ValueRangeAuto;
using mlaa::ValueRangeGiven;

//------------------------------------------------------------------------------
// VTK's messages

// "ERROR: In file, line N\nvtkImageMLAA (0x1234): The message.\n\n" -> "The message."
std::string CleanVTKMessage(const std::string& text)
{
  std::istringstream lines(text);
  std::string line;
  std::string message;
  while (std::getline(lines, line))
  {
    if (line.empty() || line.compare(0, 9, "ERROR: In") == 0 ||
      line.compare(0, 11, "Warning: In") == 0)
    {
      continue;
    }
    const size_t object = line.find(" (0x");
    const size_t colon = line.find("): ");
    if (message.empty() && object != std::string::npos && colon != std::string::npos &&
      object < colon)
    {
      line = line.substr(colon + 3);
    }
    message += (message.empty() ? "" : "; ") + line;
  }
  return message;
}

/**
 * Keeps VTK's error and warning text off the terminal: the filter's and its executive's
 * messages through observers, anything else through a string output window. Each becomes (at
 * most) one line.
 */
class VTKMessages
{
public:
  explicit VTKMessages(vtkAlgorithm* algorithm)
  {
    // VTK sends messages no observer takes to its logger, which prints on stderr, and to the
    // output window: keep them in the window only.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkOutputWindow::SetInstance(this->Window);
    this->Callback->SetCallback(&VTKMessages::Record);
    this->Callback->SetClientData(this);
    for (vtkObject* object :
      { static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
      object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    }
  }

  /** The first error: the filter's own if it gave one, else whatever VTK printed. */
  std::string GetError() const
  {
    if (!this->Errors.empty())
    {
      return this->Errors.front();
    }
    // Messages in the window end with a blank line.
    const std::string printed = this->Window->GetOutput();
    const size_t first = printed.find_first_not_of('\n');
    const size_t end = first == std::string::npos ? first : printed.find("\n\n", first);
    return CleanVTKMessage(printed.substr(0, end));
  }

  /** Warnings, and text VTK printed although nothing failed. */
  std::string GetWarnings() const
  {
    std::string warnings;
    for (const std::string& w : this->Warnings)
    {
      warnings += (warnings.empty() ? "" : "; ") + w;
    }
    const std::string printed = CleanVTKMessage(this->Window->GetOutput());
    if (!printed.empty())
    {
      warnings += (warnings.empty() ? "" : "; ") + printed;
    }
    return warnings;
  }

private:
  static void Record(vtkObject*, unsigned long event, void* clientData, void* callData)
  {
    auto* self = static_cast<VTKMessages*>(clientData);
    const std::string text = CleanVTKMessage(callData ? static_cast<const char*>(callData) : "");
    (event == vtkCommand::ErrorEvent ? self->Errors : self->Warnings).push_back(text);
  }

  vtkNew<vtkStringOutputWindow> Window;
  vtkNew<vtkCallbackCommand> Callback;
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

//------------------------------------------------------------------------------
// The two things the tool does

void WriteAreaTexture(int cellSize, const std::string& path, const std::string& format)
{
  vtkNew<vtkMLAAAreaTexture> texture;
  texture->SetMaxDistance(cellSize - 1);
  // GetImage() stores texel row t at image row size - 1 - t; written top row first, the file
  // reads as Figure 4.2 (texel (0, 0) at the top left).
  vtkImageData* image = texture->GetImage();
  const int size = texture->GetTextureSize();
  const double unitRange[2] = { 0.0, 1.0 };
  const std::string note = mlaa::WriteImageFile(image, path,
    OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8), OIIO::TypeDesc::UINT8, unitRange,
    format);
  if (!note.empty())
  {
    std::cerr << "mlaa: warning: " << mlaa::Printable(note, 600) << std::endl;
  }
}

// --value-range auto: the smallest and largest finite value of any channel (alpha included) of
// the image. False, leaving `range` alone, when there is no finite value or all are equal.
bool MeasureValueRange(vtkImageData* image, double range[2])
{
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (int k = 0; k < scalars->GetNumberOfComponents(); ++k)
  {
    double r[2];
    scalars->GetFiniteRange(r, k);
    if (r[0] <= r[1])
    {
      lo = std::min(lo, r[0]);
      hi = std::max(hi, r[1]);
    }
  }
  if (!(lo < hi))
  {
    return false;
  }
  range[0] = lo;
  range[1] = hi;
  return true;
}

void Antialias(const CommandLine& cl, const std::string& inputPath, const std::string& outputPath)
{
  const mlaa::ImageFile input = mlaa::ReadImageFile(inputPath, cl.MaxPixels);
  if (!input.Warning.empty())
  {
    std::cerr << "mlaa: warning: " << mlaa::Printable(input.Warning, 600) << std::endl;
  }

  // Straight alpha unless the file holds premultiplied colours: OpenEXR always does, TIFF does
  // unless it says its alpha is unassociated (which OpenImageIO reports, as for PNG and TGA).
  bool premultiplied = cl.AlphaMode == AlphaPremultiplied;
  if (cl.AlphaMode == AlphaAuto)
  {
    premultiplied = input.Spec.alpha_channel >= 0 &&
      input.Spec.get_int_attribute("oiio:UnassociatedAlpha", 0) == 0 &&
      (input.FormatName == "openexr" || input.FormatName == "tiff");
  }
  cl.Options->SetPremultipliedAlpha(premultiplied);

  vtkSmartPointer<vtkImageAntialiasingAlgorithm> filter;
  vtkSmartPointer<vtkImageMLAA> mlaaFilter;
  if (cl.Method == MethodDLAA)
  {
    auto dlaa = vtkSmartPointer<vtkImageDLAA>::New();
    dlaa->SetOptions(cl.DLAAOptions);
    filter = dlaa;
  }
  else
  {
    mlaaFilter = vtkSmartPointer<vtkImageMLAA>::New();
    mlaaFilter->SetOptions(cl.Options);
    filter = mlaaFilter;
  }
  double valueRange[2] = { cl.ValueRange[0], cl.ValueRange[1] };
  if (cl.ValueRangeMode == ValueRangeAuto && MeasureValueRange(input.Image, valueRange))
  {
    filter->SetValueRange(valueRange);
  }
  else if (cl.ValueRangeMode == ValueRangeGiven)
  {
    filter->SetValueRange(valueRange);
  }
  filter->SetInputData(input.Image);

  mlaa::ImageFile depth;
  if (!cl.DepthImage.empty())
  {
    depth = mlaa::ReadImageFile(cl.DepthImage, cl.MaxPixels);
    if (!depth.Warning.empty())
    {
      std::cerr << "mlaa: warning: " << mlaa::Printable(depth.Warning, 600) << std::endl;
    }
    if (depth.Spec.nchannels != 1)
    {
      throw mlaa::Error(mlaa::Printable(cl.DepthImage) + ": the depth image has " +
        std::to_string(depth.Spec.nchannels) + " channels; it must have 1");
    }
    if (depth.Spec.width != input.Spec.width || depth.Spec.height != input.Spec.height)
    {
      throw mlaa::Error(mlaa::Printable(cl.DepthImage) + ": the depth image is " +
        std::to_string(depth.Spec.width) + "x" + std::to_string(depth.Spec.height) + ", '" +
        mlaa::Printable(inputPath) + "' is " + std::to_string(input.Spec.width) + "x" +
        std::to_string(input.Spec.height));
    }
    mlaaFilter->SetDepthInputData(depth.Image); // --depth-image is refused with dlaa
  }

  VTKMessages messages(filter);
  filter->Update();
  vtkImageData* result = filter->GetOutput();
  int dims[3];
  result->GetDimensions(dims);
  vtkDataArray* scalars = result->GetPointData()->GetScalars();
  const std::string error = messages.GetError();
  if (!error.empty() || !scalars || dims[0] != input.Spec.width || dims[1] != input.Spec.height)
  {
    throw mlaa::Error(mlaa::DisplayName(inputPath, false) +
      ": cannot antialias: " +
      (error.empty() ? std::string(filter->GetClassName()) + " produced no image" : error));
  }
  const std::string warnings = messages.GetWarnings();
  if (!warnings.empty())
  {
    std::cerr << "mlaa: warning: " << mlaa::Printable(warnings, 600) << std::endl;
  }

  // The antialiased image keeps the input's description and pixel type; a debug image is
  // 8-bit RGBA whose alpha is data, not coverage, so it must be written as it is.
  OIIO::ImageSpec description = input.Spec;
  OIIO::TypeDesc pixelType = input.PixelType;
  if (cl.Options->GetDebugOutput() != vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    description = OIIO::ImageSpec(dims[0], dims[1], 4, OIIO::TypeDesc::UINT8);
    description.x = input.Spec.x;
    description.y = input.Spec.y;
    description.full_x = input.Spec.full_x;
    description.full_y = input.Spec.full_y;
    description.full_width = input.Spec.full_width;
    description.full_height = input.Spec.full_height;
    description.attribute("oiio:UnassociatedAlpha", 1);
    pixelType = OIIO::TypeDesc::UINT8;
  }
  const std::string note =
    mlaa::WriteImageFile(result, outputPath, description, pixelType, valueRange, cl.Format);
  if (!note.empty())
  {
    std::cerr << "mlaa: warning: " << mlaa::Printable(note, 600) << std::endl;
  }
}

/**
 * Builds, once, what every file of a batch shares, so that the processes forked for the files
 * find it made: vtkImageMLAA's area tables (built on first use and cached for the process) by
 * antialiasing a small staircase with the batch's options, and OpenImageIO's catalogue of
 * formats. The filter runs on VTK's Sequential backend: no thread may exist when the batch
 * forks (the TBB backend starts worker threads, which a child would not have); the children
 * return to `backend`.
 */
void PrepareBatch(const CommandLine& cl, std::string& backend)
{
  backend = vtkSMPTools::GetBackend();
  vtkSMPTools::SetBackend("Sequential");
  if (cl.Method == MethodMLAA)
  {
    vtkNew<vtkImageData> staircase;
    staircase->SetDimensions(16, 16, 1);
    staircase->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* pixels = static_cast<unsigned char*>(staircase->GetScalarPointer());
    for (int y = 0; y < 16; ++y)
    {
      for (int x = 0; x < 16; ++x)
      {
        std::fill_n(pixels + 3 * (16 * y + x), 3, static_cast<unsigned char>(3 * y < x ? 255 : 0));
      }
    }
    vtkNew<vtkImageMLAA> filter;
    filter->SetOptions(cl.Options);
    filter->SetInputData(staircase);
    VTKMessages messages(filter); // keeps anything it says off the terminal
    filter->Update();
  }
  OIIO::get_string_attribute("extension_list");
}

int AntialiasBatch(const CommandLine& cl)
{
  const std::vector<mlaa::BatchFile> files =
    mlaa::PlanBatch(mlaa::ExpandInputs(cl.Files, cl.Frames), cl.OutputDirectory);
  const int processors = mlaa::CountProcessors();
  mlaa::BatchSettings settings;
  settings.Jobs = std::min<long>(cl.Jobs > 0 ? cl.Jobs : processors, files.size());
  settings.Quiet = cl.Quiet;
  // The processors shared out between the files in flight, for VTK's and OpenImageIO's threads.
  const int threads = std::max(1, processors / settings.Jobs);
  mlaa::SetImagesInFlight(settings.Jobs);
  std::string backend;
  PrepareBatch(cl, backend);
  // Once for every file: the children inherit that it was done.
  mlaa::SweepStaleTemporaries(cl.OutputDirectory);
  settings.ProcessFile = [&](const mlaa::BatchFile& file)
  {
    vtkSMPTools::SetBackend(backend.c_str());
    vtkSMPTools::Initialize(threads);
    OIIO::attribute("threads", threads);
    try
    {
      Antialias(cl, file.Input, file.Output);
      return EXIT_SUCCESS;
    }
    catch (const std::exception& e)
    {
      std::cerr << "mlaa: " << mlaa::Printable(e.what(), 400) << std::endl;
      OIIO::geterror();
      return ExitFailure;
    }
  };
  return mlaa::RunBatch(files, settings) > 0 ? ExitFailure : EXIT_SUCCESS;
}
} // namespace

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  mlaa::InstallCrashReport();
  const std::vector<std::string> args(argv + 1, argv + argc);
  int status = EXIT_SUCCESS;
  try
  {
    CommandLine cl;
    mlaa::ParseCommandLine(args, cl);
    if (cl.Help)
    {
      mlaa::UsageFacts facts;
      facts.DefaultMaxPixels = mlaa::DefaultMaxPixels(4, OIIO::TypeDesc::UINT8);
      facts.Processors = mlaa::CountProcessors();
      mlaa::PrintUsage(std::cout, facts);
    }
    else if (cl.Batch)
    {
      status = AntialiasBatch(cl);
    }
    else
    {
      // Refused before any work: an unknown --format, and binary data for a terminal.
      if (!cl.Format.empty())
      {
        mlaa::CheckOutputFormat(cl.Format);
      }
      if (cl.Files.back() == "-" && isatty(STDOUT_FILENO))
      {
        throw UsageError("standard output is a terminal: redirect it (mlaa ... - > out.png) or "
                         "name an OUTPUT file");
      }
      if (cl.AreaTextureCellSize)
      {
        WriteAreaTexture(cl.AreaTextureCellSize, cl.Files[0], cl.Format);
      }
      else
      {
        Antialias(cl, cl.Files[0], cl.Files[1]);
      }
    }
  }
  catch (const UsageError& e)
  {
    std::cerr << "mlaa: " << mlaa::Printable(e.what(), 400, false) << " (see mlaa --help)"
              << std::endl;
    status = ExitUsage;
  }
  catch (const std::exception& e)
  {
    std::cerr << "mlaa: " << mlaa::Printable(e.what(), 400) << std::endl;
    status = ExitFailure;
  }
  // Any error OpenImageIO still holds was reported above; leaving it would make OpenImageIO
  // print it again at exit.
  OIIO::geterror();
  return status;
}
