// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Temporal antialiasing (vtkOpenGLAntialiasingPass::SetTemporal), for every method of
// PassMethods():
// - still scene: 16 renders of the silhouettes and thin-structures scenes come within reach of the
//   supersampled reference of MEASURING.md (8 x 8 renders shifted by stratified sub-pixel offsets,
//   averaged): AAR over the aliased pixels at least 0.93, and above the single-frame pass's; the
//   history counts 16 frames (ConvergedFrames), RenderConverged renders until it does, the camera's
//   parameters are the same after every render as before, and once converged a further render
//   holds the still (the same image, the camera's modified time unchanged);
// - translucent geometry (order-independent translucency, dual depth peeling): a still, and a
//   still after a short orbit, converge to the reference as opaque geometry does;
// - the box filter: after 16 renders, pixels crossed by the edges of rectangles at sub-pixel
//   positions hold the share of the pixel covered, within 1/16 (0.03 on average);
// - a moving actor (a sphere moved across a flat background): after 2 renders, the pixels it left
//   (farther than 2 pixels from where it is now) are exactly the background;
// - an animated actor (a sphere moving a few pixels a frame past a still one, over a
//   checkerboard, after the still scene converged, the camera still): the pixels it covered or
//   came within a pixel of 2 frames before are exactly the single-frame pass's (no ghost, no
//   ring where it started), and the still sphere's half of
//   the image keeps its converged quality and does not change at all, and when the sphere stops
//   it goes on accumulating from its own count of frames (no pixel steps by more than 16/255);
// - a camera orbit of a few frames: the history is reprojected (1 frame counted), flat regions of
//   the plain render stay exactly as they are, edges are antialiased, and accumulation starts
//   again when the camera stops;
// - the still after an orbit (three orbits of the thin-structures scene) converges to within
//   32/255 of a still from a reset history;
// - a fast camera: a parallel camera panned 20 pixels in one frame, or a perspective camera turned
//   10 degrees about its focal point, does not read the history (the result is exactly the
//   single-frame pass's render of that view), while a 2-pixel pan or a half-degree turn still
//   blends it (the result differs from that render);
// - disocclusion: a camera panned (perspective) or turned (parallel) past a sphere in front of a
//   checkered panel; the panel pixels the sphere hid at the previous render take the
//   single-frame pass's render exactly (the previous render's depth rejects the sphere's history,
//   which the checkerboard's range does not clamp away), while the rest of the panel blends its
//   history;
// - resets: a resize, a changed actor colour, a changed input and switching Temporal off and on
//   each give the same image as a new pass's first render (the history is discarded, the jitter
//   sequence restarts), and so does an actor moving while the camera moves; an actor that only
//   moves under a still camera keeps the history (differs from a first render);
// - picking: an area selection gives the same cells with the temporal pass as without a pass, and
//   leaves the history and the camera alone;
// - overlays: with only the text and scalar bar of the text scene visible, every render equals the
//   plain render exactly (overlays are drawn after the blend, not jittered);
// - layers: a temporal pass on a layer-1 renderer leaves layer 0's pixels exactly as they were
//   wherever layer 1 draws nothing near, and its still converges too.
// No errors are reported on the way.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkHardwareSelector.h"
#include "vtkIdTypeArray.h"
#include "vtkImageCanvasSource2D.h"
#include "vtkMath.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkSelection.h"
#include "vtkSelectionNode.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <vector>

using namespace vtkMLAATest;

