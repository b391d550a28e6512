// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Long lines (up to 256 pixels each way, MaxSearchSteps up to 128) in vtkOpenGLMLAAPass, with the
// search loop and with line lengths by recursive doubling (LineLengths):
// - a 1-degree slope (a black polygon under a white background) across a 512-pixel-wide window
//   gets one smooth ramp along each whole step of its staircase (about 57 pixels) with 32 and
//   128 steps, in both methods, while with 8 steps (16 pixels each way) the middle of each step
//   is left flat; the pass equals vtkImageMLAA on the screenshot within 2/255 on every pixel, and
//   both methods give the same image; all of this with CornerExtrapolation too (the slope's runs
//   at the image border);
// - the blending-weights debug output (vtkMLAAOptions::BLENDING_WEIGHTS) is identical with and
//   without recursive doubling on every shared scene at 8, 32 and 128 steps, with and without
//   CornerExtrapolation (the lengths are the same integers);
// - staircases of one-pixel steps (45-degree edges of diamonds, long ones and short ones, which
//   end at every distance from their units): searched unit by unit, and followed through the
//   counts of their units (with recursive doubling, so through every number of counts), they
//   give the same weights and the same image, equal to vtkImageMLAA's within 2/255;
// - AUTOMATIC resolves by MaxSearchSteps, and the doubling textures and the counts of staircase
//   units only exist while used;
// - CornerExtrapolation's sides with one step (a side between a corner and a step to a short run
//   that ends at a corner, horizontal and vertical) and ends of unknown height (the short run
//   ends at a step), as in TestImageMLAACorners: the pass's blending weights equal the filter's
//   exactly, searched and counted, at 16 and 128 steps, and differ from those without the option
//   there;
// - T junctions on a plane's sides (a band border meeting them from the inside) are no steps: the
//   pass's weights equal the filter's exactly, searched and counted, and the sides take none;
// - a ramp of greys (columns under a staircase top) has no edges inside it with local contrast
//   adaptation, in Lab, luma and colour modes: the pass's weights equal the filter's exactly.
#include "vtkAntialiasingRenderTestUtilities.h"
#include "vtkMLAAScenes.h"
#include "vtkAntialiasingTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkMath.h"
#include "vtkPointData.h"
#include "vtkDataArray.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace vtkMLAATest;

namespace
{
constexpr int Width = 512;
constexpr int Height = 64;

// Shows `polyData` unlit (its cell colours, else black) over `background` in a parallel view of
// one world unit per pixel of a width x height window whose lower-left corner is the origin.
void ShowFlat(vtkRenderer* renderer, vtkPolyData* polyData, double background, int width,
  int height)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(polyData);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 0.0, 0.0);
  actor->GetProperty()->LightingOff();
  renderer->AddActor(actor);
  renderer->SetBackground(background, background, background);
  UsePixelCamera(renderer, width, height);
}

// A black polygon below a line rising by 1 degree, on white, one world unit per pixel.
void BuildSlope(vtkRenderer* renderer)
{
  const double slope = std::tan(vtkMath::RadiansFromDegrees(1.0));
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-10.0, -10.0, 0.0);
  points->InsertNextPoint(Width + 10.0, -10.0, 0.0);
  points->InsertNextPoint(Width + 10.0, 20.0 + slope * (Width + 10.0), 0.0);
  points->InsertNextPoint(-10.0, 20.0 - slope * 10.0, 0.0);
  vtkNew<vtkCellArray> polys;
  const vtkIdType quad[4] = { 0, 1, 2, 3 };
  polys->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  ShowFlat(renderer, polyData, 1.0, Width, Height);
}

// The staircase steps of the plain render: for each, the row of the topmost dark pixels and its
// columns.
struct Step
{
  int Row, X0, X1;
};
std::vector<Step> Steps(vtkImageData* image)
{
  std::vector<Step> steps;
  int current = -1;
  for (int x = 0; x < Width; ++x)
  {
    int row = -1;
    while (row + 1 < Height && GetValue(image, x, row + 1) < 128.0)
    {
      ++row;
    }
    if (row != current)
    {
      steps.push_back(Step{ row, x, x });
      current = row;
    }
    steps.back().X1 = x;
  }
  return steps;
}

