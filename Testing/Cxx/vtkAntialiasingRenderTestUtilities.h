// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers for the offscreen rendering tests of the antialiasing passes (vtkOpenGLMLAAPass,
// vtkOpenGLDLAAPass): a renderer with a pass, the list of methods for the tests of
// vtkOpenGLAntialiasingPass's behaviour, crops, and a strict baseline comparison (VTK's own is
// too loose to show that antialiasing ran).
#ifndef vtkAntialiasingRenderTestUtilities_h
#define vtkAntialiasingRenderTestUtilities_h

#include "vtkMLAAScenes.h"
#include "vtkAntialiasingTestUtilities.h"

#include "vtkActor.h"
#include "vtkActor2D.h"
#include "vtkActor2DCollection.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkDLAAOptions.h"
#include "vtkDataObject.h"
#include "vtkExtractVOI.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkOpenGLAntialiasingPass.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>
#include <set>
#include <vector>

namespace vtkMLAATest
{
// Sets a pass of class `Pass` (delegate: the standard render steps) with `options` (its
// defaults when null) on a renderer.
template <class Pass, class Options>
vtkSmartPointer<Pass> UsePass(vtkRenderer* renderer, Options* options)
{
  vtkNew<vtkRenderStepsPass> steps;
  auto pass = vtkSmartPointer<Pass>::New();
  pass->SetDelegatePass(steps);
  if (options)
  {
    pass->SetOptions(options);
  }
  renderer->SetPass(pass);
  return pass;
}

inline vtkSmartPointer<vtkOpenGLMLAAPass> UseMLAA(
  vtkRenderer* renderer, vtkMLAAOptions* options = nullptr)
{
  return UsePass<vtkOpenGLMLAAPass>(renderer, options);
}

inline vtkSmartPointer<vtkOpenGLDLAAPass> UseDLAA(
  vtkRenderer* renderer, vtkDLAAOptions* options = nullptr)
{
  return UsePass<vtkOpenGLDLAAPass>(renderer, options);
}

// One antialiasing method of the render pass, for the tests of vtkOpenGLAntialiasingPass's
// behaviour that every method shares: its class name, a factory that sets a default-configured
// pass of the method (delegate: the standard render steps) on a renderer and returns it (the
// renderer holds it), its CPU twin: the method's filter, with the pass's options, on an image (the
// pass must match it within 2/255), and what a case asks of the method's options. PassMethods()
// lists them all; a new method is one more entry there.
struct PassMethod
{
  const char* Name;
  vtkOpenGLAntialiasingPass* (*Use)(vtkRenderer* renderer);
  vtkSmartPointer<vtkImageData> (*Filter)(vtkOpenGLAntialiasingPass* pass, vtkImageData* image);
  // Sets the options of the pass (which Filter hands to the CPU twin) for images of premultiplied
  // alpha, such as a layer's image over transparent black; a method that filters every channel
  // alike whatever the convention has nothing to set.
  void (*UsePremultipliedAlpha)(vtkOpenGLAntialiasingPass* pass);
};

inline const PassMethod& MLAAPassMethod()
{
  static const PassMethod method = { "vtkOpenGLMLAAPass",
    [](vtkRenderer* r) -> vtkOpenGLAntialiasingPass* { return UseMLAA(r); },
    [](vtkOpenGLAntialiasingPass* pass, vtkImageData* image) {
      return RunMLAA(image, static_cast<vtkOpenGLMLAAPass*>(pass)->GetOptions());
    },
    [](vtkOpenGLAntialiasingPass* pass) {
      static_cast<vtkOpenGLMLAAPass*>(pass)->GetOptions()->PremultipliedAlphaOn();
    } };
  return method;
}

inline const PassMethod& DLAAPassMethod()
{
  static const PassMethod method = { "vtkOpenGLDLAAPass",
    [](vtkRenderer* r) -> vtkOpenGLAntialiasingPass* { return UseDLAA(r); },
    [](vtkOpenGLAntialiasingPass* pass, vtkImageData* image) {
      return RunDLAA(image, static_cast<vtkOpenGLDLAAPass*>(pass)->GetOptions());
    },
    [](vtkOpenGLAntialiasingPass*) {} };
  return method;
}

inline const std::vector<PassMethod>& PassMethods()
{
  static const std::vector<PassMethod> methods = { MLAAPassMethod(), DLAAPassMethod() };
  return methods;
}

// Runs `test` for every method of PassMethods(), with an observer for the objects it makes to
// report their messages to, and checks that none reported an error.
inline void ForEachPassMethod(
  const std::function<void(const PassMethod& method, MessageObserver* messages)>& test)
{
  for (const auto& method : PassMethods())
  {
    std::cout << method.Name << std::endl;
    vtkNew<MessageObserver> messages;
    test(method, messages);
    for (const auto& e : messages->Errors)
    {
      std::cerr << method.Name << ": error: " << e << std::endl;
    }
    Check(messages->Errors.empty(), "no errors", __FILE__, __LINE__);
  }
}

// The pass's render equals the method's CPU filter on the plain RGB render within 2/255, and
// antialiases more than 50 pixels; `when` names the case in the messages.
inline void CheckParity(const PassMethod& method, vtkRenderWindow* window, vtkRenderer* renderer,
  vtkOpenGLAntialiasingPass* pass, const char* when)
{
  renderer->SetPass(nullptr);
  auto plain = vtkMLAAScenes::Capture(window);
  renderer->SetPass(pass);
  auto result = vtkMLAAScenes::Capture(window);
  auto expected = method.Filter(pass, plain);
  const Difference d = Compare(expected, result, 2.0);
  const Difference changed = Compare(plain, result, 0.0);
  std::cout << method.Name << ", " << when << ": " << d.Pixels
            << " pixels off by more than 2/255, " << changed.Pixels << " antialiased" << std::endl;
  Check(d.Count == 0, when, __FILE__, __LINE__);
  Check(changed.Pixels > 50, when, __FILE__, __LINE__);
}

// Removes the pass of `renderer` and releases its GL resources.
inline void StopPass(vtkRenderer* renderer, vtkRenderWindow* window)
{
  if (vtkRenderPass* pass = renderer->GetPass())
  {
    pass->ReleaseGraphicsResources(window);
    renderer->SetPass(nullptr);
  }
}

// The pixels [x0, x0 + w) x [y0, y0 + h) of an image.
inline vtkSmartPointer<vtkImageData> Crop(vtkImageData* image, int x0, int y0, int w, int h)
{
  vtkNew<vtkExtractVOI> voi;
  voi->SetInputData(image);
  voi->SetVOI(x0, x0 + w - 1, y0, y0 + h - 1, 0, 0);
  voi->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(voi->GetOutput());
  out->SetOrigin(0, 0, 0);
  int ext[6];
  out->GetExtent(ext);
  out->SetExtent(0, ext[1] - ext[0], 0, ext[3] - ext[2], 0, 0);
  return out;
}

// The premultiplied RGBA `upper` composited over the RGB `lower`: upper + (1 - alpha) lower.
inline vtkSmartPointer<vtkImageData> Over(vtkImageData* upper, vtkImageData* lower)
{
  int dims[3];
  lower->GetDimensions(dims);
  auto out = MakeImage(dims[0], dims[1], 3);
  FillImage(out, [&](int x, int y, int, int k) {
    const double a = GetValue(upper, x, y, 3) / 255.0;
    return std::min(
      255.0, std::round(GetValue(upper, x, y, k) + (1.0 - a) * GetValue(lower, x, y, k)));
  });
  return out;
}

// Shows or hides the 3D actors and the 2D actors (overlays) of a renderer.
inline void SetVisibility(vtkRenderer* renderer, bool actors3D, bool actors2D)
{
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
  {
    a->SetVisibility(actors3D);
  }
  vtkActor2DCollection* overlays = renderer->GetActors2D();
  overlays->InitTraversal();
  while (vtkActor2D* a = overlays->GetNextActor2D())
  {
    a->SetVisibility(actors2D);
  }
}

// What `capture()` returns with the layer `lower` hidden and its background transparent black,
// so that the layers above it are captured alone (premultiplied RGBA); `lower` is put back.
template <typename Capture>
auto CaptureWithoutLayer(vtkRenderer* lower, Capture capture) -> decltype(capture())
{
  double background[3];
  lower->GetBackground(background);
  const double backgroundAlpha = lower->GetBackgroundAlpha();
  lower->SetBackground(0.0, 0.0, 0.0);
  lower->SetBackgroundAlpha(0.0);
  SetVisibility(lower, false, false);
  auto captured = capture();
  SetVisibility(lower, true, true);
  lower->SetBackground(background);
  lower->SetBackgroundAlpha(backgroundAlpha);
  return captured;
}

// Pixels changed, and pixels with a flat (2 radius + 1)^2 neighbourhood in `plain` that changed.
struct Changes
{
  vtkIdType Changed = 0;
  vtkIdType FlatChanged = 0;
};

inline Changes CountChanges(vtkImageData* plain, vtkImageData* result, int radius)
{
  Changes c;
  int dims[3];
  plain->GetDimensions(dims);
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool same = true;
      for (int k = 0; k < plain->GetNumberOfScalarComponents(); ++k)
      {
        same = same && GetValue(plain, x, y, k) == GetValue(result, x, y, k);
      }
      if (!same)
      {
        ++c.Changed;
        c.FlatChanged += IsFlatAround(plain, x, y, radius) ? 1 : 0;
      }
    }
  }
  return c;
}

