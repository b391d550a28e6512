// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-demo: renders a scene offscreen without antialiasing and with vtkOpenGLMLAAPass, and writes
// one comparison picture: the two renders side by side (left: none, right: MLAA), and below them
// magnified crops of the two regions where MLAA changed the most (nearest-neighbour, so pixels
// stay visible).
//
//   mlaa-demo [--scene NAME] [--size WxH] [--zoom N] [--output FILE.png]
//
// Scenes are those of the project's tests and benchmarks (--list prints them). Needs an X display
// (run under Xvfb on a headless machine: scripts/with-xvfb.sh does it).
#include "vtkMLAAScenes.h"

#include "vtkExtractVOI.h"
#include "vtkImageAppend.h"
#include "vtkImageConstantPad.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkNew.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPNGWriter.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <cstring>
#include <iostream>
#include <string>

namespace
{
void Usage(std::ostream& os)
{
  os << "usage: mlaa-demo [--scene NAME] [--size WxH] [--zoom N] [--output FILE.png] [--list]\n"
        "  Renders NAME (default: mixed) at WxH (default 800x600) without antialiasing and with\n"
        "  vtkOpenGLMLAAPass, and writes FILE.png (default mlaa-demo.png): the two renders side\n"
        "  by side (left: none, right: MLAA) over N-times magnified crops (default 4).\n";
}

// Pixels of the w x h region at (x, y) that differ between two images of the same size.
int CountChanged(vtkImageData* a, vtkImageData* b, int x0, int y0, int w, int h)
{
  const auto* pa = static_cast<const unsigned char*>(a->GetScalarPointer());
  const auto* pb = static_cast<const unsigned char*>(b->GetScalarPointer());
  const int width = a->GetDimensions()[0];
  const int c = a->GetNumberOfScalarComponents();
  int changed = 0;
  for (int y = y0; y < y0 + h; ++y)
  {
    for (int x = x0; x < x0 + w; ++x)
    {
      const size_t i = (static_cast<size_t>(y) * width + x) * c;
      changed += std::equal(pa + i, pa + i + c, pb + i) ? 0 : 1;
    }
  }
  return changed;
}

vtkSmartPointer<vtkImageData> Crop(vtkImageData* image, int x, int y, int w, int h, int zoom)
{
  vtkNew<vtkExtractVOI> voi;
  voi->SetInputData(image);
  voi->SetVOI(x, x + w - 1, y, y + h - 1, 0, 0);
  vtkNew<vtkImageResize> resize;
  resize->SetInputConnection(voi->GetOutputPort());
  resize->SetOutputDimensions(w * zoom, h * zoom, 1);
  resize->InterpolateOff();
  resize->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(resize->GetOutput());
  out->SetExtent(0, w * zoom - 1, 0, h * zoom - 1, 0, 0);
  out->SetOrigin(0.0, 0.0, 0.0);
  out->SetSpacing(1.0, 1.0, 1.0);
  return out;
}

// Pads `image` with black on the right to `width` pixels.
vtkSmartPointer<vtkImageData> PadToWidth(vtkImageData* image, int width)
{
  int ext[6];
  image->GetExtent(ext);
  vtkNew<vtkImageConstantPad> pad;
  pad->SetInputData(image);
  pad->SetOutputWholeExtent(ext[0], ext[0] + width - 1, ext[2], ext[3], 0, 0);
  pad->SetConstant(0.0);
  pad->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(pad->GetOutput());
  return out;
}

// `a` then `b` along `axis` (0: side by side, 1: stacked; stacked images are first padded to
// the same width).
vtkSmartPointer<vtkImageData> Append(vtkImageData* a, vtkImageData* b, int axis)
{
  vtkSmartPointer<vtkImageData> first = a;
  vtkSmartPointer<vtkImageData> second = b;
  if (axis == 1)
  {
    const int width = std::max(a->GetDimensions()[0], b->GetDimensions()[0]);
    first = PadToWidth(a, width);
    second = PadToWidth(b, width);
  }
  vtkNew<vtkImageAppend> append;
  append->SetAppendAxis(axis);
  append->PreserveExtentsOff();
  append->AddInputData(first);
  append->AddInputData(second);
  append->Update();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->DeepCopy(append->GetOutput());
  return out;
}
}

