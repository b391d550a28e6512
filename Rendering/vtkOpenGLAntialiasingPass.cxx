// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLAntialiasingPass.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataObject.h"
#include "vtkDualDepthPeelingPass.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLAntialiasingPassInternals.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkProp.h"
#include "vtkProperty.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVersionMacros.h"
#include "vtkVolume.h"
#include "vtkWeakPointer.h"

#include "vtkAntialiasingAlphaFS.h"
#include "vtkAntialiasingTemporalFS.h"
#include "vtkAntialiasingSamplesFS.h"

#include "vtkAntialiasingOpenGL.h" // For GL enums, and the calls VTK has no wrapper for

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

using namespace vtkOpenGLAntialiasingPassInternals;

//------------------------------------------------------------------------------
class vtkOpenGLAntialiasingPass::CompositedTranslucency : public vtkRenderPass
{
public:
  static CompositedTranslucency* New();
  vtkTypeMacro(CompositedTranslucency, vtkRenderPass);

  vtkOpenGLAntialiasingPass* Owner = nullptr; // not held: the owner holds this
  vtkRenderPass* Translucent = nullptr;       // the delegate's step, during a render

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (this->Owner && this->Translucent)
    {
      this->Owner->RenderCompositedTranslucency(s, this->Translucent);
      this->NumberOfRenderedProps = this->Owner->TranslucencyPass->GetNumberOfRenderedProps();
    }
  }

protected:
  CompositedTranslucency() = default;
  ~CompositedTranslucency() override = default;

private:
  CompositedTranslucency(const CompositedTranslucency&) = delete;
  void operator=(const CompositedTranslucency&) = delete;
};
vtkStandardNewMacro(vtkOpenGLAntialiasingPass::CompositedTranslucency);

//------------------------------------------------------------------------------
// Temporal antialiasing: the history and what the last render left to compare with.
class vtkOpenGLAntialiasingPass::TemporalHistory
{
public:
  enum Mode
  {
    RESET,  // the current frame alone
    STILL,  // running average with the history at the same pixel
    MOVING, // reprojected, clamped history
    HOLD,   // a converged still: the history as it is, neither jittered nor blended
  };

  vtkTextureObject* Current = nullptr;               // this frame, antialiased
  vtkTextureObject* Previous = nullptr; // the last unjittered render's frame, antialiased
  vtkTextureObject* Motion = nullptr;   // the method's motion frame (HasMotionFrame)
  vtkTextureObject* Histories[2] = { nullptr, nullptr }; // RGBA32F, read and written in turn
  vtkTextureObject* Counts[2] = { nullptr, nullptr }; // R32F: frames each pixel's history holds
  vtkTextureObject* Mask = nullptr; // depth: the pixels a moving camera's blend writes (1)
  // The delegate's depth at the last render, where a moving camera's blend finds what hid a
  // point then (exchanged with the pass's DepthTexture at each render: no copy).
  vtkTextureObject* Depth = nullptr;
  int Latest = 0;                                    // the one written last
  vtkOpenGLFramebufferObject* Framebuffer = nullptr;
  ShaderVariant BlendQuad, OutputQuad, MaskQuad;

  bool Valid = false;  // the history holds a frame of the last render's size and scene
  int Accumulated = 0; // frames averaged since the last change
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
  bool KeepUnchanged = false;   // actors moved under a still camera: see BeginTemporalFrame
  bool PreviousValid = false;   // Previous holds the last unjittered render of this size
  // The entries (2, 2), (2, 3), (3, 2) and (3, 3) of the projection of this render and of the last
  // one, which take a window depth to the distance from the eye; and the sub-pixel offsets
  // (pixels) by which they were jittered.
  double DepthToEye[4] = {};
  double PreviousDepthToEye[4] = {};
  double Jitter[2] = {};
  double PreviousJitter[2] = {};
  vtkCamera* JitteredCamera = nullptr;
  double SavedWindowCenter[2] = { 0.0, 0.0 };

  void Release(vtkWindow* w)
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
  // The bytes of its targets, colorBytes a texel for the method's frames.
  vtkIdType TargetBytes(int colorBytes) const
  {
    return TextureBytes(this->Current, colorBytes) + TextureBytes(this->Previous, colorBytes) +
      TextureBytes(this->Motion, colorBytes) + TextureBytes(this->Histories[0], 16) +
      TextureBytes(this->Histories[1], 16) + TextureBytes(this->Counts[0], 4) +
      TextureBytes(this->Counts[1], 4) + TextureBytes(this->Mask, 2) +
      TextureBytes(this->Depth, 4);
  }
};

// The histories of a pass, one per renderer and eye that it renders (SelectHistory).
class vtkOpenGLAntialiasingPass::TemporalHistories
{
public:
  struct Entry
  {
    vtkWeakPointer<vtkRenderer> Renderer;
    bool RightEye = false;
    std::unique_ptr<TemporalHistory> History;
    std::uint64_t LastRender = 0; // Renders when it was last rendered
  };
  std::vector<Entry> Entries;
  std::uint64_t Renders = 0; // temporal renders of the pass

