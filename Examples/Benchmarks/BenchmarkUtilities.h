// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Small helpers shared by the benchmark programs of Examples/Benchmarks: command-line parsing
// (scene lists included), a stopwatch, order statistics, and the seeded colours and PNG writing of
// the synthetic image sets. Header-only; not part of any library.
#ifndef BenchmarkUtilities_h
#define BenchmarkUtilities_h

#include "mlaaOptionTable.h"
#include "vtkMLAAScenes.h"

#include "vtkImageData.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <ctime>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace mlaaBenchmark
{
// Parses "WxH" (for example "1920x1080") into positive width and height.
inline bool ParseSize(const std::string& text, int& width, int& height)
{
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos)
  {
    return false;
  }
  char* end = nullptr;
  const long w = std::strtol(text.c_str(), &end, 10);
  if (end != text.c_str() + x)
  {
    return false;
  }
  const long h = std::strtol(text.c_str() + x + 1, &end, 10);
  if (*end != '\0' || w < 1 || h < 1 || w > 16384 || h > 16384)
  {
    return false;
  }
  width = static_cast<int>(w);
  height = static_cast<int>(h);
  return true;
}

// Parses a positive integer.
inline bool ParsePositive(const std::string& text, int& value)
{
  char* end = nullptr;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || v < 1 || v > 1000000)
  {
    return false;
  }
  value = static_cast<int>(v);
  return true;
}

// Parses a finite number in [lo, hi].
inline bool ParseNumber(const std::string& text, double lo, double hi, double& value)
{
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(v >= lo && v <= hi))
  {
    return false;
  }
  value = v;
  return true;
}

// The MLAA settings the benchmarks take: the options of the `mlaa` tool that --preset sets, and
// --preset, from the tool's option table (Apps/mlaa/mlaaOptionTable.h), with the same values,
// ranges and defaults. Not --edges depth: the benchmarks have no depth image.
inline bool IsBenchmarkOption(const mlaa::Option& option)
{
  return (option.Flags & (mlaa::SetByPreset | mlaa::IsPreset)) != 0;
}

inline bool IsDepthEdges(const std::string& name, const std::string& value)
{
  return name == "--edges" &&
    value == vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH);
}

// Those settings, for the benchmarks' usage text.
inline std::string MLAAOptionsUsage()
{
  std::ostringstream usage;
  usage << "MLAA settings (vtkMLAAOptions; default: the library's defaults; mlaa --help says "
           "more):\n";
  for (const mlaa::Option& option : mlaa::GetOptions())
  {
    if (!IsBenchmarkOption(option))
    {
      continue;
    }
    std::string values;
    if (option.Names)
    {
      for (const std::string& name : option.Names())
      {
        values += IsDepthEdges(option.Name, name) ? "" : (values.empty() ? "" : "|") + name;
      }
    }
    std::string line =
      std::string("  ") + option.Name + " " + (option.Value ? option.Value : values);
    std::string about = option.Range ? "in " + mlaa::GetRangeText(option)
      : option.Value                 ? "one of " + values
                                     : std::string();
    if (option.Flags & mlaa::IsPreset)
    {
      about += "; every other setting at once (put it first)";
    }
    if (!about.empty())
    {
      line.resize(std::max<std::size_t>(line.size() + 1, 28), ' ');
    }
    usage << line << about << "\n";
  }
  return usage.str();
}

// If argv[i] is one of the MLAA settings above with a valid value, applies it to `options`,
// moves i to the value and returns true; otherwise returns false and leaves i alone.
inline bool ParseMLAAOption(int argc, char* argv[], int& i, vtkMLAAOptions* options)
{
  if (i + 1 >= argc)
  {
    return false;
  }
  const std::string name = argv[i];
  const std::string value = argv[i + 1];
  const mlaa::Option* option = mlaa::FindOption(name);
  if (!option || !IsBenchmarkOption(*option) || IsDepthEdges(name, value))
  {
    return false;
  }
  mlaa::CommandLine settings;
  settings.Options = options;
  try
  {
    mlaa::ApplyOption(*option, name, { value }, settings);
  }
  catch (const mlaa::UsageError&)
  {
    return false;
  }
  ++i;
  return true;
}

// One line describing the MLAA settings in use.
inline std::string DescribeMLAAOptions(vtkMLAAOptions* options)
{
  std::ostringstream text;
  text << "MLAA settings: threshold " << options->GetThreshold() << ", edges "
       << vtkMLAAOptions::GetEdgeDetectionAsString(options->GetEdgeDetection())
       << ", max search steps " << options->GetMaxSearchSteps() << ", diagonals "
       << (options->GetDiagonalDetection() ? "on" : "off") << ", local contrast factor "
       << options->GetLocalContrastFactor() << ", corner extrapolation "
       << (options->GetCornerExtrapolation() ? "on" : "off") << ", dominant-direction blending "
       << (options->GetDominantDirectionBlending() ? "on" : "off") << ", reconstruction "
       << (options->GetReconstruction() ? "on" : "off") << " (preset "
       << vtkMLAAOptions::GetPresetAsString(options->GetPreset()) << ")";
  return text.str();
}

