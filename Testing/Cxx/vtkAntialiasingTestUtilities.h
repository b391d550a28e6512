// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the vtkMLAA tests: building small images, running the filter, and strict
// image comparisons (VTK's regression comparison is too loose to show that antialiasing ran; see
// the project's ENVIRONMENT notes).
#ifndef vtkAntialiasingTestUtilities_h
#define vtkAntialiasingTestUtilities_h

#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkExtentTranslator.h"
#include "vtkDLAAOptions.h"
#include "vtkImageAntialiasingAlgorithm.h"
#include "vtkImageDLAA.h"
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <string>
#include <vector>

namespace vtkMLAATest
{
// Counts failed checks; a test returns Result() at the end.
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline bool Check(bool ok, const char* what, const char* file, int line)
{
  if (!ok)
  {
    std::cerr << file << ":" << line << ": check failed: " << what << std::endl;
    ++Failures();
  }
  return ok;
}

inline int Result()
{
  if (Failures())
  {
    std::cerr << Failures() << " check(s) failed" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}

// An image of the given size, type and components, every value `fill`.
inline vtkSmartPointer<vtkImageData> MakeImage(
  int width, int height, int components, int type = VTK_UNSIGNED_CHAR, double fill = 0.0, int depth = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, depth);
  image->AllocateScalars(type, components);
  image->GetPointData()->GetScalars()->Fill(fill);
  return image;
}

// Sets every component of pixel (x, y, z) from `f(x, y, z, component)`.
inline void FillImage(vtkImageData* image, const std::function<double(int, int, int, int)>& f)
{
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* s = image->GetPointData()->GetScalars();
  const int c = s->GetNumberOfComponents();
  for (int z = 0; z < dims[2]; ++z)
  {
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const vtkIdType id = (static_cast<vtkIdType>(z) * dims[1] + y) * dims[0] + x;
        for (int k = 0; k < c; ++k)
        {
          s->SetComponent(id, k, f(x, y, z, k));
        }
      }
    }
  }
}

inline double GetValue(vtkImageData* image, int x, int y, int component = 0, int z = 0)
{
  return image->GetScalarComponentAsDouble(x, y, z, component);
}

// Whether the (2 radius + 1)^2 neighbourhood of pixel (x, y) (clamped to the image) holds one
// value within `tolerance`, in component `component` or, when it is -1, in every component.
inline bool IsFlatAround(vtkImageData* image, int x, int y, int radius = 2, double tolerance = 0.0,
  int component = -1)
{
  int dims[3];
  image->GetDimensions(dims);
  const int first = component < 0 ? 0 : component;
  const int last = component < 0 ? image->GetNumberOfScalarComponents() - 1 : component;
  for (int dy = -radius; dy <= radius; ++dy)
  {
    for (int dx = -radius; dx <= radius; ++dx)
    {
      const int nx = std::min(std::max(x + dx, 0), dims[0] - 1);
      const int ny = std::min(std::max(y + dy, 0), dims[1] - 1);
      for (int k = first; k <= last; ++k)
      {
        if (std::abs(GetValue(image, nx, ny, k) - GetValue(image, x, y, k)) > tolerance)
        {
          return false;
        }
      }
    }
  }
  return true;
}

// The value after `flag` on a test's command line (-I, -V, -T), or "" when absent.
inline std::string Argument(int argc, char* argv[], const char* flag)
{
  for (int i = 1; i + 1 < argc; ++i)
  {
    if (std::strcmp(argv[i], flag) == 0)
    {
      return argv[i + 1];
    }
  }
  return std::string();
}

// Sets how a streamer splits an image into pieces: 0 blocks, 1 x slabs, 2 y slabs.
inline void SetSplitMode(vtkExtentTranslator* translator, int mode)
{
  if (mode == 0)
  {
    translator->SetSplitModeToBlock();
  }
  else if (mode == 1)
  {
    translator->SetSplitModeToXSlab();
  }
  else
  {
    translator->SetSplitModeToYSlab();
  }
}

// Runs vtkImageMLAA on `input` with `options` (defaults when null).
// Options set to the medium preset (luma edges, 8 search steps): the settings that the
// hand-computed patterns of the tests assume (the library's defaults are the high preset).
inline vtkSmartPointer<vtkMLAAOptions> MediumOptions()
{
  auto options = vtkSmartPointer<vtkMLAAOptions>::New();
  options->SetPresetToMedium();
  return options;
}

// A new `Filter` (vtkImageMLAA or vtkImageDLAA) on `input` with `options`, or with the
// library's defaults when null: a copy of its output.
template <class Filter, class Options>
vtkSmartPointer<vtkImageData> RunFilter(vtkImageData* input, Options* options)
{
  vtkNew<Filter> filter;
  if (options)
  {
    filter->SetOptions(options);
  }
  filter->SetInputData(input);
  filter->Update();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}

// vtkImageDLAA on `input` with `options`, or with the default vtkDLAAOptions.
inline vtkSmartPointer<vtkImageData> RunDLAA(vtkImageData* input, vtkDLAAOptions* options = nullptr)
{
  return RunFilter<vtkImageDLAA>(input, options);
}