  void Release(vtkWindow* w)
  {
    for (Entry& entry : this->Entries)
    {
      entry.History->Release(w);
    }
    this->Entries.clear();
  }
};

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
    vtkDataObject* input = mapper && mapper->GetNumberOfInputPorts() > 0 &&
        mapper->GetNumberOfInputConnections(0) > 0
      ? mapper->GetInputDataObject(0, 0)
      : nullptr;
    for (vtkObject* part : { static_cast<vtkObject*>(mapper), static_cast<vtkObject*>(input),
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
  for (double value : { renderer->GetBackground()[0], renderer->GetBackground()[1],
         renderer->GetBackground()[2], renderer->GetBackground2()[0],
         renderer->GetBackground2()[1], renderer->GetBackground2()[2],
         renderer->GetBackgroundAlpha() })
  {
    signature.push_back(Bits(value));
  }
  signature.push_back(renderer->GetGradientBackground() ? 1 : 0);
  return signature;
}

// Whether `predicate` holds for one of the props a render draws.
template <typename Predicate>
bool AnyProp(const vtkRenderState* s, Predicate predicate)
{
  for (int i = 0; i < s->GetPropArrayCount(); ++i)
  {
    if (predicate(s->GetPropArray()[i]))
    {
      return true;
    }
  }
  return false;
}

// Whether a render blends something per pixel, not per sample, into a multisampled target:
// translucent geometry (order-independent translucency composites one colour per pixel) or
// volumes (drawn by their own mappers' passes).
bool BlendsPerPixel(const vtkRenderState* s)
{
  return AnyProp(s, [](vtkProp* prop) {
    return prop->HasTranslucentPolygonalGeometry() || vtkVolume::SafeDownCast(prop);
  });
}

// The context of `window` current for as long as the object lives (PushContext), and the one
// current before restored after (PopContext, where the window class implements it); nothing where
// the window is gone.
class WindowContextScope
{
public:
  explicit WindowContextScope(vtkOpenGLRenderWindow* window)
    : Window(window)
  {
    if (window)
    {
      window->PushContext();
    }
  }
  ~WindowContextScope()
  {
    if (this->Window)
    {
      this->Window->PopContext();
    }
  }
  WindowContextScope(const WindowContextScope&) = delete;
  WindowContextScope& operator=(const WindowContextScope&) = delete;

  vtkOpenGLRenderWindow* const Window;
};

// OpenGL sample shading (4.0) on for the scope (every sample shaded at its own position), the
// previous setting restored after it. Nothing is changed with `on` false.
struct SampleShadingScope
{
  explicit SampleShadingScope(bool on)
    : On(on)
  {
    if (on)
    {
      // Not among the states vtkOpenGLState tracks: set and restored here.
      this->WasEnabled = glIsEnabled(GL_SAMPLE_SHADING) == GL_TRUE;
      glGetFloatv(GL_MIN_SAMPLE_SHADING_VALUE, &this->MinimumShading);
      glEnable(GL_SAMPLE_SHADING);
      glMinSampleShading(1.0f);
    }
  }
  ~SampleShadingScope()
  {
    if (this->On)
    {
      glMinSampleShading(this->MinimumShading);
      if (!this->WasEnabled)
      {
        glDisable(GL_SAMPLE_SHADING);
      }
    }
  }
  SampleShadingScope(const SampleShadingScope&) = delete;
  SampleShadingScope& operator=(const SampleShadingScope&) = delete;
  const bool On;
  bool WasEnabled = false;
  GLfloat MinimumShading = 0.0f;
};
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::UsesSampleShading(vtkOpenGLRenderWindow* renWin)
{
  if (!this->SampleShading)
  {
    return false;
  }
  int major = 0, minor = 0;
  renWin->GetOpenGLVersion(major, minor);
  if (major >= 4)
  {
    return true;
  }
  if (!this->WarnedSampleShading)
  {
    this->WarnedSampleShading = true;
    vtkWarningMacro("SampleShading: the OpenGL context (" << major << "." << minor
                                                          << ") has no sample shading (OpenGL "
                                                             "4.0); the samples are shaded per "
                                                             "pixel");
  }
  return false;
}

//------------------------------------------------------------------------------
vtkOpenGLAntialiasingPass::vtkOpenGLAntialiasingPass() = default;

//------------------------------------------------------------------------------
vtkOpenGLAntialiasingPass::~vtkOpenGLAntialiasingPass()
{
  // Replaced or removed and no longer referenced, the pass takes its GL objects with it, in the
  // context of the window that holds them (the subclass's destructor released its own). Where that
  // context is gone, only the objects are deleted.
  const WindowContextScope context(this->LiveResourceWindow());
  // vtkImageProcessingPass's destructor drops the delegate unreleased: where nothing else holds
  // it, it goes now, so its GL objects go too.
  if (context.Window && this->DelegatePass && this->DelegatePass->GetReferenceCount() == 1)
  {
    this->DelegatePass->ReleaseGraphicsResources(context.Window);
  }
  this->ReleaseSharedResources(context.Window);
  delete this->Histories;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ReleaseMethodResourcesOnDestruction()
{
  const WindowContextScope context(this->LiveResourceWindow());
  this->ReleaseMethodResources(context.Window);
}

//------------------------------------------------------------------------------
vtkOpenGLRenderWindow* vtkOpenGLAntialiasingPass::LiveResourceWindow() const
{
  // Each render allocates ColorTexture. A window that releases its resources (Finalize,
  // destruction) releases every texture, framebuffer and quad's vertex array made in it through its
  // callbacks, and its shader cache's programs, and then its renderers' passes; a pass in none of
  // its renderers is left with a texture without a handle, and quads without vertex arrays.
  if (this->ColorTexture && !this->ColorTexture->GetHandle())
  {
    return nullptr;
  }
  return this->ResourceWindow;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::UseWindow(vtkOpenGLRenderWindow* renWin)
{
  vtkOpenGLRenderWindow* live = this->LiveResourceWindow();
  if (live && live != renWin)
  {
    {
      const WindowContextScope context(live);
      this->ReleaseGraphicsResources(live);
    }
    renWin->MakeCurrent(); // where the window's PopContext does not restore the context before
  }
  else if (!live && this->ColorTexture)
  {
    // Released with a context that is gone (see LiveResourceWindow): dropped, and made again.
    this->ReleaseMethodResources(nullptr);
    this->ReleaseSharedResources(nullptr);
  }
  this->ResourceWindow = renWin;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::PrepareTargets(const Frame& frame, bool depth)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  for (vtkTextureObject** texture : { &this->ColorTexture, &this->DepthTexture })
  {
    if (!*texture)
    {
      * texture = NewTexture(renWin);
    }
  }
  bool reallocated =
    AllocateColorTarget(this->ColorTexture, frame.Width, frame.Height, 4, frame.ColorType(), false);
  if (depth)
  {
    // 24-bit depth, as a window's depth buffer, so the delegate renders as it would in the window.
    reallocated |=
      AllocateDepthTarget(this->DepthTexture, frame.Width, frame.Height, vtkTextureObject::Fixed24);
  }
  else if (this->DepthTexture->GetHandle())
  {
    this->DepthTexture->ReleaseGraphicsResources(renWin); // not needed in place
    reallocated = true;
  }
  reallocated |= this->PrepareMethodTargets(frame);
  PrepareFramebuffers(renWin, reallocated, { &this->DelegateFramebuffer, &this->WorkFramebuffer });
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::RenderDelegateToTextures(const vtkRenderState* s,
  vtkOpenGLFramebufferObject* fbo, vtkTextureObject* color, vtkTextureObject* depth, int width,
  int height, bool composite)
{
  vtkOpenGLState* ostate = fbo->GetContext()->GetState();
  vtkRenderState delegateState(s->GetRenderer());
  delegateState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  delegateState.SetRequiredKeys(s->GetRequiredKeys());
  delegateState.SetFrameBuffer(fbo);

  fbo->Bind();
  fbo->AddColorAttachment(0, color);
  fbo->ActivateDrawBuffer(0);
  fbo->AddDepthAttachment(depth);
  fbo->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  if (composite)
  {
    // The renderer preserves the colour buffer, so it will not clear this one: start from
    // transparent black. VTK's blending (source alpha, one minus source alpha for colour; one, one
    // minus source alpha for alpha) then leaves premultiplied colour here.
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
    ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
  }

  this->DelegatePass->Render(&delegateState);
  this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
}

//------------------------------------------------------------------------------
vtkOpenGLAntialiasingPass::StepsChange vtkOpenGLAntialiasingPass::UseRendererTranslucency(
  const vtkRenderState* s, vtkRenderStepsPass* steps, bool composite, bool multisampled)
{
  // What vtkOpenGLRenderer does without a pass (UpdateGeometry and
  // DeviceRenderTranslucentPolygonalGeometry), decided from its settings at this render.
  StepsChange change;
  vtkRenderPass* translucent = steps->GetTranslucentPass();
  auto* renderer = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!renderer || !vtkTranslucentPass::SafeDownCast(translucent))
  {
    return change; // no translucent step, or the user's own: theirs to decide
  }
  if (!AnyProp(s, [](vtkProp* prop) { return prop->HasTranslucentPolygonalGeometry() != 0; }))
  {
    return change; // the renderer skips the translucent step (volumes stay in their own)
  }
  // Depth peeling copies the framebuffer's depth (and colour) with glCopyTexSubImage2D, which a
  // multisampled framebuffer does not allow: a multisampled render (MultiSamples) uses
  // order-independent translucency, which blits the depth (a resolve) instead.
  const bool peeling = renderer->GetUseDepthPeeling() != 0 && !multisampled;
  const bool dual = peeling && renderer->IsDualDepthPeelingSupported();
  // As the renderer reports it after drawing translucent geometry by itself.
  this->SetLastRenderingUsedDepthPeeling(renderer, peeling);
  // With UseDepthPeelingForVolumes, volumes are peeled along with the translucent geometry, by
  // dual depth peeling only (the renderer turns the setting off where that is unsupported).
  vtkRenderPass* volumetric = steps->GetVolumetricPass();
  const bool peelVolumes = dual && renderer->GetUseDepthPeelingForVolumes() && volumetric;

  vtkRenderPass* wrapper = nullptr;
  if (!peeling)
  {
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 5, 0)
    if (!renderer->GetUseOIT())
    {
      return change; // plain blending, as the delegate's step does
    }
#endif
    if (!this->TranslucencyPass)
    {
      this->TranslucencyPass = vtkOrderIndependentTranslucentPass::New();
    }
    this->TranslucencyPass->SetTranslucentPass(translucent);
    wrapper = this->TranslucencyPass;
    if (composite && !multisampled)
    {
      if (!this->CompositedPass)
      {
        this->CompositedPass = CompositedTranslucency::New();
        this->CompositedPass->Owner = this;
      }
      this->CompositedPass->Translucent = translucent;
      wrapper = this->CompositedPass;
    }
  }
  else
  {
    if (this->PeelingPass && this->PeelingPass->IsA("vtkDualDepthPeelingPass") != dual)
    {
      DeleteObject(this->PeelingPass, renderer->GetRenderWindow()); // the support changed
    }
    if (!this->PeelingPass)
    {
      this->PeelingPass = dual ? vtkDualDepthPeelingPass::New() : vtkDepthPeelingPass::New();
    }
    this->PeelingPass->SetMaximumNumberOfPeels(renderer->GetMaximumNumberOfPeels());
    this->PeelingPass->SetOcclusionRatio(renderer->GetOcclusionRatio());
    this->PeelingPass->SetTranslucentPass(translucent);
    if (peelVolumes)
    {
      static_cast<vtkDualDepthPeelingPass*>(this->PeelingPass)->SetVolumetricPass(volumetric);
      change.Volumetric = volumetric;
      steps->SetVolumetricPass(nullptr);
    }
    wrapper = this->PeelingPass;
  }
  change.Steps = steps;
  change.Translucent = translucent;
  steps->SetTranslucentPass(wrapper);
  return change;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::RestoreDelegateSteps(const StepsChange& change)
{
  if (!change.Steps)
  {
    return;
  }
  change.Steps->SetTranslucentPass(change.Translucent);
  if (change.Volumetric)
  {
    change.Steps->SetVolumetricPass(change.Volumetric);
    static_cast<vtkDualDepthPeelingPass*>(this->PeelingPass)->SetVolumetricPass(nullptr);
  }
  // Hold none of the user's passes between renders.
  if (this->TranslucencyPass)
  {
    this->TranslucencyPass->SetTranslucentPass(nullptr);
  }
  if (this->CompositedPass)
  {
    this->CompositedPass->Translucent = nullptr;
  }
  if (this->PeelingPass)
  {
    this->PeelingPass->SetTranslucentPass(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::RenderCompositedTranslucency(
  const vtkRenderState* s, vtkRenderPass* translucent)
{
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow());
  vtkOpenGLState* ostate = renWin->GetState();
  const int width = static_cast<int>(this->ColorTexture->GetWidth());
  const int height = static_cast<int>(this->ColorTexture->GetHeight());
  if (!this->AlphaTexture)
  {
    this->AlphaTexture = NewTexture(renWin);
  }
  AllocateColorTarget(this->AlphaTexture, width, height, 1,
    this->ColorTexture->GetVTKDataType() == VTK_FLOAT ? VTK_FLOAT : VTK_UNSIGNED_CHAR, false);

  vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
  vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
  vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
  vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
  vtkOpenGLState::ScopedglScissor scissorSaver(ostate);

  // Keep the alpha of the opaque steps (the delegate's framebuffer is bound: its colour is
  // ColorTexture).
  ostate->PushFramebufferBindings();
  this->BeginWorkPass(renWin, this->AlphaTexture, width, height);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  bool kept = this->ReadyQuad(renWin, this->KeepAlphaQuad, vtkAntialiasingAlphaFS,
    Define("ANTIALIASING_KEEP_ALPHA", true));
  if (kept)
  {
    const ScopedTextures source(
      this->KeepAlphaQuad.Quad->Program, { { "source", this->ColorTexture } });
    this->KeepAlphaQuad.Quad->Render();
  }
  ostate->PopFramebufferBindings();

  this->TranslucencyPass->Render(s);
  if (!kept || !this->ReadyQuad(renWin, this->RestoreAlphaQuad, vtkAntialiasingAlphaFS, ""))
  {
    return;
  }

  // The kept alpha back, colour untouched...
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglDisable(GL_DEPTH_TEST);
  ostate->vtkglDepthMask(GL_FALSE);
  {
    const ScopedTextures source(
      this->RestoreAlphaQuad.Quad->Program, { { "source", this->AlphaTexture } });
    this->RestoreAlphaQuad.Quad->Render();
  }

  // ... and the coverage of the translucent geometry in front of the opaque depth blended into it:
  // a = a_i + (1 - a_i) a, which does not depend on the order of the fragments, leaves
  // 1 - (1 - a) * (transmittance), the alpha the colour was premultiplied with.
  ostate->vtkglEnable(GL_BLEND);
  ostate->vtkglBlendFuncSeparate(GL_ZERO, GL_ONE, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  translucent->Render(s);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::CopyTargetToColorTexture(
  const Frame& frame, unsigned int targetBinding, unsigned int targetBuffer)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  // A blit is clipped by the scissor test, and the delegate need not leave this renderer's box:
  // a camera pass restores the one it found (in ParaView's client-server rendering, a square
  // 300 x 300 in a 400 x 300 view, which left the rest of the image out).
  vtkOpenGLState::ScopedglEnableDisable scissorTestSaver(ostate, GL_SCISSOR_TEST);
  ostate->vtkglDisable(GL_SCISSOR_TEST);
  this->DelegateFramebuffer->Bind(GL_DRAW_FRAMEBUFFER);
  this->DelegateFramebuffer->AddColorAttachment(0, this->ColorTexture);
  this->DelegateFramebuffer->ActivateDrawBuffer(0);
  ostate->vtkglBindFramebuffer(GL_READ_FRAMEBUFFER, targetBinding);
  ostate->vtkglReadBuffer(targetBuffer);
  const int source[4] = { frame.X, frame.X + frame.Width, frame.Y, frame.Y + frame.Height };
  const int destination[4] = { 0, frame.Width, 0, frame.Height };
  vtkOpenGLFramebufferObject::Blit(source, destination, GL_COLOR_BUFFER_BIT, GL_NEAREST);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ShaderVariant::Release(vtkWindow* window)
{
  if (this->Quad)
  {
    this->Quad->ReleaseGraphicsResources(window);
    delete this->Quad;
    this->Quad = nullptr;
  }
  this->Defines.clear();
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::ReadyQuad(vtkOpenGLRenderWindow* renWin, ShaderVariant& variant,
  const char* fs, const std::string& defines, const char* vs)
{
  if (variant.Quad && variant.Defines != defines)
  {
    // The options changed what the shader does: build the other variant (the shader cache keeps the
    // programs, so switching back is cheap).
    variant.Release(renWin);
  }
  vtkOpenGLQuadHelper*& quad = variant.Quad;
  if (!quad)
  {
    std::string source = fs;
    vtkShaderProgram::Substitute(source, "//VTK::Antialiasing::Dec", defines, false);
    this->SubstituteShaderSnippets(source);
    quad = new vtkOpenGLQuadHelper(renWin, vs, source.c_str(), "");
    variant.Defines = defines;
  }
  else
  {
    renWin->GetShaderCache()->ReadyShaderProgram(quad->Program);
  }
  if (!quad->Program || !quad->Program->GetCompiled())
  {
    vtkErrorMacro("Could not build a shader program of " << this->GetClassName() << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::Render(const vtkRenderState* s)
{
  vtkOpenGLClearErrorMacro();
  this->NumberOfRenderedProps = 0;
  if (!this->DelegatePass)
  {
    vtkWarningMacro("No delegate pass: nothing to antialias.");
    return;
  }

  vtkRenderer* renderer = s->GetRenderer();
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  if (!renWin)
  {
    vtkErrorMacro(<< this->GetClassName() << " needs a vtkOpenGLRenderWindow.");
    return;
  }
  vtkOpenGLState* ostate = renWin->GetState();

  // A hardware selection render (picking): the colour buffer holds encoded prop, cell and point
  // ids, not colours, and a blend of two ids is a third, wrong one. Render straight into the
  // target, untouched, as vtkOpenGLRenderer does without a pass: the camera (which clears), the
  // lights, and UpdateGeometry, which hands the props to the selector. (The selector numbers the
  // props only in UpdateGeometry; render passes such as vtkRenderStepsPass do not call it.)
  if (renderer->GetSelector())
  {
    renWin->MakeCurrent();
    this->UpdateCamera(renderer);
    this->UpdateLightGeometry(renderer);
    this->UpdateLights(renderer);
    this->UpdateGeometry(renderer, s->GetFrameBuffer());
    this->NumberOfRenderedProps = renderer->GetNumberOfPropsRendered();
    vtkOpenGLCheckErrorMacro("failed after vtkOpenGLAntialiasingPass::Render");
    return;
  }

  this->UseWindow(renWin);

  // The pass and its stages in the window's render timings (TimedStage), when they are on.
  TimedStage passStage(renWin, this->GetClassName());

  // The viewport to fill: the renderer's (tiled) viewport in the window, or the whole of a
  // framebuffer object when an enclosing pass renders this one into its own target.
  Frame frame;
  frame.Window = renWin;
  if (auto* targetFbo = vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
  {
    int size[2];
    s->GetWindowSize(size);
    frame.Width = size[0];
    frame.Height = size[1];
    vtkTextureObject* target = targetFbo->GetColorAttachmentAsTextureObject(0);
    frame.FloatColor = target && target->GetVTKDataType() == VTK_FLOAT;
  }
  else
  {
    renderer->GetTiledSizeAndOrigin(&frame.Width, &frame.Height, &frame.X, &frame.Y);
  }
  if (frame.Width < 1 || frame.Height < 1)
  {
    return;
  }
  // A renderer that preserves the colour buffer (a layer above 0, or SetPreserveColorBuffer(1))
  // draws over what is already there: its image is composited over the target, and its alpha
  // (coverage) is part of the result.
  frame.Composite = renderer->Transparent() != 0;
  // Alpha is part of the result only when compositing, and with KeepAlpha. Otherwise the image is
  // opaque to whoever reads it (an RGB screenshot, the screen), and the alpha VTK leaves in the
  // framebuffer (0 on the background, 1 on geometry, whatever the background colour) would make
  // edges that nobody sees.
  frame.UseAlpha = frame.Composite || this->KeepAlpha;
  // Straight alpha: the texture of a composited renderer is premultiplied by construction.
  frame.StraightAlpha = this->KeepAlpha && !frame.Composite && this->UsesStraightAlpha();
  // In place: the delegate renders straight into the target, as it would without the pass; its
  // colour is copied (blitted) into ColorTexture, and the last pass writes only the pixels that
  // antialiasing changes. This saves copying every pixel's colour and depth back with a shader. A
  // composited renderer needs its own transparent texture, and a method that reads the delegate's
  // depth needs it as a texture: those render the delegate into the pass's textures and copy
  // everything back.
  // Temporal antialiasing reads the delegate's depth (reprojection). A debug output of the method
  // is shown as it is. A multisampled render (SetMultiSamples) renders the delegate into the
  // multisampled targets; temporal antialiasing does not combine with it (it renders one sample,
  // and converges to the supersampled picture by itself): with both on, Temporal wins.
  const bool temporal = this->Temporal && this->DrawsDeferredOverlays();
  if (temporal && this->MultiSamples > 1 && !this->WarnedTemporalMultiSamples)
  {
    vtkWarningMacro("MultiSamples " << this->MultiSamples
                                    << " is not used while Temporal is on: the pass renders one "
                                       "sample per pixel and accumulates jittered frames instead");
    this->WarnedTemporalMultiSamples = true;
  }
  const int samples = temporal ? 0 : this->ChooseMultiSamples(renWin, frame.FloatColor);
  this->RenderedMultiSamples = samples;
  this->RenderedSampleShading = false;
  this->SamplesShaded = false;
  frame.InPlace = !frame.Composite && !this->NeedsDelegateDepth() && !temporal && !samples;
  unsigned int targetBinding = 0, targetBuffer = 0;
  ostate->GetCurrentDrawFramebufferState(targetBinding, targetBuffer);

  vtkRenderStepsPass* steps = vtkRenderStepsPass::SafeDownCast(this->DelegatePass);
  vtkSmartPointer<vtkRenderPass> overlay =
    steps && !this->AntialiasOverlays ? steps->GetOverlayPass() : nullptr;
  bool done = false;
  {
    // Save the state this pass changes; restored at the end of this block.
    vtkOpenGLState::ScopedglEnableDisable blendSaver(ostate, GL_BLEND);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(ostate);
    vtkOpenGLState::ScopedglEnableDisable depthTestSaver(ostate, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglDepthFunc depthFuncSaver(ostate);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(ostate);
    vtkOpenGLState::ScopedglColorMask colorMaskSaver(ostate);
    vtkOpenGLState::ScopedglClearColor clearColorSaver(ostate);
    vtkOpenGLState::ScopedglViewport viewportSaver(ostate);
    vtkOpenGLState::ScopedglScissor scissorSaver(ostate);

    this->PrepareTargets(frame, !frame.InPlace);
    if (samples)
    {
      this->PrepareSampleTargets(frame, samples);
    }
    else
    {
      this->ReleaseSampleResources(renWin); // not used (any more)
    }
    if (!temporal && this->Histories && !this->Histories->Entries.empty())
    {
      // Temporal switched off: its histories would hold about 16 times the frame for nothing.
      this->Histories->Release(renWin);
      this->History = nullptr;
    }

    // Render the delegate, keeping its overlay step for after the antialiasing.
    if (overlay)
    {
      steps->SetOverlayPass(nullptr);
    }
    const StepsChange stepsChange =
      steps ? this->UseRendererTranslucency(s, steps, frame.Composite, samples > 0) : StepsChange();
    if (temporal)
    {
      this->SelectHistory(s);
      this->BeginTemporalFrame(s, frame);
    }
    TimedStage delegateStage(renWin, "delegate");
    if (frame.InPlace)
    {
      this->DelegatePass->Render(s);
      this->NumberOfRenderedProps += this->DelegatePass->GetNumberOfRenderedProps();
      ostate->PushFramebufferBindings();
      this->CopyTargetToColorTexture(frame, targetBinding, targetBuffer);
      ostate->PopFramebufferBindings();
    }
    else
    {
      ostate->PushFramebufferBindings();
      if (samples)
      {
        // Rasterised per sample: GL_MULTISAMPLE is on in a new context, but a window without
        // samples may have it off.
        vtkOpenGLState::ScopedglEnableDisable multisampleSaver(ostate, GL_MULTISAMPLE);
        ostate->vtkglEnable(GL_MULTISAMPLE);
        const SampleShadingScope shading(this->UsesSampleShading(renWin));
        this->RenderDelegateToTextures(s, this->SamplesFramebuffer, this->SamplesColorTexture,
          this->SamplesDepthTexture, frame.Width, frame.Height, frame.Composite);
        this->RenderedSampleShading = shading.On;
        this->SamplesShaded = shading.On && !BlendsPerPixel(s);
      }
      else
      {
        this->RenderDelegateToTextures(s, this->DelegateFramebuffer, this->ColorTexture,
          this->DepthTexture, frame.Width, frame.Height, frame.Composite);
      }
      ostate->PopFramebufferBindings();
    }
    delegateStage.Stop();
    if (temporal)
    {
      this->EndTemporalJitter(s);
    }
    this->RestoreDelegateSteps(stepsChange);
    if (overlay)
    {
      steps->SetOverlayPass(overlay);
    }

    TimedStage methodStage(renWin, "antialiasing");
    done = temporal   ? this->AntialiasTemporal(frame)
      : samples       ? this->AntialiasSamples(frame, samples)
                      : this->Antialias(frame);
  }

  // The overlays: drawn on top of the result, in the state the pass was entered with, in the
  // renderer's viewport, as the render steps would have drawn them.
  if (done && overlay && this->DrawsDeferredOverlays())
  {
    ostate->vtkglViewport(frame.X, frame.Y, frame.Width, frame.Height);
    ostate->vtkglScissor(frame.X, frame.Y, frame.Width, frame.Height);
    TimedStage overlayStage(renWin, "overlays");
    overlay->Render(s);
    this->NumberOfRenderedProps += overlay->GetNumberOfRenderedProps();
  }
  vtkOpenGLCheckErrorMacro("failed after vtkOpenGLAntialiasingPass::Render");
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ReleaseGraphicsResources(vtkWindow* w)
{
  this->Superclass::ReleaseGraphicsResources(w);
  this->ReleaseMethodResources(w);
  this->ReleaseSharedResources(w);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ReleaseSharedResources(vtkWindow* w)
{
  DeleteObject(this->DelegateFramebuffer, w);
  DeleteObject(this->WorkFramebuffer, w);
  DeleteObject(this->ColorTexture, w);
  DeleteObject(this->DepthTexture, w);
  DeleteObject(this->TranslucencyPass, w);
  DeleteObject(this->PeelingPass, w);
  if (this->CompositedPass)
  {
    this->CompositedPass->Owner = nullptr; // the delegate's step sequence may still hold it
  }
  DeleteObject(this->CompositedPass, w);
  DeleteObject(this->AlphaTexture, w);
  this->KeepAlphaQuad.Release(w);
  this->RestoreAlphaQuad.Release(w);
  if (this->Histories)
  {
    this->Histories->Release(w);
  }
  this->History = nullptr;
  this->ReleaseSampleResources(w);
  this->SupportedSampleCounts[0].clear(); // the next context may offer others
  this->SupportedSampleCounts[1].clear();
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::GetTargetMemorySize()
{
  const int colorBytes =
    (this->ColorTexture && this->ColorTexture->GetVTKDataType() == VTK_FLOAT) ? 16 : 4;
  const int samples = this->SamplesColorTexture ? this->SamplesColorTexture->GetSamples() : 0;
  vtkIdType history = 0;
  if (this->Histories)
  {
    for (const auto& entry : this->Histories->Entries)
    {
      history += entry.History->TargetBytes(colorBytes);
    }
  }
  return TextureBytes(this->ColorTexture, colorBytes) + TextureBytes(this->DepthTexture, 4) +
    TextureBytes(this->AlphaTexture, colorBytes / 4) + this->GetMethodTargetMemorySize() + history +
    TextureBytes(this->SamplesColorTexture, colorBytes * samples) +
    TextureBytes(this->SamplesDepthTexture, 4 * samples) +
    TextureBytes(this->SampleTexture, colorBytes) + TextureBytes(this->AccumulationTexture, 16);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AntialiasOverlays: " << (this->AntialiasOverlays ? "On" : "Off") << "\n";
  os << indent << "KeepAlpha: " << (this->KeepAlpha ? "On" : "Off") << "\n";
  os << indent << "Temporal: " << (this->Temporal ? "On" : "Off") << "\n";
  os << indent << "TemporalWeight: " << this->TemporalWeight << "\n";
  os << indent << "ConvergedFrames: " << this->ConvergedFrames << "\n";
  os << indent << "AccumulatedFrames: " << this->GetAccumulatedFrames() << "\n";
  os << indent << "MultiSamples: " << this->MultiSamples << "\n";
  os << indent << "RenderedMultiSamples: " << this->RenderedMultiSamples << "\n";
  os << indent << "SampleShading: " << this->SampleShading << "\n";
  os << indent << "RenderedSampleShading: " << this->RenderedSampleShading << "\n";
  os << indent << "DebugSample: " << this->DebugSample << "\n";
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::BeginWorkPass(
  vtkOpenGLRenderWindow* renWin, vtkTextureObject* texture, int width, int height)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->WorkFramebuffer;
  fbo->Bind();
  fbo->AddColorAttachment(0, texture);
  DrawToAttachments(fbo, 1);
  fbo->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::SetTemporal(bool temporal)
{
  if (this->Temporal != temporal)
  {
    this->Temporal = temporal;
    this->ResetHistory();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ResetHistory()
{
  if (this->Histories)
  {
    for (auto& entry : this->Histories->Entries)
    {
      entry.History->Valid = false;
      entry.History->Accumulated = 0;
    }
  }
}

//------------------------------------------------------------------------------
int vtkOpenGLAntialiasingPass::GetAccumulatedFrames() const
{
  // The fewest of the histories rendered last: with n histories, those among the last n renders
  // (a renderer that no longer renders with the pass, or an eye no longer rendered, drops out).
  if (!this->Histories || this->Histories->Entries.empty())
  {
    return 0;
  }
  const TemporalHistories& all = *this->Histories;
  const std::uint64_t recent =
    all.Renders - std::min<std::uint64_t>(all.Renders, all.Entries.size());
  int accumulated = std::numeric_limits<int>::max();
  for (const auto& entry : all.Entries)
  {
    if (entry.LastRender > recent)
    {
      accumulated = std::min(accumulated, entry.History->Accumulated);
    }
  }
  return accumulated;
}

//------------------------------------------------------------------------------
int vtkOpenGLAntialiasingPass::RenderConverged(vtkRenderWindow* window)
{
  if (!window)
  {
    vtkErrorMacro("RenderConverged needs a render window.");
    return 0;
  }
  if (!this->Temporal)
  {
    window->Render();
    return 1;
  }
  const int limit = 2 * this->ConvergedFrames;
  int renders = 0;
  do
  {
    window->Render();
    ++renders;
  } while (this->GetAccumulatedFrames() < this->ConvergedFrames && renders < limit);
  if (this->GetAccumulatedFrames() < this->ConvergedFrames)
  {
    vtkWarningMacro("RenderConverged: " << this->GetAccumulatedFrames() << " of "
                                        << this->ConvergedFrames << " frames accumulated after "
                                        << renders
                                        << " renders (is the pass on a renderer of this window, "
                                           "and does the scene stay unchanged?).");
  }
  return renders;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::SelectHistory(const vtkRenderState* s)
{
  if (!this->Histories)
  {
    this->Histories = new TemporalHistories;
  }
  TemporalHistories& all = *this->Histories;
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
    auto stale = std::find_if(all.Entries.begin(), all.Entries.end(),
      [renderer](const TemporalHistories::Entry& entry) {
        return entry.Renderer == renderer && entry.RightEye;
      });
    if (stale != all.Entries.end())
    {
      stale->History->Release(renderer->GetRenderWindow());
      all.Entries.erase(stale);
    }
  }
  auto found = std::find_if(all.Entries.begin(), all.Entries.end(),
    [renderer, rightEye](const TemporalHistories::Entry& entry) {
      return entry.Renderer == renderer && entry.RightEye == rightEye;
    });
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
void vtkOpenGLAntialiasingPass::BeginTemporalFrame(const vtkRenderState* s, const Frame& frame)
{
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
    h.JitterIndex = 0; // the still accumulation that may follow starts from this frame
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
  else if (h.Accumulated >= this->ConvergedFrames)
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
  StillJitter(h.JitterIndex, this->ConvergedFrames, jitter);
  h.Jitter[0] = jitter[0];
  h.Jitter[1] = jitter[1];
  h.JitteredCamera = camera;
  camera->GetWindowCenter(h.SavedWindowCenter);
  camera->SetWindowCenter(h.SavedWindowCenter[0] + 2.0 * jitter[0] / frame.Width,
    h.SavedWindowCenter[1] + 2.0 * jitter[1] / frame.Height);
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::EndTemporalJitter(const vtkRenderState* s)
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
bool vtkOpenGLAntialiasingPass::AntialiasTemporal(const Frame& frame)
{
  TemporalHistory& h = *this->History;
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  const int width = frame.Width, height = frame.Height;
  if (!h.Current)
  {
    h.Current = NewTexture(renWin);
    h.Previous = NewTexture(renWin);
    h.Histories[0] = NewTexture(renWin);
    h.Histories[1] = NewTexture(renWin);
    h.Counts[0] = NewTexture(renWin);
    h.Counts[1] = NewTexture(renWin);
    h.Mask = NewTexture(renWin);
    h.Depth = NewTexture(renWin);
    PrepareFramebuffers(renWin, false, { &h.Framebuffer });
  }
  // Previous keeps the method's frame of the last unjittered render (a still accumulation's
  // jittered frames go to Current and are not kept: the still scene's unjittered frame is the one
  // its accumulation started with).
  const int colorType = frame.ColorType(); // the method's frames
  for (vtkTextureObject* texture : { h.Current, h.Previous })
  {
    if (AllocateColorTarget(texture, width, height, 4, colorType, false))
    {
      h.PreviousValid = false;
      if (h.KeepUnchanged)
      {
        h.KeepUnchanged = false; // what Previous held is gone: start again
        h.FrameMode = TemporalHistory::RESET;
        h.Accumulated = 1;
      }
    }
  }
  for (int i = 0; i < 2; ++i)
  {
    // 32-bit floating point: a running average of many frames moves by less than 1/255 a frame.
    const bool history =
      AllocateColorTarget(h.Histories[i], width, height, 4, VTK_FLOAT, true, GL_RGBA32F);
    const bool count = AllocateColorTarget(h.Counts[i], width, height, 1, VTK_FLOAT, false, GL_R32F);
    if (history || count)
    {
      h.FrameMode = TemporalHistory::RESET;
      h.Accumulated = 1;
    }
  }
  AllocateDepthTarget(h.Mask, width, height, vtkTextureObject::Fixed16);
  // This render's kind of blend (the mode is final from here on): a moving camera's reprojects
  // the history and, for a method with one, reads its motion frame (written at every such
  // render).
  const bool moving = h.FrameMode == TemporalHistory::MOVING;
  const bool keep = moving && h.KeepUnchanged;
  const bool reproject = moving && !keep;
  const bool motionFrame = reproject && this->HasMotionFrame();
  if (motionFrame)
  {
    if (!h.Motion)
    {
      h.Motion = NewTexture(renWin);
    }
    AllocateColorTarget(h.Motion, width, height, 4, colorType, false);
  }

  auto bindTarget = [&](vtkTextureObject* texture) {
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
    else
    {
      // Current takes the delegate's image as it is (a copy; bindTarget set the whole texture as
      // the scissor box), and the method writes only the pixels it changes, as in place in the
      // target: the same image, without a shader writing every pixel.
      this->DelegateFramebuffer->Bind(GL_READ_FRAMEBUFFER);
      this->DelegateFramebuffer->ActivateReadBuffer(0);
      const int box[4] = { 0, width, 0, height };
      vtkOpenGLFramebufferObject::Blit(box, box, GL_COLOR_BUFFER_BIT, GL_NEAREST);
      local.InPlace = true;
      local.OwnTarget = h.Framebuffer;
    }
    done = this->Antialias(local); // (bindTarget below detaches the motion frame)
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
      weight = static_cast<float>(this->TemporalWeight);
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
      this->ReadyQuad(renWin, h.BlendQuad, vtkAntialiasingTemporalFS,
        Define("TEMPORAL_REPROJECT", reproject) + Define("TEMPORAL_KEEP_UNCHANGED", keep) +
          Define("TEMPORAL_MOTION_FRAME", motionFrame));
    if (done)
    {
      // While the scene is still, the frames averaged are the jittered renders themselves: their
      // mean is the supersampled picture, which the method's own blending would blur; the
      // history starts from the method's frame (its error then weighs 1 / AccumulatedFrames).
      // Each pixel's count of frames is kept with the history: pixels that moving actors did not
      // reach go on from their own count when the actors stop, instead of starting again.
      vtkTextureObject* current = still ? this->ColorTexture : h.Current;
      vtkShaderProgram* program = h.BlendQuad.Quad->Program;
      // The textures of this variant (the camera moving reads no counts; a still camera reads
      // neither this frame before the method nor the last one).
      ScopedTextures textures(program,
        { { "currentTexture", current }, { "historyTexture", h.Histories[h.Latest] },
          { "depthTexture", this->DepthTexture } });
      if (!reproject)
      {
        textures.Bind(program, "countTexture", h.Counts[h.Latest]);
      }
      else
      {
        // Not jittered: the clamp's range.
        textures.Bind(program, "frameTexture", this->ColorTexture);
        if (motionFrame)
        {
          textures.Bind(program, "motionTexture", h.Motion);
        }
        // The reprojection and the view's turn (in single precision, as GLSL takes them).
        float values[16];
        auto single = [&values](const double* v, int n) {
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
  std::swap(this->DepthTexture, h.Depth);
  if (!still && !hold)
  {
    std::swap(h.Current, h.Previous);
    h.PreviousValid = true;
  }

  blendStage.Stop();

  // The result into the target viewport, with the delegate's depth (as the method writes it when
  // not in place), composited over lower layers when the renderer preserves the colour buffer.
  TimedStage outputStage(renWin, "temporal output");
  if (!this->ReadyQuad(renWin, h.OutputQuad, vtkAntialiasingTemporalFS,
        Define("TEMPORAL_OUTPUT", true)))
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
bool vtkOpenGLAntialiasingPass::MarkBlendedPixels(
  vtkOpenGLRenderWindow* renWin, vtkTextureObject* current)
{
  TemporalHistory& h = *this->History;
  vtkOpenGLState* ostate = renWin->GetState();
  if (!this->ReadyQuad(renWin, h.MaskQuad, vtkAntialiasingTemporalFS,
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
      { { "currentTexture", current }, { "frameTexture", this->ColorTexture },
        { "depthTexture", this->DepthTexture } });
    h.MaskQuad.Quad->Render();
  }
  DrawToAttachments(h.Framebuffer, 2);
  ostate->vtkglDepthMask(GL_FALSE);
  ostate->vtkglDepthFunc(GL_LESS);
  return true;
}

//------------------------------------------------------------------------------
// Multisampled rendering (SetMultiSamples).
namespace
{
// The sample counts the driver offers for multisampled textures of every format in `formats`,
// largest first.
std::vector<int> QuerySampleCounts(
  vtkOpenGLRenderWindow* renWin, std::initializer_list<unsigned int> formats)
{
  std::vector<int> counts;
  int major = 0, minor = 0;
  renWin->GetOpenGLVersion(major, minor);
  if (major > 4 || (major == 4 && minor >= 2))
  {
    // The counts of each format (glGetInternalformativ, OpenGL 4.2): VTK has no wrapper for it.
    bool first = true;
    for (unsigned int format : formats)
    {
      GLint n = 0;
      glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_NUM_SAMPLE_COUNTS, 1, &n);
      std::vector<GLint> offered(static_cast<std::size_t>(std::max(n, 0)));
      if (n > 0)
      {
        glGetInternalformativ(GL_TEXTURE_2D_MULTISAMPLE, format, GL_SAMPLES, n, offered.data());
      }
      if (first)
      {
        counts.assign(offered.begin(), offered.end());
        first = false;
      }
      else
      {
        counts.erase(std::remove_if(counts.begin(), counts.end(),
                       [&](int c) {
                         return std::find(offered.begin(), offered.end(), c) == offered.end();
                       }),
          counts.end());
      }
    }
  }
  else
  {
    // OpenGL 3.2 guarantees multisampled textures up to these limits; powers of two below them.
    GLint maxColor = 0, maxDepth = 0;
    renWin->GetState()->vtkglGetIntegerv(GL_MAX_COLOR_TEXTURE_SAMPLES, &maxColor);
    renWin->GetState()->vtkglGetIntegerv(GL_MAX_DEPTH_TEXTURE_SAMPLES, &maxDepth);
    for (int c = 1; 2 * c <= std::min(maxColor, maxDepth); c *= 2)
    {
      counts.insert(counts.begin(), 2 * c);
    }
  }
  counts.erase(std::remove_if(counts.begin(), counts.end(), [](int c) { return c < 2; }),
    counts.end());
  std::sort(counts.rbegin(), counts.rend());
  return counts;
}
}

//------------------------------------------------------------------------------
int vtkOpenGLAntialiasingPass::ChooseMultiSamples(vtkOpenGLRenderWindow* renWin, bool floatColor)
{
  const int wanted = this->MultiSamples;
  if (wanted < 2)
  {
    return 0;
  }
  std::vector<int>& counts = this->SupportedSampleCounts[floatColor ? 1 : 0];
  if (counts.empty())
  {
    // The formats of SamplesColorTexture and SamplesDepthTexture.
    const unsigned int colorFormat = floatColor ? GL_RGBA32F : GL_RGBA8;
    counts = QuerySampleCounts(renWin, { colorFormat, GL_DEPTH_COMPONENT24 });
    if (counts.empty())
    {
      counts.push_back(0); // queried: none
    }
  }
  // The nearest offered count, the smaller one on a tie.
  int chosen = 0;
  for (int c : counts)
  {
    if (c >= 2 &&
      (!chosen || std::abs(c - wanted) < std::abs(chosen - wanted) ||
        (std::abs(c - wanted) == std::abs(chosen - wanted) && c < chosen)))
    {
      chosen = c;
    }
  }
  if (chosen != wanted && this->WarnedMultiSamples != wanted)
  {
    this->WarnedMultiSamples = wanted;
    std::string offered;
    for (int c : counts)
    {
      if (c >= 2)
      {
        offered += (offered.empty() ? "" : ", ") + std::to_string(c);
      }
    }
    if (chosen)
    {
      vtkWarningMacro("MultiSamples " << wanted << ": the OpenGL driver offers " << offered
                                      << " samples per pixel for the pass's targets; using "
                                      << chosen << ".");
    }
    else
    {
      vtkWarningMacro("MultiSamples " << wanted
                                      << ": the OpenGL driver offers no multisampled targets; "
                                         "rendering one sample per pixel.");
    }
  }
  return chosen;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::PrepareSampleTargets(const Frame& frame, int samples)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const int colorType = frame.ColorType();
  for (vtkTextureObject** texture : { &this->SamplesColorTexture, &this->SamplesDepthTexture,
         &this->SampleTexture, &this->AccumulationTexture })
  {
    if (!*texture)
    {
      *texture = NewTexture(renWin);
    }
  }
  bool reallocated = false;
  for (vtkTextureObject* texture : { this->SamplesColorTexture, this->SamplesDepthTexture })
  {
    if (texture->GetHandle() && texture->GetSamples() != static_cast<unsigned int>(samples))
    {
      texture->ReleaseGraphicsResources(renWin); // another count: allocated afresh below
      reallocated = true;
    }
    texture->SetSamples(samples);
  }
  reallocated |= AllocateColorTarget(
    this->SamplesColorTexture, frame.Width, frame.Height, 4, colorType, false);
  // 24-bit depth, as the single-sample delegate's.
  reallocated |= AllocateDepthTarget(
    this->SamplesDepthTexture, frame.Width, frame.Height, vtkTextureObject::Fixed24);
  reallocated |=
    AllocateColorTarget(this->SampleTexture, frame.Width, frame.Height, 4, colorType, false);
  // The sum of N images, each scaled by 1 / N: full floats, blended.
  reallocated |= AllocateColorTarget(
    this->AccumulationTexture, frame.Width, frame.Height, 4, VTK_FLOAT, false, GL_RGBA32F);
  PrepareFramebuffers(renWin, reallocated, { &this->SamplesFramebuffer, &this->SampleFramebuffer });
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::CopySample(
  vtkOpenGLRenderWindow* renWin, int sample, int samples, int width, int height)
{
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = this->DelegateFramebuffer;
  fbo->Bind();
  fbo->AddColorAttachment(0, this->ColorTexture);
  fbo->ActivateDrawBuffer(0);
  fbo->AddDepthAttachment(this->DepthTexture);
  // No blending; the sample's depth is copied.
  SetTargetWriteState(ostate, 0, 0, width, height, false, true);
  if (!this->ReadyQuad(
        renWin, this->SampleCopyQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_COPY", true)))
  {
    return false;
  }
  vtkShaderProgram* program = this->SampleCopyQuad.Quad->Program;
  const ScopedTextures textures(program,
    { { "samplesColor", this->SamplesColorTexture },
      { "samplesDepth", this->SamplesDepthTexture } });
  program->SetUniformi("sampleIndex", std::min(sample, samples - 1));
  this->SampleCopyQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::AntialiasSamples(const Frame& frame, int samples)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  const int width = frame.Width, height = frame.Height;
  // Each sample image is antialiased as the single-sample pass antialiases the delegate's image
  // rendered into its textures, into SampleTexture (the whole of it), then accumulated; the
  // compositing over the target, if any, is done once, with the average.
  Frame sampleFrame = frame;
  sampleFrame.X = 0;
  sampleFrame.Y = 0;
  sampleFrame.Composite = false;
  sampleFrame.InPlace = false;
  const bool debug = this->DebugSample >= 0;
  const int first = debug ? std::min(this->DebugSample, samples - 1) : 0;
  const int last = debug ? first + 1 : samples;

  ostate->PushFramebufferBindings();
  // The sample positions the driver uses, for the method (GetCurrentSampleSet): queried with
  // the multisampled framebuffer bound (glGetMultisamplefv, OpenGL 3.2: VTK has no wrapper).
  SampleSet set;
  set.Offsets.assign(2 * samples, 0.0);
  set.Colors = this->SamplesColorTexture;
  set.Shaded = this->SamplesShaded;
  this->SamplesFramebuffer->Bind();
  for (int sample = 0; sample < samples; ++sample)
  {
    GLfloat position[2] = { 0.5f, 0.5f };
    glGetMultisamplefv(GL_SAMPLE_POSITION, sample, position);
    set.Offsets[2 * sample] = position[0] - 0.5;
    set.Offsets[2 * sample + 1] = position[1] - 0.5;
  }
  bool done = true;
  for (int sample = first; done && sample < last; ++sample)
  {
    done = this->CopySample(renWin, sample, samples, width, height);
    vtkTextureObject* result = this->ColorTexture; // the plain sample image, for DebugSample
    if (done && !debug)
    {
      this->SampleFramebuffer->Bind();
      this->SampleFramebuffer->AddColorAttachment(0, this->SampleTexture);
      this->SampleFramebuffer->ActivateDrawBuffer(0);
      set.Index = sample;
      this->CurrentSampleSet = set;
      done = this->Antialias(sampleFrame);
      this->CurrentSampleSet = SampleSet();
      result = this->SampleTexture;
    }
    // Accumulated: the sum of the sample images, each scaled by 1 / N.
    done = done &&
      this->ReadyQuad(renWin, this->AccumulateQuad, vtkAntialiasingSamplesFS,
        Define("SAMPLES_ACCUMULATE", true));
    if (!done)
    {
      break;
    }
    this->SampleFramebuffer->Bind();
    this->SampleFramebuffer->AddColorAttachment(0, this->AccumulationTexture);
    this->SampleFramebuffer->ActivateDrawBuffer(0);
    ostate->vtkglViewport(0, 0, width, height);
    ostate->vtkglScissor(0, 0, width, height);
    ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    ostate->vtkglDisable(GL_DEPTH_TEST);
    if (sample == first)
    {
      ostate->vtkglClearColor(0.0, 0.0, 0.0, 0.0);
      ostate->vtkglClear(GL_COLOR_BUFFER_BIT);
    }
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
    vtkShaderProgram* program = this->AccumulateQuad.Quad->Program;
    const ScopedTextures source(program, { { "source", result } });
    program->SetUniformf("scale", 1.0f / static_cast<float>(last - first));
    this->AccumulateQuad.Quad->Render();
  }
  ostate->PopFramebufferBindings();
  if (!done ||
    !this->ReadyQuad(
      renWin, this->ResolveQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_RESOLVE", true)))
  {
    return false;
  }

  // The average into the target viewport, with the nearest depth of each pixel's samples.
  // Premultiplied "over" onto what lower layers drew, as the single-sample pass does.
  SetTargetWriteState(ostate, frame.X, frame.Y, width, height, frame.Composite, true);
  vtkShaderProgram* program = this->ResolveQuad.Quad->Program;
  const ScopedTextures textures(program,
    { { "source", this->AccumulationTexture }, { "samplesColor", this->SamplesColorTexture },
      { "samplesDepth", this->SamplesDepthTexture } });
  program->SetUniformi("numberOfSamples", samples);
  // Where a pixel's samples differ, half the method's average and half the plain average (see
  // vtkAntialiasingSamplesFS.glsl); the plain image of DebugSample and the method's debug
  // images (MLAA's edges, weights) as they are.
  const bool debugImage = debug || !this->DrawsDeferredOverlays();
  program->SetUniformf("resolveWeight", debugImage ? 0.0f : 0.5f);
  this->ResolveQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::ReleaseSampleResources(vtkWindow* w)
{
  DeleteObject(this->SamplesFramebuffer, w);
  DeleteObject(this->SampleFramebuffer, w);
  for (vtkTextureObject** texture : { &this->SamplesColorTexture, &this->SamplesDepthTexture,
         &this->SampleTexture, &this->AccumulationTexture })
  {
    DeleteObject(*texture, w);
  }
  this->SampleCopyQuad.Release(w);
  this->AccumulateQuad.Release(w);
  this->ResolveQuad.Release(w);
}
