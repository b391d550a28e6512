// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLAntialiasingPass under stereo rendering, for every method of PassMethods().
// vtkRenderWindow renders a stereo frame as the left eye's render, then the right eye's; an
// interlaced stereo window (VTK_STEREO_INTERLACED) shows the left eye's image on the even rows
// (counted from the bottom) and the right eye's on the odd ones. The eyes are set far apart
// (eye angle 8 degrees), so that they see different pictures. For the single-frame pass and for
// temporal antialiasing:
// - the interlaced window's rows are those of the same pass rendering the left eye alone
//   (VTK_STEREO_LEFT) and the right eye alone (VTK_STEREO_RIGHT), within 2/255;
// - with Temporal on, each eye accumulates its own still: RenderConverged converges in stereo
//   (one history for both would take every render for a camera motion), the pass holds a history
//   for each eye, and drops the right eye's when the window renders in mono again.
// No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

using namespace vtkMLAATest;

namespace
{
struct StereoRun
{
  vtkSmartPointer<vtkImageData> Image;
  int Accumulated = 0;
  vtkIdType TargetBytes = 0;
};

// A new window and pass rendering the silhouettes scene in the given stereo type, rendered
// once, or until converged with Temporal on.
StereoRun RenderStereo(const PassMethod& method, MessageObserver* messages, int stereoType,
  bool temporal)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(200, 150);
  window->StereoCapableWindowOn();
  window->SetStereoType(stereoType);
  window->StereoRenderOn();
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  renderer->GetActiveCamera()->SetEyeAngle(8.0);
  // A first render without the pass: VTK's camera takes the window's stereo setting while it
  // renders, so that the very first stereo render draws both eyes unsheared.
  window->Render();
  vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = method.Use(renderer);
  messages->Watch(pass);
  pass->SetTemporal(temporal);
  StereoRun run;
  if (temporal)
  {
    const int renders = pass->RenderConverged(window);
    MLAA_CHECK(renders <= 2 * pass->GetConvergedFrames());
  }
  else
  {
    window->Render();
  }
  run.Accumulated = pass->GetAccumulatedFrames();
  run.TargetBytes = pass->GetTargetMemorySize();
  run.Image = vtkMLAAScenes::Capture(window);
  if (temporal)
  {
    // Mono again: the right eye's history goes.
    window->StereoRenderOff();
    window->Render();
    const vtkIdType mono = pass->GetTargetMemorySize();
    std::cout << "  target bytes, stereo " << run.TargetBytes << ", mono " << mono << std::endl;
    if (stereoType == VTK_STEREO_INTERLACED)
    {
      MLAA_CHECK(mono < run.TargetBytes);
    }
  }
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window);
  return run;
}

// Rows of `image` with y % 2 == parity that differ from `eye`'s by more than 2/255.
int RowsDiffering(vtkImageData* image, vtkImageData* eye, int parity)
{
  int dims[3];
  image->GetDimensions(dims);
  const int components = image->GetNumberOfScalarComponents();
  auto* a = static_cast<unsigned char*>(image->GetScalarPointer());
  auto* b = static_cast<unsigned char*>(eye->GetScalarPointer());
  int rows = 0;
  for (int y = parity; y < dims[1]; y += 2)
  {
    bool differs = false;
    for (int i = y * dims[0] * components; i < (y + 1) * dims[0] * components; ++i)
    {
      differs = differs || std::abs(static_cast<int>(a[i]) - static_cast<int>(b[i])) > 2;
    }
    rows += differs ? 1 : 0;
  }
  return rows;
}
}

int TestAntialiasingPassStereo(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    for (bool temporal : { false, true })
    {
      std::cout << (temporal ? " temporal" : " single frame") << std::endl;
      const StereoRun left = RenderStereo(method, messages, VTK_STEREO_LEFT, temporal);
      const StereoRun right = RenderStereo(method, messages, VTK_STEREO_RIGHT, temporal);
      const StereoRun both = RenderStereo(method, messages, VTK_STEREO_INTERLACED, temporal);
      const Difference eyes = Compare(left.Image, right.Image, 2.0);
      std::cout << "  the eyes' images differ on " << eyes.Pixels << " pixels" << std::endl;
      MLAA_CHECK(eyes.Pixels > 500);
      const int evenRows = RowsDiffering(both.Image, left.Image, 0);
      const int oddRows = RowsDiffering(both.Image, right.Image, 1);
      std::cout << "  interlaced rows unlike the left eye's: " << evenRows
                << ", unlike the right eye's: " << oddRows << std::endl;
      MLAA_CHECK(evenRows == 0 && oddRows == 0);
      if (temporal)
      {
        std::cout << "  frames accumulated: left " << left.Accumulated << ", right "
                  << right.Accumulated << ", interlaced " << both.Accumulated << std::endl;
        MLAA_CHECK(left.Accumulated >= 16 && right.Accumulated >= 16 && both.Accumulated >= 16);
        // Two histories (the right eye's is made when the right eye is first rendered).
        MLAA_CHECK(both.TargetBytes > left.TargetBytes);
      }
    }
  });
  return Result();
}
