// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Translucent geometry and volumes under the pass (issue 21), for every method of PassMethods():
// the pass (delegate: the standard render steps, as the README's recipe and vtkmlaa.enable set
// it up) draws translucency the way the renderer does on its own, so that in every case below
// - the pass's result equals the method's CPU filter run on the renderer's own screenshot (no
//   pass) within 2/255 on at least 99.5 % of the pixels,
// - away from the pixels the filter changes (2 pixels around them), the result is the
//   renderer's own screenshot within 1/255, and the pass antialiased more than 50 pixels,
// - the delegate's translucent and volume steps are the user's objects again after the render,
//   and no error is reported.
// Cases: three spheres (one opaque, two of opacity 0.4 and 0.5) on white with order-independent
// translucency (UseDepthPeeling off), then, on the same renderer and pass, dual depth peeling
// (UseDepthPeeling on), dual depth peeling stopped after one peel (MaximumNumberOfPeels 1) or
// early by OcclusionRatio 0.5, and order-independent translucency again: decided at each render from the renderer's settings;
// vtkDepthPeelingPass (VTK_USE_LEGACY_DEPTH_PEELING set, as the renderer then uses it); a
// volume (GPU ray casting) with translucent and opaque geometry, with the volume in its own step
// and with UseDepthPeelingForVolumes (volumes peeled with the geometry), and, as the renderer
// does, in its own step with UseDepthPeelingForVolumes but without UseDepthPeeling or without
// translucent geometry; translucent geometry on a transparent background (BackgroundAlpha 0,
// KeepAlpha, read back as RGBA), with each translucency method; the spheres on layer 1 over an
// opaque sphere on layer 0 (the pass composites layer 1's premultiplied image: the filter runs
// on layer 1's image alone, as the renderer draws it, composited over layer 0's), with
// order-independent translucency and dual depth peeling; for MLAA, depth edges (the delegate
// renders into the pass's own framebuffer: its depth buffer must serve OIT and peeling) against
// the filter given the window's z-buffer. Last, a translucent step of the user's own (not a vtkTranslucentPass) is left alone:
// it renders, stays in place, and the result is the filter on the render of those steps without
// antialiasing, which differs from the renderer's order-independent translucency (so the
// scene tells the two apart).
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkConeSource.h"
#include "vtkGPUVolumeRayCastMapper.h"
#include "vtkOpenGLRenderer.h"
#include "vtkPiecewiseFunction.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRTAnalyticSource.h"
#include "vtkObjectFactory.h"
#include "vtkRenderPass.h"
#include "vtkRenderState.h"
#include "vtkSphereSource.h"
#include "vtkTranslucentPass.h"
#include "vtkVolume.h"
#include "vtkVolumeProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cstdlib>
#include <iomanip>

using namespace vtkMLAATest;