namespace
{
constexpr int Width = 160, Height = 120;

// The method's pass on `renderer` with Temporal on, its errors reported to `messages`.
vtkOpenGLAntialiasingPass* UseTemporal(
  const PassMethod& method, vtkRenderer* renderer, MessageObserver* messages)
{
  vtkOpenGLAntialiasingPass* pass = method.Use(renderer);
  pass->TemporalOn();
  pass->AddObserver(vtkCommand::ErrorEvent, messages);
  return pass;
}

// A still scene's plain render, its supersampled reference, and the AAR of the method's
// single-frame pass against that reference (the pass is removed again).
struct SingleFrame
{
  vtkSmartPointer<vtkImageData> Plain;
  std::vector<double> Reference;
  double Single = 0.0;
};

SingleFrame MeasureSingleFrame(const PassMethod& method, vtkRenderWindow* window,
  vtkRenderer* renderer, MessageObserver* messages)
{
  SingleFrame s;
  s.Plain = vtkMLAAScenes::Capture(window);
  s.Reference = SupersampledReference(window, renderer);
  method.Use(renderer)->AddObserver(vtkCommand::ErrorEvent, messages);
  s.Single = AAR(s.Plain, vtkMLAAScenes::Capture(window), s.Reference);
  StopPass(renderer, window);
  return s;
}

// Renders the unchanged scene `renders` times; the last capture.
vtkSmartPointer<vtkImageData> CaptureAfter(vtkRenderWindow* window, int renders)
{
  vtkSmartPointer<vtkImageData> result;
  for (int k = 0; k < renders; ++k)
  {
    result = vtkMLAAScenes::Capture(window);
  }
  return result;
}

struct CameraState
{
  double Values[14];
  explicit CameraState(vtkCamera* c)
  {
    c->GetPosition(this->Values);
    c->GetFocalPoint(this->Values + 3);
    c->GetViewUp(this->Values + 6);
    c->GetWindowCenter(this->Values + 9);
    c->GetClippingRange(this->Values + 11);
    this->Values[13] = c->GetViewAngle();
  }
  bool operator==(const CameraState& o) const
  {
    for (int i = 0; i < 14; ++i)
    {
      if (this->Values[i] != o.Values[i])
      {
        return false;
      }
    }
    return true;
  }
};

void StillConvergence(const PassMethod& method, MessageObserver* messages)
{
  for (const char* scene : { "silhouettes", "thin" })
  {
    auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build(scene, renderer);
    const SingleFrame measured = MeasureSingleFrame(method, window, renderer, messages);
    const vtkSmartPointer<vtkImageData>& plain = measured.Plain;
    const std::vector<double>& reference = measured.Reference;
    const double single = measured.Single;

    vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
    const CameraState before(renderer->GetActiveCamera());
    vtkSmartPointer<vtkImageData> result;
    bool cameraKept = true;
    for (int k = 0; k < 16; ++k)
    {
      result = vtkMLAAScenes::Capture(window);
      cameraKept = cameraKept && CameraState(renderer->GetActiveCamera()) == before;
    }
    const double temporal = AAR(plain, result, reference);
    const vtkMTimeType cameraTime = renderer->GetActiveCamera()->GetMTime();
    auto held = vtkMLAAScenes::Capture(window);
    std::cout << method.Name << ", " << scene << ": AAR single-frame pass " << single
              << ", temporal after 16 renders " << temporal << "; accumulated "
              << pass->GetAccumulatedFrames() << " after 17" << std::endl;
    Check(cameraKept, "the camera's parameters are kept", __FILE__, __LINE__);
    Check(pass->GetAccumulatedFrames() == 16, "16 frames accumulated", __FILE__, __LINE__);
    Check(Compare(result, held, 0.0).Count == 0 &&
        renderer->GetActiveCamera()->GetMTime() == cameraTime,
      "a converged still holds", __FILE__, __LINE__);
    // (0.96 on llvmpipe for both methods and scenes; drivers rasterise a little differently.)
    Check(temporal >= 0.93, "a still converges to the reference", __FILE__, __LINE__);
    Check(temporal > single, "better than the single-frame pass", __FILE__, __LINE__);

    // RenderConverged: from a reset, ConvergedFrames renders.
    pass->ResetHistory();
    pass->SetConvergedFrames(8);
    const int renders = pass->RenderConverged(window);
    std::cout << "  RenderConverged: " << renders << " renders, "
              << pass->GetAccumulatedFrames() << " accumulated" << std::endl;
    Check(renders == 8 && pass->GetAccumulatedFrames() == 8, "RenderConverged", __FILE__,
      __LINE__);
    StopPass(renderer, window);
  }
}

// Translucent geometry under the temporal pass: the spheres of TestAntialiasingPassTranslucency
// (BuildTranslucentSpheres), with order-independent translucency (UseDepthPeeling off) and with
// dual depth peeling. The delegate's translucent steps draw into the pass's
// textures at every jittered render; 16 renders of the still scene must come within reach of
// the supersampled reference (AAR at least 0.93, above the single-frame pass's), as for opaque
// geometry, and so must a still after a short orbit.
void TranslucentStill(const PassMethod& method, MessageObserver* messages)
{
  for (int peeling = 0; peeling <= 1; ++peeling)
  {
    auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    renderer->SetUseDepthPeeling(peeling);
    BuildTranslucentSpheres(renderer);
    const SingleFrame measured = MeasureSingleFrame(method, window, renderer, messages);
    const vtkSmartPointer<vtkImageData>& plain = measured.Plain;
    const std::vector<double>& reference = measured.Reference;
    const double single = measured.Single;

    vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
    const double still = AAR(plain, CaptureAfter(window, 16), reference);
    for (int k = 0; k < 4; ++k)
    {
      renderer->GetActiveCamera()->Azimuth(0.5);
      vtkMLAAScenes::Capture(window);
    }
    renderer->GetActiveCamera()->Azimuth(-2.0); // back where the reference was rendered
    pass->RenderConverged(window);
    const double afterOrbit = AAR(plain, vtkMLAAScenes::Capture(window), reference);
    std::cout << method.Name << ", translucent spheres ("
              << (peeling ? "dual depth peeling" : "order-independent translucency")
              << "): AAR single-frame pass " << single << ", temporal after 16 renders " << still
              << ", still after an orbit " << afterOrbit << std::endl;
    Check(still >= 0.93 && still > single, "translucency: a still converges", __FILE__,
      __LINE__);
    Check(afterOrbit >= 0.93, "translucency: a still after an orbit converges", __FILE__,
      __LINE__);
    StopPass(renderer, window);
  }
}

// The box filter: white rectangles on black under a camera of one world unit per pixel, their 24
// edges (12 vertical, 12 horizontal) at sub-pixel positions spread over the pixel. After 16
// renders of the still scene each pixel an edge crosses must hold the share of the pixel the
// rectangle covers (the box filter's exact value), within 1/16 (one render of 16; the first
// render samples the pixel's centre), and within 0.03 on average over the edges. (The jitter
// sequence is what this checks: with the Halton (2, 3) points used before, 16 renders were up to
// 0.096 off on these edges, 0.037 (MLAA) / 0.042 (DLAA) on average.)
void BoxFilter(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.0, 0.0, 0.0);
  UsePixelCamera(renderer, Width, Height);
  struct Edge
  {
    bool Vertical;
    int Pixel;       // the column (vertical) or row the edge crosses
    int From, To;    // the rows (vertical) or columns it is measured along
    double Coverage; // of that pixel by the rectangle
  };
  std::vector<Edge> edges;
  int k = 0;
  auto fraction = [&k]() {
    const double f = 0.05 + 0.6180339887 * k++;
    return f - std::floor(f);
  };
  for (int row = 0; row < 2; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      const int x = 8 + 50 * column, y = 8 + 56 * row, w = 36, h = 40;
      const double left = fraction(), bottom = fraction(), right = fraction(), top = fraction();
      vtkNew<vtkPlaneSource> plane;
      plane->SetOrigin(x + left, y + bottom, 0.0);
      plane->SetPoint1(x + w + right, y + bottom, 0.0);
      plane->SetPoint2(x + left, y + h + top, 0.0);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputConnection(plane->GetOutputPort());
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->GetProperty()->SetColor(1.0, 1.0, 1.0);
      actor->GetProperty()->LightingOff();
      renderer->AddActor(actor);
      // Measured 3 pixels clear of the corners.
      edges.push_back({ true, x, y + 3, y + h - 3, 1.0 - left });
      edges.push_back({ true, x + w, y + 3, y + h - 3, right });
      edges.push_back({ false, y, x + 3, x + w - 3, 1.0 - bottom });
      edges.push_back({ false, y + h, x + 3, x + w - 3, top });
    }
  }
  UseTemporal(method, renderer, messages);
  const vtkSmartPointer<vtkImageData> result = CaptureAfter(window, 16);
  double largest = 0.0, sum = 0.0;
  for (const Edge& e : edges)
  {
    for (int t = e.From; t <= e.To; ++t)
    {
      const int x = e.Vertical ? e.Pixel : t, y = e.Vertical ? t : e.Pixel;
      const double error = std::abs(GetValue(result, x, y, 0) / 255.0 - e.Coverage);
      largest = std::max(largest, error);
      sum += error / (e.To - e.From + 1);
    }
  }
  const double mean = sum / edges.size();
  std::cout << method.Name << ", box filter: " << edges.size()
            << " edges after 16 renders, largest error " << largest << ", mean " << mean
            << std::endl;
  Check(largest <= 1.0 / 16.0 + 2.0 / 255.0, "each edge pixel within 1/16 of its coverage",
    __FILE__, __LINE__);
  Check(mean <= 0.03, "edge pixels within 0.03 of their coverage on average", __FILE__, __LINE__);
  StopPass(renderer, window);
}

