// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The temporal antialiasing of vtkOpenGLAntialiasingPass (SetTemporal): its histories and the
// steps of a temporal frame. Private header.
#ifndef vtkOpenGLAntialiasingPassTemporal_h
#define vtkOpenGLAntialiasingPassTemporal_h

#include "vtkOpenGLAntialiasingPass.h"
#include "vtkWeakPointer.h"

#include <cstdint>
#include <memory>
#include <vector>

class vtkCamera;
class vtkRenderer;

// One history of temporal antialiasing (a renderer's, or one eye's of a stereo render): its targets
// (the owner of their GL objects: PrepareTargets makes or resizes them, Release frees them) and
// what the last render left to compare with.
class vtkOpenGLAntialiasingPass::TemporalHistory
{
public:
  TemporalHistory() = default;
  ~TemporalHistory() { this->Release(nullptr); }
  TemporalHistory(const TemporalHistory&) = delete;
  TemporalHistory& operator=(const TemporalHistory&) = delete;

  enum Mode
  {
    RESET,  // the current frame alone
    STILL,  // running average with the history at the same pixel
    MOVING, // reprojected, clamped history
    HOLD,   // a converged still: the history as it is, neither jittered nor blended
  };

  vtkTextureObject* Current = nullptr;  // this frame, antialiased
  vtkTextureObject* Previous = nullptr; // the last unjittered render's frame, antialiased
  vtkTextureObject* Motion = nullptr;   // the method's motion frame (HasMotionFrame)
  vtkTextureObject* Histories[2] = { nullptr, nullptr }; // RGBA32F, read and written in turn
  vtkTextureObject* Counts[2] = { nullptr, nullptr };    // R32F: frames each pixel's history holds
  vtkTextureObject* Mask = nullptr; // depth: the pixels a moving camera's blend writes (1)
  // The delegate's depth at the last render, where a moving camera's blend finds what hid a
  // point then (exchanged with the pass's DepthTexture at each render: no copy).
  vtkTextureObject* Depth = nullptr;
  int Latest = 0; // the one written last
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  ShaderVariant BlendQuad, OutputQuad, MaskQuad;

  bool Valid = false;            // the history holds a frame of the last render's size and scene
  int Accumulated = 0;           // frames averaged since the last change
  std::uint32_t JitterIndex = 0; // the point of StillJitter of the last render
  int Width = 0, Height = 0;
  double ViewProjection[16] = {}; // unjittered, of the last temporal render
  // Where the camera looked from at that render, homogeneous: its position (w = 1), or, for a
  // parallel projection, minus its direction of projection (a point at infinity, w = 0).
  double Eye[4] = {};
  bool Parallel = false;
  std::vector<std::uint64_t> Scene;   // SceneSignature after the last render
  std::vector<std::uint64_t> Content; // the same without the actors' placement

  // This render's decisions.
  Mode FrameMode = RESET;
  double Reprojection[16] = {}; // current to previous normalised device coordinates, transposed
  // Current normalised device coordinates to world coordinates relative to the current eye
  // (translated in double precision, so that large coordinates keep float's precision in the
  // shader), transposed; and the previous and current eyes in the same frame (RelativeEye).
  double ToPoint[16] = {};
  double PreviousEye[4] = {};
  double CurrentEye[4] = {};
  bool KeepUnchanged =
    false; // actors moved under a still camera: see TemporalHistories::BeginFrame
  bool PreviousValid = false; // Previous holds the last unjittered render of this size
  // The entries (2, 2), (2, 3), (3, 2) and (3, 3) of the projection of this render and of the last
  // one, which take a window depth to the distance from the eye; and the sub-pixel offsets
  // (pixels) by which they were jittered.
  double DepthToEye[4] = {};
  double PreviousDepthToEye[4] = {};
  double Jitter[2] = {};
  double PreviousJitter[2] = {};
  vtkCamera* JitteredCamera = nullptr;
  double SavedWindowCenter[2] = { 0.0, 0.0 };

