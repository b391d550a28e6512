// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-benchmark-gpu: the GPU speed measure of the project's MEASURING.md.
//
// Renders one scene (default "mixed") offscreen, single-sample (SetMultiSamples(0)), at one size
// (default 1920x1080) with each of these renderer configurations:
//   default       no pass set (vtkOpenGLRenderer's own render steps);
//   steps         a vtkRenderStepsPass set as the renderer's pass (the delegate of the two below);
//   FXAA-pass     vtkOpenGLFXAAPass, delegate vtkRenderStepsPass, default vtkFXAAOptions;
//   MLAA-pass     vtkOpenGLMLAAPass, delegate vtkRenderStepsPass, default vtkMLAAOptions;
//   DLAA-pass     vtkOpenGLDLAAPass, delegate vtkRenderStepsPass, default vtkDLAAOptions;
//   FXAA-builtin  no pass, renderer->UseFXAAOn() (for reference);
// and times frames: each frame turns the camera by a small azimuth, calls window->Render() and
// then WaitForCompletion() (glFinish), so that the time includes the GL work. Configurations are
// visited in rounds (a few frames each, after two untimed frames) so that load changes on a
// shared machine hit them alike; every configuration starts each round from the same camera.
// It reports the median frame time per configuration and
//   overhead(X) = median(X) - median(steps),   ratio = overhead(MLAA-pass) / overhead(FXAA-pass),
// and the MLAA pass's render-target memory relative to an RGBA8 back buffer (W * H * 4 bytes).
// Long lines (unless --no-long-lines): the MLAA pass again with MaxSearchSteps 8, 32 and 128
// (the other options as given), each with the search loop and with line lengths by recursive
// doubling (vtkOpenGLMLAAPass::LineLengths), as configurations MLAA-<steps>-loop and
// MLAA-<steps>-doubling of the same rounds, reported as overhead / overhead(FXAA-pass).
// Variants (unless --no-variants): the MLAA pass with each feature of "Morphological antialiasing
// and topological reconstruction" over the medium preset (+lab, +steps32, +steps128, +recon), the
// three together (+all3) and each preset (P-low ... P-max), reported the same way.
// Multisampling (--multisamples): the window with SetMultiSamples(2, 4, 8) and no pass (MSAA2,
// MSAA4, MSAA8), and the passes with SetMultiSamples(2, 4, 8) (MLAA-S2 ... MLAA-S8, DLAA-S4),
// reported as frame time / frame time of MSAA4 (medians of the same rounds), with the sample
// counts the driver gave.
// Temporal antialiasing (--temporal): both passes with SetTemporal(true) (MLAA-temporal,
// DLAA-temporal), each kept from frame to frame as an application renders: with the camera turning
// at every frame (--azimuth, default 0.2 degree) every frame reprojects and blends the history,
// with --azimuth 0 every frame is a jittered render of a still accumulation. Reported as
// overhead(X-temporal) / overhead(X-pass) (the single-frame pass of the same method, same rounds),
// with the temporal pass's render-target memory. With --multisamples too, the MLAA pass with both
// (SetTemporal and SetMultiSamples(4): MLAA-temporal-S4, whose moving frames render the samples),
// and the multisampling report then lists every configuration's frame time / that of MSAA4 (the
// README's column).
// Stages (--stages wall|gl): after the timed rounds, each configuration with one of the project's
// passes renders a round's frames again with the window's render timings on (vtkRenderTimerLog:
// each pass times its stages as events, waiting for the GL work at each start and end;
// BenchmarkStageTimes.h), and the mean time of each stage per frame is listed: by the steady
// clock (wall, for llvmpipe, whose GL timestamps do not time its rasteriser's work) or by VTK's GL
// timestamp queries (gl, a GPU's own times). Frames are slower while the timings are on.
#include "BenchmarkStageTimes.h"
#include "BenchmarkUtilities.h"
#include "vtkMLAAScenes.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkUnsignedCharArray.h"
#include "vtkNew.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLFXAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderTimerLog.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
// The stress scene of the searches, "stripes-DEG": black and white stripes 4 pixels wide at DEG
// degrees from horizontal over the whole view, flat-shaded, in a parallel view of one world unit
// per pixel. Every stripe edge is one long line (near 0 or 90 degrees: the search along rows or
// columns) or one long staircase of one-pixel steps (45 degrees: the diagonal search), so it is
// the worst case of their cost, not a picture anyone renders. ParseStripes: false for a name of
// another form.
bool ParseStripes(const std::string& name, double& degrees)
{
  const std::string prefix = "stripes-";
  if (name.compare(0, prefix.size(), prefix) != 0)
  {
    return false;
  }
  char* end = nullptr;
  degrees = std::strtod(name.c_str() + prefix.size(), &end);
  return end != name.c_str() + prefix.size() && *end == '\0' && degrees >= 0.0 && degrees <= 90.0;
}