vtkSmartPointer<vtkActor> AddSphere(vtkRenderer* renderer, double x, double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  sphere->SetRadius(radius);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(x, 0.0, 0.0);
  actor->GetProperty()->SetColor(0.9, 0.4, 0.1);
  renderer->AddActor(actor);
  return actor;
}

// A panel at z = -1 from x0 to x1 and from -halfHeight to halfHeight, unlit, textured with 64 x 64
// texels of light grey on which `draw` draws in dark grey.
void AddPanel(vtkRenderer* renderer, double x0, double x1, double halfHeight,
  const std::function<void(vtkImageCanvasSource2D*)>& draw)
{
  vtkNew<vtkImageCanvasSource2D> canvas;
  canvas->SetScalarTypeToUnsignedChar();
  canvas->SetNumberOfScalarComponents(3);
  canvas->SetExtent(0, 63, 0, 63, 0, 0);
  canvas->SetDrawColor(230, 230, 230);
  canvas->FillBox(0, 63, 0, 63);
  canvas->SetDrawColor(30, 30, 30);
  draw(canvas);
  vtkNew<vtkTexture> texture;
  texture->SetInputConnection(canvas->GetOutputPort());
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(x0, -halfHeight, -1.0);
  plane->SetPoint1(x1, -halfHeight, -1.0);
  plane->SetPoint2(x0, halfHeight, -1.0);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> panel;
  panel->SetMapper(planeMapper);
  panel->SetTexture(texture);
  panel->GetProperty()->SetAmbient(1.0);
  panel->GetProperty()->SetDiffuse(0.0);
  renderer->AddActor(panel);
}

// A renderer with a flat background, a sphere and a fixed camera.
void SphereScene(vtkRenderer* renderer, vtkActor*& sphere)
{
  renderer->SetBackground(0.1, 0.2, 0.35);
  sphere = AddSphere(renderer, -1.0, 0.6);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 8.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetClippingRange(4.0, 12.0);
}

// SphereScene with a second, green sphere at x = 1; the first sphere.
vtkActor* TwoSpheres(vtkRenderer* renderer)
{
  vtkActor* sphere = nullptr;
  SphereScene(renderer, sphere);
  AddSphere(renderer, 1.0, 0.8)->GetProperty()->SetColor(0.3, 0.8, 0.4);
  return sphere;
}

void MovingActor(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkActor* sphere = nullptr;
  SphereScene(renderer, sphere);
  sphere->SetPosition(1.0, 0.0, 0.0);
  auto plainNew = vtkMLAAScenes::Capture(window);
  sphere->SetPosition(-1.0, 0.0, 0.0);
  auto plainOld = vtkMLAAScenes::Capture(window);

  UseTemporal(method, renderer, messages);
  for (int k = 0; k < 8; ++k)
  {
    vtkMLAAScenes::Capture(window);
  }
  sphere->SetPosition(1.0, 0.0, 0.0);
  vtkMLAAScenes::Capture(window);
  auto result = vtkMLAAScenes::Capture(window);
  // The pixels the sphere covered and left: drawn before (not the background), and background
  // now, 2 pixels around.
  auto isBackground = [&](vtkImageData* image, int x, int y) {
    for (int c = 0; c < 3; ++c)
    {
      if (GetValue(image, x, y, c) != GetValue(plainNew, 0, 0, c))
      {
        return false;
      }
    }
    return true;
  };
  vtkIdType left = 0, ghosts = 0;
  for (int y = 0; y < Height; ++y)
  {
    for (int x = 0; x < Width; ++x)
    {
      if (isBackground(plainOld, x, y) || !isBackground(plainNew, x, y) ||
        !IsFlatAround(plainNew, x, y, 2, 0.0))
      {
        continue;
      }
      ++left;
      ghosts += isBackground(result, x, y) ? 0 : 1;
    }
  }
  std::cout << method.Name << ", moving actor: " << left << " pixels left, " << ghosts
            << " not background after 2 renders" << std::endl;
  Check(left > 500, "the sphere left pixels", __FILE__, __LINE__);
  Check(ghosts == 0, "no ghost after 2 renders", __FILE__, __LINE__);
  StopPass(renderer, window);
}

