// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-temporal: the temporal-stability measure of the project's MEASURING.md.
//
// For each scene it renders a slow camera orbit of K frames (the camera turned about its focal
// point by a fixed angle a frame, vtkCamera::Azimuth; --motion moves it otherwise: up over the
// focal point, rolled about the direction of view, or towards the focal point) with every
// method, and per frame the
// supersampled reference of MEASURING.md (N x N single-sample renders with the projection
// shifted by stratified sub-pixel offsets, averaged). Flicker and crawl are the frame-to-frame
// changes that the reference does not have:
//   TE(method)  = mean over frames k >= 1, pixels and the three colour channels of
//                 |(M_k - M_{k-1}) - (R_k - R_{k-1})|, in 1/255 units;
//   T-AAR       = 1 - TE(method) / TE(none): the share of the plain render's temporal error that
//                 the method removes (0: no steadier than no antialiasing; 1: as steady as the
//                 reference; negative: it adds flicker).
// It also reports each method's spatial AAR (1 - MSE(method, reference) / MSE(none, reference)
// over the pixels where none and the reference differ by more than 4/255, all frames pooled),
// so that stability and still-image quality can be read side by side.
//
// Methods: none (single-sample), FXAA (VTK's built-in, renderer->UseFXAAOn()), MSAA4
// (window->SetMultiSamples(4)) and vtkOpenGLMLAAPass at each preset of vtkMLAAOptions
// (MLAA-low ... MLAA-ultra; overlays drawn after the antialiasing), the MLAA pass with 4 samples
// (SetMultiSamples(4): MLAA-S4), vtkOpenGLDLAAPass with its default options (DLAA; with 4
// samples: DLAA-S4), and both passes with temporal antialiasing (SetTemporal; MLAA-temporal,
// DLAA-temporal; with 4 samples too: MLAA-temporal-S4, DLAA-temporal-S4), each one pass kept from
// frame to frame of a scene, as an application renders an orbit. Frames are read back as 8-bit
// RGB.
// Per method it also reports the still AAR: the AAR of the last frame once the camera stops, after
// 16 renders of the unchanged scene (methods without history give the same image at every render).
#include "BenchmarkUtilities.h"
#include "vtkMLAAScenes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Frame = std::vector<double>; // 3 values per pixel, 0..255

Frame Grab(vtkRenderWindow* window)
{
  vtkSmartPointer<vtkImageData> image = vtkMLAAScenes::Capture(window);
  const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
  int dims[3];
  image->GetDimensions(dims);
  return Frame(p, p + static_cast<std::size_t>(dims[0]) * dims[1] * 3);
}

// A way of rendering one frame.
struct Method
{
  std::string Name;
  std::function<void(vtkRenderer*, vtkRenderWindow*)> Enable;
  std::function<void(vtkRenderer*, vtkRenderWindow*)> Disable;
  // Methods with a history (temporal antialiasing) keep their pass from frame to frame of a
  // scene; Finish releases it at the end of the scene.
  bool Temporal = false;
  std::function<void(vtkRenderWindow*)> Finish;
};

// A temporal pass of class `Pass` kept across the frames of a scene (rendered as an application
// would render it, frame after frame; the other methods' renders in between change neither the
// camera nor the scene).
template <class Pass>
Method TemporalMethod(const std::string& name, int samples = 0)
{
  auto pass = std::make_shared<vtkSmartPointer<Pass>>();
  Method method;
  method.Name = name;
  method.Temporal = true;
  method.Enable = [pass, samples](vtkRenderer* r, vtkRenderWindow*) {
    if (!*pass)
    {
      *pass = vtkSmartPointer<Pass>::New();
      vtkNew<vtkRenderStepsPass> steps;
      (*pass)->SetDelegatePass(steps);
      (*pass)->TemporalOn();
      (*pass)->SetMultiSamples(samples);
    }
    r->SetPass(*pass);
  };
  method.Disable = [](vtkRenderer* r, vtkRenderWindow*) { r->SetPass(nullptr); };
  method.Finish = [pass](vtkRenderWindow* w) {
    if (*pass)
    {
      (*pass)->ReleaseGraphicsResources(w);
      *pass = nullptr;
    }
  };
  return method;
}

// A single-frame pass of class `Pass`, made afresh for each frame with `configure` applied, and
// released after it.
template <class Pass, class Configure>
Method FramePassMethod(const std::string& name, Configure configure)
{
  return Method{ name,
    [configure](vtkRenderer* r, vtkRenderWindow*) {
      vtkNew<vtkRenderStepsPass> steps;
      vtkNew<Pass> pass;
      pass->SetDelegatePass(steps);
      configure(pass.Get());
      r->SetPass(pass);
    },
    [](vtkRenderer* r, vtkRenderWindow* w) {
      if (r->GetPass())
      {
        r->GetPass()->ReleaseGraphicsResources(w);
      }
      r->SetPass(nullptr);
    },
    false, nullptr };
}

