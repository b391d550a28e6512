// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAARenderView.h"

#include "vtkDLAAOptions.h"
#include "vtkImageProcessingPass.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkOpenGLState.h"
#include "vtkPVRenderViewSettings.h"
#include "vtkRenderState.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkSmartPointer.h"
#include "vtkAntialiasingOpenGL.h"
#include "vtkMLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPVSynchronizedRenderer.h"
#include "vtkProcessModule.h"
#include "vtkSynchronizedRenderers.h"
#include "vtkRenderWindow.h"

#include <algorithm>

vtkStandardNewMacro(vtkMLAARenderView);

namespace
{
// Under IceT, and on a pvserver rendering for its client, the image-processing pass reads the
// image over a transparent black background; ParaView puts the background under it only when
// the image is shown (after compositing, or on the client). The
// antialiasing would then find (and blend) edges against black rather than against the
// background the user sees: the measured DLAA result on two ranks differed from one rank's by
// up to 34/255 at the silhouettes. This stage renders its delegate (the camera and IceT passes)
// and then draws the view's background under that image ("under" blending: the destination
// keeps its colour where it is opaque), so the antialiasing pass reads the image that is shown.
// The background is a vertical gradient from Bottom (the first row) to Top (the last), as
// vtkOpenGLRenderer clears a gradient background; a single colour has Bottom equal to Top.
// Textures and sky boxes are not drawn here (vtkMLAARenderView::GetDrawableBackground).
class vtkMLAABackgroundUnderPass : public vtkRenderPass
{
public:
  static vtkMLAABackgroundUnderPass* New();
  vtkTypeMacro(vtkMLAABackgroundUnderPass, vtkRenderPass);