// An animated actor: a sphere moving a few pixels a frame past a still one, over a checkerboard
// panel, after the still scene converged. Actors that only move under a still camera keep the
// history where the method's frame did not change: the pixels the moving sphere covered or came
// within a pixel of 2 frames before (3 pixels clear of it now) are exactly the single-frame
// pass's (clamping the history to the current neighbourhood would let the sphere's colour
// survive over the checkerboard; comparing each pixel alone would keep the converged edge of the
// sphere's first position where the pixel's own sample stayed the background), and
// the left half, where only the still sphere is, keeps its converged quality (AAR against the
// reference above the single-frame pass's) and does not change at all.
void AnimatedActor(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkActor* moving = nullptr;
  SphereScene(renderer, moving);
  moving->SetScale(0.6);
  AddSphere(renderer, -1.6, 0.8)->GetProperty()->SetColor(0.3, 0.8, 0.4);
  AddPanel(renderer, 0.4, 3.6, 2.5, [](vtkImageCanvasSource2D* canvas) {
    for (int i = 0; i < 64; i += 8) // a checkerboard of 8 x 8 squares
    {
      for (int j = (i / 8) % 2 * 8; j < 64; j += 16)
      {
        canvas->FillBox(i, i + 7, j, j + 7);
      }
    }
  });
  constexpr int Frames = 10;
  auto place = [&](int k) { moving->SetPosition(1.6, -1.2 + 0.25 * k, 0.0); };

  // The plain and single-frame pass's renders of each frame, the scene without the moving sphere,
  // and the reference of the first frame (for the left half).
  std::vector<vtkSmartPointer<vtkImageData>> plain, single;
  for (int k = 0; k < Frames; ++k)
  {
    place(k);
    plain.push_back(vtkMLAAScenes::Capture(window));
    method.Use(renderer)->AddObserver(vtkCommand::ErrorEvent, messages);
    single.push_back(vtkMLAAScenes::Capture(window));
    StopPass(renderer, window);
  }
  moving->VisibilityOff();
  auto bare = vtkMLAAScenes::Capture(window);
  moving->VisibilityOn();
  place(0);
  const std::vector<double> reference = SupersampledReference(window, renderer);

  // Whether the moving sphere covers (x, y) in frame k, or comes within `radius` pixels of it.
  auto covers = [&](int k, int x, int y, int radius) {
    for (int j = std::max(0, y - radius); j <= std::min(Height - 1, y + radius); ++j)
    {
      for (int i = std::max(0, x - radius); i <= std::min(Width - 1, x + radius); ++i)
      {
        for (int c = 0; c < 3; ++c)
        {
          if (GetValue(plain[k], i, j, c) != GetValue(bare, i, j, c))
          {
            return true;
          }
        }
      }
    }
    return false;
  };
  // AAR over the left half (the still sphere; the moving one and the panel stay right of it).
  auto leftAAR = [&](vtkImageData* result) {
    double none = 0.0, error = 0.0;
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width / 2; ++x)
      {
        const size_t v = 3 * (static_cast<size_t>(y) * Width + x);
        bool inE = false;
        for (int c = 0; c < 3; ++c)
        {
          inE = inE || std::abs(GetValue(plain[0], x, y, c) - reference[v + c]) > 4.0;
        }
        for (int c = 0; inE && c < 3; ++c)
        {
          const double n = GetValue(plain[0], x, y, c) - reference[v + c];
          const double m = GetValue(result, x, y, c) - reference[v + c];
          none += n * n;
          error += m * m;
        }
      }
    }
    return none > 0.0 ? 1.0 - error / none : 0.0;
  };
  auto leftChange = [&](vtkImageData* a, vtkImageData* b) {
    double sum = 0.0;
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width / 2; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          sum += std::abs(GetValue(a, x, y, c) - GetValue(b, x, y, c));
        }
      }
    }
    return sum;
  };

  vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
  pass->RenderConverged(window);
  vtkSmartPointer<vtkImageData> previous = vtkMLAAScenes::Capture(window);
  const double converged = leftAAR(previous);
  vtkIdType left = 0, ghosts = 0;
  double largestStep = 0.0;
  vtkSmartPointer<vtkImageData> result;
  for (int k = 1; k < Frames; ++k)
  {
    place(k);
    result = vtkMLAAScenes::Capture(window);
    largestStep = std::max(largestStep, leftChange(previous, result));
    previous = result;
    for (int y = 0; k >= 2 && y < Height; ++y)
    {
      for (int x = Width / 2; x < Width; ++x)
      {
        if (!covers(k - 2, x, y, 1) || covers(k, x, y, 3))
        {
          continue;
        }
        ++left;
        for (int c = 0; c < 3; ++c)
        {
          if (GetValue(result, x, y, c) != GetValue(single[k], x, y, c))
          {
            ++ghosts;
            break;
          }
        }
      }
    }
  }
  const double animated = leftAAR(result);
  const double singleAAR = leftAAR(single[0]);
  // The moving sphere stops: the still accumulation goes on, and the left half, whose pixels kept
  // their history (and their count of frames) through the motion, goes on from its count instead
  // of starting again (a new jittered render weighing 1/2 there).
  double largestAfterStop = 0.0;
  for (int r = 0; r < 4; ++r)
  {
    auto still = vtkMLAAScenes::Capture(window);
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width / 2; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          largestAfterStop = std::max(largestAfterStop,
            std::abs(GetValue(still, x, y, c) - GetValue(previous, x, y, c)));
        }
      }
    }
    previous = still;
  }
  std::cout << method.Name << ", animated actor: " << left
            << " pixels covered or within a pixel 2 frames before, " << ghosts
            << " not the single-frame pass's; left half AAR converged " << converged << ", after "
            << Frames - 1 << " frames of motion " << animated << ", single-frame pass "
            << singleAAR << "; largest change of the left half a frame " << largestStep
            << "; largest change of a left-half pixel a render in the 4 renders after it stops "
            << largestAfterStop << std::endl;
  Check(left > 300, "the moving sphere left pixels", __FILE__, __LINE__);
  Check(ghosts == 0, "no ghost 2 frames after", __FILE__, __LINE__);
  Check(animated > singleAAR + 0.05, "the still half keeps its history", __FILE__, __LINE__);
  Check(largestStep == 0.0, "the still half does not change", __FILE__, __LINE__);
  // At most a 1/16 step (the next render weighs 1/18 there); restarting gave up to about 1/2.
  Check(largestAfterStop <= 16.0, "no dip where the history was kept when the actor stops",
    __FILE__, __LINE__);
  StopPass(renderer, window);
}

