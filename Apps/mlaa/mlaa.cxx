/**
 * mlaa: morphological antialiasing of image files.
 *
 *   mlaa [options] INPUT OUTPUT
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

//------------------------------------------------------------------------------
// Option names and help

// What each edge-detection mode and debug output is, for --help. The names themselves come
// from vtkMLAAOptions.
const char* DescribeEdgeDetection(int mode)
{
  switch (mode)
  {
    case vtkMLAAOptions::LUMA:
      return "Rec. 709 luminance (section 4.2.1); cheapest, perceptual";
    case vtkMLAAOptions::COLOR:
      return "largest difference of any channel; also finds edges between colours of equal "
             "luma";
    case vtkMLAAOptions::DEPTH:
      return "difference of the --depth-image values; leaves shading edges alone, usually "
             "wants a threshold of 1e-3 to 1e-2";
    case vtkMLAAOptions::LAB:
      return "CIELAB colour difference (Biri et al., section 3.2): the threshold is Delta E / 100 "
             "(0.1 = Delta E 10); finds edges between colours of equal luma and weighs them as a "
             "person sees them; the slowest mode";
    default:
      return "";
  }
}

// The settings of a preset, from vtkMLAAOptions' own table.
std::string DescribePreset(int preset)
{
  vtkNew<vtkMLAAOptions> options;
  options->SetPreset(preset);
  std::ostringstream text;
  text << vtkMLAAOptions::GetEdgeDetectionAsString(options->GetEdgeDetection()) << ", threshold "
       << options->GetThreshold() << ", local contrast " << options->GetLocalContrastFactor()
       << ", " << options->GetMaxSearchSteps() << " search steps, diagonals "
       << (options->GetDiagonalDetection() ? "on" : "off") << ", dominant blending "
       << (options->GetDominantDirectionBlending() ? "on" : "off") << ", reconstruction "
       << (options->GetReconstruction() ? "on" : "off");
  return text.str();
}

const char* DescribeDebugOutput(int output)
{
  switch (output)
  {
    case vtkMLAAOptions::NO_DEBUG_OUTPUT:
      return "the antialiased image";
    case vtkMLAAOptions::EDGES:
      return "the edges of section 4.2: red = edge at the pixel's left, green = edge at its "
             "top, blue = 0, alpha = 255";
    case vtkMLAAOptions::BLENDING_WEIGHTS:
      return "the blending weights of section 4.3 times 255 (red/green: with the pixel above, "
             "blue/alpha: with the pixel to the left)";
    default:
      return "";
  }
}

// "luma|color|depth", from vtkMLAAOptions.
std::string EdgeDetectionNames(vtkMLAAOptions* options, const char* separator)
{
  std::string names;
  for (int m = options->GetEdgeDetectionMinValue(); m <= options->GetEdgeDetectionMaxValue(); ++m)
  {
    names += (names.empty() ? "" : separator);
    names += vtkMLAAOptions::GetEdgeDetectionAsString(m);
  }
  return names;
}

std::string DebugOutputNames(vtkMLAAOptions* options, const char* separator)
{
  std::string names;
  for (int d = options->GetDebugOutputMinValue(); d <= options->GetDebugOutputMaxValue(); ++d)
  {
    names += (names.empty() ? "" : separator);
    names += vtkMLAAOptions::GetDebugOutputAsString(d);
  }
  return names;
}

// Writes `text` word-wrapped to 80 columns, every line indented by `indent` spaces except the
// first, which continues after `first` (padded to the indentation).
void PrintWrapped(
  std::ostream& os, const std::string& first, size_t indent, const std::string& text)
{
  const size_t width = 80;
  std::string line = first;
  line.resize(std::max(line.size(), indent), ' ');
  bool atStart = line.size() == indent; // nothing but indentation on the line yet
  std::istringstream words(text);
  std::string word;
  while (words >> word)
  {
    if (!atStart && line.size() + 1 + word.size() > width)
    {
      os << line << "\n";
      line.assign(indent, ' ');
      atStart = true;
    }
    if (!atStart)
    {
      line += ' ';
    }
    line += word;
    atStart = false;
  }
  os << line << "\n";
}

void PrintUsage(std::ostream& os)
{
  // Defaults and ranges are those of the classes, not copies of them.
  vtkNew<vtkMLAAOptions> defaults;
  vtkNew<vtkImageMLAA> filter;
  vtkNew<vtkMLAAAreaTexture> texture;
  const double* valueRange = filter->GetValueRange();
  const std::string depthName = vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH);
  const std::string noDebugName =
    vtkMLAAOptions::GetDebugOutputAsString(vtkMLAAOptions::NO_DEBUG_OUTPUT);
  const size_t column = 25;
  auto option = [&](const std::string& name, const std::ostringstream& text)
  { PrintWrapped(os, "  " + name, column, text.str()); };

  os << "Usage: mlaa [options] INPUT OUTPUT\n"
        "       mlaa [options] --output-dir DIR INPUT...\n"
        "       mlaa --area-texture D OUTPUT\n"
        "\n";
  PrintWrapped(os, "", 0,
    "Removes staircase aliasing from the image INPUT with morphological antialiasing (MLAA: "
    "Jimenez et al., \"Practical Morphological Antialiasing\", GPU Pro 2, chapter 4; VTK's "
    "vtkImageMLAA), or with directionally localized antialiasing (--method dlaa; vtkImageDLAA), "
    "and writes the result to OUTPUT.");
  os << "\n";
  PrintWrapped(os, "", 0,
    "INPUT may be any image OpenImageIO reads (PNG, TIFF, OpenEXR, JPEG, ...): 8- or 16-bit, "
    "half or float, with 1 to 4 channels (grey, grey + alpha, RGB, RGBA); only its first "
    "subimage is read. OUTPUT's format comes from its extension. OUTPUT has INPUT's size, "
    "channels and pixel type; where its format cannot hold that type, OpenImageIO's closest "
    "type is written and a warning says so (floating-point values written as integers are "
    "scaled by --value-range and clamped). Pixels are used as stored: no colour-space "
    "conversion, alpha is kept as the file stores it (see --alpha), and pixels away from "
    "edges are written unchanged.");
  os << "\nOptions:\n";

  std::ostringstream text;
  text << "The method: mlaa (morphological antialiasing: recognises the staircases of edges "
          "and revectorises them; sharpest on still images) or dlaa (directionally localized "
          "antialiasing, Andreev, GDC 2011: blurs each edge along its own direction; steadier "
          "in animation). The options from --threshold to --debug are MLAA's, the --dlaa-* and "
          "--long-edges ones DLAA's; giving one to the other method is an error. Default: mlaa.";
  option("--method mlaa|dlaa", text);

  text.str("");
  text << "Smallest difference between neighbouring pixels that is an edge, with the image's "
          "value range as 1; in ["
       << defaults->GetThresholdMinValue() << ", " << defaults->GetThresholdMaxValue()
       << "]. Lower finds fainter edges (and noise). Default: " << defaults->GetThreshold() << ".";
  option("--threshold T", text);

  text.str("");
  text << "Local contrast adaptation: an edge is kept only if F times its contrast is at least "
          "the contrast of every other boundary of its two pixels, so that faint shading next "
          "to a strong silhouette does not cut it into pieces; in ["
       << defaults->GetLocalContrastFactorMinValue() << ", "
       << defaults->GetLocalContrastFactorMaxValue()
       << "], 0 keeps every edge above the threshold. Default: "
       << defaults->GetLocalContrastFactor() << ".";
  option("--local-contrast F", text);

  text.str("");
  text << "What edge detection compares (section 4.2). Default: "
       << vtkMLAAOptions::GetEdgeDetectionAsString(defaults->GetEdgeDetection()) << ".";
  option("--edges MODE", text);
  for (int m = defaults->GetEdgeDetectionMinValue(); m <= defaults->GetEdgeDetectionMaxValue(); ++m)
  {
    PrintWrapped(os,
      std::string(column + 2, ' ') + vtkMLAAOptions::GetEdgeDetectionAsString(m) + ":", column + 4,
      DescribeEdgeDetection(m));
  }

  text.str("");
  text
    << "The depth for --edges " << depthName
    << " (required there, refused otherwise): a 1-channel image of INPUT's size. "
       "Floating-point depths are used as they are, integer ones scaled to [0, 1]. Default: none.";
  option("--depth-image FILE", text);

  text.str("");
  text << "Steps of the search for the ends of each line of edges, two pixels per step (section "
          "4.3.1); in ["
       << defaults->GetMaxSearchStepsMinValue() << ", " << defaults->GetMaxSearchStepsMaxValue()
       << "]. Default: " << defaults->GetMaxSearchSteps() << " (lines followed up to "
       << defaults->GetMaxDistance() << " pixels each way).";
  option("--max-search-steps N", text);

  text.str("");
  text << "Whether staircases of one-pixel steps are smoothed as 45-degree lines (on) or only "
          "horizontal and vertical lines are followed, as in the chapter (off). Default: "
       << (defaults->GetDiagonalDetection() ? "on" : "off") << ".";
  option("--diagonals on|off", text);

  text.str("");
  text << "How the colours of an image with alpha relate to its alpha: straight (unassociated: "
          "PNG, TGA, TIFF that says so, and every other format) or premultiplied (associated: "
          "OpenEXR and other TIFF). With straight alpha the colours are blended premultiplied and divided "
          "again, so the colour of transparent pixels never shows as a fringe. Default: auto, "
          "from the file.";
  option("--alpha auto|straight|premultiplied", text);

  text.str("");
  text << "Topological reconstruction (Biri et al., section 4) before edge detection: a pixel "
          "where point sampling broke a thin shape (a wire, a streamline, an iso-line) in two "
          "is given the shape's colour. Line ends, dots and corners are left alone. Default: "
       << (defaults->GetReconstruction() ? "on" : "off") << ".";
  option("--reconstruction on|off", text);

  text.str("");
  text << "Set every quality option (--threshold, --local-contrast, --edges, "
          "--max-search-steps, --diagonals, --dominant-blending, --reconstruction) at once; "
          "those options may follow it to override it, but not precede it. Default: "
       << vtkMLAAOptions::GetPresetAsString(defaults->GetPreset())
       << " (the defaults above). The README lists what each costs and gains.";
  option("--preset NAME", text);
  for (int p = vtkMLAAOptions::LOW; p <= vtkMLAAOptions::ULTRA; ++p)
  {
    PrintWrapped(os, std::string(column + 2, ' ') + vtkMLAAOptions::GetPresetAsString(p) + ":",
      column + 4, DescribePreset(p));
  }

  text.str("");
  text << "Whether a pixel on the corner of a staircase is blended along its dominant line only "
          "(on, as SMAA does) or with every neighbour's share averaged, as in the chapter (off). "
          "Default: "
       << (defaults->GetDominantDirectionBlending() ? "on" : "off") << ".";
  option("--dominant-blending on|off", text);

  text.str("");
  text << "Write an intermediate image instead of the antialiased one, as 8-bit RGBA (all but "
       << noDebugName
       << "). Default: " << vtkMLAAOptions::GetDebugOutputAsString(defaults->GetDebugOutput())
       << ".";
  option("--debug IMAGE", text);
  for (int d = defaults->GetDebugOutputMinValue(); d <= defaults->GetDebugOutputMaxValue(); ++d)
  {
    PrintWrapped(os, std::string(column + 2, ' ') + vtkMLAAOptions::GetDebugOutputAsString(d) + ":",
      column + 4, DescribeDebugOutput(d));
  }

  vtkNew<vtkDLAAOptions> dlaaDefaults;
  text.str("");
  text << "DLAA: the offset of the contrast curve that turns an edge's high-pass response into "
          "a blend weight (saturate(lambda * response - epsilon)); in ["
       << dlaaDefaults->GetEpsilonMinValue() << ", " << dlaaDefaults->GetEpsilonMaxValue()
       << "]. Responses below epsilon / lambda are left alone. Default: "
       << dlaaDefaults->GetEpsilon() << ".";
  option("--dlaa-epsilon E", text);

  text.str("");
  text << "DLAA: the gain of that contrast curve; in [" << dlaaDefaults->GetLambdaMinValue()
       << ", " << dlaaDefaults->GetLambdaMaxValue()
       << "]. Higher blends more. Default: " << dlaaDefaults->GetLambda() << ".";
  option("--dlaa-lambda L", text);

  text.str("");
  text << "DLAA: the luminosity function, "
       << vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::REC709)
       << " (0.2126 R + 0.7152 G + 0.0722 B) or "
       << vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::GREEN)
       << " (the green channel). Default: "
       << vtkDLAAOptions::GetLumaFunctionAsString(dlaaDefaults->GetLumaFunction()) << ".";
  option("--dlaa-luma NAME", text);

  text.str("");
  text << "DLAA: whether long horizontal and vertical edges get the wide, colour-preserving "
          "step (on) or only the 5-pixel blurs (off). Default: "
       << (dlaaDefaults->GetLongEdges() ? "on" : "off") << ".";
  option("--long-edges on|off", text);

  text.str("");
  text << "The values taken as 0 and 1 by edge detection (and, for floating-point images, when "
          "writing to an integer format), for every pixel type. Default: the range of the "
          "pixel type for integer images (0 to 255, 0 to 65535), "
       << valueRange[0] << " " << valueRange[1]
       << " for floating point. 'auto': the image's own smallest and largest value, for data "
          "that uses part of its type (10-, 12- or 14-bit values in 16-bit files).";
  option("--value-range LO HI|auto", text);

  text.str("");
  text << "The largest image, in pixels (width x height), that INPUT and the depth image may "
          "be; checked from the file's header before anything is allocated. Default: what "
          "fits in half of the memory available now (about "
       << mlaa::DefaultMaxPixels(4, OIIO::TypeDesc::UINT8)
       << " RGBA 8-bit pixels), shared by the files a batch processes at the same time.";
  option("--max-pixels N", text);

  text.str("");
  text << "Batch: antialias every INPUT into the existing directory DIR, each output with its "
          "input's file name and format. Files are processed side by side on every core, each "
          "exactly as alone; one that fails is reported and the others go on. Refused if an "
          "output would replace an input, or two inputs have the same name. Default: off "
          "(INPUT OUTPUT).";
  option("--output-dir DIR", text);

  text.str("");
  text << "Batch: the frames of a numbered-sequence INPUT, in OpenImageIO's notation: 1-100, "
          "1-100x2 (every second), 1,5,9. A sequence INPUT is a name that is not an existing "
          "file and has a frame number pattern: %04d, # (four digits) or @ (one digit per @), "
          "as in frame.%04d.png or frame.#.png; the range may also be part of the name "
          "(frame.1-100#.png). Default: every existing file of the sequence.";
  option("--frames RANGE", text);

  text.str("");
  text << "Batch: files processed at the same time. Default: the number of processors this "
          "process may use ("
       << mlaa::CountProcessors() << " here).";
  option("--jobs N", text);

  text.str("");
  text << "Batch: no progress display (a bar on a terminal, else one line per file done); "
          "warnings and errors still show. Default: off.";
  option("-q, --quiet", text);

  text.str("");
  text << "Write the area texture of section 4.3.3 (Figure 4.2) to OUTPUT instead, for cells "
          "of D texels (D = 2 * search steps + 1: 9, 17, 33, ...; D in ["
       << texture->GetMaxDistanceMinValue() + 1 << ", " << texture->GetMaxDistanceMaxValue() + 1
       << "]): an 8-bit RGB image of 5D x 5D texels whose texel (D*e1 + left, D*e2 + right), "
          "counted from the top left, holds the two areas times 255 in red and green. Takes no "
          "INPUT and no other option. Default: off.";
  option("--area-texture D", text);

  text.str("");
  text << "Print this help and exit.";
  option("-h, --help", text);

  os << "\n";
  PrintWrapped(os, "", 0,
    "Options take their value as the next argument or after '=' (--threshold=0.05); '--' ends "
    "the options. OUTPUT is written to a temporary file beside it and renamed over it only "
    "once complete: if anything fails, an existing OUTPUT is left untouched.");
  os << "\n";
  PrintWrapped(os, "", 0,
    "INPUT (and the depth image) must be regular files: directories, FIFOs, devices and "
    "sockets are refused. OUTPUT's format must hold the image: formats without alpha (JPEG, "
    "PNM, HDR) get the colour channels and GIF and ICO an added alpha channel, each with a "
    "warning; what a format cannot hold, or OpenImageIO 2.4 is known to write wrongly (JPEG "
    "2000, FITS, RLA, grey + alpha DPX), is refused. The written file is read back (size and "
    "channels) before it replaces OUTPUT.");
  os << "\n";
  PrintWrapped(os, "", 0,
    "Exit status: 0 on success; 1 if reading, antialiasing or writing failed (in a batch: "
    "any file); 2 for a bad command line. Errors are one line on stderr, \"mlaa: FILE: what "
    "went wrong\". If a library crashes, a line saying so and what the library printed are shown, and no "
    "temporary file is left behind.");
}

//------------------------------------------------------------------------------
// Command line

// Where the value range comes from: vtkImageMLAA's default for the image's type, --value-range
// LO HI, or --value-range auto (the image's own minimum and maximum).
enum ValueRangeModes
{
  ValueRangeDefault = 0,
  ValueRangeGiven = 1,
  ValueRangeAuto = 2
};

// How the colour of an image with alpha relates to its alpha (vtkMLAAOptions::PremultipliedAlpha):
// from the file (auto), or as given.
enum AlphaModes
{
  AlphaAuto = 0,
  AlphaStraight = 1,
  AlphaPremultiplied = 2
};

// The antialiasing methods (--method).
enum Methods
{
  MethodMLAA = 0,
  MethodDLAA = 1
};

struct CommandLine
{
  bool Help = false;
  int Method = MethodMLAA;
  vtkNew<vtkMLAAOptions> Options;
  vtkNew<vtkDLAAOptions> DLAAOptions;
  std::string DepthImage;
  double ValueRange[2] = { 0.0, 1.0 }; // for floating-point images, unless given or measured
  int ValueRangeMode = 0;               // ValueRangeDefault, ValueRangeGiven or ValueRangeAuto
  int AlphaMode = AlphaAuto;
  int AreaTextureCellSize = 0;            // 0: antialias INPUT
  unsigned long long MaxPixels = 0;       // 0: mlaa::DefaultMaxPixels
  std::vector<std::string> FilterOptions; // the options given that configure the filter
  std::vector<std::string> MLAAOnly;      // of those, the ones only MLAA takes
  std::vector<std::string> DLAAOnly;      // of those, the ones only DLAA takes
  std::vector<std::string> Files;
  // Batch mode (--output-dir).
  bool Batch = false;
  std::string OutputDirectory;
  std::string Frames;
  int Jobs = 0; // 0: one per processor
  bool Quiet = false;
  std::vector<std::string> BatchOnly; // the batch options given
};

bool ParseDouble(const std::string& text, double& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return *end == '\0' && errno == 0 && std::isfinite(value);
}

bool ParseInt(const std::string& text, long& value)
{
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtol(text.c_str(), &end, 10);
  return *end == '\0' && errno == 0;
}

template <typename T>
std::string ToString(T value)
{
  std::ostringstream os;
  os << value;
  return os.str();
}

void ParseCommandLine(const std::vector<std::string>& args, CommandLine& cl)
{
  // Help wins over everything else on the line.
  for (const std::string& arg : args)
  {
    if (arg == "--")
    {
      break;
    }
    if (arg == "-h" || arg == "--help")
    {
      cl.Help = true;
      return;
    }
  }

  vtkNew<vtkImageMLAA> defaultFilter;
  defaultFilter->GetValueRange(cl.ValueRange);
  vtkMLAAOptions* options = cl.Options;
  bool optionsEnded = false;
  for (size_t i = 0; i < args.size(); ++i)
  {
    const std::string& arg = args[i];
    if (optionsEnded || arg.size() < 2 || arg[0] != '-')
    {
      cl.Files.push_back(arg);
      continue;
    }
    if (arg == "--")
    {
      optionsEnded = true;
      continue;
    }

    // "--name value" or "--name=value".
    std::string name = arg;
    std::string inlineValue;
    bool hasInlineValue = false;
    const size_t equals = arg.find('=');
    if (arg.compare(0, 2, "--") == 0 && equals != std::string::npos)
    {
      name = arg.substr(0, equals);
      inlineValue = arg.substr(equals + 1);
      hasInlineValue = true;
    }
    auto takeValues = [&](size_t count)
    {
      std::vector<std::string> values;
      if (hasInlineValue)
      {
        if (count != 1)
        {
          throw UsageError(name + " takes " + std::to_string(count) + " values: write " + name +
            " followed by them");
        }
        values.push_back(inlineValue);
        return values;
      }
      for (size_t k = 1; k <= count; ++k)
      {
        if (i + k >= args.size() || args[i + k].compare(0, 2, "--") == 0)
        {
          throw UsageError(
            name + " needs " + (count == 1 ? "a value" : std::to_string(count) + " values"));
        }
        values.push_back(args[i + k]);
      }
      i += count;
      return values;
    };
    // The value of a number option, which must lie in [lo, hi].
    auto takeNumber = [&](double lo, double hi)
    {
      const std::string text = takeValues(1)[0];
      double value;
      if (!ParseDouble(text, value) || value < lo || value > hi)
      {
        throw UsageError(name + ": '" + text + "' is not a number in [" + ToString(lo) + ", " +
          ToString(hi) + "]");
      }
      return value;
    };
    // The value of an on|off option.
    auto takeSwitch = [&]()
    {
      const std::string text = takeValues(1)[0];
      if (text != "on" && text != "off")
      {
        throw UsageError(name + ": '" + text + "' is neither on nor off");
      }
      return text == "on";
    };

    if (name == "--threshold")
    {
      options->SetThreshold(
        takeNumber(options->GetThresholdMinValue(), options->GetThresholdMaxValue()));
    }
    else if (name == "--local-contrast")
    {
      options->SetLocalContrastFactor(takeNumber(
        options->GetLocalContrastFactorMinValue(), options->GetLocalContrastFactorMaxValue()));
    }
    else if (name == "--edges")
    {
      const std::string text = takeValues(1)[0];
      const int mode = vtkMLAAOptions::GetEdgeDetectionFromString(text.c_str());
      if (mode < 0)
      {
        throw UsageError("--edges: unknown mode '" + text + "' (expected one of " +
          EdgeDetectionNames(options, ", ") + ")");
      }
      options->SetEdgeDetection(mode);
    }
    else if (name == "--debug")
    {
      const std::string text = takeValues(1)[0];
      const int output = vtkMLAAOptions::GetDebugOutputFromString(text.c_str());
      if (output < 0)
      {
        throw UsageError("--debug: unknown output '" + text + "' (expected one of " +
          DebugOutputNames(options, ", ") + ")");
      }
      options->SetDebugOutput(output);
    }
    else if (name == "--max-search-steps")
    {
      const std::string text = takeValues(1)[0];
      long value;
      const int lo = options->GetMaxSearchStepsMinValue();
      const int hi = options->GetMaxSearchStepsMaxValue();
      if (!ParseInt(text, value) || value < lo || value > hi)
      {
        throw UsageError("--max-search-steps: '" + text + "' is not an integer in [" +
          std::to_string(lo) + ", " + std::to_string(hi) + "]");
      }
      options->SetMaxSearchSteps(static_cast<int>(value));
    }
    else if (name == "--diagonals")
    {
      options->SetDiagonalDetection(takeSwitch());
    }
    else if (name == "--dominant-blending")
    {
      options->SetDominantDirectionBlending(takeSwitch());
    }
    else if (name == "--reconstruction")
    {
      options->SetReconstruction(takeSwitch());
    }
    else if (name == "--method")
    {
      const std::string text = takeValues(1)[0];
      if (text != "mlaa" && text != "dlaa")
      {
        throw UsageError("--method: '" + text + "' is neither mlaa nor dlaa");
      }
      cl.Method = text == "dlaa" ? MethodDLAA : MethodMLAA;
      continue; // not an option of either method
    }
    else if (name == "--dlaa-epsilon")
    {
      vtkDLAAOptions* dlaa = cl.DLAAOptions;
      dlaa->SetEpsilon(takeNumber(dlaa->GetEpsilonMinValue(), dlaa->GetEpsilonMaxValue()));
    }
    else if (name == "--dlaa-lambda")
    {
      vtkDLAAOptions* dlaa = cl.DLAAOptions;
      dlaa->SetLambda(takeNumber(dlaa->GetLambdaMinValue(), dlaa->GetLambdaMaxValue()));
    }
    else if (name == "--dlaa-luma")
    {
      const std::string text = takeValues(1)[0];
      const int function = vtkDLAAOptions::GetLumaFunctionFromString(text.c_str());
      if (function < 0)
      {
        throw UsageError("--dlaa-luma: unknown luminosity function '" + text +
          "' (expected " + vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::REC709) +
          " or " + vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::GREEN) + ")");
      }
      cl.DLAAOptions->SetLumaFunction(function);
    }
    else if (name == "--long-edges")
    {
      cl.DLAAOptions->SetLongEdges(takeSwitch());
    }
    else if (name == "--preset")
    {
      const std::string text = takeValues(1)[0];
      const int preset = vtkMLAAOptions::GetPresetFromString(text.c_str());
      if (preset < 0)
      {
        std::string names;
        for (int p = vtkMLAAOptions::LOW; p <= vtkMLAAOptions::ULTRA; ++p)
        {
          names += std::string(p > vtkMLAAOptions::LOW ? ", " : "") +
            vtkMLAAOptions::GetPresetAsString(p);
        }
        throw UsageError("--preset: unknown preset '" + text + "' (expected one of " + names + ")");
      }
      // A quality option before the preset would be silently replaced by it.
      for (const std::string& given : cl.FilterOptions)
      {
        if (given != "--alpha" && given != "--debug" && given != "--depth-image" &&
          given != "--value-range" && given != "--preset")
        {
          throw UsageError(
            "--preset sets " + given + " too: put --preset before the options that override it");
        }
      }
      options->SetPreset(preset);
    }
    else if (name == "--alpha")
    {
      const std::string text = takeValues(1)[0];
      if (text == "auto")
      {
        cl.AlphaMode = AlphaAuto;
      }
      else if (text == "straight")
      {
        cl.AlphaMode = AlphaStraight;
      }
      else if (text == "premultiplied")
      {
        cl.AlphaMode = AlphaPremultiplied;
      }
      else
      {
        throw UsageError(
          "--alpha: '" + text + "' is not one of auto, straight, premultiplied");
      }
    }
    else if (name == "--depth-image")
    {
      cl.DepthImage = takeValues(1)[0];
      if (cl.DepthImage.empty())
      {
        throw UsageError("--depth-image needs a file name");
      }
    }
    else if (name == "--value-range")
    {
      if ((hasInlineValue && inlineValue == "auto") ||
        (!hasInlineValue && i + 1 < args.size() && args[i + 1] == "auto"))
      {
        i += hasInlineValue ? 0 : 1;
        cl.ValueRangeMode = ValueRangeAuto;
        continue;
      }
      const std::vector<std::string> texts = takeValues(2);
      double range[2];
      if (!ParseDouble(texts[0], range[0]) || !ParseDouble(texts[1], range[1]) ||
        !(range[0] < range[1]))
      {
        throw UsageError("--value-range: '" + texts[0] + " " + texts[1] +
          "' is neither two finite numbers LO < HI nor 'auto'");
      }
      cl.ValueRange[0] = range[0];
      cl.ValueRange[1] = range[1];
      cl.ValueRangeMode = ValueRangeGiven;
    }
    else if (name == "--max-pixels")
    {
      const std::string text = takeValues(1)[0];
      char* end = nullptr;
      errno = 0;
      const unsigned long long value = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0 || value == 0)
      {
        throw UsageError("--max-pixels: '" + text + "' is not a positive integer");
      }
      cl.MaxPixels = value;
      continue; // not a filter option
    }
    else if (name == "--output-dir")
    {
      cl.OutputDirectory = takeValues(1)[0];
      if (cl.OutputDirectory.empty())
      {
        throw UsageError("--output-dir needs a directory name");
      }
      cl.Batch = true;
      continue; // not a filter option
    }
    else if (name == "--frames")
    {
      cl.Frames = takeValues(1)[0];
      if (cl.Frames.empty())
      {
        throw UsageError("--frames needs a frame range");
      }
      cl.BatchOnly.push_back(name);
      continue;
    }
    else if (name == "--jobs")
    {
      const std::string text = takeValues(1)[0];
      long value;
      if (!ParseInt(text, value) || value < 1 || value > 1024)
      {
        throw UsageError("--jobs: '" + text + "' is not an integer in [1, 1024]");
      }
      cl.Jobs = static_cast<int>(value);
      cl.BatchOnly.push_back(name);
      continue;
    }
    else if (name == "--quiet" || name == "-q")
    {
      if (hasInlineValue)
      {
        throw UsageError(name + " takes no value");
      }
      cl.Quiet = true;
      cl.BatchOnly.push_back(name);
      continue;
    }
    else if (name == "--area-texture")
    {
      const std::string text = takeValues(1)[0];
      vtkNew<vtkMLAAAreaTexture> texture;
      const int lo = texture->GetMaxDistanceMinValue() + 1;
      const int hi = texture->GetMaxDistanceMaxValue() + 1;
      long value;
      if (!ParseInt(text, value) || value < lo || value > hi)
      {
        throw UsageError("--area-texture: '" + text + "' is not a cell size in [" +
          std::to_string(lo) + ", " + std::to_string(hi) + "]");
      }
      cl.AreaTextureCellSize = static_cast<int>(value);
      continue; // not a filter option
    }
    else
    {
      throw UsageError("unknown option '" + arg + "'");
    }
    cl.FilterOptions.push_back(name);
    if (name == "--dlaa-epsilon" || name == "--dlaa-lambda" || name == "--dlaa-luma" ||
      name == "--long-edges")
    {
      cl.DLAAOnly.push_back(name);
    }
    else if (name != "--value-range")
    {
      cl.MLAAOnly.push_back(name);
    }
  }

  // What goes with what.
  if (!cl.Batch && !cl.BatchOnly.empty())
  {
    throw UsageError(cl.BatchOnly.front() + " is an option of batches: add --output-dir DIR");
  }
  if (cl.AreaTextureCellSize)
  {
    if (cl.Batch)
    {
      throw UsageError("--area-texture cannot be combined with --output-dir");
    }
    if (!cl.FilterOptions.empty())
    {
      throw UsageError("--area-texture cannot be combined with " + cl.FilterOptions.front());
    }
    if (cl.Files.size() != 1)
    {
      throw UsageError(cl.Files.empty() ? std::string("--area-texture needs OUTPUT")
                                        : "unexpected argument '" + cl.Files[1] + "'");
    }
    return;
  }
  if (cl.Batch)
  {
    if (cl.Files.empty())
    {
      throw UsageError("missing INPUT: --output-dir needs at least one");
    }
    if (!cl.DepthImage.empty())
    {
      throw UsageError("--depth-image cannot be used with --output-dir (one depth image "
                       "cannot belong to several inputs)");
    }
  }
  else if (cl.Files.empty())
  {
    throw UsageError("missing INPUT and OUTPUT");
  }
  else if (cl.Files.size() == 1)
  {
    throw UsageError("missing OUTPUT");
  }
  else if (cl.Files.size() > 2)
  {
    throw UsageError("unexpected argument '" + cl.Files[2] + "'");
  }
  if (cl.Method == MethodDLAA && !cl.MLAAOnly.empty())
  {
    throw UsageError(cl.MLAAOnly.front() + " is an option of --method mlaa, not dlaa");
  }
  if (cl.Method == MethodMLAA && !cl.DLAAOnly.empty())
  {
    throw UsageError(cl.DLAAOnly.front() + " is an option of --method dlaa (add --method dlaa)");
  }
  const bool depthEdges = options->GetEdgeDetection() == vtkMLAAOptions::DEPTH;
  if (depthEdges && cl.DepthImage.empty())
  {
    throw UsageError(std::string("--edges ") +
      vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH) +
      " needs --depth-image FILE");
  }
  if (!depthEdges && !cl.DepthImage.empty())
  {
    throw UsageError(std::string("--depth-image is only used with --edges ") +
      vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH));
  }
}

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

void WriteAreaTexture(int cellSize, const std::string& path)
{
  vtkNew<vtkMLAAAreaTexture> texture;
  texture->SetMaxDistance(cellSize - 1);
  // GetImage() stores texel row t at image row size - 1 - t; written top row first, the file
  // reads as Figure 4.2 (texel (0, 0) at the top left).
  vtkImageData* image = texture->GetImage();
  const int size = texture->GetTextureSize();
  const double unitRange[2] = { 0.0, 1.0 };
  const std::string note = mlaa::WriteImageFile(image, path,
    OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::UINT8), OIIO::TypeDesc::UINT8, unitRange);
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
    throw mlaa::Error(mlaa::Printable(inputPath) +
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
    mlaa::WriteImageFile(result, outputPath, description, pixelType, valueRange);
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
    ParseCommandLine(args, cl);
    if (cl.Help)
    {
      PrintUsage(std::cout);
    }
    else if (cl.AreaTextureCellSize)
    {
      WriteAreaTexture(cl.AreaTextureCellSize, cl.Files[0]);
    }
    else if (cl.Batch)
    {
      status = AntialiasBatch(cl);
    }
    else
    {
      Antialias(cl, cl.Files[0], cl.Files[1]);
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
