// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Gallery: compare antialiasing methods side by side on one scene.
//
//   mlaa-gallery-compare [--output FILE.png] [--size WxH] [--zoom N]
//
// Renders one scene (a shaded sphere's silhouette, a tilted wireframe grid, thin lines) with no
// antialiasing, VTK's FXAA, 4x multisampling, vtkOpenGLMLAAPass (default `high` preset) and
// vtkOpenGLDLAAPass, and writes one picture: the labelled renders in a row, and under each its
// magnified crop of the same region (nearest neighbour, so the pixels stay visible). The region
// is where MLAA changed the most pixels. Default: 300x225 per render, crops magnified 3 times,
// mlaa-gallery-compare.png.
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkRenderStepsPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExtractVOI.h"
#include "vtkImageAppend.h"
#include "vtkImageData.h"
#include "vtkImageProcessingPass.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{
struct Method
{
  std::string Label;
  enum Kind
  {
    NONE,
    FXAA,
    MSAA4,
    MLAA,
    DLAA
  } Kind;
};

// The scene: a lit sphere (a curved silhouette), a tilted wireframe grid (lines at many angles)
// and the method's name as a label in the corner.
void BuildScene(vtkRenderer* renderer, vtkTextActor* label)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(64);
  sphere->SetCenter(0.4, 0.2, 0.0);
  sphere->SetRadius(0.8);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(sphereMapper);
  sphereActor->GetProperty()->SetColor(0.85, 0.35, 0.2);

  vtkNew<vtkPlaneSource> grid;
  grid->SetResolution(10, 10);
  grid->SetOrigin(-1.3, -1.1, 0.9); // in front of the sphere's lower left
  grid->SetPoint1(0.5, -1.35, 0.9);
  grid->SetPoint2(-1.1, 0.6, 0.9);
  vtkNew<vtkPolyDataMapper> gridMapper;
  gridMapper->SetInputConnection(grid->GetOutputPort());
  vtkNew<vtkActor> gridActor;
  gridActor->SetMapper(gridMapper);
  gridActor->GetProperty()->SetRepresentationToWireframe();
  gridActor->GetProperty()->SetColor(0.1, 0.2, 0.45);

  label->GetTextProperty()->SetFontSize(16);
  label->GetTextProperty()->SetBold(1);
  label->GetTextProperty()->SetColor(1.0, 1.0, 1.0);
  label->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
  label->GetTextProperty()->SetBackgroundOpacity(0.75);
  label->SetDisplayPosition(6, 6);

  renderer->AddActor(sphereActor);
  renderer->AddActor(gridActor);
  renderer->AddActor2D(label);
  renderer->SetBackground(0.93, 0.93, 0.9);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Zoom(1.4);
}

vtkSmartPointer<vtkImageData> Render(const Method& method, int width, int height)
{
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkTextActor> label;
  label->SetInput(method.Label.c_str());
  BuildScene(renderer, label);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(width, height);
  window->AddRenderer(renderer);
  window->SetMultiSamples(method.Kind == Method::MSAA4 ? 4 : 0);

  vtkSmartPointer<vtkRenderPass> pass;
  if (method.Kind == Method::MLAA)
    pass = vtkSmartPointer<vtkOpenGLMLAAPass>::New();
  else if (method.Kind == Method::DLAA)
    pass = vtkSmartPointer<vtkOpenGLDLAAPass>::New();
  if (pass)
  {
    vtkNew<vtkRenderStepsPass> steps;
    vtkImageProcessingPass::SafeDownCast(pass)->SetDelegatePass(steps);
    renderer->SetPass(pass);
  }
  renderer->SetUseFXAA(method.Kind == Method::FXAA);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  grab->Update();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->DeepCopy(grab->GetOutput());
  return image;
}

