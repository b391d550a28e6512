// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLAntialiasingPass.h"

#include "vtkDualDepthPeelingPass.h"
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
#include "vtkRenderState.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkTranslucentPass.h"
#include "vtkVersionMacros.h"

#include "vtkAntialiasingAlphaFS.h"
#include "vtkAntialiasingSamplesFS.h"

#include <algorithm>
#include <cstdlib>

#include "vtk_glew.h" // For GL enums only: every call goes through VTK's classes

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
vtkOpenGLAntialiasingPass::vtkOpenGLAntialiasingPass() = default;

//------------------------------------------------------------------------------
vtkOpenGLAntialiasingPass::~vtkOpenGLAntialiasingPass()
{
  if (this->HoldsSharedResources())
  {
    vtkErrorMacro("Graphics resources should have been released by "
                  "ReleaseGraphicsResources().");
  }
  // The translucent steps free their GL objects in ReleaseGraphicsResources (or report them).
  // The delegate's step sequence may hold the last one used until its next render.
  if (this->CompositedPass)
  {
    this->CompositedPass->Owner = nullptr;
  }
  for (vtkRenderPass* pass : { static_cast<vtkRenderPass*>(this->TranslucencyPass),
         static_cast<vtkRenderPass*>(this->PeelingPass),
         static_cast<vtkRenderPass*>(this->CompositedPass) })
  {
    if (pass)
    {
      pass->Delete();
    }
  }
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
  bool reallocated = AllocateColorTarget(this->ColorTexture, frame.Width, frame.Height, 4,
    frame.FloatColor ? VTK_FLOAT : VTK_UNSIGNED_CHAR, false);
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
  if (reallocated)
  {
    // Framebuffer objects remember their attachments: start afresh with the new textures.
    DeleteObject(this->DelegateFramebuffer, renWin);
    DeleteObject(this->WorkFramebuffer, renWin);
  }
  for (vtkOpenGLFramebufferObject** fbo : { &this->DelegateFramebuffer, &this->WorkFramebuffer })
  {
    if (!*fbo)
    {
      * fbo = vtkOpenGLFramebufferObject::New();
      (*fbo)->SetContext(renWin);
    }
  }
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
  bool hasTranslucent = false;
  for (int i = 0; !hasTranslucent && i < s->GetPropArrayCount(); ++i)
  {
    hasTranslucent = s->GetPropArray()[i]->HasTranslucentPolygonalGeometry() != 0;
  }
  if (!hasTranslucent)
  {
    return change; // the renderer skips the translucent step (volumes stay in their own)
  }
  // Depth peeling copies the framebuffer's depth (and colour) with glCopyTexSubImage2D, which a
  // multisampled framebuffer does not allow: a multisampled render (MultiSamples) uses
  // order-independent translucency, which blits the depth (a resolve) instead.
  const bool peeling = renderer->GetUseDepthPeeling() != 0 && !multisampled;
  const bool dual = peeling && renderer->IsDualDepthPeelingSupported();
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
    this->ColorTexture->Activate();
    this->KeepAlphaQuad.Quad->Program->SetUniformi(
      "source", this->ColorTexture->GetTextureUnit());
    this->KeepAlphaQuad.Quad->Render();
    this->ColorTexture->Deactivate();
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
  this->AlphaTexture->Activate();
  this->RestoreAlphaQuad.Quad->Program->SetUniformi(
    "source", this->AlphaTexture->GetTextureUnit());
  this->RestoreAlphaQuad.Quad->Render();
  this->AlphaTexture->Deactivate();

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
bool vtkOpenGLAntialiasingPass::ReadyQuad(
  vtkOpenGLRenderWindow* renWin, ShaderVariant& variant, const char* fs, const std::string& defines)
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
    quad = new vtkOpenGLQuadHelper(renWin, nullptr, source.c_str(), "");
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
  // A multisampled render (SetMultiSamples) renders the delegate into the multisampled targets.
  const int samples = this->ChooseMultiSamples(renWin, frame.FloatColor);
  this->RenderedMultiSamples = samples;
  frame.InPlace = !frame.Composite && !this->NeedsDelegateDepth() && !samples;
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

    // Render the delegate, keeping its overlay step for after the antialiasing.
    if (overlay)
    {
      steps->SetOverlayPass(nullptr);
    }
    const StepsChange stepsChange =
      steps ? this->UseRendererTranslucency(s, steps, frame.Composite, samples > 0) : StepsChange();
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
        this->RenderDelegateToTextures(s, this->SamplesFramebuffer, this->SamplesColorTexture,
          this->SamplesDepthTexture, frame.Width, frame.Height, frame.Composite);
      }
      else
      {
        this->RenderDelegateToTextures(s, this->DelegateFramebuffer, this->ColorTexture,
          this->DepthTexture, frame.Width, frame.Height, frame.Composite);
      }
      ostate->PopFramebufferBindings();
    }
    this->RestoreDelegateSteps(stepsChange);
    if (overlay)
    {
      steps->SetOverlayPass(overlay);
    }

    done = samples ? this->AntialiasSamples(frame, samples) : this->Antialias(frame);
  }

  // The overlays: drawn on top of the result, in the state the pass was entered with, in the
  // renderer's viewport, as the render steps would have drawn them.
  if (done && overlay && this->DrawsDeferredOverlays())
  {
    ostate->vtkglViewport(frame.X, frame.Y, frame.Width, frame.Height);
    ostate->vtkglScissor(frame.X, frame.Y, frame.Width, frame.Height);
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
  return TextureBytes(this->ColorTexture, colorBytes) + TextureBytes(this->DepthTexture, 4) +
    TextureBytes(this->AlphaTexture, colorBytes / 4) + this->GetMethodTargetMemorySize() +
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
  os << indent << "MultiSamples: " << this->MultiSamples << "\n";
  os << indent << "RenderedMultiSamples: " << this->RenderedMultiSamples << "\n";
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
  fbo->ActivateDrawBuffer(0);
  fbo->StartNonOrtho(width, height);
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
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
  const int colorType = frame.FloatColor ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
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
  if (reallocated)
  {
    DeleteObject(this->SamplesFramebuffer, renWin);
    DeleteObject(this->SampleFramebuffer, renWin);
  }
  for (vtkOpenGLFramebufferObject** fbo : { &this->SamplesFramebuffer, &this->SampleFramebuffer })
  {
    if (!*fbo)
    {
      *fbo = vtkOpenGLFramebufferObject::New();
      (*fbo)->SetContext(renWin);
    }
  }
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
  ostate->vtkglViewport(0, 0, width, height);
  ostate->vtkglScissor(0, 0, width, height);
  ostate->vtkglDisable(GL_BLEND);
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  // Depth writes need the depth test on; ALWAYS copies the sample's depth.
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  if (!this->ReadyQuad(
        renWin, this->SampleCopyQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_COPY", true)))
  {
    return false;
  }
  vtkShaderProgram* program = this->SampleCopyQuad.Quad->Program;
  this->SamplesColorTexture->Activate();
  this->SamplesDepthTexture->Activate();
  program->SetUniformi("samplesColor", this->SamplesColorTexture->GetTextureUnit());
  program->SetUniformi("samplesDepth", this->SamplesDepthTexture->GetTextureUnit());
  program->SetUniformi("sampleIndex", std::min(sample, samples - 1));
  this->SampleCopyQuad.Quad->Render();
  this->SamplesDepthTexture->Deactivate();
  this->SamplesColorTexture->Deactivate();
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
      done = this->Antialias(sampleFrame);
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
    result->Activate();
    program->SetUniformi("source", result->GetTextureUnit());
    program->SetUniformf("scale", 1.0f / static_cast<float>(last - first));
    this->AccumulateQuad.Quad->Render();
    result->Deactivate();
  }
  ostate->PopFramebufferBindings();
  if (!done ||
    !this->ReadyQuad(
      renWin, this->ResolveQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_RESOLVE", true)))
  {
    return false;
  }

  // The average into the target viewport, with the nearest depth of each pixel's samples.
  ostate->vtkglViewport(frame.X, frame.Y, width, height);
  ostate->vtkglScissor(frame.X, frame.Y, width, height);
  if (frame.Composite)
  {
    // Premultiplied "over" onto what lower layers drew, as the single-sample pass does.
    ostate->vtkglEnable(GL_BLEND);
    ostate->vtkglBlendFuncSeparate(GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  else
  {
    ostate->vtkglDisable(GL_BLEND);
  }
  ostate->vtkglColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  ostate->vtkglEnable(GL_DEPTH_TEST);
  ostate->vtkglDepthFunc(GL_ALWAYS);
  ostate->vtkglDepthMask(GL_TRUE);
  vtkShaderProgram* program = this->ResolveQuad.Quad->Program;
  this->AccumulationTexture->Activate();
  this->SamplesColorTexture->Activate();
  this->SamplesDepthTexture->Activate();
  program->SetUniformi("source", this->AccumulationTexture->GetTextureUnit());
  program->SetUniformi("samplesColor", this->SamplesColorTexture->GetTextureUnit());
  program->SetUniformi("samplesDepth", this->SamplesDepthTexture->GetTextureUnit());
  program->SetUniformi("numberOfSamples", samples);
  // Where a pixel's samples differ, half the method's average and half the plain average (see
  // vtkAntialiasingSamplesFS.glsl); the plain image of DebugSample and the method's debug
  // images (MLAA's edges, weights) as they are.
  const bool debugImage = debug || !this->DrawsDeferredOverlays();
  program->SetUniformf("resolveWeight", debugImage ? 0.0f : 0.5f);
  this->ResolveQuad.Quad->Render();
  this->SamplesDepthTexture->Deactivate();
  this->SamplesColorTexture->Deactivate();
  this->AccumulationTexture->Deactivate();
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