void CameraOrbit(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = UseTemporal(method, renderer, messages);
  vtkMLAAScenes::Capture(window);
  vtkMLAAScenes::Capture(window);
  Check(pass->GetAccumulatedFrames() == 2, "still: 2 frames", __FILE__, __LINE__);
  bool reprojected = true;
  for (int k = 0; k < 4; ++k)
  {
    renderer->GetActiveCamera()->Azimuth(0.5);
    auto result = vtkMLAAScenes::Capture(window);
    reprojected = reprojected && pass->GetAccumulatedFrames() == 1;
    if (k == 3)
    {
      // The blend of the clamped history stays close to this frame's plain render away from edges.
      renderer->SetPass(nullptr);
      auto plain = vtkMLAAScenes::Capture(window);
      renderer->SetPass(pass);
      // (Flat: 9 x 9 pixels of one colour; the jitter moves edges by up to half a pixel, and
      // DLAA's long-edge filter reaches farther than MLAA's blending.)
      const Changes c = CountChanges(plain, result, 4);
      std::cout << method.Name << ", orbit: " << c.Changed << " pixels differ from the plain "
                << "render, " << c.FlatChanged << " of them in flat regions" << std::endl;
      Check(c.FlatChanged == 0, "flat regions kept while the camera moves", __FILE__, __LINE__);
      Check(c.Changed > 50, "antialiased while the camera moves", __FILE__, __LINE__);
    }
  }
  Check(reprojected, "a moving camera reprojects the history", __FILE__, __LINE__);
  vtkMLAAScenes::Capture(window); // the camera as at the last render of the orbit: still
  vtkMLAAScenes::Capture(window);
  std::cout << "  accumulated after the camera stopped: " << pass->GetAccumulatedFrames()
            << std::endl;
  Check(pass->GetAccumulatedFrames() == 3, "accumulation after the camera stops", __FILE__,
    __LINE__);
  StopPass(renderer, window);
}

// The still after a camera orbit converges like a new one: every value within 32/255 of a still
// accumulated from a reset history under the same camera (only the one reprojected frame the
// accumulation starts from differs), in each of three orbits of the thin-structures scene at 400
// x 300. (Per-pixel counts of the history left undefined during the motion, by a draw-buffer
// switch that VTK 9.1's state cache dropped, blackened whole 64 x 64 tiles of such stills on
// llvmpipe, in some runs and not others.)
void StillAfterOrbit(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(400, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("thin", renderer);
  vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = UseTemporal(method, renderer, messages);
  Difference worst;
  for (int orbit = 0; orbit < 3; ++orbit)
  {
    pass->RenderConverged(window);
    for (int k = 0; k < 12; ++k)
    {
      renderer->GetActiveCamera()->Azimuth(0.2);
      vtkMLAAScenes::Capture(window);
    }
    pass->RenderConverged(window);
    auto afterMotion = vtkMLAAScenes::Capture(window);
    pass->ResetHistory();
    pass->RenderConverged(window);
    auto fresh = vtkMLAAScenes::Capture(window);
    const Difference d = Compare(afterMotion, fresh, 32.0);
    worst.Pixels = std::max(worst.Pixels, d.Pixels);
    worst.Max = std::max(worst.Max, d.Max);
  }
  std::cout << method.Name << ", still after an orbit: at most " << worst.Pixels
            << " pixels more than 32/255 from a new still's, largest difference " << worst.Max
            << std::endl;
  Check(worst.Pixels == 0, "the still after an orbit converges like a new one", __FILE__,
    __LINE__);
  StopPass(renderer, window);
}

// A pan of the camera by `pixels` pixels to the right, measured at the focal point's distance (a
// parallel projection: every point moves by that much on the screen).
void Pan(vtkCamera* camera, double pixels)
{
  const double halfHeight = camera->GetParallelProjection()
    ? camera->GetParallelScale()
    : camera->GetDistance() * std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle() / 2.0));
  const double shift = pixels * 2.0 * halfHeight / Height;
  double position[3], focal[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->SetPosition(position[0] + shift, position[1], position[2]);
  camera->SetFocalPoint(focal[0] + shift, focal[1], focal[2]);
}

