// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "mlaaOptionTable.h"

#include "vtkImageMLAA.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkNew.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <ostream>
#include <sstream>

namespace mlaa
{
namespace
{
//------------------------------------------------------------------------------
// Text

// The parts streamed one after the other, as std::ostream writes them.
template <typename... Parts>
std::string Text(const Parts&... parts)
{
  std::ostringstream os;
  (os << ... << parts);
  return os.str();
}

const char* OnOff(bool value)
{
  return value ? "on" : "off";
}

// "a, b, c" (or "a|b|c" with separator "|").
std::string Join(const std::vector<std::string>& names, const char* separator)
{
  std::string joined;
  for (const std::string& name : names)
  {
    joined += (joined.empty() ? "" : separator) + name;
  }
  return joined;
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

//------------------------------------------------------------------------------
// Names and what they mean, from the option classes

std::vector<std::string> OnOffNames()
{
  return { "on", "off" };
}

std::vector<std::string> EdgeDetectionNames()
{
  vtkNew<vtkMLAAOptions> options;
  std::vector<std::string> names;
  for (int m = options->GetEdgeDetectionMinValue(); m <= options->GetEdgeDetectionMaxValue(); ++m)
  {
    names.emplace_back(vtkMLAAOptions::GetEdgeDetectionAsString(m));
  }
  return names;
}

std::vector<std::string> DebugOutputNames()
{
  vtkNew<vtkMLAAOptions> options;
  std::vector<std::string> names;
  for (int d = options->GetDebugOutputMinValue(); d <= options->GetDebugOutputMaxValue(); ++d)
  {
    names.emplace_back(vtkMLAAOptions::GetDebugOutputAsString(d));
  }
  return names;
}

std::vector<std::string> PresetNames()
{
  std::vector<std::string> names;
  for (int p = vtkMLAAOptions::LOW; p <= vtkMLAAOptions::MAX; ++p)
  {
    names.emplace_back(vtkMLAAOptions::GetPresetAsString(p));
  }
  return names;
}

std::vector<std::string> LumaFunctionNames()
{
  vtkNew<vtkDLAAOptions> options;
  std::vector<std::string> names;
  for (int f = options->GetLumaFunctionMinValue(); f <= options->GetLumaFunctionMaxValue(); ++f)
  {
    names.emplace_back(vtkDLAAOptions::GetLumaFunctionAsString(f));
  }
  return names;
}

std::vector<std::string> MethodNames()
{
  return { "mlaa", "dlaa" }; // indexed by Methods
}

std::vector<std::string> AlphaNames()
{
  return { "auto", "straight", "premultiplied" }; // indexed by AlphaModes
}

// What each edge-detection mode is, for --help.
std::string DescribeEdgeDetection(const std::string& name)
{
  switch (vtkMLAAOptions::GetEdgeDetectionFromString(name.c_str()))
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
std::string DescribePreset(const std::string& name)
{
  vtkNew<vtkMLAAOptions> options;
  options->SetPreset(vtkMLAAOptions::GetPresetFromString(name.c_str()));
  return Text(vtkMLAAOptions::GetEdgeDetectionAsString(options->GetEdgeDetection()),
    ", threshold ", options->GetThreshold(), ", local contrast ",
    options->GetLocalContrastFactor(), ", ", options->GetMaxSearchSteps(),
    " search steps, diagonals ",
    OnOff(options->GetDiagonalDetection()), ", corners ",
    OnOff(options->GetCornerExtrapolation()), ", dominant blending ",
    OnOff(options->GetDominantDirectionBlending()), ", reconstruction ",
    OnOff(options->GetReconstruction()));
}

std::string DescribeDebugOutput(const std::string& name)
{
  switch (vtkMLAAOptions::GetDebugOutputFromString(name.c_str()))
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

//------------------------------------------------------------------------------
// The table

// Ranges of the option classes' clamped parameters.
template <typename Options, typename Getter>
void ClassRange(double range[2], Getter getMin, Getter getMax)
{
  vtkNew<Options> options;
  range[0] = ((*options).*getMin)();
  range[1] = ((*options).*getMax)();
}

const std::vector<Option> OptionTable = {
  { "--method", nullptr, nullptr, ValueKind::Name, ToolSetting, 0, nullptr, nullptr, MethodNames,
    nullptr,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Method = v.Text == "dlaa" ? MethodDLAA : MethodMLAA; },
    [](const CommandLine& d) { return MethodNames()[d.Method]; },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return "The method: mlaa (morphological antialiasing: recognises the staircases of edges "
             "and revectorises them; sharpest on still images) or dlaa (DLAA, Andreev 2011, "
             "directionally localized antialiasing: blurs each edge along its own direction; "
             "steadier in animation). The options from --threshold to --debug are MLAA's, the --dlaa-* and "
             "--long-edges ones DLAA's; giving one to the other method is an error. Default: " +
        MethodNames()[d.Method] + ".";
    } },

  { "--threshold", nullptr, "T", ValueKind::Number, ForMLAA, RefusedBeforePreset | SetByPreset,
    nullptr,
    [](double r[2])
    {
      ClassRange<vtkMLAAOptions>(
        r, &vtkMLAAOptions::GetThresholdMinValue, &vtkMLAAOptions::GetThresholdMaxValue);
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Options->SetThreshold(v.Number); },
    [](const CommandLine& d) { return Text(d.Options->GetThreshold()); },
    [](const CommandLine& d, const UsageFacts&, const std::string& range)
    {
      return Text("Smallest difference between neighbouring pixels that is an edge, with the "
                  "image's value range as 1; in ",
        range, ". Lower finds fainter edges (and noise). Default: ", d.Options->GetThreshold(),
        ".");
    } },

  { "--local-contrast", nullptr, "F", ValueKind::Number, ForMLAA,
    RefusedBeforePreset | SetByPreset, nullptr,
    [](double r[2])
    {
      ClassRange<vtkMLAAOptions>(r, &vtkMLAAOptions::GetLocalContrastFactorMinValue,
        &vtkMLAAOptions::GetLocalContrastFactorMaxValue);
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Options->SetLocalContrastFactor(v.Number); },
    [](const CommandLine& d) { return Text(d.Options->GetLocalContrastFactor()); },
    [](const CommandLine& d, const UsageFacts&, const std::string& range)
    {
      return Text("Local contrast adaptation: an edge is kept only if F times its contrast is at "
                  "least the contrast of every other boundary of its two pixels, so that faint "
                  "shading next to a strong silhouette does not cut it into pieces, and "
                  "edges inside ramps of shading (the boundaries before and after them change "
                  "the values the same way, by at least half as much) are dropped; in ",
        range, ", 0 keeps every edge above the threshold. Default: ",
        d.Options->GetLocalContrastFactor(), ".");
    } },

  { "--edges", nullptr, "MODE", ValueKind::Name, ForMLAA, RefusedBeforePreset | SetByPreset,
    "mode", nullptr, EdgeDetectionNames, DescribeEdgeDetection,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Options->SetEdgeDetection(vtkMLAAOptions::GetEdgeDetectionFromString(v.Text.c_str())); },
    [](const CommandLine& d)
    {
      return std::string(
        vtkMLAAOptions::GetEdgeDetectionAsString(d.Options->GetEdgeDetection()));
    },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("What edge detection compares (section 4.2). Default: ",
        vtkMLAAOptions::GetEdgeDetectionAsString(d.Options->GetEdgeDetection()), ".");
    } },