// Whether every inner step of the staircase is one monotonic ramp in `image`: the sum of the two
// rows of the step (the dark one and the bright one above it) never grows from one pixel to the
// next, goes from well above 255 to well below it, and is not flat over more than a quarter of
// the step.
bool AllRamps(vtkImageData* image, const std::vector<Step>& steps)
{
  for (size_t s = 1; s + 1 < steps.size(); ++s)
  {
    const Step& step = steps[s];
    std::vector<double> ramp;
    for (int x = step.X0; x <= step.X1; ++x)
    {
      ramp.push_back(GetValue(image, x, step.Row) + GetValue(image, x, step.Row + 1));
    }
    int flat = 0, longestFlat = 0;
    for (size_t i = 1; i < ramp.size(); ++i)
    {
      if (ramp[i] > ramp[i - 1])
      {
        return false;
      }
      flat = ramp[i] == ramp[i - 1] ? flat + 1 : 0;
      longestFlat = std::max(longestFlat, flat);
    }
    if (longestFlat > static_cast<int>(ramp.size()) / 4 || ramp.front() < 255.0 * 1.4 ||
      ramp.back() > 255.0 * 0.6)
    {
      return false;
    }
  }
  return true;
}

void OneDegreeSlope()
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildSlope(renderer);
  auto plain = vtkMLAAScenes::Capture(window);
  const std::vector<Step> steps = Steps(plain);
  MLAA_CHECK(steps.size() >= 8);
  for (size_t s = 1; s + 1 < steps.size(); ++s)
  {
    MLAA_CHECK(steps[s].X1 - steps[s].X0 + 1 >= 55 && steps[s].X1 - steps[s].X0 + 1 <= 60);
  }
  for (int run = 0; run < 6; ++run)
  {
    const int searchSteps = (run % 3 == 0) ? 8 : (run % 3 == 1 ? 32 : 128);
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(searchSteps);
    options->SetCornerExtrapolation(run >= 3); // the slope's ends lie on the image border
    auto cpu = RunMLAA(plain, options);
    vtkSmartPointer<vtkImageData> images[2];
    for (int doubling = 0; doubling < 2; ++doubling)
    {
      auto pass = UseMLAA(renderer, options);
      pass->SetLineLengths(
        doubling ? vtkOpenGLMLAAPass::RECURSIVE_DOUBLING : vtkOpenGLMLAAPass::SEARCH_LOOP);
      images[doubling] = vtkMLAAScenes::Capture(window);
      StopPass(renderer, window);
      const Difference parity = Compare(cpu, images[doubling], 2.0);
      const bool ramps = AllRamps(images[doubling], steps);
      std::cout << searchSteps << " steps, corners " << (run >= 3 ? "on, " : "off, ") << (doubling ? "recursive doubling" : "search loop")
                << ": " << parity.Pixels << " pixels differ from the filter by more than 2/255"
                << " (largest " << parity.Max << "), ramps " << (ramps ? "smooth" : "broken")
                << std::endl;
      MLAA_CHECK(parity.Count == 0);
      MLAA_CHECK(ramps == (searchSteps >= 32));
    }
    MLAA_CHECK(AllRamps(cpu, steps) == (searchSteps >= 32));
    MLAA_CHECK(Compare(images[0], images[1], 0.0).Count == 0);
  }
}

// Two diamonds (edges at 45 degrees both ways): a large black one whose edges cross the window,
// longer than any maximum distance, with a small white one inside, whose staircases end at
// corners.
void BuildDiamonds(vtkRenderer* renderer, int size)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkUnsignedCharArray> colors;
  colors->SetNumberOfComponents(3);
  const double center[2] = { size / 2.0 + 0.3, size / 2.0 + 0.2 };
  for (const double radius : { 0.75 * size, 0.2 * size })
  {
    const double z = radius < size / 2.0 ? 1.0 : 0.0; // the small one in front
    vtkIdType ids[4];
    ids[0] = points->InsertNextPoint(center[0] - radius, center[1], z);
    ids[1] = points->InsertNextPoint(center[0], center[1] - radius, z);
    ids[2] = points->InsertNextPoint(center[0] + radius, center[1], z);
    ids[3] = points->InsertNextPoint(center[0], center[1] + radius, z);
    polys->InsertNextCell(4, ids);
    const unsigned char value = z > 0.0 ? 255 : 0;
    colors->InsertNextTuple3(value, value, value);
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  polyData->GetCellData()->SetScalars(colors);
  ShowFlat(renderer, polyData, 0.6, size, size);
}