// A point that moved 16 pixels or more since the last frame, or whose direction of view turned 8
// degrees or more, takes the current frame alone (its history would be mostly reprojection error,
// or shading and outlines seen from elsewhere); one that moved a few pixels keeps some history.
// The scene: spheres over a textured panel; the result after each move compared with the
// single-frame pass's render of the same view.
void FastCamera(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  TwoSpheres(renderer);
  AddPanel(renderer, -6.0, 6.0, 4.0,
    [](vtkImageCanvasSource2D* canvas) { canvas->FillTriangle(4, 4, 60, 20, 12, 58); });
  vtkCamera* camera = renderer->GetActiveCamera();

  // Two moves of the camera from a converged still: the first small, whose result blends the
  // history (differs from the single-frame pass's render of that view), the second large, whose
  // result is exactly that render.
  auto check = [&](const char* what, const std::function<void(int)>& move) {
    std::vector<vtkSmartPointer<vtkImageData>> single;
    vtkNew<vtkCamera> saved;
    saved->DeepCopy(camera);
    method.Use(renderer)->AddObserver(vtkCommand::ErrorEvent, messages);
    for (int i = 0; i < 2; ++i)
    {
      move(i);
      single.push_back(vtkMLAAScenes::Capture(window));
    }
    StopPass(renderer, window);
    camera->DeepCopy(saved);
    vtkSmartPointer<vtkOpenGLAntialiasingPass> pass = UseTemporal(method, renderer, messages);
    CaptureAfter(window, 4); // a still accumulation, whose history differs from the method's frame
    Difference d[2];
    for (int i = 0; i < 2; ++i)
    {
      move(i);
      d[i] = Compare(vtkMLAAScenes::Capture(window), single[i]);
    }
    std::cout << method.Name << ", " << what << ": " << d[0].Pixels << " / " << d[1].Pixels
              << " pixels differ from the single-frame pass's render (largest difference "
              << d[1].Max << " after the large move)" << std::endl;
    Check(d[0].Pixels > 20, "a small move blends the history", __FILE__, __LINE__);
    Check(d[1].Pixels == 0, "a large move takes the current frame alone", __FILE__, __LINE__);
    StopPass(renderer, window);
    camera->DeepCopy(saved);
  };
  // A parallel camera panned 2, then 20 pixels: every point moves that much on the screen.
  camera->ParallelProjectionOn();
  camera->SetParallelScale(2.5);
  check("pans of 2 and 20 pixels", [camera](int i) { Pan(camera, i == 0 ? 2.0 : 20.0); });
  // A perspective camera turned about its focal point by 0.5, then 10 degrees: the view turns by
  // that much at every point, while points near the focal point move less than 16 pixels.
  camera->ParallelProjectionOff();
  check("turns of 0.5 and 10 degrees",
    [camera](int i) { camera->Azimuth(i == 0 ? 0.5 : 10.0); });
}

// Disocclusion: a camera moved past a small sphere in front of a panel checkered in texels of
// about 5 pixels, so that the panel moves 6 pixels on the screen relative to the sphere: a
// perspective camera panned sideways (the panel twice as far as the sphere: the sphere moves 12
// pixels, the panel 6), and a parallel camera turned about the sphere (the sphere stays, the panel
// behind it moves). The panel pixels the sphere covered at the previous render and no longer
// comes within 2 pixels of were hidden behind it: their history is the sphere's, which the
// checkerboard's dark-to-light range does not clamp away, and the depth of the previous render
// rejects it (the result is exactly the single-frame pass's render of that view), while the rest
// of the panel keeps blending its history.
void Disocclusion(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  renderer->SetBackground(0.1, 0.2, 0.35);
  vtkSmartPointer<vtkActor> sphere = AddSphere(renderer, 0.0, 0.08);
  AddPanel(renderer, -1.5, 1.5, 1.0, [](vtkImageCanvasSource2D* canvas) {
    for (int j = 0; j < 64; ++j)
    {
      for (int i = j % 2; i < 64; i += 2)
      {
        canvas->FillBox(i, i, j, j);
      }
    }
  });
  vtkCamera* camera = renderer->GetActiveCamera();
  // The sphere's pixels (where the render differs from one without it), and the render.
  auto covered = [&]() {
    auto with = vtkMLAAScenes::Capture(window);
    sphere->VisibilityOff();
    auto without = vtkMLAAScenes::Capture(window);
    sphere->VisibilityOn();
    std::vector<bool> mask(static_cast<std::size_t>(Width) * Height);
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          mask[y * Width + x] = mask[y * Width + x] ||
            GetValue(with, x, y, c) != GetValue(without, x, y, c);
        }
      }
    }
    return std::make_pair(mask, with);
  };
  // Where the panel's centre is on the screen.
  auto panelCentre = [&](double display[3]) {
    renderer->SetWorldPoint(0.0, 0.0, -1.0, 1.0);
    renderer->WorldToDisplay();
    renderer->GetDisplayPoint(display);
  };
  auto check = [&](const char* what, const std::function<void()>& move) {
    vtkNew<vtkCamera> saved;
    saved->DeepCopy(camera);
    const std::vector<bool> before = covered().first;
    double from[3], to[3];
    panelCentre(from);
    move();
    panelCentre(to);
    // The panel's move on the screen: its point at (x, y) was at (x + dx, y + dy).
    const int dx = static_cast<int>(std::lround(from[0] - to[0]));
    const int dy = static_cast<int>(std::lround(from[1] - to[1]));
    const auto after = covered();
    method.Use(renderer)->AddObserver(vtkCommand::ErrorEvent, messages);
    auto single = vtkMLAAScenes::Capture(window);
    StopPass(renderer, window);

    camera->DeepCopy(saved);
    UseTemporal(method, renderer, messages);
    CaptureAfter(window, 4);
    move();
    auto result = vtkMLAAScenes::Capture(window);
    auto near = [&](int x, int y) {
      for (int j = std::max(y - 2, 0); j <= std::min(y + 2, Height - 1); ++j)
      {
        for (int i = std::max(x - 2, 0); i <= std::min(x + 2, Width - 1); ++i)
        {
          if (after.first[j * Width + i])
          {
            return true;
          }
        }
      }
      return false;
    };
    vtkIdType revealed = 0, edges = 0, kept = 0, blended = 0;
    for (int y = 0; y < Height; ++y)
    {
      for (int x = 0; x < Width; ++x)
      {
        if (near(x, y))
        {
          continue;
        }
        bool same = true;
        for (int c = 0; c < 3; ++c)
        {
          same = same && GetValue(result, x, y, c) == GetValue(single, x, y, c);
        }
        const int xb = x + dx, yb = y + dy;
        if (xb >= 0 && xb < Width && yb >= 0 && yb < Height && before[yb * Width + xb])
        {
          ++revealed;
          const bool edge = !IsFlatAround(after.second, x, y, 1, 0.0);
          edges += edge ? 1 : 0;
          kept += edge && !same ? 1 : 0;
        }
        else
        {
          blended += same ? 0 : 1;
        }
      }
    }
    std::cout << method.Name << ", disocclusion, " << what << " (the panel moved " << -dx << ", "
              << -dy << " pixels): " << revealed << " pixels uncovered, " << edges
              << " of them beside an edge of the checkerboard, " << kept
              << " of those differ from the single-frame pass's render; " << blended
              << " other pixels blended" << std::endl;
    Check(std::abs(dx) + std::abs(dy) >= 4, "the panel moved", __FILE__, __LINE__);
    Check(edges > 20, "the move uncovered pixels beside edges", __FILE__, __LINE__);
    Check(kept == 0, "uncovered pixels do not keep the hidden history", __FILE__, __LINE__);
    Check(blended > 200, "the rest of the panel blends its history", __FILE__, __LINE__);
    StopPass(renderer, window);
    camera->DeepCopy(saved);
  };

  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewAngle(30.0);
  camera->SetClippingRange(0.5, 3.0);
  // 12 pixels at the sphere's distance (the focal point's).
  check("perspective pan", [camera]() { Pan(camera, 12.0); });
  // The same scale at the sphere; the panel, 1 behind it, moves sin(angle) on the screen.
  camera->ParallelProjectionOn();
  camera->SetParallelScale(std::tan(vtkMath::RadiansFromDegrees(15.0)));
  const double scale = camera->GetParallelScale();
  check("parallel turn", [camera, scale]() {
    camera->Azimuth(vtkMath::DegreesFromRadians(std::asin(6.0 * 2.0 * scale / Height)));
  });
}