// vtkImageMLAA on `input` with `options`, or with the library's defaults.
inline vtkSmartPointer<vtkImageData> RunMLAA(vtkImageData* input, vtkMLAAOptions* options = nullptr)
{
  return RunFilter<vtkImageMLAA>(input, options);
}

// The ramp of the tests of edges inside ramps (issue 20): columns RampFirst to RampLast rising
// in grey from 30 to 230, 20 levels a column, column x up to row RampTop(x) (a staircase top),
// on black.
constexpr int RampFirst = 8;
constexpr int RampLast = 18;
inline double RampGrey(int x)
{
  return 30.0 + 20.0 * (x - RampFirst);
}
inline int RampTop(int x)
{
  return 9 + (x - RampFirst) / 3;
}

// vtkImageMLAA's edges (the EDGES debug output) of `input` with `options`, with its local
// contrast adaptation ([0]) and without ([1]).
inline std::array<vtkSmartPointer<vtkImageData>, 2> EdgesWithAndWithoutAdaptation(
  vtkImageData* input, vtkMLAAOptions* options)
{
  vtkNew<vtkMLAAOptions> edges;
  edges->DeepCopy(options);
  edges->SetDebugOutput(vtkMLAAOptions::EDGES);
  vtkNew<vtkMLAAOptions> off;
  off->DeepCopy(edges);
  off->SetLocalContrastFactor(0.0);
  return { RunMLAA(input, edges), RunMLAA(input, off) };
}

// A named option set of one method. The tests of the behaviour every method shares run each of
// a method's configurations, so that each way through the method (how far it reaches, how it
// finds edges) meets every check.
struct FilterConfiguration
{
  std::string Name;
  std::function<void(vtkImageAntialiasingAlgorithm*)> Apply; // sets the options of a new filter
};

// One antialiasing method of the CPU filter, for the tests of vtkImageAntialiasingAlgorithm's
// behaviour that every method shares: its class name, a factory of default-configured filters
// and its configurations (the first is the defaults). FilterMethods() lists them all; a new
// method is one more entry there.
struct FilterMethod
{
  const char* Name;
  vtkSmartPointer<vtkImageAntialiasingAlgorithm> (*New)();
  std::vector<FilterConfiguration> Configurations;
};

template <class Filter>
vtkSmartPointer<vtkImageAntialiasingAlgorithm> NewFilter()
{
  return vtkSmartPointer<Filter>::New();
}

// The options of a vtkImageMLAA or vtkImageDLAA made by a FilterMethod.
template <class Filter>
auto OptionsOf(vtkImageAntialiasingAlgorithm* filter)
  -> decltype(static_cast<Filter*>(filter)->GetOptions())
{
  return static_cast<Filter*>(filter)->GetOptions();
}

// MLAA: the defaults (Lab edges, the high preset's search steps), luma edges, reconstruction,
// search distances from 1 step to 128 (line lengths by search loop and by the exact count, and
// padding from a few pixels to 256), and corner extrapolation at 16 and 128 steps (padding up to
// 514).
inline std::vector<FilterConfiguration> MLAAConfigurations()
{
  std::vector<FilterConfiguration> configurations = {
    { "defaults", [](vtkImageAntialiasingAlgorithm*) {} },
    { "luma edges",
      [](vtkImageAntialiasingAlgorithm* f) { OptionsOf<vtkImageMLAA>(f)->SetEdgeDetectionToLuma(); } },
    { "reconstruction",
      [](vtkImageAntialiasingAlgorithm* f) { OptionsOf<vtkImageMLAA>(f)->ReconstructionOn(); } },
  };
  for (int steps : { 1, 4, 8, 32, 128 })
  {
    configurations.push_back({ std::to_string(steps) + " search steps",
      [steps](vtkImageAntialiasingAlgorithm* f) {
        OptionsOf<vtkImageMLAA>(f)->SetMaxSearchSteps(steps);
      } });
  }
  for (int steps : { 16, 128 })
  {
    configurations.push_back({ "corner extrapolation, " + std::to_string(steps) + " search steps",
      [steps](vtkImageAntialiasingAlgorithm* f) {
        OptionsOf<vtkImageMLAA>(f)->SetMaxSearchSteps(steps);
        OptionsOf<vtkImageMLAA>(f)->CornerExtrapolationOn();
      } });
  }
  return configurations;
}

// DLAA: the defaults (long edges, 10 pixels of padding) and short edges alone (2 pixels).
inline std::vector<FilterConfiguration> DLAAConfigurations()
{
  return {
    { "defaults", [](vtkImageAntialiasingAlgorithm*) {} },
    { "long edges off",
      [](vtkImageAntialiasingAlgorithm* f) { OptionsOf<vtkImageDLAA>(f)->LongEdgesOff(); } },
  };
}

inline const std::vector<FilterMethod>& FilterMethods()
{
  static const std::vector<FilterMethod> methods = {
    { "vtkImageMLAA", &NewFilter<vtkImageMLAA>, MLAAConfigurations() },
    { "vtkImageDLAA", &NewFilter<vtkImageDLAA>, DLAAConfigurations() },
  };
  return methods;
}