namespace
{
// A volume (the wavelet, ray cast on the GPU) with a translucent sphere through it and an opaque
// cone beside it, on a dark background; returns the sphere.
vtkActor* BuildVolumeScene(vtkRenderer* renderer)
{
  renderer->SetBackground(0.1, 0.1, 0.2);
  vtkNew<vtkRTAnalyticSource> wavelet;
  wavelet->SetWholeExtent(-15, 15, -15, 15, -15, 15);
  vtkNew<vtkGPUVolumeRayCastMapper> mapper;
  mapper->SetInputConnection(wavelet->GetOutputPort());
  vtkNew<vtkColorTransferFunction> colours;
  colours->AddRGBPoint(40.0, 0.1, 0.3, 1.0);
  colours->AddRGBPoint(160.0, 1.0, 0.9, 0.2);
  colours->AddRGBPoint(280.0, 1.0, 0.2, 0.1);
  vtkNew<vtkPiecewiseFunction> opacities;
  opacities->AddPoint(40.0, 0.0);
  opacities->AddPoint(280.0, 0.3);
  vtkNew<vtkVolumeProperty> property;
  property->SetColor(colours);
  property->SetScalarOpacity(opacities);
  property->SetInterpolationTypeToLinear();
  vtkNew<vtkVolume> volume;
  volume->SetMapper(mapper);
  volume->SetProperty(property);
  renderer->AddVolume(volume);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(6.0, 4.0, 2.0);
  sphere->SetRadius(9.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(0.9, 0.9, 0.9);
  sphereActor->GetProperty()->SetOpacity(0.35);
  renderer->AddActor(sphereActor);

  vtkNew<vtkConeSource> cone;
  cone->SetCenter(-17.0, -5.0, 0.0);
  cone->SetHeight(12.0);
  cone->SetRadius(5.0);
  cone->SetResolution(9);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.9, 0.5, 0.2);
  renderer->AddActor(coneActor);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(25);
  renderer->GetActiveCamera()->Elevation(15);
  return sphereActor;
}

// A translucent step of the user's own: draws with VTK's plain (unsorted) blending through a
// vtkTranslucentPass, and counts its renders.
class UserTranslucentPass : public vtkRenderPass
{
public:
  static UserTranslucentPass* New() { return new UserTranslucentPass; }
  vtkTypeMacro(UserTranslucentPass, vtkRenderPass);
  int Renders = 0;
  void Render(const vtkRenderState* s) override
  {
    ++this->Renders;
    this->Plain->Render(s);
    this->NumberOfRenderedProps = this->Plain->GetNumberOfRenderedProps();
  }

private:
  vtkNew<vtkTranslucentPass> Plain;
};

// The pass's `result` against `expected`, what the method's filter makes of the renderer's own
// image `plain`: within 2/255 on >= 99.5 % of the pixels; away from the pixels where `expected`
// differs from `plain` (by more than `edgeTolerance`), the renderer's own within 1/255;
// antialiased.
void CheckAgainst(const PassMethod& method, vtkImageData* plain, vtkImageData* result,
  vtkImageData* expected, const std::string& what, double edgeTolerance = 0.0)
{
  const Difference parity = Compare(expected, result, 2.0);
  const double share =
    parity.Count < 0 ? 0.0 : 1.0 - static_cast<double>(parity.Pixels) / parity.Total;

  // Pixels within 2 of one the filter changes: near an edge. The others must be the renderer's.
  int dims[3];
  plain->GetDimensions(dims);
  const int components = plain->GetNumberOfScalarComponents();
  std::vector<bool> edge(static_cast<size_t>(dims[0]) * dims[1], false);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      for (int k = 0; k < components; ++k)
      {
        if (std::abs(GetValue(expected, x, y, k) - GetValue(plain, x, y, k)) > edgeTolerance)
        {
          edge[static_cast<size_t>(y) * dims[0] + x] = true;
        }
      }
    }
  }
  vtkIdType away = 0, awayOff = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool near = false;
      for (int dy = -2; dy <= 2 && !near; ++dy)
      {
        for (int dx = -2; dx <= 2 && !near; ++dx)
        {
          const int nx = x + dx, ny = y + dy;
          near = nx >= 0 && ny >= 0 && nx < dims[0] && ny < dims[1] &&
            edge[static_cast<size_t>(ny) * dims[0] + nx];
        }
      }
      if (near)
      {
        continue;
      }
      ++away;
      for (int k = 0; k < components; ++k)
      {
        if (std::abs(GetValue(result, x, y, k) - GetValue(plain, x, y, k)) > 1.0)
        {
          ++awayOff;
          break;
        }
      }
    }
  }
  const Difference changed = Compare(plain, result, 0.0);
  std::cout << method.Name << ", " << what << ": " << std::fixed << std::setprecision(2)
            << 100.0 * share << " % of pixels within 2/255 of the filter (largest difference "
            << parity.Max << "), " << awayOff << " of " << away
            << " pixels away from edges off the renderer's by more than 1/255, " << changed.Pixels
            << " antialiased" << std::endl;
  Check(share >= 0.995, (what + ": the filter's result").c_str(), __FILE__, __LINE__);
  Check(awayOff == 0, (what + ": the renderer's pixels away from edges").c_str(), __FILE__,
    __LINE__);
  Check(away > parity.Total / 2, (what + ": most pixels are away from edges").c_str(), __FILE__,
    __LINE__);
  Check(changed.Pixels > 50, (what + ": antialiased").c_str(), __FILE__, __LINE__);
  if (share < 0.995 || awayOff)
  {
    const std::string name = std::string(method.Name) + "-translucency";
    WritePNG(plain, name + "-renderer.png");
    WritePNG(result, name + "-pass.png");
    WritePNG(expected, name + "-filter.png");
  }
}

// The translucent and volume steps of `pass`'s delegate. (Their reference counts are not
// compared: vtkRenderStepsPass keeps the steps of its last render in a collection of its own.)
struct StepsSnapshot
{
  vtkRenderPass* Translucent = nullptr;
  vtkRenderPass* Volumetric = nullptr;
  explicit StepsSnapshot(vtkOpenGLAntialiasingPass* pass)
  {
    auto* steps = vtkRenderStepsPass::SafeDownCast(pass->GetDelegatePass());
    this->Translucent = steps->GetTranslucentPass();
    this->Volumetric = steps->GetVolumetricPass();
  }
  bool operator==(const StepsSnapshot& o) const
  {
    return this->Translucent == o.Translucent && this->Volumetric == o.Volumetric;
  }
};

