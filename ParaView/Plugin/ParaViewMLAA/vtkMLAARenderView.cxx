// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAARenderView.h"

#include "vtkDLAAOptions.h"
#include "vtkImageProcessingPass.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPVRenderViewSettings.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtk_glew.h"
#include "vtkMLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkProcessModule.h"
#include "vtkSynchronizedRenderers.h"
#include "vtkRenderWindow.h"

vtkStandardNewMacro(vtkMLAARenderView);

namespace
{
// Under IceT, and on a pvserver rendering for its client, the image-processing pass reads the
// image over a transparent black background; ParaView puts the background colour under it only
// when the image is shown (after compositing, or on the client). The
// antialiasing would then find (and blend) edges against black rather than against the
// background the user sees: the measured DLAA result on two ranks differed from one rank's by
// up to 34/255 at the silhouettes. This stage renders its delegate (the camera and IceT passes)
// and then draws the renderer's background colour under that image ("under" blending: the
// destination keeps its colour where it is opaque), so the antialiasing pass reads the image
// that is shown. Solid backgrounds only (vtkMLAARenderView::GetSolidBackground): a gradient,
// texture or sky box is left as it is.
class vtkMLAABackgroundUnderPass : public vtkRenderPass
{
public:
  static vtkMLAABackgroundUnderPass* New();
  vtkTypeMacro(vtkMLAABackgroundUnderPass, vtkRenderPass);

  vtkSmartPointer<vtkRenderPass> Delegate;
  double Background[3] = { 0.0, 0.0, 0.0 }; // the colour to put under the image

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (!this->Delegate)
    {
      return;
    }
    this->Delegate->Render(s);
    this->NumberOfRenderedProps = this->Delegate->GetNumberOfRenderedProps();
    vtkRenderer* renderer = s->GetRenderer();
    auto* window = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
    if (!window || renderer->GetSelector())
    {
      return;
    }
    if (!this->Quad)
    {
      this->Quad = new vtkOpenGLQuadHelper(window, nullptr,
        "//VTK::System::Dec\n"
        "//VTK::Output::Dec\n"
        "in vec2 texCoord; // unused, but the quad helper binds it\n"
        "uniform vec3 background;\n"
        "void main() { gl_FragData[0] = vec4(background, step(-1.0, texCoord.x)); }\n",
        "");
    }
    else
    {
      window->GetShaderCache()->ReadyShaderProgram(this->Quad->Program);
    }
    if (!this->Quad->Program || !this->Quad->Program->GetCompiled())
    {
      vtkErrorMacro("Could not build the background shader.");
      return;
    }
    const float background[3] = { static_cast<float>(this->Background[0]),
      static_cast<float>(this->Background[1]), static_cast<float>(this->Background[2]) };
    this->Quad->Program->SetUniform3f("background", background);
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    // The whole of the renderer's viewport, set here: the camera pass that ParaView puts before
    // IceT restores, on its way out, whatever viewport was current when it started, which need
    // not be the renderer's (a square 300 x 300 in a 400 x 300 view was measured). The quad then
    // covered part of the image only, the antialiasing read transparent black beyond it, and
    // DLAA on two ranks differed from one rank by up to 39/255 at the edges near that border.
    // (When the antialiasing pass renders its delegate into a framebuffer object of its own,
    // that object is the target, whole.)
    int size[2] = { 0, 0 }, origin[2] = { 0, 0 };
    if (s->GetFrameBuffer())
    {
      s->GetWindowSize(size);
    }
    else
    {
      renderer->GetTiledSizeAndOrigin(&size[0], &size[1], &origin[0], &origin[1]);
    }
    state->vtkglViewport(origin[0], origin[1], size[0], size[1]);
    state->vtkglScissor(origin[0], origin[1], size[0], size[1]);
    state->vtkglEnable(GL_BLEND);
    state->vtkglBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    this->Quad->Render();
  }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    if (this->Quad)
    {
      this->Quad->ReleaseGraphicsResources(window);
      delete this->Quad;
      this->Quad = nullptr;
    }
    if (this->Delegate)
    {
      this->Delegate->ReleaseGraphicsResources(window);
    }
  }