  // Creates or resizes the targets for `frame` (the method's frames of its colour type), and the
  // motion frame where this render reprojects with a method that has one (`motionFrames`). A
  // target allocated afresh that the history needed resets this render (FrameMode RESET).
  void PrepareTargets(const Frame& frame, bool motionFrames);
  // Frees the targets' GL objects (only deletes them where `w` is null: their context is gone).
  void Release(vtkWindow* w);
  // The bytes of its targets, colorBytes a texel for the method's frames.
  vtkIdType TargetBytes(int colorBytes) const;
};

// The temporal antialiasing of a pass: the histories of the renderers, and of the eyes of stereo
// renders, that it renders (one each, made when first needed and released with the pass's
// resources, when temporal antialiasing is switched off, and when their renderer is gone), and
// the steps of a temporal frame around the delegate's render.
class vtkOpenGLAntialiasingPass::TemporalHistories
{
public:
  explicit TemporalHistories(vtkOpenGLAntialiasingPass* pass)
    : Pass(pass)
  {
  }
  ~TemporalHistories() { this->Release(nullptr); }
  TemporalHistories(const TemporalHistories&) = delete;
  TemporalHistories& operator=(const TemporalHistories&) = delete;

  // Before the delegate's render: selects the history of the renderer and eye that `s` renders,
  // decides whether it is kept, and jitters the camera.
  void BeginFrame(const vtkRenderState* s, const Frame& frame);
  // Whether this render's blend reads the method's frame (the history reset, or the camera or
  // actors moving), decided by BeginFrame; not during a still accumulation or a converged still.
  bool RendersMethodFrame() const
  {
    return this->History &&
      (this->History->FrameMode == TemporalHistory::RESET ||
        this->History->FrameMode == TemporalHistory::MOVING);
  }
  // After it: puts the camera back and keeps the scene's state for the next render.
  void EndJitter(const vtkRenderState* s);
  // Antialiases the frame into the history's current target, blends it with the history and
  // writes the result (and the delegate's depth) into the target viewport. With `samples` (2 or
  // more) the delegate rendered into the multisampled targets: the frame antialiased is their
  // resolve (SampleTargets::Antialias), and the frame before the method and its depth are their
  // plain average and nearest depth (SampleTargets::ResolvePlain).
  bool Antialias(const Frame& frame, int samples);

  // Frees every history (only deletes their objects where `w` is null: their context is gone).
  void Release(vtkWindow* w);
  bool Empty() const { return this->Entries.empty(); }
  // Discards what every history holds: their next renders start new accumulations.
  void Reset();
  // See vtkOpenGLAntialiasingPass::GetAccumulatedFrames.
  int GetAccumulatedFrames() const;
  // Bytes of the histories' targets, colorBytes a texel of the method's frames.
  vtkIdType TargetBytes(int colorBytes) const;

private:
  // Points History at the history of the renderer and eye that `s` renders, made when first
  // needed; drops the histories of renderers that are gone.
  void Select(const vtkRenderState* s);
  // The mask of the moving camera's blend (TEMPORAL_MASK in vtkAntialiasingTemporalFS.glsl):
  // copies the current frame `current` into the history being written (draw buffer 0), marks the
  // pixels whose blend is not that frame in the history's depth attachment, and leaves the depth
  // test on for the blend.
  bool MarkBlendedPixels(vtkOpenGLRenderWindow* renWin, vtkTextureObject* current);

  struct Entry
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    bool RightEye = false;
    std::unique_ptr<TemporalHistory> History;
    std::uint64_t LastRender = 0; // Renders when it was last rendered
  };
  vtkOpenGLAntialiasingPass* const Pass; // not held: the pass holds this
  std::vector<Entry> Entries;
  std::uint64_t Renders = 0;          // temporal renders of the pass
  TemporalHistory* History = nullptr; // the one of the render under way
};

#endif