void DiagonalStaircases()
{
  const int size = 200;
  auto window = vtkMLAAScenes::NewOffscreenWindow(size, size);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildDiamonds(renderer, size);
  auto plain = vtkMLAAScenes::Capture(window);
  for (int searchSteps : { 4, 16, 128 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(searchSteps);
    auto cpu = RunMLAA(plain, options);
    vtkSmartPointer<vtkImageData> images[2], weights[2];
    for (int doubling = 0; doubling < 2; ++doubling)
    {
      auto pass = UseMLAA(renderer, options);
      pass->SetLineLengths(
        doubling ? vtkOpenGLMLAAPass::RECURSIVE_DOUBLING : vtkOpenGLMLAAPass::SEARCH_LOOP);
      MLAA_CHECK(pass->GetUsesRecursiveDoubling() == (doubling == 1));
      images[doubling] = vtkMLAAScenes::Capture(window);
      options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS); // the pass's options
      weights[doubling] = vtkMLAAScenes::Capture(window, true);
      options->SetDebugOutput(vtkMLAAOptions::NO_DEBUG_OUTPUT);
      StopPass(renderer, window);
      const Difference parity = Compare(cpu, images[doubling], 2.0);
      const vtkIdType changed = Compare(plain, images[doubling], 2.0).Pixels;
      std::cout << "diamonds, " << searchSteps << " steps, "
                << (doubling ? "recursive doubling" : "search loop") << ": " << parity.Pixels
                << " pixels differ from the filter by more than 2/255 (largest " << parity.Max
                << "), " << changed << " antialiased" << std::endl;
      MLAA_CHECK(parity.Count == 0);
      MLAA_CHECK(changed > 3 * size); // the edges of both diamonds, blended
    }
    MLAA_CHECK(Compare(weights[0], weights[1], 0.0).Count == 0);
    MLAA_CHECK(Compare(images[0], images[1], 0.0).Count == 0);
  }
}

void SameWeightsOnSharedScenes()
{
  for (const std::string& name : vtkMLAAScenes::Names())
  {
    auto window = vtkMLAAScenes::NewOffscreenWindow(400, 300);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build(name, renderer);
    // A first render without the pass: the scenes' first frame (camera clipping range, text
    // layout) can differ from the later ones, which this test must not mistake for the method.
    window->Render();
    for (int run = 0; run < 6; ++run)
    {
      const int searchSteps = (run % 3 == 0) ? 8 : (run % 3 == 1 ? 32 : 128);
      vtkNew<vtkMLAAOptions> options;
      options->SetMaxSearchSteps(searchSteps);
      options->SetCornerExtrapolation(run >= 3); // reads the next runs' lengths as well
      options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
      vtkSmartPointer<vtkImageData> weights[2];
      for (int doubling = 0; doubling < 2; ++doubling)
      {
        auto pass = UseMLAA(renderer, options);
        pass->SetLineLengths(
          doubling ? vtkOpenGLMLAAPass::RECURSIVE_DOUBLING : vtkOpenGLMLAAPass::SEARCH_LOOP);
        weights[doubling] = vtkMLAAScenes::Capture(window, true);
        StopPass(renderer, window);
      }
      const Difference d = Compare(weights[0], weights[1], 0.0);
      // (and there are weights to compare, but on an axis-aligned scene: its sides are straight,
      // and without a step they get none, issue 50)
      const double largest = weights[0]->GetPointData()->GetScalars()->GetRange(0)[1];
      if (!MLAA_CHECK(d.Count == 0 && (largest > 0.0 || vtkMLAAScenes::AxisAligned(name))))
      {
        std::cerr << "scene " << name << ", " << searchSteps << " steps, corners " << (run >= 3)
                  << ": " << d.Pixels
                  << " pixels of the weights differ" << std::endl;
      }
    }
  }
}