// Compares the antialiased render `result` of `window` with the baseline given by -V:
// - no pixel may differ from the baseline by more than 2/255 (llvmpipe is deterministic);
// - VTK's own regression test must pass too (it records the images for CDash);
// - the result must differ from the plain render `plain` on more than `minChanged` pixels, so a
//   baseline of an image that was not antialiased cannot pass.
// On failure the result is written to the -T directory as <name>.png.
inline void CheckBaseline(int argc, char* argv[], const std::string& name, vtkRenderWindow* window,
  vtkImageData* result, vtkImageData* plain, vtkIdType minChanged)
{
  const std::string baselinePath = Argument(argc, argv, "-V");
  const std::string resultPath = Argument(argc, argv, "-T") + "/" + name + ".png";
  const Difference changed = Compare(plain, result, 0.0);
  std::cout << name << ": the pass changed " << changed.Pixels << " of " << changed.Total
            << " pixels" << std::endl;
  Check(changed.Pixels > minChanged, "the pass changed the render", __FILE__, __LINE__);

  auto baseline = ReadPNG(baselinePath);
  if (!baseline)
  {
    WritePNG(result, resultPath);
    std::cerr << "no baseline at " << baselinePath << "; the result is in " << resultPath
              << std::endl;
    Check(false, "baseline present", __FILE__, __LINE__);
    return;
  }
  // Alternatives, as VTK's tester takes them: <name>_1.png, <name>_2.png, ... beside the
  // baseline, for what legitimately differs between platforms (VTK 9.6 draws the overlays'
  // scalar bar otherwise than 9.1). The nearest one is the one compared.
  Difference d = Compare(result, baseline, 2.0);
  std::string chosen = baselinePath;
  const std::string stem = baselinePath.substr(0, baselinePath.size() - 4); // without ".png"
  for (int k = 1; d.Count != 0; ++k)
  {
    const std::string alternative = stem + "_" + std::to_string(k) + ".png";
    auto other = ReadPNG(alternative);
    if (!other)
    {
      break;
    }
    const Difference e = Compare(result, other, 2.0);
    if (e.Count >= 0 && (d.Count < 0 || e.Count < d.Count))
    {
      d = e;
      baseline = other;
      chosen = alternative;
    }
  }
  std::cout << name << ": compared with " << chosen << std::endl;
  if (!Check(d.Count == 0, "result within 2/255 of the baseline", __FILE__, __LINE__))
  {
    WritePNG(result, resultPath);
    std::cerr << d.Pixels << " pixels differ from the nearest baseline by more than 2/255 "
              << "(largest " << d.Max << "); the result is in " << resultPath << std::endl;
  }
  Check(Compare(plain, baseline, 0.0).Pixels > minChanged, "the baseline is antialiased",
    __FILE__, __LINE__);
  const int vtkResult = vtkRegressionTestImage(window);
  Check(vtkResult == vtkRegressionTester::PASSED, "VTK's regression test", __FILE__, __LINE__);
}