  { "--depth-image", nullptr, "FILE", ValueKind::Text, ForMLAA, 0, "a file name", nullptr,
    nullptr, nullptr, [](CommandLine& cl, const OptionValue& v) { cl.DepthImage = v.Text; },
    [](const CommandLine&) { return std::string("none"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    {
      return Text("The depth for --edges ",
        vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH),
        " (required there, refused otherwise): a 1-channel image of INPUT's size. "
        "Floating-point depths are used as they are, integer ones scaled to [0, 1]. Default: "
        "none.");
    } },

  { "--max-search-steps", nullptr, "N", ValueKind::Integer, ForMLAA,
    RefusedBeforePreset | SetByPreset, "an integer",
    [](double r[2])
    {
      ClassRange<vtkMLAAOptions>(r, &vtkMLAAOptions::GetMaxSearchStepsMinValue,
        &vtkMLAAOptions::GetMaxSearchStepsMaxValue);
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Options->SetMaxSearchSteps(static_cast<int>(v.Integer)); },
    [](const CommandLine& d) { return Text(d.Options->GetMaxSearchSteps()); },
    [](const CommandLine& d, const UsageFacts&, const std::string& range)
    {
      return Text("Steps of the search for the ends of each line of edges, two pixels per step "
                  "(section 4.3.1); in ",
        range, ". Default: ", d.Options->GetMaxSearchSteps(), " (lines followed up to ",
        d.Options->GetMaxDistance(), " pixels each way).");
    } },

  { "--diagonals", nullptr, nullptr, ValueKind::Name, ForMLAA, RefusedBeforePreset | SetByPreset,
    nullptr, nullptr, OnOffNames, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Options->SetDiagonalDetection(v.Text == "on"); },
    [](const CommandLine& d) { return std::string(OnOff(d.Options->GetDiagonalDetection())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Whether staircases of one-pixel steps are smoothed as 45-degree lines (on) or "
                  "only horizontal and vertical lines are followed, as in the chapter (off). "
                  "Default: ",
        OnOff(d.Options->GetDiagonalDetection()), ".");
    } },