std::vector<Method> Methods()
{
  std::vector<Method> methods;
  auto nothing = [](vtkRenderer*, vtkRenderWindow*) {};
  methods.push_back(Method{ "none", nothing, nothing, false, nullptr });
  methods.push_back(Method{ "FXAA", [](vtkRenderer* r, vtkRenderWindow*) { r->UseFXAAOn(); },
    [](vtkRenderer* r, vtkRenderWindow*) { r->UseFXAAOff(); }, false, nullptr });
  methods.push_back(Method{ "MSAA4", [](vtkRenderer*, vtkRenderWindow* w) { w->SetMultiSamples(4); },
    [](vtkRenderer*, vtkRenderWindow* w) { w->SetMultiSamples(0); }, false, nullptr });
  for (int preset = vtkMLAAOptions::LOW; preset <= vtkMLAAOptions::ULTRA; ++preset)
  {
    methods.push_back(FramePassMethod<vtkOpenGLMLAAPass>(
      std::string("MLAA-") + vtkMLAAOptions::GetPresetAsString(preset),
      [preset](vtkOpenGLMLAAPass* pass) { pass->GetOptions()->SetPreset(preset); }));
  }
  methods.push_back(FramePassMethod<vtkOpenGLMLAAPass>(
    "MLAA-S4", [](vtkOpenGLMLAAPass* pass) { pass->SetMultiSamples(4); }));
  methods.push_back(FramePassMethod<vtkOpenGLDLAAPass>("DLAA", [](vtkOpenGLDLAAPass*) {}));
  methods.push_back(FramePassMethod<vtkOpenGLDLAAPass>(
    "DLAA-S4", [](vtkOpenGLDLAAPass* pass) { pass->SetMultiSamples(4); }));
  methods.push_back(TemporalMethod<vtkOpenGLMLAAPass>("MLAA-temporal"));
  methods.push_back(TemporalMethod<vtkOpenGLDLAAPass>("DLAA-temporal"));
  methods.push_back(TemporalMethod<vtkOpenGLMLAAPass>("MLAA-temporal-S4", 4));
  methods.push_back(TemporalMethod<vtkOpenGLDLAAPass>("DLAA-temporal-S4", 4));
  return methods;
}

// Writes `frame` (rows bottom to top, as read back) as a binary PPM, top row first.
bool WritePPM(const std::string& path, const Frame& frame, int width, int height)
{
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << width << " " << height << "\n255\n";
  std::vector<unsigned char> row(static_cast<std::size_t>(width) * 3);
  for (int y = height - 1; y >= 0; --y)
  {
    for (std::size_t v = 0; v < row.size(); ++v)
    {
      row[v] = static_cast<unsigned char>(
        std::lround(std::min(255.0, std::max(0.0, frame[y * row.size() + v]))));
    }
    out.write(reinterpret_cast<const char*>(row.data()), static_cast<std::streamsize>(row.size()));
  }
  return static_cast<bool>(out);
}

// AAR of MEASURING.md: 1 - MSE_E(method, reference) / MSE_E(none, reference) over the values of
// the pixels where none and the reference differ by more than 4/255 in some channel.
double AAR(const Frame& none, const Frame& method, const Frame& reference)
{
  double sumNone = 0.0, sumMethod = 0.0;
  for (std::size_t p = 0; p < none.size(); p += 3)
  {
    bool inE = false;
    for (int c = 0; c < 3; ++c)
    {
      inE = inE || std::abs(none[p + c] - reference[p + c]) > 4.0;
    }
    for (int c = 0; inE && c < 3; ++c)
    {
      sumNone += (none[p + c] - reference[p + c]) * (none[p + c] - reference[p + c]);
      sumMethod += (method[p + c] - reference[p + c]) * (method[p + c] - reference[p + c]);
    }
  }
  return sumNone > 0.0 ? 1.0 - sumMethod / sumNone : 0.0;
}

struct Result
{
  double TE = 0.0;         // mean temporal error, 1/255 units
  double SpatialSSE = 0.0; // squared error against the reference over E, all frames
  double StillAAR = 0.0;   // AAR of the last frame's still after StillRenders renders
};

// Renders of the unchanged last frame after which the stills are measured (a method without
// history gives the same image at every render).
constexpr int StillRenders = 16;