void AutomaticAndResources()
{
  vtkNew<vtkOpenGLMLAAPass> pass;
  MLAA_CHECK(pass->GetLineLengths() == vtkOpenGLMLAAPass::AUTOMATIC);
  pass->GetOptions()->SetMaxSearchSteps(vtkMLAAOptions::ExactLineLengthsSteps - 1);
  MLAA_CHECK(!pass->GetUsesRecursiveDoubling());
  pass->GetOptions()->SetMaxSearchSteps(vtkMLAAOptions::ExactLineLengthsSteps);
  MLAA_CHECK(pass->GetUsesRecursiveDoubling());
  pass->SetLineLengthsToSearchLoop();
  MLAA_CHECK(!pass->GetUsesRecursiveDoubling());
  pass->SetLineLengthsToRecursiveDoubling();
  pass->GetOptions()->SetMaxSearchSteps(1);
  MLAA_CHECK(pass->GetUsesRecursiveDoubling());

  // The two RGBA16F textures of the doubling (8 bytes per pixel each) are held while doubling is
  // used only, and so are the RG8 counts of staircase units (2 bytes per pixel), with diagonal
  // detection only.
  auto window = vtkMLAAScenes::NewOffscreenWindow(64, 48);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build(vtkMLAAScenes::Names().front(), renderer);
  vtkNew<vtkRenderStepsPass> steps;
  pass->SetDelegatePass(steps);
  renderer->SetPass(pass);
  window->Render();
  const vtkIdType withDoubling = pass->GetTargetMemorySize();
  pass->SetLineLengthsToSearchLoop();
  window->Render();
  const vtkIdType withLoop = pass->GetTargetMemorySize();
  MLAA_CHECK(withDoubling - withLoop == (2 * 8 + 2) * 64 * 48);
  pass->GetOptions()->DiagonalDetectionOff();
  window->Render();
  MLAA_CHECK(pass->GetTargetMemorySize() == withLoop);
  pass->SetLineLengthsToRecursiveDoubling();
  window->Render();
  MLAA_CHECK(pass->GetTargetMemorySize() - withLoop == 2 * 8 * 64 * 48);
  pass->ReleaseGraphicsResources(window);
  MLAA_CHECK(pass->GetTargetMemorySize() == 0);
  renderer->SetPass(nullptr);
}

// Rectangles on white, one world unit per pixel, given by their pixel ranges (inclusive): black,
// or with `greys`, each the grey level of its rectangle.
void BuildRectangles(vtkRenderer* renderer, const std::vector<std::array<int, 4>>& rectangles,
  int width, int height, const std::vector<unsigned char>& greys = {})
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> polys;
  for (const auto& r : rectangles)
  {
    const vtkIdType first = points->GetNumberOfPoints();
    points->InsertNextPoint(r[0], r[2], 0.0);
    points->InsertNextPoint(r[1] + 1.0, r[2], 0.0);
    points->InsertNextPoint(r[1] + 1.0, r[3] + 1.0, 0.0);
    points->InsertNextPoint(r[0], r[3] + 1.0, 0.0);
    const vtkIdType quad[4] = { first, first + 1, first + 2, first + 3 };
    polys->InsertNextCell(4, quad);
  }
  vtkNew<vtkPolyData> polyData;
  polyData->SetPoints(points);
  polyData->SetPolys(polys);
  if (!greys.empty())
  {
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetNumberOfComponents(3);
    for (const unsigned char grey : greys)
    {
      colors->InsertNextTuple3(grey, grey, grey);
    }
    polyData->GetCellData()->SetScalars(colors);
  }
  ShowFlat(renderer, polyData, 1.0, width, height);
}