// Sets what a renderer's GetLastRenderingUsedDepthPeeling returns (a render pass may).
class PeelingReport : public vtkRenderPass
{
public:
  static PeelingReport* New();
  vtkTypeMacro(PeelingReport, vtkRenderPass);
  void Render(const vtkRenderState*) override {}
  void Set(vtkRenderer* renderer, bool value) { this->SetLastRenderingUsedDepthPeeling(renderer, value); }

protected:
  PeelingReport() = default;
};
vtkStandardNewMacro(PeelingReport);

// Renders `window` without the pass (the renderer's own translucency) and with `pass`, and
// checks the pass's result against the method's filter on the renderer's screenshot.
void CheckCase(const PassMethod& method, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkOpenGLAntialiasingPass* pass, const std::string& what, bool alpha = false)
{
  renderer->SetPass(nullptr);
  auto plain = vtkMLAAScenes::Capture(window, alpha);
  renderer->SetPass(pass);
  const StepsSnapshot before(pass);
  auto result = vtkMLAAScenes::Capture(window, alpha);
  Check(StepsSnapshot(pass) == before, (what + ": the delegate's steps as they were").c_str(),
    __FILE__, __LINE__);
  // GetLastRenderingUsedDepthPeeling says what it says without the pass, from either value
  // left by an earlier render (the renderer leaves it as it was when nothing is translucent).
  vtkNew<PeelingReport> report;
  for (const bool earlier : { false, true })
  {
    report->Set(renderer, earlier);
    renderer->SetPass(nullptr);
    window->Render();
    const bool plainPeeled = renderer->GetLastRenderingUsedDepthPeeling() != 0;
    report->Set(renderer, earlier);
    renderer->SetPass(pass);
    window->Render();
    Check((renderer->GetLastRenderingUsedDepthPeeling() != 0) == plainPeeled,
      (what + ": GetLastRenderingUsedDepthPeeling as without the pass").c_str(), __FILE__,
      __LINE__);
  }
  CheckAgainst(method, plain, result, method.Filter(pass, plain), what);
}

// The image of the layer-1 renderer of `window` alone as the renderer draws it, premultiplied
// RGBA (what the pass composites): its colour over opaque black is the premultiplied colour, and
// its colour over opaque white less that is (1 - alpha) white. (Read back, the alpha VTK's
// order-independent translucency leaves is not the coverage.) `lower`: the layer-0 renderer.
vtkSmartPointer<vtkImageData> LayerImage(vtkRenderWindow* window, vtkRenderer* lower)
{
  double background[3];
  lower->GetBackground(background);
  SetVisibility(lower, false, false);
  lower->SetBackground(0.0, 0.0, 0.0);
  auto black = vtkMLAAScenes::Capture(window);
  lower->SetBackground(1.0, 1.0, 1.0);
  auto white = vtkMLAAScenes::Capture(window);
  lower->SetBackground(background);
  SetVisibility(lower, true, true);
  int dims[3];
  black->GetDimensions(dims);
  auto layer = MakeImage(dims[0], dims[1], 4);
  FillImage(layer, [&](int x, int y, int, int k) {
    if (k < 3)
    {
      return GetValue(black, x, y, k);
    }
    double transmitted = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      transmitted += (GetValue(white, x, y, c) - GetValue(black, x, y, c)) / 3.0;
    }
    return std::round(255.0 - transmitted);
  });
  return layer;
}

// A 400 x 300 window with one renderer.
struct Window
{
  vtkSmartPointer<vtkRenderWindow> RenderWindow = vtkMLAAScenes::NewOffscreenWindow(400, 300);
  vtkNew<vtkRenderer> Renderer;
  Window() { this->RenderWindow->AddRenderer(this->Renderer); }
  ~Window() { StopPass(this->Renderer, this->RenderWindow); }
};
}