  vtkSmartPointer<vtkRenderPass> Delegate;
  double Bottom[3] = { 0.0, 0.0, 0.0 }; // the background's colour at the bottom of the image
  double Top[3] = { 0.0, 0.0, 0.0 };    // and at the top

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
        "in vec2 texCoord;\n"
        "uniform vec3 bottom;\n"
        "uniform vec3 top;\n"
        "void main() { gl_FragData[0] = vec4(mix(bottom, top, texCoord.y), 1.0); }\n",
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
    const float bottom[3] = { static_cast<float>(this->Bottom[0]),
      static_cast<float>(this->Bottom[1]), static_cast<float>(this->Bottom[2]) };
    const float top[3] = { static_cast<float>(this->Top[0]), static_cast<float>(this->Top[1]),
      static_cast<float>(this->Top[2]) };
    this->Quad->Program->SetUniform3f("bottom", bottom);
    this->Quad->Program->SetUniform3f("top", top);
    vtkOpenGLState* state = window->GetState();
    vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
    vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);
    vtkOpenGLState::ScopedglBlendFuncSeparate blendFuncSaver(state);
    vtkOpenGLState::ScopedglDepthMask depthMaskSaver(state);
    vtkOpenGLState::ScopedglViewport viewportSaver(state);
    vtkOpenGLState::ScopedglScissor scissorSaver(state);
    // The whole image: IceT leaves a viewport of its own (measured: the background went under
    // the first 300 columns of a 400 x 300 view only, which made an edge of the 301st column).
    // The image is the renderer's viewport in the window, or the whole of a framebuffer object
    // when the antialiasing pass renders its delegate into one.
    int x = 0, y = 0, width = 0, height = 0;
    if (vtkOpenGLFramebufferObject::SafeDownCast(s->GetFrameBuffer()))
    {
      int size[2];
      s->GetWindowSize(size);
      width = size[0];
      height = size[1];
    }
    else
    {
      renderer->GetTiledSizeAndOrigin(&width, &height, &x, &y);
    }
    state->vtkglViewport(x, y, width, height);
    state->vtkglScissor(x, y, width, height);
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
// put under the image first where the process renders over transparent black (IceT, or a
// pvserver rendering for its client: see vtkMLAABackgroundUnderPass); with a background that
// cannot be put there, the image is left as it is.
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
    const bool backgroundUnder = RendersOverFixedBackground(this->View->SynchronizedRenderers);
    if (backgroundUnder &&
      !this->View->GetDrawableBackground(this->Under->Bottom, this->Under->Top))
    {
      this->View->WarnUndrawableBackground();
      this->DelegatePass->Render(s);
      this->NumberOfRenderedProps = this->DelegatePass->GetNumberOfRenderedProps();
      return;
    }
    if (auto* pass = vtkOpenGLAntialiasingPass::SafeDownCast(this->Antialiasing))
    {
      pass->SetMultiSamples(this->View->GetRenderMultiSamples(backgroundUnder));
      pass->SetSampleShading(this->View->GetAntialiasingSampleShading());
    }
    if (backgroundUnder)
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
void vtkMLAARenderView::SetAntialiasingMethod(int method)
{
  if (method < FXAA_OR_NONE || method > DLAA)
  {
    vtkErrorMacro("SetAntialiasingMethod: " << method
                                            << " is not FXAA_OR_NONE (0), MLAA (1) or DLAA (2).");
    return;
  }
  if (method != this->AntialiasingMethod)
  {
    this->AntialiasingMethod = method;
    this->Modified();
    this->UpdatePasses();
  }
}

//------------------------------------------------------------------------------
int vtkMLAARenderView::GetEffectiveAntialiasingMethod()
{
  if (this->AntialiasingMethod != FXAA_OR_NONE)
  {
    return this->AntialiasingMethod;
  }
  return this->UseMLAA ? MLAA : (this->UseDLAA ? DLAA : FXAA_OR_NONE);
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetAntialiasingKeepAlpha(bool keep)
{
  this->MLAAPass->SetKeepAlpha(keep);
  this->DLAAPass->SetKeepAlpha(keep);
}

//------------------------------------------------------------------------------
bool vtkMLAARenderView::GetAntialiasingKeepAlpha()
{
  // Both passes are only set together, here.
  return this->MLAAPass->GetKeepAlpha() && this->DLAAPass->GetKeepAlpha();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetAntialiasingTemporal(bool temporal)
{
  this->MLAAPass->SetTemporal(temporal);
  this->DLAAPass->SetTemporal(temporal);
}

//------------------------------------------------------------------------------
bool vtkMLAARenderView::GetAntialiasingTemporal()
{
  return this->MLAAPass->GetTemporal() && this->DLAAPass->GetTemporal();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetAntialiasingConvergedFrames(int frames)
{
  this->MLAAPass->SetConvergedFrames(frames);
  this->DLAAPass->SetConvergedFrames(frames);
}

//------------------------------------------------------------------------------
int vtkMLAARenderView::GetAntialiasingConvergedFrames()
{
  return this->MLAAPass->GetConvergedFrames();
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::StillRender()
{
  // A fixed number of renders, not "until converged": every process (ranks, client and server)
  // must render as many times as the others.
  const int method = this->GetEffectiveAntialiasingMethod();
  const int renders = (method == MLAA || method == DLAA) && this->GetAntialiasingTemporal()
    ? this->GetAntialiasingConvergedFrames()
    : 1;
  for (int i = 0; i < renders; ++i)
  {
    this->Superclass::StillRender();
  }
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetAntialiasingMultiSamples(int samples)
{
  samples = std::max(0, std::min(samples, 16));
  if (samples != this->AntialiasingMultiSamples)
  {
    this->AntialiasingMultiSamples = samples;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkMLAARenderView::GetRenderMultiSamples(bool composited)
{
  if (!composited || this->AntialiasingMultiSamples < 2)
  {
    return this->AntialiasingMultiSamples;
  }
  if (!this->WarnedSingleSampleComposite)
  {
    this->WarnedSingleSampleComposite = true;
    vtkWarningMacro("AntialiasingMultiSamples " << this->AntialiasingMultiSamples
                                               << " is not applied: under parallel compositing "
                                                  "(IceT) or on a pvserver, MLAA and DLAA run "
                                                  "on the composited image, one sample per "
                                                  "pixel.");
  }
  return 0;
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::SetMLAALineLengths(int method)
{
  this->MLAAPass->SetLineLengths(method);
}

//------------------------------------------------------------------------------
int vtkMLAARenderView::GetMLAALineLengths()
{
  return this->MLAAPass->GetLineLengths();
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
bool vtkMLAARenderView::GetDrawableBackground(double bottom[3], double top[3])
{
  // The background as vtkPVRenderView::UpdateBackground chooses it (the renderer's own colour is
  // black while IceT composites).
  int mode = this->BackgroundMode;
  this->GetBackground(bottom);
  this->GetBackground2(top);
  if (this->GetUseRenderViewSettingsForBackground())
  {
    vtkPVRenderViewSettings* settings = vtkPVRenderViewSettings::GetInstance();
    mode = settings->GetBackgroundColorMode();
    settings->GetBackgroundColor(bottom);
    settings->GetBackground2Color(top);
  }
  if (mode == vtkPVRenderView::DEFAULT)
  {
    std::copy(bottom, bottom + 3, top);
    return true;
  }
  return mode == vtkPVRenderView::GRADIENT;
}

//------------------------------------------------------------------------------
void vtkMLAARenderView::WarnUndrawableBackground()
{
  int mode = this->GetUseRenderViewSettingsForBackground()
    ? vtkPVRenderViewSettings::GetInstance()->GetBackgroundColorMode()
    : this->BackgroundMode;
  if (mode != this->WarnedBackgroundMode)
  {
    this->WarnedBackgroundMode = mode;
    vtkWarningMacro("MLAA and DLAA are not applied: under parallel compositing (IceT) or on "
                    "a pvserver, the view cannot put a textured or sky-box background under "
                    "the rendered image, and antialiasing against black would blend wrong colours into the "
                    "silhouettes. Use a single-colour or gradient background, or "
                    "AntialiasingMethod 'None or FXAA'.");
  }
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
  const int method = this->GetEffectiveAntialiasingMethod();
  vtkImageProcessingPass* pass = method == MLAA
    ? static_cast<vtkImageProcessingPass*>(this->MLAAPass)
    : (method == DLAA ? static_cast<vtkImageProcessingPass*>(this->DLAAPass) : nullptr);
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
  os << indent << "AntialiasingMethod: " << this->AntialiasingMethod << "\n";
  os << indent << "UseMLAA: " << (this->UseMLAA ? "On" : "Off") << "\n";
  os << indent << "UseDLAA: " << (this->UseDLAA ? "On" : "Off") << "\n";
  os << indent << "AntialiasingMultiSamples: " << this->AntialiasingMultiSamples << "\n";
  os << indent << "AntialiasingSampleShading: " << this->AntialiasingSampleShading << "\n";
  os << indent << "RequestedFXAA: " << (this->RequestedFXAA ? "On" : "Off") << "\n";
  os << indent << "RequestedToneMapping: " << (this->RequestedToneMapping ? "On" : "Off") << "\n";
  os << indent << "MLAAPass:\n";
  this->MLAAPass->PrintSelf(os, indent.GetNextIndent());
  os << indent << "DLAAPass:\n";
  this->DLAAPass->PrintSelf(os, indent.GetNextIndent());
}
