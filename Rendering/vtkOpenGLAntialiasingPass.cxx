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
void vtkOpenGLAntialiasingPass::RenderDelegateToTextures(
  const vtkRenderState* s, int width, int height, bool composite)
{
  vtkOpenGLState* ostate = this->DelegateFramebuffer->GetContext()->GetState();
  vtkRenderState delegateState(s->GetRenderer());
  delegateState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  delegateState.SetRequiredKeys(s->GetRequiredKeys());
  delegateState.SetFrameBuffer(this->DelegateFramebuffer);

  this->DelegateFramebuffer->Bind();
  this->DelegateFramebuffer->AddColorAttachment(0, this->ColorTexture);
  this->DelegateFramebuffer->ActivateDrawBuffer(0);
  this->DelegateFramebuffer->AddDepthAttachment(this->DepthTexture);
  this->DelegateFramebuffer->StartNonOrtho(width, height);
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
  const vtkRenderState* s, vtkRenderStepsPass* steps, bool composite)
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
  const bool peeling = renderer->GetUseDepthPeeling() != 0;
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
    if (composite)
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
  frame.InPlace = !frame.Composite && !this->NeedsDelegateDepth();
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

    // Render the delegate, keeping its overlay step for after the antialiasing.
    if (overlay)
    {
      steps->SetOverlayPass(nullptr);
    }
    const StepsChange stepsChange =
      steps ? this->UseRendererTranslucency(s, steps, frame.Composite) : StepsChange();
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
      this->RenderDelegateToTextures(s, frame.Width, frame.Height, frame.Composite);
      ostate->PopFramebufferBindings();
    }
    this->RestoreDelegateSteps(stepsChange);
    if (overlay)
    {
      steps->SetOverlayPass(overlay);
    }

    done = this->Antialias(frame);
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
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::GetTargetMemorySize()
{
  const int colorBytes =
    (this->ColorTexture && this->ColorTexture->GetVTKDataType() == VTK_FLOAT) ? 16 : 4;
  return TextureBytes(this->ColorTexture, colorBytes) + TextureBytes(this->DepthTexture, 4) +
    TextureBytes(this->AlphaTexture, colorBytes / 4) + this->GetMethodTargetMemorySize();
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AntialiasOverlays: " << (this->AntialiasOverlays ? "On" : "Off") << "\n";
  os << indent << "KeepAlpha: " << (this->KeepAlpha ? "On" : "Off") << "\n";
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
