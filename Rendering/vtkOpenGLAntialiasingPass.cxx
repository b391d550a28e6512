// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLAntialiasingPass.h"

#include "vtkDualDepthPeelingPass.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLAntialiasingPassInternals.h"
#include "vtkOpenGLAntialiasingPassSamples.h"
#include "vtkOpenGLAntialiasingPassTemporal.h"
#include "vtkOpenGLError.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkOrderIndependentTranslucentPass.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVersionMacros.h"

#include "vtkAntialiasingAlphaFS.h"
#include "vtkAntialiasingSamplesDiffer.h"

#include "vtkAntialiasingOpenGL.h" // For GL enums, and the calls VTK has no wrapper for

#include <algorithm>
#include <cstdlib>

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


namespace
{
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
}

vtkOpenGLAntialiasingPass::vtkOpenGLAntialiasingPass()
  : Histories(new TemporalHistories(this))
  , Samples(new SampleTargets(this))
{
}

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
    vtkShaderProgram::Substitute(
      source, "//VTK::Antialiasing::SamplesDiffer", vtkAntialiasingSamplesDiffer, false);
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
  // multisampled targets; with Temporal on too, the history blends their antialiased resolve.
  const bool temporal = this->Temporal && this->DrawsDeferredOverlays();
  const int chosenSamples = this->Samples->Choose(renWin, frame.FloatColor);
  int samples = chosenSamples;
  this->RenderedSampleShading = false;
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

    if (temporal)
    {
      // Whether the history is kept, and the camera jittered for a still accumulation (put back
      // by EndJitter below). The renders of a still accumulation and a converged still render
      // one sample per pixel: their jittered renders average to the supersampled picture, which
      // the spread of a multisampled render's samples would blur.
      this->Histories->BeginFrame(s, frame);
      if (!this->Histories->RendersMethodFrame())
      {
        samples = 0;
      }
    }
    this->RenderedMultiSamples = samples;
    this->PrepareTargets(frame, !frame.InPlace);
    if (chosenSamples)
    {
      // Also while a temporal still renders one sample per pixel: the next moving render uses
      // them again.
      this->Samples->Prepare(frame, chosenSamples);
    }
    else
    {
      this->Samples->Release(renWin); // not used (any more)
    }
    if (!temporal && !this->Histories->Empty())
    {
      // Temporal switched off: its histories would hold about 16 times the frame for nothing.
      this->Histories->Release(renWin);
    }

    // Render the delegate, keeping its overlay step for after the antialiasing.
    if (overlay)
    {
      steps->SetOverlayPass(nullptr);
    }
    const StepsChange stepsChange =
      steps ? this->UseRendererTranslucency(s, steps, frame.Composite, samples > 0) : StepsChange();
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
        this->RenderedSampleShading = this->Samples->RenderDelegate(s, frame);
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
      this->Histories->EndJitter(s);
    }
    this->RestoreDelegateSteps(stepsChange);
    if (overlay)
    {
      steps->SetOverlayPass(overlay);
    }

    TimedStage methodStage(renWin, "antialiasing");
    done = temporal   ? this->Histories->Antialias(frame, samples)
      : samples       ? this->Samples->Antialias(frame, samples)
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
  this->Histories->Release(w);
  this->Samples->Release(w);
  this->Samples->ForgetContext(); // the next context may offer other sample counts
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::GetTargetMemorySize()
{
  const int colorBytes =
    (this->ColorTexture && this->ColorTexture->GetVTKDataType() == VTK_FLOAT) ? 16 : 4;
  return TextureBytes(this->ColorTexture, colorBytes) + TextureBytes(this->DepthTexture, 4) +
    TextureBytes(this->AlphaTexture, colorBytes / 4) + this->GetMethodTargetMemorySize() +
    this->Histories->TargetBytes(colorBytes) + this->Samples->TargetBytes(colorBytes);
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
  this->Histories->Reset();
}

//------------------------------------------------------------------------------
int vtkOpenGLAntialiasingPass::GetAccumulatedFrames() const
{
  return this->Histories->GetAccumulatedFrames();
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