// The pass's blending weights (`options` has the BLENDING_WEIGHTS debug output) equal `cpu`, the
// filter's, exactly, with the lines searched and with their lengths counted by recursive doubling.
void CheckPassWeights(vtkRenderer* renderer, vtkRenderWindow* window, vtkMLAAOptions* options,
  vtkImageData* cpu, const std::string& label)
{
  for (int doubling = 0; doubling < 2; ++doubling)
  {
    auto pass = UseMLAA(renderer, options);
    pass->SetLineLengths(
      doubling ? vtkOpenGLMLAAPass::RECURSIVE_DOUBLING : vtkOpenGLMLAAPass::SEARCH_LOOP);
    auto gpu = vtkMLAAScenes::Capture(window, true);
    StopPass(renderer, window);
    const Difference d = Compare(cpu, gpu, 0.0);
    if (!MLAA_CHECK(d.Count == 0))
    {
      std::cerr << label << ", " << (doubling ? "doubling" : "search loop") << ": " << d.Pixels
                << " pixels of the weights differ from the filter's" << std::endl;
    }
  }
}

void UnknownHeightEnds()
{
  // A side of 20 pixels (columns 10 to 29, top row 14) between a corner and a step up to a run
  // of 2 pixels that ends at a corner (the side's only step); the same turned by 90 degrees (a
  // side of 20 pixels in column 40); and the first again with one more step up past the 2-pixel
  // run (columns 5 to 7, top row 36 over a side in row 34), an end of unknown height.
  const int width = 64, height = 48;
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildRectangles(renderer,
    { { 10, 29, 2, 14 }, { 8, 9, 2, 15 }, { 40, 52, 20, 39 }, { 40, 53, 18, 19 },
      { 10, 29, 22, 34 }, { 8, 9, 22, 35 }, { 5, 7, 22, 36 } },
    width, height);
  auto plain = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(GetValue(plain, 29, 14) < 128.0 && GetValue(plain, 29, 15) > 128.0 &&
    GetValue(plain, 9, 15) < 128.0 && GetValue(plain, 10, 15) > 128.0 &&
    GetValue(plain, 52, 39) < 128.0 && GetValue(plain, 53, 39) > 128.0 &&
    GetValue(plain, 7, 36) < 128.0 && GetValue(plain, 7, 37) > 128.0 &&
    GetValue(plain, 4, 36) > 128.0 && GetValue(plain, 29, 34) < 128.0 &&
    GetValue(plain, 29, 35) > 128.0 &&
    GetValue(plain, 53, 19) < 128.0);
  for (const int searchSteps : { 16, 128 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(searchSteps);
    options->SetDiagonalDetection(false);
    options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
    auto chapter = RunMLAA(plain, options);
    options->SetCornerExtrapolation(true);
    auto cpu = RunMLAA(plain, options);
    // The side's pixels nearer the corner take the step's longer ramp (one step) or half the
    // corner's ramp (unknown height): they differ.
    MLAA_CHECK(GetValue(cpu, 27, 14, 0) < GetValue(chapter, 27, 14, 0));
    MLAA_CHECK(GetValue(cpu, 27, 34, 0) < GetValue(chapter, 27, 34, 0));
    MLAA_CHECK(GetValue(cpu, 27, 14, 1) != GetValue(cpu, 27, 34, 1));
    MLAA_CHECK(GetValue(cpu, 53, 37, 2) < GetValue(chapter, 53, 37, 2) ||
      GetValue(cpu, 53, 37, 3) < GetValue(chapter, 53, 37, 3));
    CheckPassWeights(renderer, window, options, cpu, std::to_string(searchSteps) + " steps");
  }
}

void TJunctions()
{
  // A plane on pixel boundaries (columns 10 to 29, across the window) in two bands, grey below
  // row 24 and black from it up, on white: its sides go on straight past the band border, a T
  // junction on each, which is no step (issue 20), and run into the image border at both ends.
  // The pass's weights equal the filter's exactly, searched and counted, at 16 and 128 steps, and
  // the sides' pixels take none (TestImageMLAAPatterns has the filter's cases with and without
  // the rule). No local contrast adaptation: it would drop the band border next to the sides.
  const int width = 48, height = 48;
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  BuildRectangles(renderer, { { 10, 29, -8, 23 }, { 10, 29, 24, 55 } }, width, height, { 96, 0 });
  auto plain = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(GetValue(plain, 29, 23) == 96.0 && GetValue(plain, 29, 24) == 0.0 &&
    GetValue(plain, 30, 23) == 255.0 && GetValue(plain, 9, 24) == 255.0);
  for (const int searchSteps : { 16, 128 })
  {
    vtkNew<vtkMLAAOptions> options;
    options->SetMaxSearchSteps(searchSteps);
    options->SetLocalContrastFactor(0.0);
    options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
    auto cpu = RunMLAA(plain, options);
    for (int y = 0; y < height; ++y)
    {
      for (int x : { 10, 30 }) // the pixels that own the sides' left edgels
      {
        MLAA_CHECK(GetValue(cpu, x, y, 2) == 0.0 && GetValue(cpu, x, y, 3) == 0.0);
      }
    }
    CheckPassWeights(
      renderer, window, options, cpu, "T junctions, " + std::to_string(searchSteps) + " steps");
  }
}

void Ramps()
{
  // The utilities' ramp (columns 8 to 18 rising in grey from 30 to 230 under a staircase top, on
  // black). With local contrast adaptation the boundaries inside the ramp (columns 9 to 17's left
  // edgels) are no edges (issue 20); without it they are. With Lab, luma and colour edges, the
  // pass's edges and blending weights equal the filter's exactly (TestMLAAStages and
  // TestImageMLAAEdgeModes have the filter's cases).
  const int width = 40, height = 24;
  auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  std::vector<std::array<int, 4>> columns;
  std::vector<unsigned char> greys;
  for (int x = RampFirst; x <= RampLast; ++x)
  {
    columns.push_back({ x, x, -4, RampTop(x) });
    greys.push_back(static_cast<unsigned char>(RampGrey(x)));
  }
  BuildRectangles(renderer, columns, width, height, greys);
  renderer->SetBackground(0.0, 0.0, 0.0);
  auto plain = vtkMLAAScenes::Capture(window);
  MLAA_CHECK(GetValue(plain, 8, 9) == 30.0 && GetValue(plain, 8, 10) == 0.0 &&
    GetValue(plain, 18, 0) == 230.0 && GetValue(plain, 18, 12) == 230.0 &&
    GetValue(plain, 18, 13) == 0.0 && GetValue(plain, 19, 0) == 0.0);
  for (int mode : { vtkMLAAOptions::LAB, vtkMLAAOptions::LUMA, vtkMLAAOptions::COLOR })
  {
    const std::string label = "ramps, edge detection " + std::to_string(mode);
    vtkNew<vtkMLAAOptions> options;
    options->SetEdgeDetection(mode);
    options->SetThreshold(0.05);
    const auto cpu = EdgesWithAndWithoutAdaptation(plain, options);
    for (int y = 0; y < 10; ++y)
    {
      for (int x = RampFirst + 1; x < RampLast; ++x)
      {
        MLAA_CHECK(GetValue(cpu[0], x, y, 0) == 0.0 && GetValue(cpu[1], x, y, 0) == 255.0);
      }
    }
    options->SetDebugOutput(vtkMLAAOptions::EDGES);
    auto pass = UseMLAA(renderer, options);
    auto gpu = vtkMLAAScenes::Capture(window, true);
    StopPass(renderer, window);
    const Difference d = Compare(cpu[0], gpu, 0.0);
    if (!MLAA_CHECK(d.Count == 0))
    {
      std::cerr << label << ": " << d.Count << " pixels of edges differ from the filter's\n";
    }
    options->SetDebugOutput(vtkMLAAOptions::BLENDING_WEIGHTS);
    CheckPassWeights(renderer, window, options, RunMLAA(plain, options), label);
  }
}
}

int TestMLAAPassLongLines(int, char*[])
{
  UnknownHeightEnds();
  TJunctions();
  Ramps();
  OneDegreeSlope();
  DiagonalStaircases();
  SameWeightsOnSharedScenes();
  AutomaticAndResources();
  return Result();
}