void Usage(const char* program)
{
  std::cout << "Usage: " << program << " [options]\n"
            << "Measures temporal stability against a supersampled reference sequence "
               "(MEASURING.md).\n"
            << "  --size WxH        render size (default 400x300)\n"
            << "  --scenes a,b,c    scenes (default horizon,thin,texture,silhouettes,orbit);\n"
            << "                    \"all\" and \"held-out\" stand for vtkMLAAScenes' lists (the\n"
            << "                    held-out scenes are kept out of tuning, as in mlaa-quality)\n"
            << "  --frames K        frames of the orbit (default 60)\n"
            << "  --degrees D       camera step per frame (default 0.25): degrees of azimuth,\n"
            << "                    elevation or roll; for dolly, D % closer to the focal point\n"
            << "                    (a parallel projection: magnified as much)\n"
            << "  --motion M        azimuth (default), elevation, roll or dolly: how the camera\n"
            << "                    moves (vtkCamera's Azimuth, Elevation, Roll, Dolly)\n"
            << "  --samples N       reference is N x N shifted renders per frame (default 8)\n"
            << "  --methods a,b,c   methods measured (default all; none, the T-AAR's baseline, always)\n"
            << "  --output-dir DIR  where temporal.csv goes (default .)\n"
            << "  --write-frames    also write every frame of every method and the reference as\n"
            << "                    DIR/frames/<scene>-<method>-<k>.ppm (binary PPM, 8-bit RGB)\n"
            << "  --require-t-aar M fail (exit status 1) where a method's T-AAR is below M on a\n"
            << "                    scene: a regression check\n";
}

// The camera's motions (--motion), the first the default.
const std::array<std::string, 4> Motions = { "azimuth", "elevation", "roll", "dolly" };

// One frame's step of the camera (--motion, --degrees).
void MoveCamera(vtkCamera* camera, const std::string& motion, double step)
{
  if (motion == "elevation")
  {
    camera->Elevation(step);
    camera->OrthogonalizeViewUp(); // (Elevation leaves the view-up as it was)
  }
  else if (motion == "roll")
  {
    camera->Roll(step);
  }
  else if (motion == "dolly")
  {
    // Closer by step %: a parallel projection shows the same picture from any distance, and
    // magnifies it by its scale instead.
    const double factor = 1.0 / (1.0 - step / 100.0);
    if (camera->GetParallelProjection())
    {
      camera->Zoom(factor);
    }
    else
    {
      camera->Dolly(factor);
    }
  }
  else
  {
    camera->Azimuth(step);
  }
}
}