// A 600 x 300 window of two renderers side by side: the silhouettes scene in the left viewport,
// the wireframe scene in the right one, and the window's plain (single-sample) render.
struct TwoViewportWindow
{
  static constexpr int Width = 600, Height = 300, ViewportWidth = 300;
  static constexpr const char* Scenes[2] = { "silhouettes", "wireframe" };
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderers[2];
  vtkSmartPointer<vtkImageData> Plain;

  TwoViewportWindow()
  {
    this->Window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
    for (int side = 0; side < 2; ++side)
    {
      this->Renderers[side]->SetViewport(0.5 * side, 0.0, 0.5 * (side + 1), 1.0);
      vtkMLAAScenes::Build(Scenes[side], this->Renderers[side]);
      this->Window->AddRenderer(this->Renderers[side]);
    }
    this->Plain = vtkMLAAScenes::Capture(this->Window);
  }
  ~TwoViewportWindow()
  {
    for (auto& renderer : this->Renderers)
    {
      StopPass(renderer, this->Window);
    }
  }
  // The pixels of viewport `side` (0 left, 1 right) of a capture of the window.
  static vtkSmartPointer<vtkImageData> Viewport(vtkImageData* capture, int side)
  {
    return Crop(capture, side * ViewportWidth, 0, ViewportWidth, Height);
  }
};

