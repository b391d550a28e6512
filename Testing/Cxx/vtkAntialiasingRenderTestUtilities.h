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
#include "vtkDLAAOptions.h"
#include "vtkExtractVOI.h"
#include "vtkOpenGLAntialiasingPass.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

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
// renderer holds it), and its CPU twin: the method's filter, with the pass's options, on an
// image (the pass must match it within 2/255). PassMethods() lists them all; a new method is one
// more entry there.
struct PassMethod
{
  const char* Name;
  vtkOpenGLAntialiasingPass* (*Use)(vtkRenderer* renderer);
  vtkSmartPointer<vtkImageData> (*Filter)(vtkOpenGLAntialiasingPass* pass, vtkImageData* image);
};

inline const std::vector<PassMethod>& PassMethods()
{
  static const std::vector<PassMethod> methods = {
    { "vtkOpenGLMLAAPass", [](vtkRenderer* r) -> vtkOpenGLAntialiasingPass* { return UseMLAA(r); },
      [](vtkOpenGLAntialiasingPass* pass, vtkImageData* image) {
        return RunMLAA(image, static_cast<vtkOpenGLMLAAPass*>(pass)->GetOptions());
      } },
    { "vtkOpenGLDLAAPass", [](vtkRenderer* r) -> vtkOpenGLAntialiasingPass* { return UseDLAA(r); },
      [](vtkOpenGLAntialiasingPass* pass, vtkImageData* image) {
        return RunDLAA(image, static_cast<vtkOpenGLDLAAPass*>(pass)->GetOptions());
      } },
  };
  return methods;
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
  const Difference d = Compare(result, baseline, 2.0);
  if (!Check(d.Count == 0, "result within 2/255 of the baseline", __FILE__, __LINE__))
  {
    WritePNG(result, resultPath);
    std::cerr << d.Pixels << " pixels differ from the baseline by more than 2/255 (largest "
              << d.Max << "); the result is in " << resultPath << std::endl;
  }
  Check(Compare(plain, baseline, 0.0).Pixels > minChanged, "the baseline is antialiased",
    __FILE__, __LINE__);
  const int vtkResult = vtkRegressionTestImage(window);
  Check(vtkResult == vtkRegressionTester::PASSED, "VTK's regression test", __FILE__, __LINE__);
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
}

#endif