protected:
  vtkMLAABackgroundUnderPass() = default;
  ~vtkMLAABackgroundUnderPass() override { delete this->Quad; }

private:
  vtkOpenGLQuadHelper* Quad = nullptr;
};
vtkStandardNewMacro(vtkMLAABackgroundUnderPass);


// Whether this process renders the view over transparent black, for the background to be put
// under the image later: the server processes' synchronizers do so (FixBackground) under IceT
// (several ranks) and, in client-server, for the client (which blends the image it receives
// over the background).
bool RendersOverFixedBackground(vtkPVSynchronizedRenderer* renderers)
{
  if (vtkProcessModule::GetProcessType() == vtkProcessModule::PROCESS_CLIENT)
  {
    return false;
  }
  for (vtkSynchronizedRenderers* synchronizer :
    { renderers->GetParallelSynchronizer(), renderers->GetCSSynchronizer() })
  {
    if (synchronizer && synchronizer->GetFixBackground())
    {
      return true;
    }
  }
  return false;
}
}

// What the view puts into the image-processing slot: the MLAA or DLAA pass, whose delegate is
// the slot's delegate (the camera pass that ParaView or IceT gives it), with the background
// put under the image first where the process renders over transparent black (see
// vtkMLAABackgroundUnderPass).
// The wiring is made at every render, since ParaView sets the slot's delegate again whenever
// the slot is set (after every selection, for one).
class vtkMLAARenderView::vtkSlotPass : public vtkImageProcessingPass
{
public:
  static vtkSlotPass* New();
  vtkTypeMacro(vtkSlotPass, vtkImageProcessingPass);

  vtkSmartPointer<vtkImageProcessingPass> Antialiasing;
  vtkMLAARenderView* View = nullptr; // the view that owns this pass

  void Render(const vtkRenderState* s) override
  {
    this->NumberOfRenderedProps = 0;
    if (!this->Antialiasing || !this->DelegatePass)
    {
      return;
    }
    if (RendersOverFixedBackground(this->View->SynchronizedRenderers) &&
      this->View->GetSolidBackground(this->Under->Background))
    {
      this->Under->Delegate = this->DelegatePass;
      this->Antialiasing->SetDelegatePass(this->Under);
    }
    else
    {
      this->Antialiasing->SetDelegatePass(this->DelegatePass);
    }
    this->Antialiasing->Render(s);
    this->NumberOfRenderedProps = this->Antialiasing->GetNumberOfRenderedProps();
  }

  void ReleaseGraphicsResources(vtkWindow* window) override
  {
    this->Superclass::ReleaseGraphicsResources(window);
    this->Under->ReleaseGraphicsResources(window);
    if (this->Antialiasing)
    {
      this->Antialiasing->ReleaseGraphicsResources(window);
    }
  }

protected:
  vtkSlotPass() = default;
  ~vtkSlotPass() override = default;

private:
  vtkNew<vtkMLAABackgroundUnderPass> Under;
};
vtkStandardNewMacro(vtkMLAARenderView::vtkSlotPass);

