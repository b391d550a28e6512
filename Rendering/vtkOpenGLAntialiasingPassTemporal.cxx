// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLAntialiasingPassTemporal.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLAntialiasingPassInternals.h"
#include "vtkOpenGLAntialiasingPassSamples.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include "vtkAntialiasingTemporalFS.h"

#include "vtkAntialiasingOpenGL.h" // For GL enums, and the calls VTK has no wrapper for

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

using namespace vtkOpenGLAntialiasingPassInternals;

namespace
{
// The sub-pixel offset, in [-1/2, 1/2) pixel, of the `index`-th render of a still accumulation
// (index 0: its first, unjittered render) whose first `frames` renders are to sample the pixel's
// box as evenly as possible. The points are the two-dimensional Sobol sequence (van der Corput in
// base 2, and the Pascal matrix's digits): any 2^m of them from a multiple of 2^m put exactly one
// point in each of the pixel's 2^m strata of every shape (2^m columns, 2^m rows, 2 x 2^(m-1)
// rectangles, ...), so their mean converges to the box filter of the supersampled reference at the
// rate of a stratified grid, at every power of two on the way. They are shifted, modulo the
// pixel, by half a pixel (point 0 falls on the pixel's centre, which the unjittered first render
// samples) and by half the width of the finest strata of the smallest power of two >= `frames`
// (the points of that net then lie on the centres of their strata: no bias of the mean). A Halton
// (2, 3) sequence, as before, reached AAR 0.945 instead of 0.971 on the colour bands of
// mlaa-quality at 800 x 600 after 16 renders (docs/measurements.md).
void StillJitter(std::uint32_t index, int frames, double offset[2])
{
  std::uint32_t x = 0, y = 0, direction = 1u << 31;
  for (int bit = 0; index; ++bit, index >>= 1, direction ^= direction >> 1)
  {
    if (index & 1u)
    {
      x ^= (1u << 31) >> bit;
      y ^= direction;
    }
  }
  int strata = 1;
  while (strata < frames)
  {
    strata *= 2;
  }
  const double centre = 0.5 + 0.5 / strata;
  for (int i = 0; i < 2; ++i)
  {
    const double value = (i == 0 ? x : y) / 4294967296.0 + centre;
    offset[i] = value - std::floor(value) - 0.5;
  }
}

// Changes of the camera that move no point by more than this (in pixels) leave it still: a
// vtkWindowToImageFilter that renders again recomputes the view angle in single precision.
constexpr double StillDisplacement = 1e-3;

// The homogeneous eye `eye` (a position, w = 1, or a point at infinity, w = 0) in world
// coordinates translated so that the eye `origin` is at 0 when it is a position (a point at
// infinity stays where it is).
void RelativeEye(const double eye[4], const double origin[4], double relative[4])
{
  for (int i = 0; i < 3; ++i)
  {
    relative[i] = eye[i] - origin[i] * origin[3] * eye[3];
  }
  relative[3] = eye[3];
}

// The largest displacement, in pixels of a width x height viewport, that `reprojection` (current to
// previous normalised device coordinates, row-major) gives the corners and centre of the view
// volume.
double MaximumDisplacement(const double reprojection[16], int width, int height)
{
  double largest = 0.0;
  for (double x : { -1.0, 0.0, 1.0 })
  {
    for (double y : { -1.0, 0.0, 1.0 })
    {
      for (double z : { -1.0, 0.0, 1.0 })
      {
        const double in[4] = { x, y, z, 1.0 };
        double out[4];
        vtkMatrix4x4::MultiplyPoint(reprojection, in, out);
        if (out[3] <= 0.0)
        {
          return VTK_DOUBLE_MAX;
        }
        largest = std::max(largest,
          std::max(std::abs(out[0] / out[3] - x) * 0.5 * width,
            std::abs(out[1] / out[3] - y) * 0.5 * height));
      }
    }
  }
  return largest;
}

std::uint64_t Bits(double value)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof(bits));
  return bits;
}

