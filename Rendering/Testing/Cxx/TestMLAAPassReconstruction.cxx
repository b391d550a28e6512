// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Topological reconstruction in vtkOpenGLMLAAPass on point-sampled lines under a pixel wide,
// drawn pixel by pixel (one unit square per lit pixel, in a parallel view of one world unit per
// pixel): lines 0.35 and 0.55 pixels wide at 24 and 66 degrees, dark on light.
// - The reconstruction stage alone (depth edges find no edge in the nearly flat depth of the
//   squares and of the background square just behind them, so the output is the reconstructed
//   picture) equals vtkImageMLAA's with the same depth within
//   2/255: the gaps it fills and, on the 0.35-pixel lines, the lit pixels that the thin line rule
//   lightens (vtkMLAATopology::GetLineShare: they keep 1, 2 or 3 sevenths of the ink); both
//   rules change pixels here.
// - The Max preset (Ultra with reconstruction) through the pass equals the filter on the plain
//   render within 2/255.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkWindowToImageFilter.h"

#include <cmath>

using namespace vtkMLAATest;

namespace
{
constexpr int Width = 96;
constexpr int Height = 80;
constexpr double Background = 0.9;
constexpr double Ink = 0.15;

// The unit squares of the pixels whose centres lie within width / 2 of a line at `degrees`
// through the middle of the window (as a renderer samples a thin line).
vtkSmartPointer<vtkPolyData> SampledLine(double width, double degrees)
{
  const double pi = std::acos(-1.0);
  const double nx = -std::sin(degrees * pi / 180.0);
  const double ny = std::cos(degrees * pi / 180.0);
  const double cx = 0.5 * Width + 0.31; // off the pixel grid
  const double cy = 0.5 * Height + 0.17;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> squares;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      if (std::abs((x + 0.5 - cx) * nx + (y + 0.5 - cy) * ny) <= 0.5 * width)
      {
        const vtkIdType first = points->GetNumberOfPoints();
        points->InsertNextPoint(x, y, 0.0);
        points->InsertNextPoint(x + 1, y, 0.0);
        points->InsertNextPoint(x + 1, y + 1, 0.0);
        points->InsertNextPoint(x, y + 1, 0.0);
        const vtkIdType square[4] = { first, first + 1, first + 2, first + 3 };
        squares->InsertNextCell(4, square);
      }
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetPolys(squares);
  return polyData;
}

void CheckLine(double width, double degrees, int& filled, int& lightened)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(SampledLine(width, degrees));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(Ink, Ink, Ink);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
  // The background as a square just behind the line's, so that the depth is flat.
  vtkNew<vtkPoints> corners;
  corners->InsertNextPoint(-1.0, -1.0, -0.01);
  corners->InsertNextPoint(Width + 1.0, -1.0, -0.01);
  corners->InsertNextPoint(Width + 1.0, Height + 1.0, -0.01);
  corners->InsertNextPoint(-1.0, Height + 1.0, -0.01);
  vtkNew<vtkCellArray> backdropCells;
  const vtkIdType backdropSquare[4] = { 0, 1, 2, 3 };
  backdropCells->InsertNextCell(4, backdropSquare);
  vtkNew<vtkPolyData> backdrop;
  backdrop->SetPoints(corners);
  backdrop->SetPolys(backdropCells);
  vtkNew<vtkPolyDataMapper> backdropMapper;
  backdropMapper->SetInputData(backdrop);
  vtkNew<vtkActor> backdropActor;
  backdropActor->SetMapper(backdropMapper);
  backdropActor->GetProperty()->SetColor(Background, Background, Background);
  backdropActor->GetProperty()->LightingOff();
  renderer->AddActor(backdropActor);
  renderer->SetBackground(0.0, 0.0, 0.0);
  UsePixelCamera(renderer, Width, Height);
  auto plain = vtkMLAAScenes::Capture(window);
  auto depth = ZBuffer(window);
  const double background = GetValue(plain, 0, 0); // a corner, away from the line

  // The reconstruction stage alone: no depth edge on the flat squares.
  vtkNew<vtkMLAAOptions> options;
  options->SetEdgeDetectionToDepth();
  options->ReconstructionOn();
  auto pass = UseMLAA(renderer, options);
  auto gpu = vtkMLAAScenes::Capture(window);
  vtkNew<vtkImageMLAA> filter;
  filter->SetOptions(options);
  filter->SetInputData(plain);
  filter->SetDepthInputData(depth);
  filter->Update();
  const Difference parity = Compare(filter->GetOutput(), gpu, 2.0);
  int gaps = 0, lit = 0, litInSevenths = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      const double before = GetValue(plain, x, y);
      const double after = GetValue(gpu, x, y);
      if (after == before)
      {
        continue;
      }
      if (before == background)
      {
        ++gaps;
        continue;
      }
      ++lit;
      for (int k = 1; k <= 3; ++k)
      {
        // The lit pixel keeps k sevenths of the ink's difference to the gap's colour.
        const double expected = background + k * (before - background) / 7.0;
        litInSevenths += std::abs(after - expected) <= 2.0 ? 1 : 0;
      }
    }
  }
  std::cout << "width " << width << ", " << degrees << " degrees: reconstruction alone: "
            << parity.Pixels << " pixels off the filter by more than 2/255; " << gaps
            << " gaps filled, " << lit << " lit pixels lightened (" << litInSevenths
            << " by sevenths)" << std::endl;
  MLAA_CHECK(std::abs(background - 255.0 * Background) <= 1.0);
  MLAA_CHECK(parity.Count == 0);
  MLAA_CHECK(litInSevenths == lit);
  filled += gaps;
  lightened += lit;

  // The Max preset through the pass equals the filter on the plain render.
  vtkNew<vtkMLAAOptions> max;
  max->SetPresetToMax();
  pass->SetOptions(max);
  auto maxGpu = vtkMLAAScenes::Capture(window);
  const Difference maxParity = Compare(RunMLAA(plain, max), maxGpu, 2.0);
  const Difference changed = Compare(plain, maxGpu, 0.0);
  std::cout << "  max: " << maxParity.Pixels << " pixels off the filter by more than 2/255, "
            << changed.Pixels << " changed" << std::endl;
  MLAA_CHECK(maxParity.Count == 0);
  MLAA_CHECK(changed.Pixels > 50);
  StopPass(renderer, window);
}
}

int TestMLAAPassReconstruction(int, char*[])
{
  int filled = 0, lightened = 0;
  for (double width : { 0.35, 0.55 })
  {
    for (double degrees : { 24.0, 66.0 })
    {
      CheckLine(width, degrees, filled, lightened);
    }
  }
  // Both rules were exercised.
  MLAA_CHECK(filled > 20);
  MLAA_CHECK(lightened > 10);
  return Result();
}