//------------------------------------------------------------------------------
vtkMLAARenderView::vtkMLAARenderView()
{
  this->SlotPass->View = this;
  this->RequestedFXAA = this->UseFXAA;
  this->RequestedToneMapping = this->UseToneMapping;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
vtkMLAARenderView::~vtkMLAARenderView()
{
  // The renderer releases its pass's resources when it leaves the window, in vtkPVRenderView's
  // destructor; the passes leave the renderer first (below), so they release them themselves.
  if (vtkRenderWindow* window = this->GetRenderWindow())
  {
    this->SlotPass->ReleaseGraphicsResources(window);
    this->MLAAPass->ReleaseGraphicsResources(window);
    this->DLAAPass->ReleaseGraphicsResources(window);
  }
  if (this->SynchronizedRenderers && this->UsesOwnPass())
  {
    this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseMLAA(bool use)
{
  if (use != this->UseMLAA)
  {
    this->UseMLAA = use;
    this->Modified();
    this->UpdatePasses();
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseDLAA(bool use)
{
  if (use != this->UseDLAA)
  {
    this->UseDLAA = use;
    this->Modified();
    this->UpdatePasses();
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetDLAAOptions(vtkDLAAOptions* options)
{
  this->DLAAPass->SetOptions(options);
}

//------------------------------------------------------------------------------
vtkDLAAOptions* vtkMLAARenderView::GetDLAAOptions()
{
  return this->DLAAPass->GetOptions();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetBackgroundColorMode(int mode)
{
  this->Superclass::SetBackgroundColorMode(mode);
  this->BackgroundMode = mode;
}

//------------------------------------------------------------------------------
bool vtkMLAARenderView::GetSolidBackground(double colour[3])
{
  // The background as vtkPVRenderView::UpdateBackground chooses it (the renderer's own colour is
  // black while IceT composites).
  int mode = this->BackgroundMode;
  this->GetBackground(colour);
  if (this->GetUseRenderViewSettingsForBackground())
  {
    vtkPVRenderViewSettings* settings = vtkPVRenderViewSettings::GetInstance();
    mode = settings->GetBackgroundColorMode();
    settings->GetBackgroundColor(colour);
  }
  return mode == vtkPVRenderView::DEFAULT;
}

//------------------------------------------------------------------------------
bool vtkMLAARenderView::UsesOwnPass()
{
  return this->SynchronizedRenderers->GetImageProcessingPass() == this->SlotPass.GetPointer();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetMLAAOptions(vtkMLAAOptions* options)
{
  this->MLAAPass->SetOptions(options);
}

//------------------------------------------------------------------------------
vtkMLAAOptions* vtkMLAARenderView::GetMLAAOptions()
{
  return this->MLAAPass->GetOptions();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseFXAA(bool use)
{
  this->RequestedFXAA = use;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetUseToneMapping(bool use)
{
  this->RequestedToneMapping = use;
  this->UpdatePasses();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::UpdatePasses()
{
  vtkImageProcessingPass* pass = this->UseMLAA
    ? static_cast<vtkImageProcessingPass*>(this->MLAAPass)
    : (this->UseDLAA ? static_cast<vtkImageProcessingPass*>(this->DLAAPass) : nullptr);
  if (pass)
  {
    this->SlotPass->Antialiasing = pass;
    // The tone-mapping pass leaves the slot first (vtkPVRenderView only removes its own pass).
    this->Superclass::SetUseToneMapping(false);
    this->SynchronizedRenderers->SetImageProcessingPass(this->SlotPass);
  }
  else
  {
    if (this->UsesOwnPass())
    {
      this->SynchronizedRenderers->SetImageProcessingPass(nullptr);
    }
    this->Superclass::SetUseToneMapping(this->RequestedToneMapping);
  }
  // vtkPVRenderView reads UseFXAA at every render.
  this->Superclass::SetUseFXAA(this->RequestedFXAA && !pass);
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "UseMLAA: " << (this->UseMLAA ? "On" : "Off") << "\n";
  os << indent << "UseDLAA: " << (this->UseDLAA ? "On" : "Off") << "\n";
  os << indent << "RequestedFXAA: " << (this->RequestedFXAA ? "On" : "Off") << "\n";
  os << indent << "RequestedToneMapping: " << (this->RequestedToneMapping ? "On" : "Off") << "\n";
  os << indent << "MLAAPass:\n";
  this->MLAAPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "DLAAPass:\n";
  this->DLAAPass->PrintSelf(os, indent.GetNextIndent());
}