// What a temporal history depends on besides the camera: the props drawn (which, and their
// modified times, mappers and inputs included), the lights that do not follow the camera (those
// that do move with it, which reprojection handles) and the background. With `placement` false an
// actor's own modified time (its position, orientation, scale, user matrix and visibility) is left
// out and the times of what it draws are taken instead (its mapper, the mapper's input, its
// properties and texture): a change of that signature discards the history, a change of the
// other one alone (actors moved, shown or hidden) keeps it, reprojected and clamped.
std::vector<std::uint64_t> SceneSignature(const vtkRenderState* s, bool placement)
{
  std::vector<std::uint64_t> signature;
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    vtkProp* prop = s->GetPropArray()[i];
    signature.push_back(reinterpret_cast<std::uintptr_t>(prop));
    const vtkMTimeType redraw = prop->GetRedrawMTime(); // brings the mapper's input up to date
    vtkActor* actor = vtkActor::SafeDownCast(prop);
    if (placement || !actor)
    {
      signature.push_back(redraw);
      continue;
    }
    vtkMapper* mapper = actor->GetMapper();
    vtkDataObject* input =
      mapper && mapper->GetNumberOfInputPorts() > 0 && mapper->GetNumberOfInputConnections(0) > 0
      ? mapper->GetInputDataObject(0, 0)
      : nullptr;
    for (vtkObject* part : { static_cast<vtkObject*>(mapper),
           static_cast<vtkObject*>(input),
           static_cast<vtkObject*>(actor->GetProperty()),
           static_cast<vtkObject*>(actor->GetBackfaceProperty()),
           static_cast<vtkObject*>(actor->GetTexture()) })
    {
      signature.push_back(reinterpret_cast<std::uintptr_t>(part));
      signature.push_back(part ? part->GetMTime() : 0);
    }
  }
  vtkRenderer* renderer = s->GetRenderer();
  vtkLightCollection* lights = renderer->GetLights();
  vtkCollectionSimpleIterator it;
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (light->LightTypeIsSceneLight())
    {
      signature.push_back(reinterpret_cast<std::uintptr_t>(light));
      signature.push_back(light->GetMTime());
    }
  }
  for (double value : { renderer->GetBackground()[0],
         renderer->GetBackground()[1],
         renderer->GetBackground()[2],
         renderer->GetBackground2()[0],
         renderer->GetBackground2()[1],
         renderer->GetBackground2()[2],
         renderer->GetBackgroundAlpha() })
  {
    signature.push_back(Bits(value));
  }
  signature.push_back(renderer->GetGradientBackground() ? 1 : 0);
  return signature;
}
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistory::PrepareTargets(const Frame& frame,
  bool motionFrames)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const int width = frame.Width, height = frame.Height;
  if (!this->Current)
  {
    this->Current = NewTexture(renWin);
    this->Previous = NewTexture(renWin);
    this->Histories[0] = NewTexture(renWin);
    this->Histories[1] = NewTexture(renWin);
    this->Counts[0] = NewTexture(renWin);
    this->Counts[1] = NewTexture(renWin);
    this->Mask = NewTexture(renWin);
    this->Depth = NewTexture(renWin);
    PrepareFramebuffers(renWin, false, { &this->Framebuffer });
  }
  // Previous keeps the method's frame of the last unjittered render (a still accumulation's
  // jittered frames go to Current and are not kept: the still scene's unjittered frame is the one
  // its accumulation started with).
  const int colorType = frame.ColorType(); // the method's frames
  for (vtkTextureObject* texture : { this->Current, this->Previous })
  {
    if (AllocateColorTarget(texture, width, height, 4, colorType, false))
    {
      this->PreviousValid = false;
      if (this->KeepUnchanged)
      {
        this->KeepUnchanged = false; // what Previous held is gone: start again
        this->FrameMode = RESET;
        this->Accumulated = 1;
      }
    }
  }
  for (int i = 0; i < 2; ++i)
  {
    // 32-bit floating point: a running average of many frames moves by less than 1/255 a frame.
    const bool history =
      AllocateColorTarget(this->Histories[i], width, height, 4, VTK_FLOAT, true, GL_RGBA32F);
    const bool count =
      AllocateColorTarget(this->Counts[i], width, height, 1, VTK_FLOAT, false, GL_R32F);
    if (history || count)
    {
      this->FrameMode = RESET;
      this->Accumulated = 1;
    }
  }
  AllocateDepthTarget(this->Mask, width, height, vtkTextureObject::Fixed16);
  // The motion frame, where this render's blend (its mode is final from here on) reprojects the
  // history with a method that has one.
  if (motionFrames && this->FrameMode == MOVING && !this->KeepUnchanged)
  {
    if (!this->Motion)
    {
      this->Motion = NewTexture(renWin);
    }
    AllocateColorTarget(this->Motion, width, height, 4, colorType, false);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistory::Release(vtkWindow* w)
{
  DeleteObject(this->Current, w);
  DeleteObject(this->Previous, w);
  DeleteObject(this->Motion, w);
  DeleteObject(this->Histories[0], w);
  DeleteObject(this->Histories[1], w);
  DeleteObject(this->Counts[0], w);
  DeleteObject(this->Counts[1], w);
  DeleteObject(this->Mask, w);
  DeleteObject(this->Depth, w);
  DeleteObject(this->Framebuffer, w);
  this->BlendQuad.Release(w);
  this->OutputQuad.Release(w);
  this->MaskQuad.Release(w);
  this->Valid = false;
  this->PreviousValid = false;
  this->Accumulated = 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::TemporalHistory::TargetBytes(int colorBytes) const
{
  return TextureBytes(this->Current, colorBytes) + TextureBytes(this->Previous, colorBytes) +
    TextureBytes(this->Motion, colorBytes) + TextureBytes(this->Histories[0], 16) +
    TextureBytes(this->Histories[1], 16) + TextureBytes(this->Counts[0], 4) +
    TextureBytes(this->Counts[1], 4) + TextureBytes(this->Mask, 2) + TextureBytes(this->Depth, 4);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistories::Select(const vtkRenderState* s)
{
  TemporalHistories& all = *this;
  // A pass shared by several renderers renders each with its own camera and scene: one history
  // would be reset (or reprojected from another view) at every render. And vtkRenderWindow
  // renders a stereo frame as the left eye's render, then the right eye's, with the active
  // camera's LeftEye set accordingly (and LeftEye 1 in mono): the two eyes see the scene from two
  // places, and one history would average their pictures.
  vtkRenderer* renderer = s->GetRenderer();
  // The histories of renderers that are gone go too (a long-lived pass set on renderer after
  // renderer).
  for (auto entry = all.Entries.begin(); entry != all.Entries.end();)
  {
    if (entry->Renderer)
    {
      ++entry;
      continue;
    }
    entry->History->Release(renderer->GetRenderWindow());
    entry = all.Entries.erase(entry);
  }
  const bool stereo = renderer->GetRenderWindow()->GetStereoRender() != 0;
  const bool rightEye = stereo && renderer->GetActiveCamera()->GetLeftEye() == 0;
  if (!stereo)
  {
    // Mono again: this renderer's right-eye history would be stale when stereo comes back.
    auto stale = std::find_if(all.Entries.begin(),
      all.Entries.end(),
      [renderer](const TemporalHistories::Entry& entry)
      { return entry.Renderer == renderer && entry.RightEye; });
    if (stale != all.Entries.end())
    {
      stale->History->Release(renderer->GetRenderWindow());
      all.Entries.erase(stale);
    }
  }
  auto found = std::find_if(all.Entries.begin(),
    all.Entries.end(),
    [renderer, rightEye](const TemporalHistories::Entry& entry)
    { return entry.Renderer == renderer && entry.RightEye == rightEye; });
  if (found == all.Entries.end())
  {
    TemporalHistories::Entry entry;
    entry.Renderer = renderer;
    entry.RightEye = rightEye;
    entry.History.reset(new TemporalHistory);
    all.Entries.push_back(std::move(entry));
    found = all.Entries.end() - 1;
  }
  found->LastRender = ++all.Renders;
  this->History = found->History.get();
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistories::BeginFrame(const vtkRenderState* s,
  const Frame& frame)
{
  this->Select(s);
  TemporalHistory& h = *this->History;
  vtkRenderer* renderer = s->GetRenderer();
  vtkCamera* camera = renderer->GetActiveCamera();

  // The camera's view and projection, unjittered, as vtkOpenGLCamera computes them.
  vtkNew<vtkMatrix4x4> viewProjection;
  viewProjection->DeepCopy(
    camera->GetCompositeProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1));
  const bool parallel = camera->GetParallelProjection() != 0;
  std::copy(h.DepthToEye, h.DepthToEye + 4, h.PreviousDepthToEye);
  std::copy(h.Jitter, h.Jitter + 2, h.PreviousJitter);
  vtkMatrix4x4* projection =
    camera->GetProjectionTransformMatrix(renderer->GetTiledAspectRatio(), -1, 1);
  for (int i = 0; i < 4; ++i)
  {
    h.DepthToEye[i] = projection->GetElement(2 + i / 2, 2 + i % 2);
  }
  h.Jitter[0] = h.Jitter[1] = 0.0;
  double eye[4] = { 0.0, 0.0, 0.0, parallel ? 0.0 : 1.0 };
  if (parallel)
  {
    camera->GetDirectionOfProjection(eye);
    eye[0] = -eye[0];
    eye[1] = -eye[1];
    eye[2] = -eye[2];
  }
  else
  {
    camera->GetPosition(eye);
  }
  // Current to previous normalised device coordinates: previous * inverse(current).
  vtkNew<vtkMatrix4x4> inverse;
  vtkMatrix4x4::Invert(viewProjection, inverse);
  vtkNew<vtkMatrix4x4> reprojection;
  vtkMatrix4x4::Multiply4x4(h.ViewProjection, inverse->GetData(), reprojection->GetData());
  const bool cameraMoved =
    MaximumDisplacement(reprojection->GetData(), frame.Width, frame.Height) > StillDisplacement;
  // Actors moved (or turned, scaled, shown or hidden) and nothing else changed, under a still
  // camera: the history is kept where the method's frame did not change since the last
  // unjittered render (the motion did not reach those pixels) and replaced by the current frame
  // where it did (no ghost: without per-object motion vectors, clamping the history to the
  // current neighbourhood lets an actor's colour survive over a textured background). With the
  // camera moving too, the history is reset.
  const bool actorsMoved = h.Valid && h.Scene != SceneSignature(s, true);
  h.KeepUnchanged = actorsMoved && !cameraMoved && h.PreviousValid;
  const bool reset = !h.Valid || h.Width != frame.Width || h.Height != frame.Height ||
    h.Parallel != parallel || h.Content != SceneSignature(s, false) ||
    (actorsMoved && !h.KeepUnchanged);
  const bool moved = !reset && (h.KeepUnchanged || cameraMoved);
  if (reset)
  {
    h.FrameMode = TemporalHistory::RESET;
    h.Accumulated = 1;
    h.JitterIndex = 0;
  }
  else if (moved)
  {
    h.FrameMode = TemporalHistory::MOVING;
    h.Accumulated = 1;
    h.JitterIndex = 0;         // the still accumulation that may follow starts from this frame
    reprojection->Transpose(); // vtkShaderProgram uploads the elements as GLSL's column order
    std::memcpy(h.Reprojection, reprojection->GetData(), sizeof(h.Reprojection));
    // How far the direction of view turned at each point (the shader's ViewTurn): the points
    // and both eyes translated so that the current eye, when it is a position, is at 0.
    vtkNew<vtkMatrix4x4> toEye;
    for (int i = 0; i < 3; ++i)
    {
      toEye->SetElement(i, 3, -eye[i] * eye[3]);
    }
    vtkNew<vtkMatrix4x4> toPoint;
    vtkMatrix4x4::Multiply4x4(toEye, inverse, toPoint);
    toPoint->Transpose();
    std::memcpy(h.ToPoint, toPoint->GetData(), sizeof(h.ToPoint));
    RelativeEye(h.Eye, eye, h.PreviousEye);
    RelativeEye(eye, eye, h.CurrentEye);
  }
  else if (h.Accumulated >= this->Pass->ConvergedFrames)
  {
    // Converged (RenderConverged's aim): further renders of the still scene show the same image,
    // whatever their number, and leave the camera alone.
    h.FrameMode = TemporalHistory::HOLD;
  }
  else
  {
    h.FrameMode = TemporalHistory::STILL;
    ++h.Accumulated;
  }
  if (h.FrameMode != TemporalHistory::STILL && h.FrameMode != TemporalHistory::HOLD)
  {
    // A still camera keeps the matrices its accumulation started with, so that changes below
    // StillDisplacement cannot add up.
    std::memcpy(h.ViewProjection, viewProjection->GetData(), sizeof(h.ViewProjection));
    std::memcpy(h.Eye, eye, sizeof(h.Eye));
  }
  h.Parallel = parallel;
  h.Width = frame.Width;
  h.Height = frame.Height;

  // The sub-pixel offset of this render, in (-1/2, 1/2) pixel, through the window centre (in
  // normalised device coordinates: 2 / size a pixel), as the reference of MEASURING.md shifts it.
  // While the camera moves the frame is not jittered: the motion itself moves the samples, and
  // the jitter's frame-to-frame noise, which the blend keeps a tenth of, flickered more than it
  // removed (mlaa-temporal at 200 x 150, 24 frames of 0.2 degree: mean T-AAR 0.36 without, -0.12
  // with, for MLAA; docs/render-pass.md). The first frame after a reset is not jittered either:
  // it may be the first of a motion, whose history would otherwise start shifted by the offset
  // and drift back over the next frames (thin orbit scene at 0.2 degree: T-AAR 0.23 to 0.45).
  if (h.FrameMode != TemporalHistory::STILL)
  {
    return;
  }
  ++h.JitterIndex; // point 0 is the accumulation's first, unjittered render
  double jitter[2];
  StillJitter(h.JitterIndex, this->Pass->ConvergedFrames, jitter);
  h.Jitter[0] = jitter[0];
  h.Jitter[1] = jitter[1];
  h.JitteredCamera = camera;
  camera->GetWindowCenter(h.SavedWindowCenter);
  camera->SetWindowCenter(h.SavedWindowCenter[0] + 2.0 * jitter[0] / frame.Width,
    h.SavedWindowCenter[1] + 2.0 * jitter[1] / frame.Height);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistories::EndJitter(const vtkRenderState* s)
{
  TemporalHistory& h = *this->History;
  if (h.JitteredCamera)
  {
    h.JitteredCamera->SetWindowCenter(h.SavedWindowCenter[0], h.SavedWindowCenter[1]);
    h.JitteredCamera = nullptr;
  }
  // The scene as the render left it (mappers may update themselves while they draw): what the
  // next render compares with.
  h.Scene = SceneSignature(s, true);
  h.Content = SceneSignature(s, false);
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::TemporalHistories::Antialias(const Frame& frame, int samples)
{
  vtkOpenGLAntialiasingPass* pass = this->Pass;
  TemporalHistory& h = *this->History;
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  const int width = frame.Width, height = frame.Height;
  // With samples, the method's frame is the multisampled render's antialiased resolve, which
  // needs no motion frame (its sample images are not blurred by the method alone).
  const bool methodMotionFrame = pass->HasMotionFrame() && !samples;
  h.PrepareTargets(frame, methodMotionFrame);
  // This render's kind of blend (the mode is final from here on): a moving camera's reprojects
  // the history and, for a method with one, reads its motion frame (written at every such
  // render).
  const bool moving = h.FrameMode == TemporalHistory::MOVING;
  const bool keep = moving && h.KeepUnchanged;
  const bool reproject = moving && !keep;
  const bool motionFrame = reproject && methodMotionFrame;

  auto bindTarget = [&](vtkTextureObject* texture)
  {
    h.Framebuffer->Bind();
    h.Framebuffer->AddColorAttachment(0, texture);
    h.Framebuffer->RemoveColorAttachment(1);
    DrawToAttachments(h.Framebuffer, 1);
    h.Framebuffer->StartNonOrtho(width, height);
    ostate->vtkglViewport(0, 0, width, height);
    ostate->vtkglScissor(0, 0, width, height);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  };

  // The method antialiases this frame into Current. A still accumulation averages the jittered
  // renders themselves (see below), so the method does not run there: its frame would not be read.
  const bool still = h.FrameMode == TemporalHistory::STILL;
  // A converged still (HOLD) neither runs the method nor blends: the history is the result.
  const bool hold = h.FrameMode == TemporalHistory::HOLD;
  ostate->PushFramebufferBindings();
  bool done = true;
  if (!still && !hold)
  {
    Frame local = frame;
    local.X = 0;
    local.Y = 0;
    bindTarget(h.Current);
    if (motionFrame)
    {
      // The motion frame beside it, cleared or copied with it.
      h.Framebuffer->AddColorAttachment(1, h.Motion);
      DrawToAttachments(h.Framebuffer, 2);
      local.MotionFrame = true;
    }
    if (frame.Composite)
    {
      // Transparent black first: a composited image is written with premultiplied "over", which
      // onto transparent black leaves it as it is.
      ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    }
    if (samples)
    {
      // The sample sets antialiased and resolved into Current (every pixel written).
      done = pass->Samples->Antialias(local, samples);
    }
    else
    {
      if (!frame.Composite)
      {
        // Current takes the delegate's image as it is (a copy; bindTarget set the whole texture
        // as the scissor box), and the method writes only the pixels it changes, as in place in
        // the target: the same image, without a shader writing every pixel.
        pass->DelegateFramebuffer->Bind(GL_READ_FRAMEBUFFER);
        pass->DelegateFramebuffer->ActivateReadBuffer(0);
        const int box[4] = { 0, width, 0, height };
        vtkOpenGLFramebufferObject::Blit(box, box, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        local.InPlace = true;
        local.OwnTarget = h.Framebuffer;
      }
      done = pass->Antialias(local); // (bindTarget below detaches the motion frame)
    }
  }
  if (done && samples)
  {
    // The frame as multisampling resolves it, and the nearest depth of each pixel's samples, in
    // ColorTexture and DepthTexture, where the blend reads the frame before the method (the
    // still accumulation's jittered renders, the clamp's range) and the depth it reprojects with.
    done = pass->Samples->ResolvePlain(frame, samples);
  }

  // The blend into the other history.
  const int next = hold ? h.Latest : 1 - h.Latest;
  TimedStage blendStage(renWin, "temporal");
  if (done && !hold)
  {
    bindTarget(h.Histories[next]);
    h.Framebuffer->AddColorAttachment(1, h.Counts[next]); // each pixel's count of frames
    DrawToAttachments(h.Framebuffer, 2);
    ostate->vtkglDisable(GL_BLEND);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    ostate->vtkglDepthMask(GL_FALSE);
    if (reproject)
    {
      // Every pixel's count starts at 1 (a moving camera's blend writes 1 where it runs).
      const float one[4] = { 1.0f, 1.0f, 1.0f, 1.0f };
      glClearBufferfv(GL_COLOR, 1, one);
    }
    float weight = 1.0f;
    if (moving)
    {
      weight = static_cast<float>(pass->TemporalWeight);
    }
    else if (h.FrameMode == TemporalHistory::STILL)
    {
      weight = 1.0f / h.Accumulated; // (the shader weighs by each pixel's own count)
    }
    if (reproject)
    {
      // The new history starts as a copy of the current frame, and the pixels the blend changes
      // are marked (depth 1, the others 0) in the same pass: the reprojecting blend leaves out
      // the pixels whose result is the current frame whatever the history (see
      // vtkAntialiasingTemporalFS.glsl), and runs with the quad's depth (1/2) tested LESS, so that
      // the depth test drops those before their shader runs. A blend that discards them still
      // costs rasterisers that shade pixels in lock-step (llvmpipe) the write of every pixel of
      // the floating-point history (docs/measurements.md, issue 23).
      TimedStage maskStage(renWin, "history copy and mask");
      done = this->MarkBlendedPixels(renWin, h.Current);
    }
    done = done &&
      pass->ReadyQuad(renWin,
        h.BlendQuad,
        vtkAntialiasingTemporalFS,
        Define("TEMPORAL_REPROJECT", reproject) + Define("TEMPORAL_KEEP_UNCHANGED", keep) +
          Define("TEMPORAL_MOTION_FRAME", motionFrame));
    if (done)
    {
      // While the scene is still, the frames averaged are the jittered renders themselves: their
      // mean is the supersampled picture, which the method's own blending would blur; the
      // history starts from the method's frame (its error then weighs 1 / AccumulatedFrames).
      // Each pixel's count of frames is kept with the history: pixels that moving actors did not
      // reach go on from their own count when the actors stop, instead of starting again.
      vtkTextureObject* current = still ? pass->ColorTexture : h.Current;
      vtkShaderProgram* program = h.BlendQuad.Quad->Program;
      // The textures of this variant (the camera moving reads no counts; a still camera reads
      // neither this frame before the method nor the last one).
      ScopedTextures textures(program,
        { { "currentTexture", current },
          { "historyTexture", h.Histories[h.Latest] },
          { "depthTexture", pass->DepthTexture } });
      if (!reproject)
      {
        textures.Bind(program, "countTexture", h.Counts[h.Latest]);
      }
      else
      {
        // Not jittered: the clamp's range.
        textures.Bind(program, "frameTexture", pass->ColorTexture);
        if (motionFrame)
        {
          textures.Bind(program, "motionTexture", h.Motion);
        }
        // The reprojection and the view's turn (in single precision, as GLSL takes them).
        float values[16];
        auto single = [&values](const double* v, int n)
        {
          std::copy(v, v + n, values);
          return values;
        };
        program->SetUniformMatrix4x4("reprojection", single(h.Reprojection, 16));
        program->SetUniformMatrix4x4("toPoint", single(h.ToPoint, 16));
        program->SetUniform4f("previousEye", single(h.PreviousEye, 4));
        program->SetUniform4f("currentEye", single(h.CurrentEye, 4));
        program->SetUniform4f("previousDepthToEye", single(h.PreviousDepthToEye, 4));
        program->SetUniform2f("previousJitter", single(h.PreviousJitter, 2));
        textures.Bind(program, "previousDepthTexture", h.Depth);
      }
      if (keep)
      {
        textures.Bind(program, "previousTexture", h.Previous);
      }
      program->SetUniformf("currentWeight", weight);
      TimedStage stage(renWin, "blend");
      h.BlendQuad.Quad->Render();
    }
    if (reproject)
    {
      ostate->vtkglDisable(GL_DEPTH_TEST);
      h.Framebuffer->RemoveDepthAttachment();
    }
  }
  ostate->PopFramebufferBindings();
  if (!done)
  {
    h.Valid = false;
    return false;
  }
  h.Latest = next;
  h.Valid = true;
  // This render's depth is the one the next render reprojects from; the pass's depth target takes
  // the texture that held the last one.
  std::swap(pass->DepthTexture, h.Depth);
  if (!still && !hold)
  {
    std::swap(h.Current, h.Previous);
    h.PreviousValid = true;
  }

  blendStage.Stop();

  // The result into the target viewport, with the delegate's depth (as the method writes it when
  // not in place), composited over lower layers when the renderer preserves the colour buffer.
  TimedStage outputStage(renWin, "temporal output");
  if (!pass->ReadyQuad(
        renWin, h.OutputQuad, vtkAntialiasingTemporalFS, Define("TEMPORAL_OUTPUT", true)))
  {
    return false;
  }
  SetTargetWriteState(ostate, frame.X, frame.Y, frame.Width, frame.Height, frame.Composite, true);
  const ScopedTextures textures(h.OutputQuad.Quad->Program,
    { { "historyTexture", h.Histories[h.Latest] }, { "depthTexture", h.Depth } });
  h.OutputQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::TemporalHistories::MarkBlendedPixels(vtkOpenGLRenderWindow* renWin,
  vtkTextureObject* current)
{
  vtkOpenGLAntialiasingPass* pass = this->Pass;
  TemporalHistory& h = *this->History;
  vtkOpenGLState* ostate = renWin->GetState();
  if (!pass->ReadyQuad(renWin,
        h.MaskQuad,
        vtkAntialiasingTemporalFS,
        Define("TEMPORAL_REPROJECT", true) + Define("TEMPORAL_MASK", true)))
  {
    return false;
  }
  // Colour into the history only (its counts were cleared to 1), and depth at every pixel: no
  // clear of the mask, no discard.
  h.Framebuffer->AddDepthAttachment(h.Mask);
  DrawToAttachments(h.Framebuffer, 1);
  ostate->vtkglDepthMask(GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  {
    const ScopedTextures textures(h.MaskQuad.Quad->Program,
      { { "currentTexture", current },
        { "frameTexture", pass->ColorTexture },
        { "depthTexture", pass->DepthTexture } });
    h.MaskQuad.Quad->Render();
  }
  DrawToAttachments(h.Framebuffer, 2);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDepthFunc(GL_LESS);
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistories::Release(vtkWindow* w)
{
  for (Entry& entry : this->Entries)
  {
    entry.History->Release(w);
  }
  this->Entries.clear();
  this->History = nullptr;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::TemporalHistories::Reset()
{
  for (Entry& entry : this->Entries)
  {
    entry.History->Valid = false;
    entry.History->Accumulated = 0;
  }
}

//------------------------------------------------------------------------------
int vtkOpenGLAntialiasingPass::TemporalHistories::GetAccumulatedFrames() const
{
  // The fewest of the histories rendered last: with n histories, those among the last n renders
  // (a renderer that no longer renders with the pass, or an eye no longer rendered, drops out).
  if (this->Entries.empty())
  {
    return 0;
  }
  const std::uint64_t recent =
    this->Renders - std::min<std::uint64_t>(this->Renders, this->Entries.size());
  int accumulated = std::numeric_limits<int>::max();
  for (const Entry& entry : this->Entries)
  {
    if (entry.LastRender > recent)
    {
      accumulated = std::min(accumulated, entry.History->Accumulated);
    }
  }
  return accumulated;
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::TemporalHistories::TargetBytes(int colorBytes) const
{
  vtkIdType bytes = 0;
  for (const Entry& entry : this->Entries)
  {
    bytes += entry.History->TargetBytes(colorBytes);
  }
  return bytes;
}