  { "--alpha", nullptr, nullptr, ValueKind::Name, ForMLAA, 0, nullptr, nullptr, AlphaNames,
    nullptr,
    [](CommandLine& cl, const OptionValue& v)
    {
      const std::vector<std::string> names = AlphaNames();
      cl.AlphaMode =
        static_cast<int>(std::find(names.begin(), names.end(), v.Text) - names.begin());
    },
    [](const CommandLine& d) { return AlphaNames()[d.AlphaMode]; },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return "How the colours of an image with alpha relate to its alpha: straight (unassociated: "
             "PNG, TGA, TIFF that says so, and every other format) or premultiplied (associated: "
             "OpenEXR and other TIFF). With straight alpha the colours are blended premultiplied "
             "and divided again, so the colour of transparent pixels never shows as a fringe. "
             "Default: " +
        AlphaNames()[d.AlphaMode] + ", from the file.";
    } },

  { "--reconstruction", nullptr, nullptr, ValueKind::Name, ForMLAA,
    RefusedBeforePreset | SetByPreset, nullptr, nullptr, OnOffNames, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Options->SetReconstruction(v.Text == "on"); },
    [](const CommandLine& d) { return std::string(OnOff(d.Options->GetReconstruction())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Topological reconstruction (Biri et al., section 4) before edge detection: a "
                  "pixel where point sampling broke a thin shape (a wire, a streamline, an "
                  "iso-line) in two moves towards the shape's colour by the share of the shape "
                  "that covers it. Line ends, dots, corners and the space between lines passing "
                  "close by are left alone. Default: ",
        OnOff(d.Options->GetReconstruction()), ".");
    } },

  { "--preset", nullptr, "NAME", ValueKind::Name, ForMLAA, IsPreset, "preset", nullptr,
    PresetNames, DescribePreset,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Options->SetPreset(vtkMLAAOptions::GetPresetFromString(v.Text.c_str())); },
    [](const CommandLine& d)
    { return std::string(vtkMLAAOptions::GetPresetAsString(d.Options->GetPreset())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Set every quality option (--threshold, --local-contrast, --edges, "
                  "--max-search-steps, --diagonals, --corners, --dominant-blending, "
                  "--reconstruction) at "
                  "once; those options may follow it to override it, but not precede it. "
                  "Default: ",
        vtkMLAAOptions::GetPresetAsString(d.Options->GetPreset()),
        " (the defaults above). The README lists what each costs and gains.");
    } },

  { "--corners", nullptr, nullptr, ValueKind::Name, ForMLAA, RefusedBeforePreset | SetByPreset,
    nullptr, nullptr, OnOffNames, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Options->SetCornerExtrapolation(v.Text == "on"); },
    [](const CommandLine& d) { return std::string(OnOff(d.Options->GetCornerExtrapolation())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Whether a line that ends at a corner of a shape or at the image border takes "
                  "its height there from the staircase seen at its other end (on), or every "
                  "crossing edge is read as a one-pixel step, as in the chapter (off). Default: ",
        OnOff(d.Options->GetCornerExtrapolation()), ".");
    } },

  { "--dominant-blending", nullptr, nullptr, ValueKind::Name, ForMLAA,
    RefusedBeforePreset | SetByPreset, nullptr, nullptr, OnOffNames, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Options->SetDominantDirectionBlending(v.Text == "on"); },
    [](const CommandLine& d)
    { return std::string(OnOff(d.Options->GetDominantDirectionBlending())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Whether a pixel on the corner of a staircase is blended along its dominant "
                  "line only (on, as SMAA does) or with every neighbour's share averaged, as in "
                  "the chapter (off). Default: ",
        OnOff(d.Options->GetDominantDirectionBlending()), ".");
    } },

  { "--debug", nullptr, "IMAGE", ValueKind::Name, ForMLAA, 0, "output", nullptr, DebugOutputNames,
    DescribeDebugOutput,
    [](CommandLine& cl, const OptionValue& v)
    { cl.Options->SetDebugOutput(vtkMLAAOptions::GetDebugOutputFromString(v.Text.c_str())); },
    [](const CommandLine& d)
    { return std::string(vtkMLAAOptions::GetDebugOutputAsString(d.Options->GetDebugOutput())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("Write an intermediate image instead of the antialiased one, as 8-bit RGBA (all "
                  "but ",
        vtkMLAAOptions::GetDebugOutputAsString(vtkMLAAOptions::NO_DEBUG_OUTPUT), "). Default: ",
        vtkMLAAOptions::GetDebugOutputAsString(d.Options->GetDebugOutput()), ".");
    } },

  { "--dlaa-epsilon", nullptr, "E", ValueKind::Number, ForDLAA, RefusedBeforePreset, nullptr,
    [](double r[2])
    {
      ClassRange<vtkDLAAOptions>(
        r, &vtkDLAAOptions::GetEpsilonMinValue, &vtkDLAAOptions::GetEpsilonMaxValue);
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.DLAAOptions->SetEpsilon(v.Number); },
    [](const CommandLine& d) { return Text(d.DLAAOptions->GetEpsilon()); },
    [](const CommandLine& d, const UsageFacts&, const std::string& range)
    {
      return Text("DLAA: the offset of the contrast curve that turns an edge's high-pass response "
                  "into a blend weight (saturate(lambda * response - epsilon)); in ",
        range, ". Responses below epsilon / lambda are left alone. Default: ",
        d.DLAAOptions->GetEpsilon(), ".");
    } },

  { "--dlaa-lambda", nullptr, "L", ValueKind::Number, ForDLAA, RefusedBeforePreset, nullptr,
    [](double r[2])
    {
      ClassRange<vtkDLAAOptions>(
        r, &vtkDLAAOptions::GetLambdaMinValue, &vtkDLAAOptions::GetLambdaMaxValue);
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.DLAAOptions->SetLambda(v.Number); },
    [](const CommandLine& d) { return Text(d.DLAAOptions->GetLambda()); },
    [](const CommandLine& d, const UsageFacts&, const std::string& range)
    {
      return Text("DLAA: the gain of that contrast curve; in ", range,
        ". Higher blends more. Default: ", d.DLAAOptions->GetLambda(), ".");
    } },

  { "--dlaa-luma", nullptr, "NAME", ValueKind::Name, ForDLAA, RefusedBeforePreset,
    "luminosity function", nullptr, LumaFunctionNames, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    { cl.DLAAOptions->SetLumaFunction(vtkDLAAOptions::GetLumaFunctionFromString(v.Text.c_str())); },
    [](const CommandLine& d)
    {
      return std::string(
        vtkDLAAOptions::GetLumaFunctionAsString(d.DLAAOptions->GetLumaFunction()));
    },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("DLAA: the luminosity function, ",
        vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::REC709),
        " (0.2126 R + 0.7152 G + 0.0722 B) or ",
        vtkDLAAOptions::GetLumaFunctionAsString(vtkDLAAOptions::GREEN),
        " (the green channel). Default: ",
        vtkDLAAOptions::GetLumaFunctionAsString(d.DLAAOptions->GetLumaFunction()), ".");
    } },

  { "--long-edges", nullptr, nullptr, ValueKind::Name, ForDLAA, RefusedBeforePreset, nullptr,
    nullptr, OnOffNames, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.DLAAOptions->SetLongEdges(v.Text == "on"); },
    [](const CommandLine& d) { return std::string(OnOff(d.DLAAOptions->GetLongEdges())); },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("DLAA: whether long horizontal and vertical edges get the wide, "
                  "colour-preserving step (on) or only the 5-pixel blurs (off). Default: ",
        OnOff(d.DLAAOptions->GetLongEdges()), ".");
    } },

  { "--value-range", nullptr, "LO HI|auto", ValueKind::ValueRange, ForBothMethods, 0, nullptr,
    nullptr, nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    {
      cl.ValueRangeMode = v.Auto ? ValueRangeAuto : ValueRangeGiven;
      if (!v.Auto)
      {
        cl.ValueRange[0] = v.Range[0];
        cl.ValueRange[1] = v.Range[1];
      }
    },
    [](const CommandLine& d)
    {
      return Text("the pixel type's range (", d.ValueRange[0], " ", d.ValueRange[1],
        " for floating point)");
    },
    [](const CommandLine& d, const UsageFacts&, const std::string&)
    {
      return Text("The values taken as 0 and 1 by edge detection (and, for floating-point images, "
                  "when writing to an integer format), for every pixel type. Default: the range "
                  "of the pixel type for integer images (0 to 255, 0 to 65535), ",
        d.ValueRange[0], " ", d.ValueRange[1],
        " for floating point. 'auto': the image's own smallest and largest value, for data that "
        "uses part of its type (10-, 12- or 14-bit values in 16-bit files).");
    } },

  { "--max-pixels", nullptr, "N", ValueKind::Count, ToolSetting, 0, nullptr, nullptr, nullptr,
    nullptr, [](CommandLine& cl, const OptionValue& v) { cl.MaxPixels = v.Count; },
    [](const CommandLine&) { return std::string("what fits in half of the memory available"); },
    [](const CommandLine&, const UsageFacts& facts, const std::string&)
    {
      return Text("The largest image, in pixels (width x height), that INPUT and the depth image "
                  "may be; checked from the file's header before anything is allocated. Default: "
                  "what fits in half of the memory available now (about ",
        facts.DefaultMaxPixels,
        " RGBA 8-bit pixels), shared by the files a batch processes at the same time.");
    } },

  { "--format", nullptr, "NAME", ValueKind::Text, ToolSetting, 0, "a format name", nullptr,
    nullptr, nullptr, [](CommandLine& cl, const OptionValue& v) { cl.Format = v.Text; },
    [](const CommandLine&) { return std::string("OUTPUT's extension"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    {
      return std::string(
        "The format OUTPUT is written in, as an OpenImageIO format name or extension (png, tif, "
        "exr, jpg, ...); needed when OUTPUT is - (standard output). INPUT - is standard input, "
        "its format found from its bytes; with -, the whole image is read before antialiasing "
        "starts, and written to standard output only once it is complete. Not for batches. "
        "Default: OUTPUT's extension.");
    } },

  { "--output-dir", nullptr, "DIR", ValueKind::Text, ToolSetting, 0, "a directory name", nullptr,
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    {
      cl.OutputDirectory = v.Text;
      cl.Batch = true;
    },
    [](const CommandLine&) { return std::string("off (INPUT OUTPUT)"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    {
      return std::string(
        "Batch: antialias every INPUT into the existing directory DIR, each output with its "
        "input's file name and format. Files are processed side by side on every core, each "
        "exactly as alone; one that fails is reported and the others go on. Refused if an "
        "output would replace an input, or two inputs have the same name. Default: off "
        "(INPUT OUTPUT).");
    } },

  { "--frames", nullptr, "RANGE", ValueKind::Text, ToolSetting, BatchOnly, "a frame range",
    nullptr, nullptr, nullptr, [](CommandLine& cl, const OptionValue& v) { cl.Frames = v.Text; },
    [](const CommandLine&) { return std::string("every existing file of the sequence"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    {
      return std::string(
        "Batch: the frames of a numbered-sequence INPUT, in OpenImageIO's notation: 1-100, "
        "1-100x2 (every second), 1,5,9. A sequence INPUT is a name that is not an existing "
        "file and has a frame number pattern: %04d, # (four digits) or @ (one digit per @), "
        "as in frame.%04d.png or frame.#.png; the range may also be part of the name "
        "(frame.1-100#.png). Default: every existing file of the sequence.");
    } },

  { "--jobs", nullptr, "N", ValueKind::Integer, ToolSetting, BatchOnly, "an integer",
    [](double r[2])
    {
      r[0] = 1;
      r[1] = 1024;
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v) { cl.Jobs = static_cast<int>(v.Integer); },
    [](const CommandLine&) { return std::string("the number of processors"); },
    [](const CommandLine&, const UsageFacts& facts, const std::string&)
    {
      return Text("Batch: files processed at the same time. Default: the number of processors "
                  "this process may use (",
        facts.Processors, " here).");
    } },

  { "--quiet", "-q", nullptr, ValueKind::None, ToolSetting, BatchOnly, nullptr, nullptr, nullptr,
    nullptr, [](CommandLine& cl, const OptionValue&) { cl.Quiet = true; },
    [](const CommandLine&) { return std::string("off"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    {
      return std::string("Batch: no progress display (a bar on a terminal, else one line per "
                         "file done); warnings and errors still show. Default: off.");
    } },

  { "--area-texture", nullptr, "D", ValueKind::Integer, ToolSetting, 0, "a cell size",
    [](double r[2])
    {
      // D = MaxDistance + 1 texels per cell side.
      vtkNew<vtkMLAAAreaTexture> texture;
      r[0] = texture->GetMaxDistanceMinValue() + 1;
      r[1] = texture->GetMaxDistanceMaxValue() + 1;
    },
    nullptr, nullptr,
    [](CommandLine& cl, const OptionValue& v)
    { cl.AreaTextureCellSize = static_cast<int>(v.Integer); },
    [](const CommandLine&) { return std::string("off"); },
    [](const CommandLine&, const UsageFacts&, const std::string& range)
    {
      return "Write the area texture of section 4.3.3 (Figure 4.2) to OUTPUT instead, for cells "
             "of D texels (D = 2 * search steps + 1: 9, 17, 33, ...; D in " +
        range +
        "): an 8-bit RGB image of 5D x 5D texels whose texel (D*e1 + left, D*e2 + right), "
        "counted from the top left, holds the two areas times 255 in red and green. Takes no "
        "INPUT and no other option. Default: off.";
    } },

  { "--help", "-h", nullptr, ValueKind::Help, ToolSetting, 0, nullptr, nullptr, nullptr, nullptr,
    [](CommandLine& cl, const OptionValue&) { cl.Help = true; },
    [](const CommandLine&) { return std::string("off"); },
    [](const CommandLine&, const UsageFacts&, const std::string&)
    { return std::string("Print this help and exit."); } },
};

//------------------------------------------------------------------------------
// Values

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

// "--edges: unknown mode 'x' (expected one of luma, color, depth, lab)", or, for options whose
// names are not nouns, "--diagonals: 'x' is neither on nor off".
std::string BadNameMessage(
  const Option& option, const std::string& name, const std::string& text)
{
  const std::vector<std::string> names = option.Names();
  const bool two = names.size() == 2;
  if (option.Noun)
  {
    return name + ": unknown " + option.Noun + " '" + text + "' (expected " +
      (two ? names[0] + " or " + names[1] : "one of " + Join(names, ", ")) + ")";
  }
  return name + ": '" + text + "' is " +
    (two ? "neither " + names[0] + " nor " + names[1] : "not one of " + Join(names, ", "));
}

// `text` in a Markdown table cell: '|' (even in code spans) escaped.
std::string EscapeCell(const std::string& text)
{
  std::string escaped;
  for (char c : text)
  {
    escaped += c == '|' ? std::string("\\|") : std::string(1, c);
  }
  return escaped;
}

// The label of an option in the usage: "-q, --quiet", "--threshold T", "--diagonals on|off".
std::string Label(const Option& option)
{
  std::string label = option.ShortName ? std::string(option.ShortName) + ", " : "";
  label += option.Name;
  if (option.Value)
  {
    label += std::string(" ") + option.Value;
  }
  else if (option.Names)
  {
    label += " " + Join(option.Names(), "|");
  }
  return label;
}
} // namespace

//------------------------------------------------------------------------------
CommandLine::CommandLine()
  : Options(vtkSmartPointer<vtkMLAAOptions>::New())
  , DLAAOptions(vtkSmartPointer<vtkDLAAOptions>::New())
{
  vtkNew<vtkImageMLAA> defaultFilter;
  defaultFilter->GetValueRange(this->ValueRange);
}

//------------------------------------------------------------------------------
const std::vector<Option>& GetOptions()
{
  return OptionTable;
}

//------------------------------------------------------------------------------
const Option* FindOption(const std::string& name)
{
  for (const Option& option : OptionTable)
  {
    if (name == option.Name || (option.ShortName && name == option.ShortName))
    {
      return &option;
    }
  }
  return nullptr;
}

//------------------------------------------------------------------------------
std::string GetRangeText(const Option& option)
{
  if (!option.Range)
  {
    return "";
  }
  double range[2];
  option.Range(range);
  return Text("[", range[0], ", ", range[1], "]");
}

//------------------------------------------------------------------------------
void ApplyOption(const Option& option, const std::string& name,
  const std::vector<std::string>& values, CommandLine& cl)
{
  OptionValue value;
  value.Text = values.empty() ? std::string() : values[0];
  const std::string& text = value.Text;
  double range[2] = { 0.0, 0.0 };
  if (option.Range)
  {
    option.Range(range);
  }
  switch (option.Kind)
  {
    case ValueKind::Number:
      if (!ParseDouble(text, value.Number) || value.Number < range[0] || value.Number > range[1])
      {
        throw UsageError(
          name + ": '" + text + "' is not a number in " + GetRangeText(option));
      }
      break;
    case ValueKind::Integer:
      if (!ParseInt(text, value.Integer) || value.Integer < range[0] || value.Integer > range[1])
      {
        throw UsageError(name + ": '" + text + "' is not " + option.Noun + " in [" +
          std::to_string(static_cast<long>(range[0])) + ", " +
          std::to_string(static_cast<long>(range[1])) + "]");
      }
      break;
    case ValueKind::Count:
    {
      char* end = nullptr;
      errno = 0;
      value.Count = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || *end != '\0' || errno != 0 || value.Count == 0)
      {
        throw UsageError(name + ": '" + text + "' is not a positive integer");
      }
      break;
    }
    case ValueKind::Name:
    {
      const std::vector<std::string> names = option.Names();
      if (std::find(names.begin(), names.end(), text) == names.end())
      {
        throw UsageError(BadNameMessage(option, name, text));
      }
      break;
    }
    case ValueKind::Text:
      if (text.empty())
      {
        throw UsageError(name + " needs " + option.Noun);
      }
      break;
    case ValueKind::ValueRange:
      value.Auto = values.size() == 1 && text == "auto";
      if (!value.Auto &&
        (values.size() != 2 || !ParseDouble(values[0], value.Range[0]) ||
          !ParseDouble(values[1], value.Range[1]) || !(value.Range[0] < value.Range[1])))
      {
        throw UsageError(name + ": '" + Join(values, " ") +
          "' is neither two finite numbers LO < HI nor 'auto'");
      }
      break;
    case ValueKind::None:
    case ValueKind::Help:
      break;
  }
  if (option.Flags & IsPreset)
  {
    // A quality option before the preset would be silently replaced by it.
    for (const std::string& given : cl.FilterOptions)
    {
      const Option* earlier = FindOption(given);
      if (earlier && (earlier->Flags & RefusedBeforePreset))
      {
        throw UsageError(
          name + " sets " + given + " too: put " + name + " before the options that override it");
      }
    }
  }
  option.Apply(cl, value);
}

//------------------------------------------------------------------------------
void ParseCommandLine(const std::vector<std::string>& args, CommandLine& cl)
{
  // Help wins over everything else on the line.
  for (const std::string& arg : args)
  {
    if (arg == "--")
    {
      break;
    }
    const Option* option = FindOption(arg);
    if (option && option->Kind == ValueKind::Help)
    {
      option->Apply(cl, OptionValue());
      return;
    }
  }

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
    const Option* option = FindOption(name);
    if (!option)
    {
      throw UsageError("unknown option '" + arg + "'");
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

    std::vector<std::string> values;
    if (option->Kind == ValueKind::None)
    {
      if (hasInlineValue)
      {
        throw UsageError(name + " takes no value");
      }
    }
    else if (option->Kind == ValueKind::ValueRange &&
      ((hasInlineValue && inlineValue == "auto") ||
        (!hasInlineValue && i + 1 < args.size() && args[i + 1] == "auto")))
    {
      // "auto" is not counted among the filter options given (--area-texture takes it).
      i += hasInlineValue ? 0 : 1;
      ApplyOption(*option, name, { "auto" }, cl);
      continue;
    }
    else
    {
      values = takeValues(option->Kind == ValueKind::ValueRange ? 2 : 1);
    }
    ApplyOption(*option, name, values, cl);

    if (option->Flags & BatchOnly)
    {
      cl.BatchOnly.push_back(name);
    }
    if (option->Methods == ToolSetting)
    {
      continue;
    }
    cl.FilterOptions.push_back(name);
    if (option->Methods == ForDLAA)
    {
      cl.DLAAOnly.push_back(name);
    }
    else if (option->Methods == ForMLAA)
    {
      cl.MLAAOnly.push_back(name);
    }
  }

  // What goes with what.
  if (!cl.Batch && !cl.BatchOnly.empty())
  {
    throw UsageError(cl.BatchOnly.front() + " is an option of batches: add --output-dir DIR");
  }
  if (!cl.Format.empty() && cl.Batch)
  {
    throw UsageError("--format cannot be used with --output-dir (a batch writes each output in "
                     "its input's format)");
  }
  if (cl.Batch && std::find(cl.Files.begin(), cl.Files.end(), "-") != cl.Files.end())
  {
    throw UsageError("- (standard input) cannot be an INPUT of a batch (--output-dir)");
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
    if (cl.Files[0] == "-" && cl.Format.empty())
    {
      throw UsageError("OUTPUT - (standard output) needs --format NAME, e.g. --format png");
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
  if (!cl.Batch && cl.Files.back() == "-" && cl.Format.empty())
  {
    throw UsageError("OUTPUT - (standard output) needs --format NAME, e.g. --format png");
  }
  if (!cl.Batch && cl.Files[0] == "-" && cl.DepthImage == "-")
  {
    throw UsageError("INPUT and --depth-image cannot both be - (standard input)");
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
void PrintUsage(std::ostream& os, const UsageFacts& facts)
{
  // Defaults and ranges are those of the classes, not copies of them.
  const CommandLine defaults;
  const size_t column = 25;

  os << "Usage: mlaa [options] INPUT OUTPUT\n"
        "       mlaa [options] --output-dir DIR INPUT...\n"
        "       mlaa --area-texture D OUTPUT\n"
        "\n";
  PrintWrapped(os, "", 0,
    "Removes staircase aliasing from the image INPUT with morphological antialiasing (MLAA: "
    "Jimenez et al., \"Practical Morphological Antialiasing\", GPU Pro 2, chapter 4; VTK's "
    "vtkImageMLAA), or with DLAA (--method dlaa; Andreev 2011, directionally localized "
    "antialiasing, not the learned method of the same initials; VTK's vtkImageDLAA), and writes "
    "the result to OUTPUT.");
  os << "\n";
  PrintWrapped(os, "", 0,
    "INPUT may be any image OpenImageIO reads (PNG, TIFF, OpenEXR, JPEG, ...): 8- or 16-bit, "
    "half or float, with 1 to 4 channels (grey, grey + alpha, RGB, RGBA); only its first "
    "subimage is read. OUTPUT's format comes from its extension, or from --format. Either may be "
    "- (standard input or output; see --format). OUTPUT has INPUT's size, "
    "channels and pixel type; where its format cannot hold that type, OpenImageIO's closest "
    "type is written and a warning says so (floating-point values written as integers are "
    "scaled by --value-range and clamped). Pixels are used as stored: no colour-space "
    "conversion, alpha is kept as the file stores it (see --alpha), and pixels away from "
    "edges are written unchanged.");
  os << "\nOptions:\n";

  for (const Option& option : OptionTable)
  {
    PrintWrapped(
      os, "  " + Label(option), column, option.Help(defaults, facts, GetRangeText(option)));
    if (option.DescribeName)
    {
      for (const std::string& name : option.Names())
      {
        PrintWrapped(
          os, std::string(column + 2, ' ') + name + ":", column + 4, option.DescribeName(name));
      }
    }
  }

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
    "went wrong\". If a library crashes, a line saying so and what the library printed are "
    "shown, and no temporary file is left behind.");
}

//------------------------------------------------------------------------------
void PrintOptionsMarkdown(std::ostream& os)
{
  const CommandLine defaults;
  os << "| Option | Value | Method | Default |\n"
        "| --- | --- | --- | --- |\n";
  for (const Option& option : OptionTable)
  {
    std::string value;
    switch (option.Kind)
    {
      case ValueKind::Number:
        value = "a number in " + GetRangeText(option);
        break;
      case ValueKind::Integer:
        value = "an integer in " + GetRangeText(option);
        break;
      case ValueKind::Count:
        value = "a positive integer";
        break;
      case ValueKind::Name:
        value = "`" + Join(option.Names(), "`, `") + "`";
        break;
      case ValueKind::Text:
        value = std::string(option.Noun);
        break;
      case ValueKind::ValueRange:
        value = "`LO HI` (LO < HI) or `auto`";
        break;
      case ValueKind::None:
      case ValueKind::Help:
        value = "none";
        break;
    }
    const char* methods[] = { "the tool", "mlaa", "dlaa", "both" };
    std::string label = option.ShortName ? std::string("`") + option.ShortName + "`, " : "";
    label += std::string("`") + option.Name +
      (option.Value ? std::string(" ") + option.Value : std::string()) + "`";
    os << "| " << EscapeCell(label) << " | " << EscapeCell(value) << " | "
       << methods[option.Methods] << " | " << EscapeCell(option.Default(defaults)) << " |\n";
  }
}
} // namespace mlaa