int main(int argc, char* argv[])
{
  int width = 400, height = 300, frames = 60, samples = 8;
  double degrees = 0.25;
  std::string motion = Motions[0];
  std::vector<std::string> scenes = { "horizon", "thin", "texture", "silhouettes", "orbit" };
  std::string outputDir = ".";
  std::vector<std::string> chosen; // empty: every method
  bool writeFrames = false;
  double requiredTAAR = -std::numeric_limits<double>::infinity();
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
    else if (arg == "--scenes" && hasValue)
    {
      scenes = mlaaBenchmark::SceneList(argv[++i]);
    }
    else if (arg == "--frames" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], frames) &&
      frames >= 2)
    {
      ++i;
    }
    else if (arg == "--degrees" && hasValue &&
      mlaaBenchmark::ParseNumber(argv[i + 1], 0.0, 10.0, degrees))
    {
      ++i;
    }
    else if (arg == "--motion" && hasValue &&
      std::find(Motions.begin(), Motions.end(), argv[i + 1]) != Motions.end())
    {
      motion = argv[++i];
    }
    else if (arg == "--samples" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], samples))
    {
      ++i;
    }
    else if (arg == "--write-frames")
    {
      writeFrames = true;
    }
    else if (arg == "--methods" && hasValue)
    {
      chosen = mlaaBenchmark::SplitList(argv[++i]);
    }
    else if (arg == "--require-t-aar" && hasValue &&
      mlaaBenchmark::ParseNumber(argv[i + 1], -1e9, 1.0, requiredTAAR))
    {
      ++i;
    }
    else if (arg == "--output-dir" && hasValue)
    {
      outputDir = argv[++i];
    }
    else
    {
      std::cerr << "bad or incomplete argument: " << arg << std::endl;
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  for (const auto& scene : scenes)
  {
    if (vtkMLAAScenes::Describe(scene).empty())
    {
      std::cerr << "unknown scene: " << scene << std::endl;
      return EXIT_FAILURE;
    }
  }
  std::error_code directoryError;
  std::filesystem::create_directories(outputDir, directoryError);
  if (directoryError)
  {
    std::cerr << "mlaa-temporal: cannot create " << outputDir << ": " << directoryError.message()
              << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << "mlaa-temporal: " << width << "x" << height << ", " << frames << " frames, "
            << degrees << (motion == "dolly" ? " % of dolly" : " degree(s) of " + motion)
            << " a frame, reference " << samples << "x" << samples
            << " shifted renders a frame" << std::endl;
  std::vector<Method> methods;
  {
    std::vector<Method> all = Methods();
    for (const auto& name : chosen)
    {
      bool known = false;
      for (const auto& method : all)
      {
        known = known || method.Name == name;
      }
      if (!known)
      {
        std::cerr << "unknown method: " << name << " (known:";
        for (const auto& method : all)
        {
          std::cerr << " " << method.Name;
        }
        std::cerr << ")" << std::endl;
        return EXIT_FAILURE;
      }
    }
    for (auto& method : all)
    {
      bool wanted = chosen.empty() || method.Name == "none";
      for (const auto& name : chosen)
      {
        wanted = wanted || method.Name == name;
      }
      if (wanted)
      {
        methods.push_back(std::move(method));
      }
    }
  }
  std::map<std::string, std::map<std::string, Result>> results; // scene -> method -> result
  std::string rendererName;
  const std::size_t values = static_cast<std::size_t>(width) * height * 3;
  for (const auto& scene : scenes)
  {
    mlaaBenchmark::Stopwatch clock;
    auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build(scene, renderer);
    vtkCamera* camera = renderer->GetActiveCamera();
    double center[2];
    camera->GetWindowCenter(center);
    if (rendererName.empty())
    {
      window->Render();
      rendererName = mlaaBenchmark::OpenGLRenderer(window);
      mlaaBenchmark::PrintRasteriserNote(rendererName);
    }

    std::map<std::string, Frame> previous;
    Frame previousReference;
    std::map<std::string, double> sumTE, sumSSE;
    double sumNoneSSE = 0.0;
    for (int k = 0; k < frames; ++k)
    {
      if (k > 0)
      {
        MoveCamera(camera, motion, degrees);
      }
      renderer->ResetCameraClippingRange();
      // The reference of this frame.
      Frame reference(values, 0.0);
      for (int j = 0; j < samples; ++j)
      {
        for (int i = 0; i < samples; ++i)
        {
          const double sx = (i + 0.5) / samples - 0.5;
          const double sy = (j + 0.5) / samples - 0.5;
          camera->SetWindowCenter(center[0] + 2.0 * sx / width, center[1] + 2.0 * sy / height);
          const Frame shifted = Grab(window);
          for (std::size_t v = 0; v < values; ++v)
          {
            reference[v] += shifted[v];
          }
        }
      }
      for (double& v : reference)
      {
        v /= static_cast<double>(samples) * samples;
      }
      camera->SetWindowCenter(center[0], center[1]);

      std::map<std::string, Frame> current;
      for (const auto& method : methods)
      {
        method.Enable(renderer, window);
        current[method.Name] = Grab(window);
        method.Disable(renderer, window);
      }
      if (writeFrames)
      {
        const std::string stem = outputDir + "/frames/" + scene + "-";
        std::filesystem::create_directories(outputDir + "/frames", directoryError);
        bool written = WritePPM(stem + "reference-" + std::to_string(k) + ".ppm", reference,
          width, height);
        for (const auto& method : methods)
        {
          written = written &&
            WritePPM(stem + method.Name + "-" + std::to_string(k) + ".ppm", current[method.Name],
              width, height);
        }
        if (!written)
        {
          std::cerr << "mlaa-temporal: cannot write the frames under " << outputDir << "/frames"
                    << std::endl;
          return EXIT_FAILURE;
        }
      }
      // Spatial error over E (none and reference differ by more than 4/255 in some channel).
      const Frame& none = current["none"];
      for (std::size_t p = 0; p < values; p += 3)
      {
        bool inE = false;
        for (int c = 0; c < 3; ++c)
        {
          inE = inE || std::abs(none[p + c] - reference[p + c]) > 4.0;
        }
        if (!inE)
        {
          continue;
        }
        for (int c = 0; c < 3; ++c)
        {
          const double dn = none[p + c] - reference[p + c];
          sumNoneSSE += dn * dn;
          for (const auto& method : methods)
          {
            const double d = current[method.Name][p + c] - reference[p + c];
            sumSSE[method.Name] += d * d;
          }
        }
      }
      // Temporal error against the reference's own change.
      if (k > 0)
      {
        for (const auto& method : methods)
        {
          const Frame& m = current[method.Name];
          const Frame& mp = previous[method.Name];
          double sum = 0.0;
          for (std::size_t v = 0; v < values; ++v)
          {
            sum += std::abs((m[v] - mp[v]) - (reference[v] - previousReference[v]));
          }
          sumTE[method.Name] += sum / values;
        }
      }
      if (k == frames - 1)
      {
        // The still: the camera stops at the last frame; a method with history renders it
        // StillRenders times in all (it has rendered it once).
        for (const auto& method : methods)
        {
          Frame still = current[method.Name];
          if (method.Temporal)
          {
            method.Enable(renderer, window);
            for (int n = 1; n < StillRenders; ++n)
            {
              still = Grab(window);
            }
            method.Disable(renderer, window);
          }
          results[scene][method.Name].StillAAR = AAR(current["none"], still, reference);
        }
      }
      previous = std::move(current);
      previousReference = std::move(reference);
    }
    for (const auto& method : methods)
    {
      Result& r = results[scene][method.Name];
      r.TE = sumTE[method.Name] / (frames - 1);
      r.SpatialSSE = sumNoneSSE > 0.0 ? sumSSE[method.Name] / sumNoneSSE : 0.0;
      if (method.Finish)
      {
        method.Finish(window);
      }
    }
    std::cout << "scene " << scene << " (" << vtkMLAAScenes::Describe(scene) << "): "
              << std::fixed << std::setprecision(1) << clock.Milliseconds() / 1000.0 << " s"
              << std::defaultfloat << std::endl;
  }

  // The table: per scene and method, then the means over the scenes.
  std::ofstream csv(outputDir + "/temporal.csv");
  csv << "scene,method,TE,T_AAR,AAR,still_AAR\n";
  std::cout << "\n"
            << std::left << std::setw(13) << "scene" << std::setw(15) << "method" << std::right
            << std::setw(9) << "TE" << std::setw(9) << "T-AAR" << std::setw(9) << "AAR"
            << std::setw(11) << "still AAR" << "\n";
  std::map<std::string, double> meanTAAR, meanAAR, meanStill, worstTAAR;
  std::vector<std::string> belowRequired;
  for (const auto& scene : scenes)
  {
    const double noneTE = results[scene]["none"].TE;
    for (const auto& method : methods)
    {
      const Result& r = results[scene][method.Name];
      const double tAAR = noneTE > 0.0 ? 1.0 - r.TE / noneTE : 0.0;
      const double aar = 1.0 - r.SpatialSSE;
      meanTAAR[method.Name] += tAAR / scenes.size();
      meanAAR[method.Name] += aar / scenes.size();
      meanStill[method.Name] += r.StillAAR / scenes.size();
      worstTAAR[method.Name] =
        worstTAAR.count(method.Name) ? std::min(worstTAAR[method.Name], tAAR) : tAAR;
      std::cout << std::left << std::setw(13) << scene << std::setw(15) << method.Name
                << std::right << std::fixed << std::setprecision(3) << std::setw(9) << r.TE
                << std::setw(9) << tAAR << std::setw(9) << aar << std::setw(11) << r.StillAAR
                << std::defaultfloat << "\n";
      csv << scene << "," << method.Name << "," << r.TE << "," << tAAR << "," << aar << ","
          << r.StillAAR << "\n";
      if (method.Name != "none" && !(tAAR >= requiredTAAR))
      {
        std::ostringstream what;
        what << method.Name << " on " << scene << ": T-AAR " << tAAR;
        belowRequired.push_back(what.str());
      }
    }
  }
  std::cout << "\n"
            << std::left << std::setw(15) << "method" << std::right << std::setw(12)
            << "mean T-AAR" << std::setw(13) << "worst T-AAR" << std::setw(10) << "mean AAR"
            << std::setw(16) << "mean still AAR" << "\n";
  for (const auto& method : methods)
  {
    std::cout << std::left << std::setw(15) << method.Name << std::right << std::fixed
              << std::setprecision(3) << std::setw(12) << meanTAAR[method.Name] << std::setw(13)
              << worstTAAR[method.Name] << std::setw(10) << meanAAR[method.Name] << std::setw(16)
              << meanStill[method.Name] << std::defaultfloat << "\n";
  }
  std::cout << "(still AAR: the last frame after " << StillRenders
            << " renders of the unchanged scene; methods without history render it once)\n";
  std::cout << "\nCSV: " << outputDir << "/temporal.csv" << std::endl;
  for (const auto& what : belowRequired)
  {
    std::cerr << "mlaa-temporal: below the required T-AAR " << requiredTAAR << ": " << what
              << std::endl;
  }
  return csv && belowRequired.empty() ? EXIT_SUCCESS : EXIT_FAILURE;
}