// A new filter of `method` in `configuration`.
inline vtkSmartPointer<vtkImageAntialiasingAlgorithm> NewConfigured(
  const FilterMethod& method, const FilterConfiguration& configuration)
{
  auto filter = method.New();
  configuration.Apply(filter);
  return filter;
}

// A new filter of `method` in `configuration` (the defaults when null) on `input`: a copy of
// its output.
inline vtkSmartPointer<vtkImageData> RunConfigured(const FilterMethod& method,
  vtkImageData* input, const FilterConfiguration* configuration = nullptr)
{
  auto filter = NewConfigured(method, configuration ? *configuration : method.Configurations[0]);
  filter->SetInputData(input);
  filter->Update();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}

// The VTK scalar types a vtkImageData can hold as numbers, and the value range of each that
// the filters normalise by default ([0, 1] for floating point).
inline const std::vector<int>& ScalarTypes()
{
  static const std::vector<int> types = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR,
    VTK_SHORT, VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG,
    VTK_LONG_LONG, VTK_UNSIGNED_LONG_LONG, VTK_ID_TYPE, VTK_FLOAT, VTK_DOUBLE };
  return types;
}

inline void TypeRange(int type, double& lo, double& hi)
{
  if (type == VTK_FLOAT || type == VTK_DOUBLE)
  {
    lo = 0.0;
    hi = 1.0;
  }
  else
  {
    lo = vtkDataArray::GetDataTypeMin(type);
    hi = vtkDataArray::GetDataTypeMax(type);
  }
}

// An image of `type` whose values are lo + n (hi - lo) for the normalised picture
// n = picture(x, y, z, component), rounded for integer types.
inline vtkSmartPointer<vtkImageData> MakeTypedImage(int width, int height, int depth, int type,
  int components, double lo, double hi, const std::function<double(int, int, int, int)>& picture)
{
  auto image = MakeImage(width, height, components, type, 0.0, depth);
  FillImage(image, [&](int x, int y, int z, int k) {
    const double v = lo + picture(x, y, z, k) * (hi - lo);
    return type == VTK_FLOAT || type == VTK_DOUBLE ? v : std::round(v);
  });
  return image;
}

// Strict comparison: the number of values (all components) whose absolute difference exceeds
// `tolerance`, and the largest difference. Images of different size or components compare as
// entirely different (returns -1).
struct Difference
{
  vtkIdType Count = 0;      // values that differ by more than the tolerance
  vtkIdType Pixels = 0;     // pixels with such a value
  vtkIdType Total = 0;      // pixels compared
  double Max = 0.0;         // largest difference
};

inline Difference Compare(vtkImageData* a, vtkImageData* b, double tolerance = 0.0)
{
  Difference d;
  int da[3], db[3];
  a->GetDimensions(da);
  b->GetDimensions(db);
  vtkDataArray* sa = a->GetPointData()->GetScalars();
  vtkDataArray* sb = b->GetPointData()->GetScalars();
  if (!sa || !sb || da[0] != db[0] || da[1] != db[1] || da[2] != db[2] ||
    sa->GetNumberOfComponents() != sb->GetNumberOfComponents())
  {
    d.Count = -1;
    return d;
  }
  const int c = sa->GetNumberOfComponents();
  d.Total = sa->GetNumberOfTuples();
  for (vtkIdType i = 0; i < d.Total; ++i)
  {
    bool pixelDiffers = false;
    for (int k = 0; k < c; ++k)
    {
      const double va = sa->GetComponent(i, k);
      const double vb = sb->GetComponent(i, k);
      const bool bothNaN = std::isnan(va) && std::isnan(vb);
      const double diff = bothNaN ? 0.0 : (va == vb ? 0.0 : std::abs(va - vb));
      if (std::isnan(diff) || diff > tolerance)
      {
        ++d.Count;
        pixelDiffers = true;
      }
      if (!std::isnan(diff))
      {
        d.Max = std::max(d.Max, diff);
      }
    }
    d.Pixels += pixelDiffers ? 1 : 0;
  }
  return d;
}

// Records the error and warning messages an object emits (instead of printing them), so that a
// test can assert that bad input was reported.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const std::string text = data ? static_cast<const char*>(data) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }
  bool HasError(const std::string& fragment) const
  {
    for (const auto& e : this->Errors)
    {
      if (e.find(fragment) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }
  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
};

inline bool WritePNG(vtkImageData* image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

inline vtkSmartPointer<vtkImageData> ReadPNG(const std::string& path)
{
  vtkNew<vtkPNGReader> reader;
  if (!reader->CanReadFile(path.c_str()))
  {
    return nullptr;
  }
  reader->SetFileName(path.c_str());
  reader->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(reader->GetOutput());
  return image;
}
} // namespace vtkMLAATest

#define MLAA_CHECK(cond) vtkMLAATest::Check((cond), #cond, __FILE__, __LINE__)

#endif
