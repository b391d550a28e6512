// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-benchmark-cpu: the CPU speed measure of the project's MEASURING.md.
//
// On one RGB image (by default a 1920x1080 single-sample render of the "mixed" scene, or a PNG
// file) it times, in one run and interleaved repetition by repetition:
//   MLAA        vtkImageMLAA, default options (vtkSMPTools, Initialize(n)), one filter updated
//               again and again (as a render loop or an interactive pipeline runs it);
//   MLAA-new    the same with a new filter per image (as the mlaa tool, vtkmlaa.antialias_array,
//               the ParaView filter and most image pipelines run it);
//   ultra, ultra-new  the same two ways with the ultra preset;
//   Gaussian    vtkImageGaussianSmooth, standard deviations (1, 1), radius factors (1.5, 1.5), 2D,
//               with EnableSMP on, so that it runs on the same vtkSMPTools backend and thread
//               count as MLAA (the comparison MEASURING.md asks for);
//   Gaussian-new  the same with a new filter per image;
//   Gaussian-MT the same filter with EnableSMP off and SetNumberOfThreads(n) (vtkMultiThreader;
//               VTK 9.1's default for imaging filters), for reference;
//   DeepCopy    vtkImageData::DeepCopy of the image (allocation + copy, as a filter output is);
//   memcpy      a copy of the scalars into a preallocated buffer (the memory-bandwidth floor);
//   DLAA        vtkImageDLAA, default vtkDLAAOptions (directionally localized antialiasing);
//   DLAA-new    the same with a new filter per image;
//   MLAA-stages the stages of vtkImageMLAA (vtkMLAAStages::RunSlice) run directly into a
//               preallocated output, each stage timed (features+edges, weights, blending);
//   variants    (unless --no-variants) vtkImageMLAA with each feature of "Morphological
//               antialiasing and topological reconstruction" over the medium preset (+lab, +steps32,
//               +steps128, +recon), the three together (+all3) and each preset (P-low ...
//               P-max), reported as time / Gaussian;
// for each thread count n (default 1 and 2), and reports the median time per operation and the
// ratios MLAA / Gaussian and MLAA / copy, for a reused filter and for a new filter per image.
#include "BenchmarkUtilities.h"
#include "vtkMLAAScenes.h"
#include "vtkMLAAStages.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageDLAA.h"
#include "vtkImageGaussianSmooth.h"
#include "vtkImageMLAA.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPointData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkThreadedImageAlgorithm.h"

#include <cstring>
#include <sys/resource.h>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace
{
void Usage(const char* program)
{
  std::cout << "Usage: " << program << " [options]\n"
            << "Times vtkImageMLAA against vtkImageGaussianSmooth and a plain copy (MEASURING.md).\n"
            << "  --size WxH          render size (default 1920x1080)\n"
            << "  --scene NAME        scene to render (default mixed)\n"
            << "  --image FILE.png    use this PNG instead of a render\n"
            << "  --repetitions N     timed repetitions per operation and thread count (default 30)\n"
            << "  --warmup N          untimed repetitions first (default 3)\n"
            << "  --threads a,b       thread counts (default 1,2)\n"
            << "  --no-variants       do not time the variants (+lab ... P-max)\n"
            << mlaaBenchmark::MLAAOptionsUsage();
}

// The stages of vtkImageMLAA (vtkMLAAStages::RunSlice) on the whole of a 2D image, as the filter
// runs them, timed one by one.
template <typename T>
void RunStages(vtkImageData* image, vtkImageMLAA* filter, vtkImageData* output,
  vtkMLAAStages::SliceBuffers& buffers, vtkMLAAStages::StageTimes& times)
{
  int ext[6];
  image->GetExtent(ext);
  const int components = image->GetNumberOfScalarComponents();
  double range[2];
  filter->GetEffectiveValueRange(image->GetScalarType(), range);
  vtkMLAAStages::SliceSetup setup;
  setup.Whole = setup.Input = setup.Output = { ext[0], ext[1], ext[2], ext[3] };
  vtkMLAAStages::ConfigureSlice(filter->GetOptions(), components, range[0], range[1], setup);
  vtkMLAAStages::Progress progress;
  vtkIdType increments[3];
  image->GetIncrements(increments);
  vtkMLAAStages::RunSlice(setup, static_cast<const T*>(image->GetScalarPointer()), increments[1],
    vtkMLAAStages::DepthRows(), static_cast<T*>(output->GetScalarPointer()), nullptr, buffers,
    progress, &times);
}

// One timed operation.
struct Operation
{
  Operation(std::string name, std::function<void()> run, std::vector<double> times = {})
    : Name(std::move(name))
    , Run(std::move(run))
    , Times(std::move(times))
  {
  }
  std::string Name;
  std::function<void()> Run;
  std::vector<double> Times;
  std::vector<double> Faults; // minor page faults of each run: fresh pages the run touched
};

// The minor page faults of this process so far (pages mapped in on first touch). A page costs
// from under a microsecond to over ten, depending on the machine, so the count says what
// allocations cost where they cost most.
double MinorPageFaults()
{
  struct rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_minflt);
}
}