// A sphere of radius 0.5 at (x, y, z), of colour (r, g, b) and the given opacity.
inline void AddColoredSphere(vtkRenderer* renderer, double x, double y, double z, double r,
  double g, double b, double opacity)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(x, y, z);
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetOpacity(opacity);
  renderer->AddActor(actor);
}

// Translucent geometry (issue 21): an opaque sphere behind two translucent ones (opacity 0.4 and
// 0.5) that overlap it and each other, on white, seen from a little above and aside.
inline void BuildTranslucentSpheres(vtkRenderer* renderer)
{
  renderer->SetBackground(1.0, 1.0, 1.0);
  AddColoredSphere(renderer, -0.5, 0.0, -0.6, 0.9, 0.3, 0.2, 1.0);
  AddColoredSphere(renderer, 0.0, 0.0, 0.0, 0.2, 0.5, 0.9, 0.4);
  AddColoredSphere(renderer, 0.5, 0.1, 0.5, 0.3, 0.8, 0.3, 0.5);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Azimuth(30);
  renderer->GetActiveCamera()->Elevation(20);
}

// A one-renderer window with a scene, and the scene's plain (single-sample) render.
struct SceneWindow
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkSmartPointer<vtkImageData> Plain;

  SceneWindow(const std::string& scene, int width = 400, int height = 300, bool alpha = false)
  {
    this->Window = vtkMLAAScenes::NewOffscreenWindow(width, height);
    this->Window->AddRenderer(this->Renderer);
    vtkMLAAScenes::Build(scene, this->Renderer);
    this->Plain = vtkMLAAScenes::Capture(this->Window, alpha);
  }
  ~SceneWindow() { StopPass(this->Renderer, this->Window); }
};

// The window's z-buffer as it was last rendered (not rendered again), as an image.
inline vtkSmartPointer<vtkImageData> ZBuffer(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToZBuffer();
  grab->ReadFrontBufferOff();
  grab->ShouldRerenderOff();
  grab->Update();
  auto depth = vtkSmartPointer<vtkImageData>::New();
  depth->DeepCopy(grab->GetOutput());
  return depth;
}