void BuildStripes(double degrees, vtkRenderer* renderer, int width, int height)
{
  const double angle = vtkMath::RadiansFromDegrees(degrees);
  const double along[2] = { std::cos(angle), std::sin(angle) };
  const double across[2] = { -along[1], along[0] };
  const double reach = std::hypot(width, height); // every stripe long enough to cross the view
  const double stripeWidth = 4.0;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> quads;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  const int count = static_cast<int>(reach / stripeWidth) + 2;
  for (int i = -count / 2; i <= count / 2; ++i)
  {
    const double c0 = i * stripeWidth, c1 = c0 + stripeWidth;
    vtkIdType ids[4];
    const double corners[4][2] = { { -reach, c0 }, { reach, c0 }, { reach, c1 }, { -reach, c1 } };
    for (int k = 0; k < 4; ++k)
    {
      ids[k] = points->InsertNextPoint(corners[k][0] * along[0] + corners[k][1] * across[0],
        corners[k][0] * along[1] + corners[k][1] * across[1], 0.0);
    }
    quads->InsertNextCell(4, ids);
    const unsigned char value = (i & 1) ? 255 : 0;
    colors->InsertNextTuple3(value, value, value);
  }
  vtkNew<vtkPolyData> stripes;
  stripes->SetPoints(points);
  stripes->SetPolys(quads);
  stripes->GetCellData()->SetScalars(colors);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(stripes);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
  renderer->SetBackground(0.5, 0.5, 0.5);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetPosition(0.3, 0.2, 1000.0); // stripe edges off the pixel centres
  camera->SetFocalPoint(0.3, 0.2, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(height / 2.0);
  renderer->ResetCameraClippingRange();
}

void Usage(const char* program)
{
  std::cout << "Usage: " << program << " [options]\n"
            << "Times frames with and without the MLAA and FXAA passes (MEASURING.md).\n"
            << "  --size WxH       window size (default 1920x1080)\n"
            << "  --scene NAME     scene (default mixed), or stripes-DEG: stripes 4 pixels wide at\n"
            << "                   DEG degrees, the worst case of the searches (e.g. stripes-45)\n"
            << "  --frames N       timed frames per configuration (default 100)\n"
            << "  --warmup N       untimed frames per configuration first (default 10)\n"
            << "  --rounds N       split the timed frames into N interleaved rounds (default 5)\n"
            << "  --azimuth DEG    camera azimuth step per frame (default 0.2; 0 = still)\n"
            << "  --clock cpu      time the process's CPU time per frame instead of the wall\n"
            << "                   clock: for llvmpipe (whose GL work runs on the process's\n"
            << "                   threads) on a machine shared with other work; not for a GPU\n"
            << "  --no-variants    leave out the MLAA pass with each feature and preset (+lab ...\n"
            << "                   P-max)\n"
            << "  --no-long-lines  leave out the MLAA pass at 8, 32 and 128 steps with the search\n"
            << "                   loop and with recursive doubling\n"
            << "  --multisamples   also time 2x, 4x and 8x MSAA and the passes with 2, 4 and 8\n"
            << "                   samples, as frame time / frame time of 4x MSAA\n"
            << "  --temporal       also time both passes with temporal antialiasing (moving\n"
            << "                   camera: reprojection; --azimuth 0: still accumulation), as\n"
            << "                   overhead / overhead of the same method's single-frame pass\n"
            << "  --stages CLOCK   then list the mean time of each stage of each pass per frame,\n"
            << "                   CLOCK wall (steady clock; llvmpipe) or gl (GL timestamp\n"
            << "                   queries; a GPU)\n"
            << "For the MLAA pass, " << mlaaBenchmark::MLAAOptionsUsage();
}

struct Configuration
{
  std::string Name;
  vtkRenderPass* Pass; // nullptr: the renderer's own steps
  bool BuiltinFXAA;
  std::vector<double> Times;
  int WindowSamples = 0; // the window's MultiSamples while it renders
};
}