int main(int argc, char* argv[])
{
  std::string scene = "mixed";
  std::string output = "mlaa-demo.png";
  int width = 800, height = 600, zoom = 4;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--help" || arg == "-h")
    {
      Usage(std::cout);
      return EXIT_SUCCESS;
    }
    else if (arg == "--list")
    {
      for (const auto& name : vtkMLAAScenes::Names())
      {
        std::cout << name << ": " << vtkMLAAScenes::Describe(name) << "\n";
      }
      for (const auto& name : vtkMLAAScenes::HeldOutNames())
      {
        std::cout << name << " (held out): " << vtkMLAAScenes::Describe(name) << "\n";
      }
      return EXIT_SUCCESS;
    }
    else if (arg == "--scene" && hasValue)
    {
      scene = argv[++i];
    }
    else if (arg == "--output" && hasValue)
    {
      output = argv[++i];
    }
    else if (arg == "--zoom" && hasValue)
    {
      zoom = std::atoi(argv[++i]);
    }
    else if (arg == "--size" && hasValue &&
      std::sscanf(argv[++i], "%dx%d", &width, &height) == 2)
    {
    }
    else
    {
      std::cerr << "mlaa-demo: bad argument '" << arg << "'\n";
      Usage(std::cerr);
      return EXIT_FAILURE;
    }
  }
  if (width < 64 || height < 64 || width > 8192 || height > 8192 || zoom < 1 || zoom > 16)
  {
    std::cerr << "mlaa-demo: --size must be 64x64 to 8192x8192 and --zoom 1 to 16\n";
    return EXIT_FAILURE;
  }

  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  if (!vtkMLAAScenes::Build(scene, renderer))
  {
    std::cerr << "mlaa-demo: unknown scene '" << scene << "' (--list shows the scenes)\n";
    return EXIT_FAILURE;
  }
  auto none = vtkMLAAScenes::Capture(window);

  // The pass: the renderer's usual steps as its delegate.
  vtkNew<vtkRenderStepsPass> steps;
  vtkNew<vtkOpenGLMLAAPass> mlaa;
  mlaa->SetDelegatePass(steps);
  renderer->SetPass(mlaa);
  auto antialiased = vtkMLAAScenes::Capture(window);
  renderer->SetPass(nullptr);
  mlaa->ReleaseGraphicsResources(window);

  // Two crops where MLAA changed the most pixels (two regions apart), sized so that
  // the four magnified crops span the width of the two renders.
  const int cropW = std::max(8, width / (2 * zoom));
  const int cropH = std::max(8, std::min(height / 2, (height * 2 / 3) / zoom));
  int cx[2] = { 0, 0 }, cy[2] = { 0, 0 };
  int best[2] = { -1, -1 };
  for (int y = 0; y + cropH <= height; y += cropH / 4)
  {
    for (int x = 0; x + cropW <= width; x += cropW / 4)
    {
      const int changed = CountChanged(none, antialiased, x, y, cropW, cropH);
      // The second region lies at least two crop widths away from the first, to show two things.
      const bool nearFirst = best[0] >= 0 && std::abs(x - cx[0]) < 2 * cropW &&
        std::abs(y - cy[0]) < 2 * cropH;
      if (changed > best[0])
      {
        if (best[0] >= 0 && !nearFirst)
        {
          best[1] = best[0];
          cx[1] = cx[0];
          cy[1] = cy[0];
        }
        best[0] = changed;
        cx[0] = x;
        cy[0] = y;
      }
      else if (changed > best[1] && !nearFirst)
      {
        best[1] = changed;
        cx[1] = x;
        cy[1] = y;
      }
    }
  }
  auto row = Append(none, antialiased, 0);
  vtkSmartPointer<vtkImageData> crops;
  for (int c = 0; c < 2; ++c)
  {
    auto pair = Append(Crop(none, cx[c], cy[c], cropW, cropH, zoom),
      Crop(antialiased, cx[c], cy[c], cropW, cropH, zoom), 0);
    crops = crops ? Append(crops, pair, 0) : pair;
  }
  // Crops below the renders (image row 0 is the bottom).
  auto picture = Append(crops, row, 1);

  // Written to a temporary file and renamed, so a failure never leaves a partial picture.
  const std::string temporary = output + ".partial.png";
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(picture);
  writer->SetFileName(temporary.c_str());
  writer->Write();
  if (writer->GetErrorCode() != 0 || std::rename(temporary.c_str(), output.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    std::cerr << "mlaa-demo: cannot write " << output << "\n";
    return EXIT_FAILURE;
  }
  int dims[3];
  picture->GetDimensions(dims);
  std::cout << "mlaa-demo: wrote " << output << " (" << dims[0] << "x" << dims[1] << "): scene '"
            << scene << "' at " << width << "x" << height
            << "; top: no antialiasing (left) and MLAA (right); bottom: the same regions magnified "
            << zoom << "x, each as none | MLAA.\n";
  return EXIT_SUCCESS;
}