// The supersampled reference of MEASURING.md of what `window` shows without a pass: the mean of
// samples x samples renders shifted by stratified sub-pixel offsets (RGB, row by row, 0..255).
inline std::vector<double> SupersampledReference(
  vtkRenderWindow* window, vtkRenderer* renderer, int samples = 8)
{
  int* size = window->GetSize();
  const int w = size[0], h = size[1];
  vtkCamera* camera = renderer->GetActiveCamera();
  double center[2];
  camera->GetWindowCenter(center);
  std::vector<double> sum(static_cast<size_t>(w) * h * 3, 0.0);
  for (int j = 0; j < samples; ++j)
  {
    for (int i = 0; i < samples; ++i)
    {
      camera->SetWindowCenter(center[0] + 2.0 * ((i + 0.5) / samples - 0.5) / w,
        center[1] + 2.0 * ((j + 0.5) / samples - 0.5) / h);
      auto image = vtkMLAAScenes::Capture(window);
      const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
      for (size_t v = 0; v < sum.size(); ++v)
      {
        sum[v] += p[v];
      }
    }
  }
  camera->SetWindowCenter(center[0], center[1]);
  for (double& v : sum)
  {
    v /= samples * samples;
  }
  return sum;
}

// AAR of MEASURING.md: 1 - MSE(result, reference) / MSE(plain, reference) over the pixels where
// plain and reference differ by more than 4/255.
inline double AAR(vtkImageData* plain, vtkImageData* result, const std::vector<double>& reference)
{
  const auto* n = static_cast<const unsigned char*>(plain->GetScalarPointer());
  const auto* m = static_cast<const unsigned char*>(result->GetScalarPointer());
  double none = 0.0, method = 0.0;
  for (size_t p = 0; p < reference.size(); p += 3)
  {
    bool inE = false;
    for (int c = 0; c < 3; ++c)
    {
      inE = inE || std::abs(n[p + c] - reference[p + c]) > 4.0;
    }
    for (int c = 0; inE && c < 3; ++c)
    {
      none += (n[p + c] - reference[p + c]) * (n[p + c] - reference[p + c]);
      method += (m[p + c] - reference[p + c]) * (m[p + c] - reference[p + c]);
    }
  }
  return none > 0.0 ? 1.0 - method / none : 0.0;
}

// A parallel camera over a `width` x `height` window that maps one world unit to one pixel:
// world (x, y, 0) lands at pixel (x, y) counted from the bottom left corner of the window.
inline void UsePixelCamera(vtkRenderer* renderer, int width, int height)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(width / 2.0, height / 2.0, 0.0);
  camera->SetPosition(width / 2.0, height / 2.0, 100.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetParallelScale(height / 2.0);
  renderer->ResetCameraClippingRange();
}

// The ids of every node of a selection, with the node's prop id (plus one) in the high bits.
inline std::set<vtkIdType> SelectedIds(vtkSelection* selection)
{
  std::set<vtkIdType> ids;
  for (unsigned int n = 0; selection && n < selection->GetNumberOfNodes(); ++n)
  {
    vtkSelectionNode* node = selection->GetNode(n);
    auto* list = vtkIdTypeArray::SafeDownCast(node->GetSelectionList());
    const int prop = node->GetProperties()->Has(vtkSelectionNode::PROP_ID())
      ? node->GetProperties()->Get(vtkSelectionNode::PROP_ID())
      : -1;
    for (vtkIdType i = 0; list && i < list->GetNumberOfTuples(); ++i)
    {
      ids.insert((static_cast<vtkIdType>(prop + 1) << 40) + list->GetValue(i));
    }
  }
  return ids;
}

// The cells (SelectedIds) of a hardware area selection of the renderer's whole
// `width` x `height` window.
inline std::set<vtkIdType> SelectCells(vtkRenderer* renderer, int width, int height)
{
  vtkNew<vtkHardwareSelector> selector;
  selector->SetRenderer(renderer);
  selector->SetFieldAssociation(vtkDataObject::FIELD_ASSOCIATION_CELLS);
  selector->SetArea(0, 0, width - 1, height - 1);
  vtkSmartPointer<vtkSelection> selection;
  selection.TakeReference(selector->Select());
  return SelectedIds(selection);
}
}

#endif