int main(int argc, char* argv[])
{
  int width = 1920, height = 1080, repetitions = 30, warmup = 3;
  std::string scene = "mixed", imageFile;
  std::vector<int> threadCounts = { 1, 2 };
  bool variants = true;
  vtkNew<vtkMLAAOptions> options;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--help" || arg == "-h")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    else if (arg == "--size" && hasValue && mlaaBenchmark::ParseSize(argv[i + 1], width, height))
    {
      ++i;
    }
    else if (arg == "--scene" && hasValue)
    {
      scene = argv[++i];
    }
    else if (arg == "--image" && hasValue)
    {
      imageFile = argv[++i];
    }
    else if (arg == "--repetitions" && hasValue &&
      mlaaBenchmark::ParsePositive(argv[i + 1], repetitions))
    {
      ++i;
    }
    else if (arg == "--warmup" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], warmup))
    {
      ++i;
    }
    else if (arg == "--threads" && hasValue)
    {
      threadCounts.clear();
      for (const auto& item : mlaaBenchmark::SplitList(argv[++i]))
      {
        int n = 0;
        if (!mlaaBenchmark::ParsePositive(item, n))
        {
          std::cerr << "bad thread count: " << item << std::endl;
          return EXIT_FAILURE;
        }
        threadCounts.push_back(n);
      }
    }
    else if (arg == "--no-variants")
    {
      variants = false;
    }
    else if (mlaaBenchmark::ParseMLAAOption(argc, argv, i, options))
    {
      continue; // applied to `options`
    }
    else
    {
      std::cerr << "bad or incomplete argument: " << arg << std::endl;
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }

  // The input image.
  vtkNew<vtkImageData> image;
  std::string source;
  if (!imageFile.empty())
  {
    vtkNew<vtkPNGReader> reader;
    if (!reader->CanReadFile(imageFile.c_str()))
    {
      std::cerr << "cannot read PNG file " << imageFile << std::endl;
      return EXIT_FAILURE;
    }
    reader->SetFileName(imageFile.c_str());
    reader->Update();
    image->DeepCopy(reader->GetOutput());
    source = imageFile;
  }
  else
  {
    if (vtkMLAAScenes::Describe(scene).empty())
    {
      std::cerr << "unknown scene: " << scene << std::endl;
      return EXIT_FAILURE;
    }
    auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build(scene, renderer);
    image->DeepCopy(vtkMLAAScenes::Capture(window));
    source = "scene '" + scene + "' rendered offscreen, single-sample";
  }
  int dims[3];
  image->GetDimensions(dims);
  const int components = image->GetNumberOfScalarComponents();
  std::cout << "mlaa-benchmark-cpu: " << dims[0] << "x" << dims[1] << " x " << components << " "
            << image->GetScalarTypeAsString() << " (" << source << "), " << repetitions
            << " timed repetitions after " << warmup << " warm-up, median ms" << std::endl;
  std::cout << "vtkSMPTools backend: " << vtkSMPTools::GetBackend()
            << "; hardware threads: " << std::thread::hardware_concurrency()
            << "; vtkThreadedImageAlgorithm global default EnableSMP: "
            << (vtkThreadedImageAlgorithm::GetGlobalDefaultEnableSMP() ? "on" : "off") << std::endl;
  std::cout << mlaaBenchmark::DescribeMLAAOptions(options) << std::endl;

  vtkNew<vtkImageMLAA> mlaa;
  mlaa->SetInputData(image);
  mlaa->SetOptions(options);
  vtkNew<vtkImageDLAA> dlaa;
  dlaa->SetInputData(image);
  vtkNew<vtkMLAAOptions> ultraOptions;
  ultraOptions->SetPresetToUltra();
  vtkNew<vtkImageMLAA> ultra;
  ultra->SetInputData(image);
  ultra->SetOptions(ultraOptions);
  // A new filter per image: what a call of the mlaa tool, of vtkmlaa.antialias_array or of the
  // ParaView filter costs, including whatever the filter allocates afresh.
  auto newMLAA = [&image](vtkMLAAOptions* filterOptions) {
    vtkNew<vtkImageMLAA> filter;
    filter->SetInputData(image);
    filter->SetOptions(filterOptions);
    filter->Update();
  };
  auto setUpGaussian = [&image](vtkImageGaussianSmooth* gaussian) {
    gaussian->SetInputData(image);
    gaussian->SetDimensionality(2);
    gaussian->SetStandardDeviations(1.0, 1.0);
    gaussian->SetRadiusFactors(1.5, 1.5);
  };
  vtkNew<vtkImageGaussianSmooth> gaussianSMP;
  setUpGaussian(gaussianSMP);
  gaussianSMP->SetEnableSMP(true);
  vtkNew<vtkImageGaussianSmooth> gaussianMT;
  setUpGaussian(gaussianMT);
  gaussianMT->SetEnableSMP(false);
  vtkNew<vtkImageData> copy;
  const std::size_t bytes = static_cast<std::size_t>(image->GetPointData()->GetScalars()->GetDataSize()) *
    image->GetPointData()->GetScalars()->GetDataTypeSize();
  std::vector<unsigned char> buffer(bytes);
  const void* scalars = image->GetScalarPointer();
  volatile unsigned char sink = 0;

  // One filter per variant, each with options of its own.
  std::vector<vtkSmartPointer<vtkImageMLAA>> variantFilters;
  if (variants)
  {
    for (const auto& variant : mlaaBenchmark::Variants())
    {
      vtkNew<vtkMLAAOptions> variantOptions;
      variant.Configure(variantOptions);
      auto filter = vtkSmartPointer<vtkImageMLAA>::New();
      filter->SetInputData(image);
      filter->SetOptions(variantOptions);
      variantFilters.push_back(filter);
    }
  }

  struct Row
  {
    int Threads;
    std::map<std::string, double> Median;
  };
  std::vector<Row> rows;
  vtkNew<vtkImageData> stagesOutput;
  stagesOutput->CopyStructure(image);
  stagesOutput->AllocateScalars(image->GetScalarType(), components);
  vtkMLAAStages::SliceBuffers stageBuffers;
  std::map<std::string, std::vector<double>> stageTimes;
  for (int threads : threadCounts)
  {
    vtkSMPTools::Initialize(threads);
    gaussianSMP->SetNumberOfThreads(threads); // ignored with EnableSMP on; set for clarity
    gaussianMT->SetNumberOfThreads(threads);
    std::vector<Operation> operations = {
      { "MLAA",
        [&]() {
          mlaa->Modified();
          mlaa->Update();
        },
        {} },
      { "MLAA-new", [&]() { newMLAA(options); }, {} },
      { "ultra",
        [&]() {
          ultra->Modified();
          ultra->Update();
        },
        {} },
      { "ultra-new", [&]() { newMLAA(ultraOptions); }, {} },
      { "DLAA",
        [&]() {
          dlaa->Modified();
          dlaa->Update();
        },
        {} },
      { "DLAA-new",
        [&]() {
          vtkNew<vtkImageDLAA> filter;
          filter->SetInputData(image);
          filter->Update();
        },
        {} },
      { "Gaussian",
        [&]() {
          gaussianSMP->Modified();
          gaussianSMP->Update();
        },
        {} },
      { "Gaussian-new",
        [&]() {
          vtkNew<vtkImageGaussianSmooth> filter;
          setUpGaussian(filter);
          filter->SetEnableSMP(true);
          filter->Update();
        },
        {} },
      { "Gaussian-MT",
        [&]() {
          gaussianMT->Modified();
          gaussianMT->Update();
        },
        {} },
      { "DeepCopy",
        [&]() {
          copy->Initialize();
          copy->DeepCopy(image);
        },
        {} },
      { "memcpy",
        [&]() {
          std::memcpy(buffer.data(), scalars, bytes);
          sink = sink + buffer[bytes / 2];
        },
        {} },
      { "MLAA-stages",
        [&]() {
          vtkMLAAStages::StageTimes times;
          switch (image->GetScalarType())
          {
            vtkTemplateMacro(RunStages<VTK_TT>(image, mlaa, stagesOutput, stageBuffers, times));
          }
          stageTimes["features+edges"].push_back(1e3 * times.FeaturesAndEdges);
          stageTimes["weights"].push_back(1e3 * times.BlendingWeights);
          stageTimes["blending"].push_back(1e3 * times.Blending);
        },
        {} },
    };
    for (size_t v = 0; v < variantFilters.size(); ++v)
    {
      vtkImageMLAA* filter = variantFilters[v];
      operations.push_back({ mlaaBenchmark::Variants()[v].Name,
        [filter]() {
          filter->Modified();
          filter->Update();
        },
        {} });
    }
    for (int w = 0; w < warmup; ++w)
    {
      for (auto& op : operations)
      {
        op.Run();
      }
    }
    stageTimes.clear();
    // Interleaved: load changes on a shared machine hit every operation alike.
    for (int r = 0; r < repetitions; ++r)
    {
      for (auto& op : operations)
      {
        const double faults = MinorPageFaults();
        mlaaBenchmark::Stopwatch clock;
        op.Run();
        op.Times.push_back(clock.Milliseconds());
        op.Faults.push_back(MinorPageFaults() - faults);
      }
    }
    Row row;
    row.Threads = threads;
    std::cout << "\nthreads " << threads << " (vtkSMPTools::GetEstimatedNumberOfThreads() = "
              << vtkSMPTools::GetEstimatedNumberOfThreads() << ")\n";
    std::cout << "  " << std::left << std::setw(13) << "operation" << std::right << std::setw(10)
              << "median" << std::setw(10) << "min" << std::setw(10) << "p90" << "  ms"
              << std::setw(14) << "page faults" << "\n";
    for (const auto& op : operations)
    {
      row.Median[op.Name] = mlaaBenchmark::Median(op.Times);
      std::cout << "  " << std::left << std::setw(13) << op.Name << std::right << std::fixed
                << std::setprecision(2) << std::setw(10) << row.Median[op.Name] << std::setw(10)
                << mlaaBenchmark::Quantile(op.Times, 0.0) << std::setw(10)
                << mlaaBenchmark::Quantile(op.Times, 0.9) << std::defaultfloat << std::setw(16)
                << mlaaBenchmark::Median(op.Faults) << "\n";
    }
    // The stages, run directly into a preallocated output (no pipeline, no allocation).
    const double gaussian = row.Median["Gaussian"];
    std::cout << "  stages of MLAA-stages (median ms, and / Gaussian):";
    for (const auto& name : { "features+edges", "weights", "blending" })
    {
      const double m = mlaaBenchmark::Median(stageTimes[name]);
      std::cout << "  " << name << " " << std::fixed << std::setprecision(2) << m << " ("
                << m / gaussian << ")" << std::defaultfloat;
    }
    std::cout << "\n";
    if (!variantFilters.empty())
    {
      std::cout << "  variants (median ms, and / Gaussian; MLAA = the settings above):";
      for (const auto& variant : mlaaBenchmark::Variants())
      {
        const double m = row.Median[variant.Name];
        std::cout << "\n    " << std::left << std::setw(11) << variant.Name << std::right
                  << std::fixed << std::setprecision(2) << std::setw(9) << m << std::setw(8)
                  << m / gaussian << std::defaultfloat;
      }
      std::cout << "\n";
    }
    rows.push_back(row);
  }

  std::cout << "\nratios of medians (same run):\n"
            << std::right << std::setw(8) << "threads" << std::setw(16) << "MLAA/Gaussian"
            << std::setw(18) << "MLAA/Gaussian-MT" << std::setw(16) << "MLAA/DeepCopy"
            << std::setw(13) << "MLAA/memcpy" << std::setw(15) << "DLAA/Gaussian" << "\n";
  for (const auto& row : rows)
  {
    const double m = row.Median.at("MLAA");
    std::cout << std::setw(8) << row.Threads << std::fixed << std::setprecision(2) << std::setw(16)
              << m / row.Median.at("Gaussian") << std::setw(18) << m / row.Median.at("Gaussian-MT")
              << std::setw(16) << m / row.Median.at("DeepCopy") << std::setw(13)
              << m / row.Median.at("memcpy") << std::setw(15)
              << row.Median.at("DLAA") / row.Median.at("Gaussian") << std::defaultfloat << "\n";
  }
  // The way users call it: a reused filter against a reused Gaussian, and a new filter per image
  // against a new Gaussian per image.
  std::cout << "\nratios, reused filter / new filter per image (each against the Gaussian used the "
               "same way):\n"
            << std::right << std::setw(8) << "threads" << std::setw(20) << "MLAA" << std::setw(20)
            << "ultra" << std::setw(20) << "DLAA" << "\n";
  for (const auto& row : rows)
  {
    std::cout << std::setw(8) << row.Threads << std::fixed << std::setprecision(2);
    for (const std::string name : { "MLAA", "ultra", "DLAA" })
    {
      std::ostringstream pair;
      pair << std::fixed << std::setprecision(2)
           << row.Median.at(name) / row.Median.at("Gaussian") << " / "
           << row.Median.at(name + "-new") / row.Median.at("Gaussian-new");
      std::cout << std::setw(20) << pair.str();
    }
    std::cout << std::defaultfloat << "\n";
  }
  if (rows.size() > 1)
  {
    std::cout << "\nspeed-up from " << rows.front().Threads << " to " << rows.back().Threads
              << " threads:";
    for (const auto& name : { "MLAA", "Gaussian", "Gaussian-MT" })
    {
      std::cout << " " << name << " " << std::fixed << std::setprecision(2)
                << rows.front().Median.at(name) / rows.back().Median.at(name) << "x";
    }
    std::cout << std::defaultfloat << "\n";
  }
  std::cout << "Gaussian: vtkImageGaussianSmooth (sd 1, radius factor 1.5, 2D) with EnableSMP on "
               "(vtkSMPTools, same thread count as MLAA); Gaussian-MT: EnableSMP off, "
               "SetNumberOfThreads(n). Absolute times drift on shared machines: quote the ratios."
            << std::endl;
  (void)sink;
  return EXIT_SUCCESS;
}