void Resets(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkActor* sphere = TwoSpheres(renderer);

  // A new pass's first render, for the current window and scene.
  auto firstRender = [&]() {
    vtkRenderPass* kept = renderer->GetPass();
    kept->Register(nullptr);
    UseTemporal(method, renderer, messages);
    auto image = vtkMLAAScenes::Capture(window);
    StopPass(renderer, window);
    renderer->SetPass(kept);
    kept->UnRegister(nullptr);
    return image;
  };
  auto expectReset = [&](vtkOpenGLAntialiasingPass* pass, const char* what) {
    auto image = vtkMLAAScenes::Capture(window);
    const int accumulated = pass->GetAccumulatedFrames();
    auto expected = firstRender();
    const Difference d = Compare(expected, image, 0.0);
    std::cout << method.Name << ", " << what << ": accumulated " << accumulated << ", " << d.Pixels
              << " pixels differ from a new pass's first render" << std::endl;
    Check(accumulated == 1 && d.Pixels == 0, what, __FILE__, __LINE__);
  };

  vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
  for (int k = 0; k < 6; ++k)
  {
    vtkMLAAScenes::Capture(window);
  }
  Check(pass->GetAccumulatedFrames() == 6, "6 frames accumulated", __FILE__, __LINE__);
  // The accumulated still differs from a first render (or the checks below show nothing).
  auto accumulated = vtkMLAAScenes::Capture(window);
  Check(Compare(firstRender(), accumulated, 0.0).Pixels > 50, "accumulation changes the image",
    __FILE__, __LINE__);

  window->SetSize(Width + 24, Height + 10);
  expectReset(pass, "resize");
  vtkMLAAScenes::Capture(window);
  sphere->GetProperty()->SetColor(0.2, 0.5, 0.9);
  expectReset(pass, "a changed colour");
  vtkMLAAScenes::Capture(window);
  vtkSphereSource::SafeDownCast(sphere->GetMapper()->GetInputAlgorithm())->SetRadius(0.5);
  expectReset(pass, "a changed input");
  for (int k = 0; k < 4; ++k)
  {
    vtkMLAAScenes::Capture(window);
  }
  // An actor that only moves keeps the history (the other sphere keeps what it accumulated).
  sphere->AddPosition(0.1, 0.0, 0.0);
  auto moved = vtkMLAAScenes::Capture(window);
  const vtkIdType keptPixels = Compare(firstRender(), moved, 0.0).Pixels;
  std::cout << method.Name << ", a moved actor: " << keptPixels
            << " pixels differ from a new pass's first render" << std::endl;
  Check(keptPixels > 50, "a moved actor keeps the history", __FILE__, __LINE__);
  vtkMLAAScenes::Capture(window);
  sphere->AddPosition(0.1, 0.0, 0.0);
  renderer->GetActiveCamera()->Azimuth(0.5);
  expectReset(pass, "an actor and the camera moved together");
  vtkMLAAScenes::Capture(window);
  pass->TemporalOff();
  pass->TemporalOn();
  expectReset(pass, "switched off and on");
  StopPass(renderer, window);
}