int TestAntialiasingPassTranslucency(int, char*[])
{
  // The cases named "dual depth peeling" are dual where the driver allows it.
  unsetenv("VTK_USE_LEGACY_DEPTH_PEELING");
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    {
      // Each translucency method in turn on one renderer and pass: chosen at each render.
      Window w;
      BuildTranslucentSpheres(w.Renderer);
      vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(w.Renderer);
      messages->Watch(pass);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, order-independent");
      w.Renderer->UseDepthPeelingOn();
      w.Renderer->SetMaximumNumberOfPeels(100);
      w.Renderer->SetOcclusionRatio(0.0);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, dual depth peeling");
      w.Renderer->SetPass(nullptr);
      auto allPeels = vtkMLAAScenes::Capture(w.RenderWindow);
      w.Renderer->SetMaximumNumberOfPeels(1);
      auto onePeel = vtkMLAAScenes::Capture(w.RenderWindow);
      std::cout << "one peel against all: " << Compare(allPeels, onePeel, 0.0).Pixels
                << " pixels differ" << std::endl;
      MLAA_CHECK(Compare(allPeels, onePeel, 0.0).Pixels > 100);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, one peel");
      w.Renderer->SetMaximumNumberOfPeels(100);
      w.Renderer->SetOcclusionRatio(0.5);
      w.Renderer->SetPass(nullptr);
      const vtkIdType occluded =
        Compare(allPeels, vtkMLAAScenes::Capture(w.RenderWindow), 0.0).Pixels;
      std::cout << "occlusion ratio 0.5 against 0: " << occluded << " pixels differ" << std::endl;
      MLAA_CHECK(occluded > 100);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, occlusion ratio 0.5");
      w.Renderer->SetOcclusionRatio(0.0);
      w.Renderer->UseDepthPeelingOff();
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, order-independent again");

      // A transparent background, read back as RGBA, with each translucency method.
      w.Renderer->SetBackgroundAlpha(0.0);
      pass->KeepAlphaOn();
      CheckCase(method, w.RenderWindow, w.Renderer, pass,
        "spheres, transparent background, order-independent", true);
      w.Renderer->UseDepthPeelingOn();
      w.Renderer->SetMaximumNumberOfPeels(100);
      CheckCase(method, w.RenderWindow, w.Renderer, pass,
        "spheres, transparent background, dual depth peeling", true);
    }
    {
      // The renderer's other depth peeling, where dual depth peeling is unsupported (or, as
      // here, VTK_USE_LEGACY_DEPTH_PEELING is set): the pass follows the renderer's choice.
      Window dual;
      BuildTranslucentSpheres(dual.Renderer);
      dual.Renderer->UseDepthPeelingOn();
      auto dualImage = vtkMLAAScenes::Capture(dual.RenderWindow);
      const bool dualSupported =
        vtkOpenGLRenderer::SafeDownCast(dual.Renderer)->IsDualDepthPeelingSupported();
      setenv("VTK_USE_LEGACY_DEPTH_PEELING", "1", 1);
      {
        Window w;
        BuildTranslucentSpheres(w.Renderer);
        w.Renderer->UseDepthPeelingOn();
        // The renderer's own image shows that it peels differently now.
        const vtkIdType differ =
          Compare(dualImage, vtkMLAAScenes::Capture(w.RenderWindow), 0.0).Pixels;
        std::cout << "depth peeling against dual depth peeling: " << differ << " pixels differ"
                  << std::endl;
        MLAA_CHECK(!dualSupported || differ > 100);
        vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(w.Renderer);
        messages->Watch(pass);
        CheckCase(method, w.RenderWindow, w.Renderer, pass, "spheres, depth peeling");
      }
      unsetenv("VTK_USE_LEGACY_DEPTH_PEELING");
    }
    {
      // A volume with geometry: in the volume step (order-independent translucency for the
      // geometry), and peeled with the geometry.
      Window w;
      vtkActor* sphere = BuildVolumeScene(w.Renderer);
      vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(w.Renderer);
      messages->Watch(pass);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "volume, order-independent");
      w.Renderer->SetPass(nullptr);
      auto volumeStep = vtkMLAAScenes::Capture(w.RenderWindow);
      w.Renderer->UseDepthPeelingOn();
      w.Renderer->UseDepthPeelingForVolumesOn();
      auto peeled = vtkMLAAScenes::Capture(w.RenderWindow);
      std::cout << "volume peeled against volume step: " << Compare(volumeStep, peeled, 0.0).Pixels
                << " pixels differ" << std::endl;
      MLAA_CHECK(Compare(volumeStep, peeled, 0.0).Pixels > 100);
      CheckCase(method, w.RenderWindow, w.Renderer, pass, "volume, peeled with the geometry");
      // The renderer peels volumes only along with translucent geometry, and only when it peels.
      w.Renderer->UseDepthPeelingOff();
      CheckCase(method, w.RenderWindow, w.Renderer, pass,
        "volume, UseDepthPeelingForVolumes without UseDepthPeeling");
      w.Renderer->UseDepthPeelingOn();
      sphere->GetProperty()->SetOpacity(1.0);
      CheckCase(method, w.RenderWindow, w.Renderer, pass,
        "volume, UseDepthPeelingForVolumes without translucent geometry");
    }
    {
      // A renderer on layer 1 (composited over layer 0 by the pass).
      vtkSmartPointer<vtkRenderWindow> window = vtkMLAAScenes::NewOffscreenWindow(400, 300);
      window->SetNumberOfLayers(2);
      vtkNew<vtkRenderer> lower;
      lower->SetBackground(0.3, 0.3, 0.35);
      AddColoredSphere(lower, 0.0, 0.0, -2.5, 0.9, 0.8, 0.2, 1.0);
      vtkNew<vtkRenderer> upper;
      upper->SetLayer(1);
      BuildTranslucentSpheres(upper);
      lower->SetActiveCamera(upper->GetActiveCamera());
      window->AddRenderer(lower);
      window->AddRenderer(upper);
      vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(upper);
      method.UsePremultipliedAlpha(pass);
      messages->Watch(pass);
      for (const bool peeling : { false, true })
      {
        upper->SetUseDepthPeeling(peeling);
        upper->SetPass(nullptr);
        auto plain = vtkMLAAScenes::Capture(window);
        SetVisibility(upper, false, false);
        auto lowerOnly = vtkMLAAScenes::Capture(window);
        SetVisibility(upper, true, true);
        auto layer = LayerImage(window, lower);
        upper->SetPass(pass);
        auto result = vtkMLAAScenes::Capture(window);
        CheckAgainst(method, plain, result, Over(method.Filter(pass, layer), lowerOnly),
          peeling ? "layer 1, dual depth peeling" : "layer 1, order-independent", 1.0);
      }
      StopPass(upper, window);
    }
    if (std::string(method.Name) == "vtkOpenGLMLAAPass")
    {
      // Depth edges: the delegate renders into the pass's framebuffer, whose depth buffer OIT and
      // peeling read. The filter gets the window's z-buffer (translucency does not write depth).
      for (const bool peeling : { false, true })
      {
        Window w;
        BuildTranslucentSpheres(w.Renderer);
        w.Renderer->SetUseDepthPeeling(peeling);
        auto plain = vtkMLAAScenes::Capture(w.RenderWindow);
        auto depth = ZBuffer(w.RenderWindow);
        vtkNew<vtkMLAAOptions> options;
        options->SetEdgeDetectionToDepth();
        options->SetThreshold(0.005);
        auto pass = UseMLAA(w.Renderer, options);
        messages->Watch(pass);
        auto result = vtkMLAAScenes::Capture(w.RenderWindow);
        vtkNew<vtkImageMLAA> filter;
        filter->SetOptions(options);
        filter->SetInputData(plain);
        filter->SetDepthInputData(depth);
        filter->Update();
        CheckAgainst(method, plain, result, filter->GetOutput(),
          peeling ? "spheres, depth edges, dual depth peeling"
                  : "spheres, depth edges, order-independent");
      }
    }
    {
      // A translucent step of the user's own is left alone.
      Window w;
      BuildTranslucentSpheres(w.Renderer);
      auto oit = vtkMLAAScenes::Capture(w.RenderWindow);
      vtkNew<vtkRenderStepsPass> plainSteps;
      vtkNew<UserTranslucentPass> userStep;
      plainSteps->SetTranslucentPass(userStep);
      w.Renderer->SetPass(plainSteps);
      auto unsorted = vtkMLAAScenes::Capture(w.RenderWindow);
      plainSteps->ReleaseGraphicsResources(w.RenderWindow);
      vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(w.Renderer);
      messages->Watch(pass);
      vtkRenderStepsPass::SafeDownCast(pass->GetDelegatePass())->SetTranslucentPass(userStep);
      userStep->Renders = 0;
      auto result = vtkMLAAScenes::Capture(w.RenderWindow);
      const vtkIdType unsortedOff = Compare(oit, unsorted, 2.0).Pixels;
      std::cout << "plain blending against order-independent: " << unsortedOff
                << " pixels off by more than 2/255" << std::endl;
      MLAA_CHECK(unsortedOff > 1000);
      MLAA_CHECK(userStep->Renders >= 1);
      MLAA_CHECK(
        vtkRenderStepsPass::SafeDownCast(pass->GetDelegatePass())->GetTranslucentPass() == userStep);
      CheckAgainst(method, unsorted, result, method.Filter(pass, unsorted),
        "spheres, the user's own translucent step");
    }
  });
  return Result();
}