// Variants of the MLAA settings that the benchmarks measure besides the settings given: each
// feature of "Morphological antialiasing and topological reconstruction" alone over the medium
// preset (luma edges, 8 steps: the chapter's edge detection and search length), the three
// together over it, and each preset.
struct Variant
{
  std::string Name;
  std::function<void(vtkMLAAOptions*)> Configure;
};
const std::vector<Variant>& Variants()
{
  static const std::vector<Variant> variants = {
    { "+lab",
      [](vtkMLAAOptions* o)
      {
        o->SetPresetToMedium();
        o->SetEdgeDetectionToLab();
      } },
    { "+steps32",
      [](vtkMLAAOptions* o)
      {
        o->SetPresetToMedium();
        o->SetMaxSearchSteps(32);
      } },
    { "+steps128",
      [](vtkMLAAOptions* o)
      {
        o->SetPresetToMedium();
        o->SetMaxSearchSteps(128);
      } },
    { "+recon",
      [](vtkMLAAOptions* o)
      {
        o->SetPresetToMedium();
        o->ReconstructionOn();
      } },
    { "+all3",
      [](vtkMLAAOptions* o)
      {
        o->SetPresetToMedium();
        o->SetEdgeDetectionToLab();
        o->SetMaxSearchSteps(128);
        o->ReconstructionOn();
      } },
    { "P-low", [](vtkMLAAOptions* o) { o->SetPresetToLow(); } },
    { "P-medium", [](vtkMLAAOptions* o) { o->SetPresetToMedium(); } },
    { "P-high", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); } },
    { "P-ultra", [](vtkMLAAOptions* o) { o->SetPresetToUltra(); } },
    { "P-max", [](vtkMLAAOptions* o) { o->SetPresetToMax(); } },
  };
  return variants;
}

// Splits "a,b,c" into its non-empty items.
inline std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}

// The scenes of a --scenes list: "all" and "held-out" stand for vtkMLAAScenes' two lists.
inline std::vector<std::string> SceneList(const std::string& text)
{
  std::vector<std::string> scenes;
  for (const std::string& name : SplitList(text))
  {
    const std::vector<std::string> group = name == "all" ? vtkMLAAScenes::Names()
      : name == "held-out"                               ? vtkMLAAScenes::HeldOutNames()
                                                         : std::vector<std::string>{ name };
    scenes.insert(scenes.end(), group.begin(), group.end());
  }
  return scenes;
}

// Uniform numbers from the 32-bit Mersenne twister's raw output (whose sequence the standard
// fixes), so that the synthetic sets are the same with every standard library.
class Random
{
public:
  explicit Random(std::uint32_t seed)
    : Engine(seed)
  {
  }
  double Uniform(double lo, double hi)
  {
    return lo + (hi - lo) * (static_cast<double>(this->Engine()) / 4294967296.0);
  }
  int Integer(int lo, int hi) { return std::min(hi, static_cast<int>(this->Uniform(lo, hi + 1))); }

private:
  std::mt19937 Engine;
};

inline std::array<int, 3> RandomColour(Random& random)
{
  return { random.Integer(0, 255), random.Integer(0, 255), random.Integer(0, 255) };
}

// A colour whose largest channel difference from `base` is `contrast` (or as near as the range
// allows).
inline std::array<int, 3> Contrasting(Random& random, const std::array<int, 3>& base, int contrast)
{
  std::array<int, 3> colour;
  const int strongest = random.Integer(0, 2);
  for (int c = 0; c < 3; ++c)
  {
    const double share = c == strongest ? 1.0 : random.Uniform(0.0, 1.0);
    int delta = static_cast<int>(std::lround(share * contrast));
    if (base[c] + delta > 255 && base[c] - delta >= 0)
    {
      delta = -delta;
    }
    else if (base[c] + delta <= 255 && base[c] - delta >= 0 && random.Uniform(0, 1) < 0.5)
    {
      delta = -delta;
    }
    colour[c] = std::min(255, std::max(0, base[c] + delta));
  }
  return colour;
}

inline void WritePNG(vtkImageData* data, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(data);
  writer->SetFileName(path.c_str());
  writer->Write();
}

// Wall-clock stopwatch in milliseconds (steady clock).
class Stopwatch
{
public:
  void Start() { this->Begin = std::chrono::steady_clock::now(); }
  double Milliseconds() const
  {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - this->Begin)
      .count();
  }

private:
  std::chrono::steady_clock::time_point Begin = std::chrono::steady_clock::now();
};

// CPU time of the whole process (every thread) in milliseconds. With Mesa's llvmpipe the GL work
// runs on the process's own threads, so a frame's CPU time is its cost there; unlike wall-clock
// time it hardly grows when other processes share the cores. It does not count work done by a
// GPU: use it on llvmpipe only.
class CpuStopwatch
{
public:
  double Milliseconds() const { return Now() - this->Begin; }

private:
  static double Now()
  {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
  }
  double Begin = Now();
};

// The q-quantile (0 = min, 0.5 = median, 1 = max) of `values`, linear interpolation.
inline double Quantile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const double position = q * (values.size() - 1);
  const std::size_t below = static_cast<std::size_t>(position);
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double t = position - below;
  return values[below] * (1.0 - t) + values[above] * t;
}

inline double Median(const std::vector<double>& values)
{
  return Quantile(values, 0.5);
}

// The "OpenGL renderer string" line of the window's capabilities (after a first render), so the
// output says what rasterised the frames.
inline std::string OpenGLRenderer(vtkRenderWindow* window)
{
  const char* report = window->ReportCapabilities();
  std::stringstream stream(report ? report : "");
  std::string line;
  while (std::getline(stream, line))
  {
    if (line.find("renderer string") != std::string::npos)
    {
      const std::size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(colon + 1);
    }
  }
  return "unknown";
}

// A note for output taken on Mesa's software rasteriser.
inline void PrintRasteriserNote(const std::string& renderer)
{
  std::cout << "OpenGL renderer:" << renderer << std::endl;
  if (renderer.find("llvmpipe") != std::string::npos ||
    renderer.find("softpipe") != std::string::npos)
  {
    std::cout << "NOTE: llvmpipe is Mesa's CPU rasteriser: 'GPU' work runs on the CPU cores here, "
                 "so GPU timings are not representative of graphics hardware."
              << std::endl;
  }
}
}

#endif