int main(int argc, char* argv[])
{
  int width = 1920, height = 1080, frames = 100, warmup = 10, rounds = 5;
  double azimuth = 0.2;
  bool longLines = true;
  bool variants = true;
  bool cpuClock = false;
  bool multisamples = false;
  bool temporal = false;
  bool stages = false;
  bool wallStages = true;
  std::string scene = "mixed";
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
    else if (arg == "--frames" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], frames))
    {
      ++i;
    }
    else if (arg == "--warmup" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], warmup))
    {
      ++i;
    }
    else if (arg == "--rounds" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], rounds))
    {
      ++i;
    }
    else if (arg == "--no-variants")
    {
      variants = false;
    }
    else if (arg == "--multisamples")
    {
      multisamples = true;
    }
    else if (arg == "--temporal")
    {
      temporal = true;
    }
    else if (arg == "--stages" && hasValue &&
      (std::string(argv[i + 1]) == "wall" || std::string(argv[i + 1]) == "gl"))
    {
      stages = true;
      wallStages = std::string(argv[++i]) == "wall";
    }
    else if (arg == "--no-long-lines")
    {
      longLines = false;
    }
    else if (arg == "--clock" && hasValue &&
      (std::string(argv[i + 1]) == "cpu" || std::string(argv[i + 1]) == "wall"))
    {
      cpuClock = std::string(argv[++i]) == "cpu";
    }
    else if (arg == "--azimuth" && hasValue)
    {
      azimuth = std::atof(argv[++i]);
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
  double stripesDegrees = 0.0;
  const bool stripes = ParseStripes(scene, stripesDegrees);
  if (!stripes && vtkMLAAScenes::Describe(scene).empty())
  {
    std::cerr << "unknown scene: " << scene << std::endl;
    return EXIT_FAILURE;
  }
  rounds = std::min(rounds, frames);

  if (stages && wallStages)
  {
    mlaaBenchmark::UseWallClockRenderTimings();
  }
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  if (stripes)
  {
    BuildStripes(stripesDegrees, renderer, width, height);
  }
  else
  {
    vtkMLAAScenes::Build(scene, renderer);
  }
  window->Render();
  auto* glWindow = vtkOpenGLRenderWindow::SafeDownCast(window);
  if (!glWindow)
  {
    std::cerr << "not an OpenGL render window" << std::endl;
    return EXIT_FAILURE;
  }
  int actual[2] = { window->GetSize()[0], window->GetSize()[1] };
  std::cout << "mlaa-benchmark-gpu: scene '" << scene << "', " << actual[0] << "x" << actual[1]
            << " offscreen, MultiSamples " << window->GetMultiSamples() << ", " << frames
            << " timed frames per configuration in " << rounds << " rounds after " << warmup
            << " warm-up frames, azimuth step " << azimuth << " deg, Render() + WaitForCompletion()"
            << (cpuClock ? ", process CPU time" : ", wall clock")
            << std::endl;
  mlaaBenchmark::PrintRasteriserNote(mlaaBenchmark::OpenGLRenderer(window));
  std::cout << mlaaBenchmark::DescribeMLAAOptions(options) << std::endl;
  if (const char* lp = std::getenv("LP_NUM_THREADS"))
  {
    std::cout << "LP_NUM_THREADS=" << lp << std::endl;
  }

  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkRenderStepsPass> fxaaSteps;
  vtkNew<vtkOpenGLFXAAPass> fxaa;
  fxaa->SetDelegatePass(fxaaSteps);
  vtkNew<vtkRenderStepsPass> mlaaSteps;
  vtkNew<vtkOpenGLMLAAPass> mlaa;
  mlaa->SetDelegatePass(mlaaSteps);
  mlaa->SetOptions(options);

  vtkNew<vtkRenderStepsPass> dlaaSteps;
  vtkNew<vtkOpenGLDLAAPass> dlaa;
  dlaa->SetDelegatePass(dlaaSteps);
  std::vector<Configuration> configurations = {
    { "default", nullptr, false, {} },
    { "steps", steps, false, {} },
    { "FXAA-pass", fxaa, false, {} },
    { "MLAA-pass", mlaa, false, {} },
    { "DLAA-pass", dlaa, false, {} },
    { "FXAA-builtin", nullptr, true, {} },
  };
  // Long lines: one pass per search length and line-length method.
  std::vector<vtkSmartPointer<vtkOpenGLMLAAPass>> longLinePasses;
  if (longLines)
  {
    for (int searchSteps : { 8, 32, 128 })
    {
      for (int method : { vtkOpenGLMLAAPass::SEARCH_LOOP, vtkOpenGLMLAAPass::RECURSIVE_DOUBLING })
      {
        auto pass = vtkSmartPointer<vtkOpenGLMLAAPass>::New();
        vtkNew<vtkRenderStepsPass> delegate;
        pass->SetDelegatePass(delegate);
        pass->GetOptions()->DeepCopy(options);
        pass->GetOptions()->SetMaxSearchSteps(searchSteps);
        pass->SetLineLengths(method);
        longLinePasses.push_back(pass);
        configurations.push_back({ "MLAA-" + std::to_string(searchSteps) +
            (method == vtkOpenGLMLAAPass::SEARCH_LOOP ? "-loop" : "-doubling"),
          pass, false, {} });
      }
    }
  }

  // Variants: one pass per feature and preset.
  std::vector<vtkSmartPointer<vtkOpenGLMLAAPass>> variantPasses;
  if (variants)
  {
    for (const auto& variant : mlaaBenchmark::Variants())
    {
      auto pass = vtkSmartPointer<vtkOpenGLMLAAPass>::New();
      vtkNew<vtkRenderStepsPass> delegate;
      pass->SetDelegatePass(delegate);
      variant.Configure(pass->GetOptions());
      variantPasses.push_back(pass);
      configurations.push_back({ variant.Name, pass, false, {} });
    }
  }

  // Multisampling: the window's MSAA, and the passes on each sample set.
  std::vector<vtkSmartPointer<vtkOpenGLAntialiasingPass>> samplePasses;
  if (multisamples)
  {
    for (int count : { 2, 4, 8 })
    {
      configurations.push_back({ "MSAA" + std::to_string(count), nullptr, false, {}, count });
    }
    for (int count : { 2, 4, 8 })
    {
      auto pass = vtkSmartPointer<vtkOpenGLMLAAPass>::New();
      vtkNew<vtkRenderStepsPass> delegate;
      pass->SetDelegatePass(delegate);
      pass->SetOptions(options);
      pass->SetMultiSamples(count);
      samplePasses.push_back(pass);
      configurations.push_back({ "MLAA-S" + std::to_string(count), pass, false, {} });
    }
    auto pass = vtkSmartPointer<vtkOpenGLDLAAPass>::New();
    vtkNew<vtkRenderStepsPass> delegate;
    pass->SetDelegatePass(delegate);
    pass->SetMultiSamples(4);
    samplePasses.push_back(pass);
    configurations.push_back({ "DLAA-S4", pass, false, {} });
  }

  // Temporal antialiasing: one pass per method, kept from frame to frame.
  vtkNew<vtkOpenGLMLAAPass> mlaaTemporal;
  vtkNew<vtkOpenGLDLAAPass> dlaaTemporal;
  vtkNew<vtkOpenGLMLAAPass> mlaaTemporalSamples;
  if (temporal)
  {
    for (vtkOpenGLAntialiasingPass* pass :
      { static_cast<vtkOpenGLAntialiasingPass*>(mlaaTemporal.Get()),
        static_cast<vtkOpenGLAntialiasingPass*>(dlaaTemporal.Get()),
        static_cast<vtkOpenGLAntialiasingPass*>(mlaaTemporalSamples.Get()) })
    {
      vtkNew<vtkRenderStepsPass> delegate;
      pass->SetDelegatePass(delegate);
      pass->TemporalOn();
    }
    mlaaTemporal->SetOptions(options);
    configurations.push_back({ "MLAA-temporal", mlaaTemporal, false, {} });
    configurations.push_back({ "DLAA-temporal", dlaaTemporal, false, {} });
    if (multisamples)
    {
      mlaaTemporalSamples->SetOptions(options);
      mlaaTemporalSamples->SetMultiSamples(4);
      configurations.push_back({ "MLAA-temporal-S4", mlaaTemporalSamples, false, {} });
    }
  }

  vtkCamera* camera = renderer->GetActiveCamera();
  vtkNew<vtkCamera> start;
  start->DeepCopy(camera);
  auto frame = [&]() {
    camera->Azimuth(azimuth);
    mlaaBenchmark::Stopwatch clock;
    mlaaBenchmark::CpuStopwatch cpu;
    window->Render();
    glWindow->WaitForCompletion();
    return cpuClock ? cpu.Milliseconds() : clock.Milliseconds();
  };
  auto use = [&](const Configuration& c) {
    renderer->SetPass(c.Pass);
    renderer->SetUseFXAA(c.BuiltinFXAA);
    window->SetMultiSamples(c.WindowSamples);
    camera->DeepCopy(start);
  };

  for (auto& c : configurations)
  {
    use(c);
    for (int f = 0; f < warmup; ++f)
    {
      frame();
    }
  }
  for (int r = 0; r < rounds; ++r)
  {
    const int count = frames / rounds + (r < frames % rounds ? 1 : 0);
    for (auto& c : configurations)
    {
      use(c);
      frame();
      frame();
      camera->DeepCopy(start);
      for (int f = 0; f < count; ++f)
      {
        c.Times.push_back(frame());
      }
    }
  }
  // Memory, measured while the MLAA pass still holds its targets.
  use(configurations[3]);
  window->Render();
  const double backBuffer = static_cast<double>(actual[0]) * actual[1] * 4.0;
  const double targets = static_cast<double>(mlaa->GetTargetMemorySize());
  const double mlaaTargets = static_cast<double>(mlaa->GetMLAATargetMemorySize());

  std::cout << "\n"
            << std::left << std::setw(18) << "configuration" << std::right << std::setw(10)
            << "median" << std::setw(10) << "min" << std::setw(10) << "p90" << std::setw(12)
            << "-steps" << "  ms/frame\n";
  double stepsMedian = 0.0;
  for (const auto& c : configurations)
  {
    if (c.Name == "steps")
    {
      stepsMedian = mlaaBenchmark::Median(c.Times);
    }
  }
  double fxaaOverhead = 0.0, mlaaOverhead = 0.0;
  for (const auto& c : configurations)
  {
    const double median = mlaaBenchmark::Median(c.Times);
    if (c.Name == "FXAA-pass")
    {
      fxaaOverhead = median - stepsMedian;
    }
    if (c.Name == "MLAA-pass")
    {
      mlaaOverhead = median - stepsMedian;
    }
    std::cout << std::left << std::setw(18) << c.Name << std::right << std::fixed
              << std::setprecision(2) << std::setw(10) << median << std::setw(10)
              << mlaaBenchmark::Quantile(c.Times, 0.0) << std::setw(10)
              << mlaaBenchmark::Quantile(c.Times, 0.9) << std::setw(12) << median - stepsMedian
              << std::defaultfloat << "\n";
  }
  std::cout << std::fixed << std::setprecision(2) << "\noverhead (median - median(steps)): FXAA-pass "
            << fxaaOverhead << " ms, MLAA-pass " << mlaaOverhead << " ms\n"
            << "overhead(MLAA-pass) / overhead(FXAA-pass) = ";
  if (fxaaOverhead > 0.0)
  {
    std::cout << mlaaOverhead / fxaaOverhead << "\n";
  }
  else
  {
    std::cout << "n/a (FXAA overhead not positive: within noise)\n";
  }
  for (const auto& c : configurations)
  {
    if (c.Name == "DLAA-pass" && fxaaOverhead > 0.0)
    {
      std::cout << "overhead(DLAA-pass) / overhead(FXAA-pass) = "
                << (mlaaBenchmark::Median(c.Times) - stepsMedian) / fxaaOverhead << "\n";
    }
  }
  if (longLines)
  {
    std::cout << "long lines: overhead / overhead(FXAA-pass), search loop and recursive doubling\n"
              << std::left << std::setw(8) << "steps" << std::right << std::setw(12) << "loop"
              << std::setw(12) << "doubling" << "\n";
    for (int searchSteps : { 8, 32, 128 })
    {
      std::cout << std::left << std::setw(8) << searchSteps << std::right;
      for (const char* method : { "-loop", "-doubling" })
      {
        const std::string name = "MLAA-" + std::to_string(searchSteps) + method;
        for (const auto& c : configurations)
        {
          if (c.Name == name)
          {
            const double overhead = mlaaBenchmark::Median(c.Times) - stepsMedian;
            std::cout << std::setw(12);
            if (fxaaOverhead > 0.0)
            {
              std::cout << overhead / fxaaOverhead;
            }
            else
            {
              std::cout << "n/a";
            }
          }
        }
      }
      std::cout << "\n";
    }
  }
  if (variants)
  {
    std::cout << "variants: overhead / overhead(FXAA-pass)\n";
    for (const auto& variant : mlaaBenchmark::Variants())
    {
      for (const auto& c : configurations)
      {
        if (c.Name == variant.Name)
        {
          const double overhead = mlaaBenchmark::Median(c.Times) - stepsMedian;
          std::cout << "  " << std::left << std::setw(11) << variant.Name << std::right
                    << std::setw(8);
          if (fxaaOverhead > 0.0)
          {
            std::cout << overhead / fxaaOverhead;
          }
          else
          {
            std::cout << "n/a";
          }
          std::cout << "\n";
        }
      }
    }
  }
  if (multisamples)
  {
    double msaa4 = 0.0;
    for (const auto& c : configurations)
    {
      if (c.Name == "MSAA4")
      {
        msaa4 = mlaaBenchmark::Median(c.Times);
      }
    }
    std::cout << "multisampling: frame time / frame time of MSAA4 (" << msaa4 << " ms)"
              << (temporal ? ", every configuration" : "") << "\n";
    for (const auto& c : configurations)
    {
      auto* pass = vtkOpenGLAntialiasingPass::SafeDownCast(c.Pass);
      if (temporal || c.WindowSamples || (pass && pass->GetMultiSamples()))
      {
        std::cout << "  " << std::left << std::setw(16) << c.Name << std::right << std::setw(8)
                  << mlaaBenchmark::Median(c.Times) / msaa4;
        if (pass && pass->GetMultiSamples())
        {
          std::cout << "  (" << pass->GetRenderedMultiSamples() << " samples used)";
        }
        std::cout << "\n";
      }
    }
  }
  if (temporal)
  {
    std::cout << "temporal antialiasing ("
              << (azimuth != 0.0 ? "camera turning every frame: reprojected history"
                                 : "still camera: jittered accumulation")
              << "): overhead / overhead of the same method's single-frame pass\n";
    for (const char* method : { "MLAA", "DLAA" })
    {
      double single = 0.0, withHistory = 0.0;
      for (const auto& c : configurations)
      {
        if (c.Name == std::string(method) + "-pass")
        {
          single = mlaaBenchmark::Median(c.Times) - stepsMedian;
        }
        if (c.Name == std::string(method) + "-temporal")
        {
          withHistory = mlaaBenchmark::Median(c.Times) - stepsMedian;
        }
      }
      std::cout << "  " << method << "-temporal " << withHistory << " ms, " << method << "-pass "
                << single << " ms: ";
      if (single > 0.0)
      {
        std::cout << withHistory / single << "\n";
      }
      else
      {
        std::cout << "n/a (single-frame overhead not positive: within noise)\n";
      }
    }
    std::cout << "MLAA-temporal render targets: "
              << mlaaTemporal->GetTargetMemorySize() / (1024.0 * 1024.0) << " MiB = "
              << mlaaTemporal->GetTargetMemorySize() / backBuffer << " x the back buffer\n";
  }
  std::cout << "MLAA pass render targets: " << targets / (1024.0 * 1024.0) << " MiB = "
            << targets / backBuffer << " x the RGBA8 back buffer (" << backBuffer / (1024.0 * 1024.0)
            << " MiB); MLAA-specific targets (edges + blending weights): "
            << mlaaTargets / (1024.0 * 1024.0) << " MiB = " << mlaaTargets / backBuffer
            << " x the back buffer" << std::defaultfloat << std::endl;

  if (stages)
  {
    vtkRenderTimerLog* log = window->GetRenderTimer();
    if (!log->IsSupported())
    {
      std::cout << "stages: the render timings are not supported here\n";
    }
    else
    {
      const int count = std::max(frames / rounds, 2);
      std::cout << "stages: mean time per frame (ms, "
                << (wallStages ? "steady clock" : "GL timestamp queries") << ") over " << count
                << " frames each, render timings on\n";
      for (auto& c : configurations)
      {
        auto* pass = vtkOpenGLAntialiasingPass::SafeDownCast(c.Pass);
        if (!pass)
        {
          continue;
        }
        use(c);
        frame();
        log->LoggingEnabledOn();
        std::map<std::string, std::pair<double, int>> totals;
        int timedFrames = 0;
        auto collect = [&]() {
          while (log->FrameReady())
          {
            const vtkRenderTimerLog::Frame f = log->PopFirstReadyFrame();
            for (const auto& event : f.Events)
            {
              mlaaBenchmark::AddStageTimes(
                event, pass->GetClassName(), std::string(), false, totals);
            }
            ++timedFrames;
          }
        };
        for (int f = 0; f < count; ++f)
        {
          frame();
          collect();
        }
        for (int f = 0; f < 8 && timedFrames < count; ++f)
        {
          window->Render(); // marks a new frame, so that the last ones become ready
          glWindow->WaitForCompletion();
          collect();
        }
        log->LoggingEnabledOff();
        std::cout << "  " << c.Name << " (" << timedFrames << " frames)\n";
        for (const auto& stage : totals)
        {
          std::cout << "    " << std::left << std::setw(40) << stage.first << std::right
                    << std::fixed << std::setprecision(2) << std::setw(10)
                    << stage.second.first / std::max(timedFrames, 1) << std::defaultfloat
                    << "\n";
        }
      }
    }
  }

  renderer->SetPass(nullptr);
  renderer->UseFXAAOff();
  mlaa->ReleaseGraphicsResources(window);
  for (auto& pass : longLinePasses)
  {
    pass->ReleaseGraphicsResources(window);
  }
  for (auto& pass : variantPasses)
  {
    pass->ReleaseGraphicsResources(window);
  }
  for (auto& pass : samplePasses)
  {
    pass->ReleaseGraphicsResources(window);
  }
  fxaa->ReleaseGraphicsResources(window);
  dlaa->ReleaseGraphicsResources(window);
  mlaaTemporal->ReleaseGraphicsResources(window);
  dlaaTemporal->ReleaseGraphicsResources(window);
  mlaaTemporalSamples->ReleaseGraphicsResources(window);
  steps->ReleaseGraphicsResources(window);
  return EXIT_SUCCESS;
}