// Number of pixels in the square at (x0, y0) that differ between two images of the same size.
int Changed(vtkImageData* a, vtkImageData* b, int x0, int y0, int w, int h)
{
  int count = 0;
  for (int y = y0; y < y0 + h; ++y)
  {
    for (int x = x0; x < x0 + w; ++x)
    {
      for (int c = 0; c < a->GetNumberOfScalarComponents(); ++c)
      {
        if (a->GetScalarComponentAsDouble(x, y, 0, c) != b->GetScalarComponentAsDouble(x, y, 0, c))
        {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

// The w x h region at (x, y), magnified to outWidth x outHeight.
vtkSmartPointer<vtkImageData> Crop(
  vtkImageData* image, int x, int y, int w, int h, int outWidth, int outHeight)
{
  vtkNew<vtkExtractVOI> voi;
  voi->SetInputData(image);
  voi->SetVOI(x, x + w - 1, y, y + h - 1, 0, 0);
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(voi->GetOutputPort());
  resize->SetOutputDimensions(outWidth, outHeight, 1);
  resize->InterpolateOff(); // nearest neighbour: each pixel becomes a block
  resize->Update();
  auto crop = vtkSmartPointer<vtkImageData>::New();
  crop->DeepCopy(resize->GetOutput());
  crop->SetExtent(0, outWidth - 1, 0, outHeight - 1, 0, 0);
  return crop;
}

vtkSmartPointer<vtkImageData> Append(const std::vector<vtkSmartPointer<vtkImageData>>& images,
  int axis)
{
  vtkNew<vtkImageAppend> append;
  append->SetAppendAxis(axis);
  for (const auto& image : images)
    append->AddInputData(image);
  append->Update();
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->DeepCopy(append->GetOutput());
  return result;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string output = "mlaa-gallery-compare.png";
  int width = 300, height = 225, zoom = 3;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--output" && i + 1 < argc)
      output = argv[++i];
    else if (arg == "--size" && i + 1 < argc &&
      std::sscanf(argv[i + 1], "%dx%d", &width, &height) == 2 && width >= 64 && height >= 64)
      ++i;
    else if (arg == "--zoom" && i + 1 < argc && std::sscanf(argv[i + 1], "%d", &zoom) == 1 &&
      zoom >= 2 && zoom <= 16)
      ++i;
    else
    {
      std::cerr << "usage: " << argv[0]
                << " [--output FILE.png] [--size WxH (at least 64x64)] [--zoom 2..16]\n";
      return 2;
    }
  }

  const std::vector<Method> methods = { { "none", Method::NONE }, { "FXAA", Method::FXAA },
    { "4x MSAA", Method::MSAA4 }, { "MLAA", Method::MLAA }, { "DLAA", Method::DLAA } };
  std::vector<vtkSmartPointer<vtkImageData>> renders;
  for (const Method& method : methods)
    renders.push_back(Render(method, width, height));

  // The crop: the region (1/zoom of the width and height) where MLAA changed the most,
  // searched on a coarse grid, above the label. Each crop is magnified to the size of a render.
  const int cw = width / zoom, ch = height / zoom;
  int bestX = 0, bestY = 0, best = -1;
  for (int y = height / 8; y + ch <= height; y += std::max(1, ch / 4))
  {
    for (int x = 0; x + cw <= width; x += std::max(1, cw / 4))
    {
      const int changed = Changed(renders[0], renders[3], x, y, cw, ch);
      if (changed > best)
      {
        best = changed;
        bestX = x;
        bestY = y;
      }
    }
  }

  std::vector<vtkSmartPointer<vtkImageData>> crops;
  for (const auto& render : renders)
    crops.push_back(Crop(render, bestX, bestY, cw, ch, width, height));
  // Rows from the bottom up (VTK images start at the bottom): crops under the renders.
  auto picture = Append({ Append(crops, 0), Append(renders, 0) }, 1);

  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(picture);
  writer->SetFileName(output.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << output << ": not written\n";
    return 1;
  }
  int dims[3];
  picture->GetDimensions(dims);
  std::cout << "wrote " << output << " (" << dims[0] << "x" << dims[1]
            << "): none | FXAA | 4x MSAA | MLAA | DLAA, crops of " << cw << "x" << ch
            << " pixels at (" << bestX << ", " << bestY << ") magnified " << zoom << " times\n";
  return 0;
}