void Picking(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("silhouettes", renderer);
  window->Render();
  const std::set<vtkIdType> plain = SelectCells(renderer, Width, Height);
  vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
  for (int k = 0; k < 4; ++k)
  {
    vtkMLAAScenes::Capture(window);
  }
  const CameraState before(renderer->GetActiveCamera());
  const std::set<vtkIdType> temporal = SelectCells(renderer, Width, Height);
  const bool cameraKept = CameraState(renderer->GetActiveCamera()) == before;
  const int accumulated = pass->GetAccumulatedFrames();
  vtkMLAAScenes::Capture(window);
  std::cout << method.Name << ", picking: " << plain.size() << " cells without a pass, "
            << temporal.size() << " with the temporal pass; accumulated " << accumulated
            << " before the next render, " << pass->GetAccumulatedFrames() << " after"
            << std::endl;
  Check(!plain.empty() && plain == temporal, "the same cells selected", __FILE__, __LINE__);
  Check(cameraKept, "the camera kept by a selection", __FILE__, __LINE__);
  Check(accumulated == 4 && pass->GetAccumulatedFrames() == 5, "the history kept by a selection",
    __FILE__, __LINE__);
  StopPass(renderer, window);
}

void Overlays(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width * 2, Height * 2);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkMLAAScenes::Build("text", renderer);
  SetVisibility(renderer, false, true);
  auto plain = vtkMLAAScenes::Capture(window);
  vtkOpenGLAntialiasingPass* pass = UseTemporal(method, renderer, messages);
  vtkIdType worst = 0;
  for (int k = 0; k < 6; ++k)
  {
    worst = std::max(worst, Compare(plain, vtkMLAAScenes::Capture(window), 0.0).Pixels);
  }
  std::cout << method.Name << ", overlays alone: at most " << worst
            << " pixels differ from the plain render over 6 renders; accumulated "
            << pass->GetAccumulatedFrames() << std::endl;
  Check(worst == 0, "overlays untouched and not jittered", __FILE__, __LINE__);
  Check(pass->GetAccumulatedFrames() == 6, "the overlays do not reset the history", __FILE__,
    __LINE__);
  StopPass(renderer, window);
}

// Checks a capture of the layers scene: layer 0's pixels where layer 1 draws nothing within 2
// pixels (in `plain` against `lowerOnly`) are exactly layer 0's in `result`, and layer 1 is
// antialiased there.
void CheckLayerZeroKept(const PassMethod& method, const char* when, vtkImageData* plain,
  vtkImageData* lowerOnly, vtkImageData* result)
{
  vtkIdType kept = 0, changed = 0;
  for (int y = 2; y < Height - 2; ++y)
  {
    for (int x = 2; x < Width - 2; ++x)
    {
      bool away = true;
      for (int dy = -2; dy <= 2; ++dy)
      {
        for (int dx = -2; dx <= 2; ++dx)
        {
          for (int c = 0; c < 3; ++c)
          {
            away = away && GetValue(plain, x + dx, y + dy, c) == GetValue(lowerOnly, x + dx, y + dy, c);
          }
        }
      }
      if (!away)
      {
        continue;
      }
      ++kept;
      for (int c = 0; c < 3; ++c)
      {
        if (GetValue(result, x, y, c) != GetValue(lowerOnly, x, y, c))
        {
          ++changed;
          break;
        }
      }
    }
  }
  const Difference antialiased = Compare(plain, result, 0.0);
  std::cout << method.Name << ", layers, " << when << ": " << changed << " of " << kept
            << " layer-0 pixels changed; " << antialiased.Pixels
            << " pixels differ from the plain render" << std::endl;
  Check(kept > 1000 && changed == 0, "layer 0 untouched", __FILE__, __LINE__);
  Check(antialiased.Pixels > 20, "layer 1 antialiased", __FILE__, __LINE__);
}

void Layers(const PassMethod& method, MessageObserver* messages)
{
  auto window = vtkMLAAScenes::NewOffscreenWindow(Width, Height);
  window->SetNumberOfLayers(2);
  vtkNew<vtkRenderer> lower;
  vtkMLAAScenes::Build("silhouettes", lower);
  window->AddRenderer(lower);
  vtkNew<vtkRenderer> upper;
  upper->SetLayer(1);
  AddSphere(upper, 0.0, 0.5)->GetProperty()->SetColor(0.95, 0.85, 0.2);
  upper->GetActiveCamera()->SetPosition(0.0, 0.0, 8.0);
  upper->GetActiveCamera()->SetClippingRange(4.0, 12.0);
  window->AddRenderer(upper);
  upper->SetDraw(false);
  auto lowerOnly = vtkMLAAScenes::Capture(window);
  upper->SetDraw(true);
  auto plain = vtkMLAAScenes::Capture(window);

  vtkOpenGLAntialiasingPass* pass = UseTemporal(method, upper, messages);
  CheckLayerZeroKept(method, "still", plain, lowerOnly, CaptureAfter(window, 16));
  Check(pass->GetAccumulatedFrames() == 16, "layer 1 accumulates", __FILE__, __LINE__);
  // Layer 1's camera turning about the sphere (the same silhouette): a moving camera's frames,
  // reprojected and blended (DLAA with its motion frame), composited over layer 0 too.
  vtkSmartPointer<vtkImageData> moving;
  for (int frame = 0; frame < 3; ++frame)
  {
    upper->GetActiveCamera()->Azimuth(3.0);
    moving = vtkMLAAScenes::Capture(window);
  }
  CheckLayerZeroKept(method, "camera turning", plain, lowerOnly, moving);
  Check(pass->GetAccumulatedFrames() == 1, "layer 1's camera moves", __FILE__, __LINE__);
  StopPass(upper, window);
}
}

int TestAntialiasingPassTemporal(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    StillConvergence(method, messages);
    TranslucentStill(method, messages);
    BoxFilter(method, messages);
    MovingActor(method, messages);
    AnimatedActor(method, messages);
    CameraOrbit(method, messages);
    StillAfterOrbit(method, messages);
    FastCamera(method, messages);
    Disocclusion(method, messages);
    Resets(method, messages);
    Picking(method, messages);
    Overlays(method, messages);
    Layers(method, messages);
  });
  return Result();
}
