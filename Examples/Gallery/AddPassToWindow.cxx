// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Gallery: add MLAA to an existing VTK application.
//
//   mlaa-gallery-add-pass [--output FILE.png] [--without-mlaa]
//
// A small application of the usual shape (a few actors, a text overlay, an interactor). The
// lines marked "MLAA" are all that antialiasing needs: a vtkOpenGLMLAAPass around the renderer's
// usual render steps, and no multisampling. Text and other 2D overlays are drawn after the
// antialiasing, untouched; picking, several renderers and layers keep working.
//
// With --output the window renders once offscreen and the picture is written to FILE.png
// instead of opening an interactive window; --without-mlaa leaves the pass out (to compare).
#include "vtkOpenGLMLAAPass.h" // MLAA
#include "vtkRenderStepsPass.h" // MLAA

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeSource.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  std::string output;
  bool useMLAA = true;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
      output = argv[++i];
    else if (arg == "--without-mlaa")
      useMLAA = false;
    else
    {
      std::cerr << "usage: " << argv[0] << " [--output FILE.png] [--without-mlaa]\n";
      return 2;
    }
  }

  // The existing application: a wireframe sphere, a cone and a title.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(16);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetRepresentationToWireframe();
  sphereActor->GetProperty()->SetColor(0.1, 0.1, 0.1);

  vtkNew<vtkConeSource> cone;
  cone->SetResolution(40);
  cone->SetCenter(1.2, 0.0, 0.0);
  vtkNew<vtkPolyDataMapper> coneMapper;
  coneMapper->SetInputConnection(cone->GetOutputPort());
  vtkNew<vtkActor> coneActor;
  coneActor->SetMapper(coneMapper);
  coneActor->GetProperty()->SetColor(0.9, 0.45, 0.1);

  vtkNew<vtkTextActor> title;
  title->SetInput("vtkOpenGLMLAAPass");
  title->GetTextProperty()->SetFontSize(18);
  title->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
  title->SetDisplayPosition(10, 10);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(sphereActor);
  renderer->AddActor(coneActor);
  renderer->AddActor2D(title);
  renderer->SetBackground(1.0, 1.0, 1.0);
  renderer->GetActiveCamera()->Azimuth(20.0);
  renderer->ResetCamera();

  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(400, 300);

  // MLAA: the pass wraps the renderer's usual steps (vtkRenderStepsPass), and replaces
  // multisampling. The options (presets, threshold, ...) are in mlaa->GetOptions().
  if (useMLAA)
  {
    vtkNew<vtkRenderStepsPass> steps;
    vtkNew<vtkOpenGLMLAAPass> mlaa;
    mlaa->SetDelegatePass(steps);
    renderer->SetPass(mlaa);
    window->SetMultiSamples(0);
  }
  else
  {
    window->SetMultiSamples(0); // the same aliased render, for comparison
  }

  if (output.empty())
  {
    vtkNew<vtkRenderWindowInteractor> interactor;
    interactor->SetRenderWindow(window);
    window->Render();
    interactor->Start();
    return 0;
  }

  window->SetOffScreenRendering(1);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(output.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << output << ": not written\n";
    return 1;
  }
  std::cout << "wrote " << output << (useMLAA ? " (MLAA)" : " (no antialiasing)") << "\n";
  return 0;
}
