// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOpenGLAntialiasingPassSamples.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLAntialiasingPassInternals.h"
#include "vtkOpenGLFramebufferObject.h"
#include "vtkOpenGLQuadHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLState.h"
#include "vtkProp.h"
#include "vtkRenderState.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkVolume.h"

#include "vtkAntialiasingSamplesFS.h"

#include "vtkAntialiasingOpenGL.h" // For GL enums, and the calls VTK has no wrapper for

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

using namespace vtkOpenGLAntialiasingPassInternals;

namespace
{
// The sample counts the driver offers for multisampled textures of every format in `formats`,
// largest first.
std::vector<int> QuerySampleCounts(vtkOpenGLRenderWindow* renWin,
  std::initializer_list<unsigned int> formats)
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
        counts.erase(
          std::remove_if(counts.begin(),
            counts.end(),
            [&](int c) { return std::find(offered.begin(), offered.end(), c) == offered.end(); }),
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
  counts.erase(
    std::remove_if(counts.begin(), counts.end(), [](int c) { return c < 2; }), counts.end());
  std::sort(counts.rbegin(), counts.rend());
  return counts;
}

// Whether a render blends something per pixel, not per sample, into a multisampled target:
// translucent geometry (order-independent translucency composites one colour per pixel) or
// volumes (drawn by their own mappers' passes).
bool BlendsPerPixel(const vtkRenderState* s)
{
  return AnyProp(s,
    [](vtkProp* prop)
    { return prop->HasTranslucentPolygonalGeometry() || vtkVolume::SafeDownCast(prop); });
}

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
int vtkOpenGLAntialiasingPass::SampleTargets::Choose(vtkOpenGLRenderWindow* renWin, bool floatColor)
{
  const int wanted = this->Pass->MultiSamples;
  if (wanted < 2)
  {
    return 0;
  }
  std::vector<int>& counts = this->SupportedCounts[floatColor ? 1 : 0];
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
      vtkWarningWithObjectMacro(this->Pass,
        "MultiSamples " << wanted << ": the OpenGL driver offers " << offered
                        << " samples per pixel for the pass's targets; using " << chosen << ".");
    }
    else
    {
      vtkWarningWithObjectMacro(this->Pass,
        "MultiSamples " << wanted
                        << ": the OpenGL driver offers no multisampled targets; "
                           "rendering one sample per pixel.");
    }
  }
  return chosen;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::SampleTargets::Prepare(const Frame& frame, int samples)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  const int colorType = frame.ColorType();
  for (vtkTextureObject** texture : { &this->SamplesColorTexture,
         &this->SamplesDepthTexture,
         &this->SampleTexture,
         &this->AccumulationTexture })
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
  reallocated |=
    AllocateColorTarget(this->SamplesColorTexture, frame.Width, frame.Height, 4, colorType, false);
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
bool vtkOpenGLAntialiasingPass::SampleTargets::RenderDelegate(const vtkRenderState* s,
  const Frame& frame)
{
  vtkOpenGLRenderWindow* renWin = frame.Window;
  vtkOpenGLState* ostate = renWin->GetState();
  // Rasterised per sample: GL_MULTISAMPLE is on in a new context, but a window without samples may
  // have it off.
  vtkOpenGLState::ScopedglEnableDisable multisampleSaver(ostate, GL_MULTISAMPLE);
  ostate->vtkglEnable(GL_MULTISAMPLE);
  const SampleShadingScope shading(this->UsesSampleShading(renWin));
  this->Pass->RenderDelegateToTextures(s,
    this->SamplesFramebuffer,
    this->SamplesColorTexture,
    this->SamplesDepthTexture,
    frame.Width,
    frame.Height,
    frame.Composite);
  this->Shaded = shading.On && !BlendsPerPixel(s);
  return shading.On;
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::SampleTargets::CopySample(vtkOpenGLRenderWindow* renWin,
  int sample,
  int samples,
  int width,
  int height)
{
  vtkOpenGLAntialiasingPass* pass = this->Pass;
  vtkOpenGLState* ostate = renWin->GetState();
  vtkOpenGLFramebufferObject* fbo = pass->DelegateFramebuffer;
  fbo->Bind();
  fbo->AddColorAttachment(0, pass->ColorTexture);
  fbo->ActivateDrawBuffer(0);
  fbo->AddDepthAttachment(pass->DepthTexture);
  // No blending; the sample's depth is copied.
  SetTargetWriteState(ostate, 0, 0, width, height, false, true);
  const bool plain = sample < 0;
  ShaderVariant& quad = plain ? this->PlainQuad : this->SampleCopyQuad;
  if (!pass->ReadyQuad(renWin, quad, vtkAntialiasingSamplesFS,
        Define(plain ? "SAMPLES_PLAIN" : "SAMPLES_COPY", true)))
  {
    return false;
  }
  vtkShaderProgram* program = quad.Quad->Program;
  const ScopedTextures textures(program,
    { { "samplesColor", this->SamplesColorTexture },
      { "samplesDepth", this->SamplesDepthTexture } });
  if (plain)
  {
    program->SetUniformi("numberOfSamples", samples);
  }
  else
  {
    program->SetUniformi("sampleIndex", std::min(sample, samples - 1));
  }
  quad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::SampleTargets::ResolvePlain(const Frame& frame, int samples)
{
  vtkOpenGLState* ostate = frame.Window->GetState();
  ostate->PushFramebufferBindings();
  const bool done = this->CopySample(frame.Window, -1, samples, frame.Width, frame.Height);
  ostate->PopFramebufferBindings();
  return done;
}

//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::SampleTargets::Antialias(const Frame& frame, int samples)
{
  vtkOpenGLAntialiasingPass* pass = this->Pass;
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
  const bool debug = pass->DebugSample >= 0;
  const int first = debug ? std::min(pass->DebugSample, samples - 1) : 0;
  const int last = debug ? first + 1 : samples;

  ostate->PushFramebufferBindings();
  // The sample positions the driver uses, for the method (GetCurrentSampleSet): queried with
  // the multisampled framebuffer bound (glGetMultisamplefv, OpenGL 3.2: VTK has no wrapper).
  SampleSet set;
  set.Offsets.assign(2 * samples, 0.0);
  set.Colors = this->SamplesColorTexture;
  set.Shaded = this->Shaded;
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
    vtkTextureObject* result = pass->ColorTexture; // the plain sample image, for DebugSample
    if (done && !debug)
    {
      this->SampleFramebuffer->Bind();
      this->SampleFramebuffer->AddColorAttachment(0, this->SampleTexture);
      this->SampleFramebuffer->ActivateDrawBuffer(0);
      set.Index = sample;
      pass->CurrentSampleSet = set;
      done = pass->Antialias(sampleFrame);
      pass->CurrentSampleSet = SampleSet();
      result = this->SampleTexture;
    }
    // Accumulated: the sum of the sample images, each scaled by 1 / N.
    done = done &&
      pass->ReadyQuad(
        renWin, this->AccumulateQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_ACCUMULATE", true));
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
    !pass->ReadyQuad(
      renWin, this->ResolveQuad, vtkAntialiasingSamplesFS, Define("SAMPLES_RESOLVE", true)))
  {
    return false;
  }

  // The average into the target viewport, with the nearest depth of each pixel's samples.
  // Premultiplied "over" onto what lower layers drew, as the single-sample pass does.
  SetTargetWriteState(ostate, frame.X, frame.Y, width, height, frame.Composite, true);
  vtkShaderProgram* program = this->ResolveQuad.Quad->Program;
  const ScopedTextures textures(program,
    { { "source", this->AccumulationTexture },
      { "samplesColor", this->SamplesColorTexture },
      { "samplesDepth", this->SamplesDepthTexture } });
  program->SetUniformi("numberOfSamples", samples);
  // Where a pixel's samples differ, half the method's average and half the plain average (see
  // vtkAntialiasingSamplesFS.glsl); the plain image of DebugSample and the method's debug
  // images (MLAA's edges, weights) as they are.
  const bool debugImage = debug || !pass->DrawsDeferredOverlays();
  program->SetUniformf("resolveWeight", debugImage ? 0.0f : 0.5f);
  this->ResolveQuad.Quad->Render();
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::SampleTargets::Release(vtkWindow* w)
{
  DeleteObject(this->SamplesFramebuffer, w);
  DeleteObject(this->SampleFramebuffer, w);
  for (vtkTextureObject** texture : { &this->SamplesColorTexture,
         &this->SamplesDepthTexture,
         &this->SampleTexture,
         &this->AccumulationTexture })
  {
    DeleteObject(*texture, w);
  }
  this->SampleCopyQuad.Release(w);
  this->PlainQuad.Release(w);
  this->AccumulateQuad.Release(w);
  this->ResolveQuad.Release(w);
}

//------------------------------------------------------------------------------
//------------------------------------------------------------------------------
bool vtkOpenGLAntialiasingPass::SampleTargets::UsesSampleShading(vtkOpenGLRenderWindow* renWin)
{
  if (!this->Pass->SampleShading)
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
    vtkWarningWithObjectMacro(this->Pass,
      "SampleShading: the OpenGL context (" << major << "." << minor
                                            << ") has no sample shading (OpenGL "
                                               "4.0); the samples are shaded per "
                                               "pixel");
  }
  return false;
}

//------------------------------------------------------------------------------
void vtkOpenGLAntialiasingPass::SampleTargets::ForgetContext()
{
  this->SupportedCounts[0].clear();
  this->SupportedCounts[1].clear();
}

//------------------------------------------------------------------------------
vtkIdType vtkOpenGLAntialiasingPass::SampleTargets::TargetBytes(int colorBytes) const
{
  const int samples = this->SamplesColorTexture ? this->SamplesColorTexture->GetSamples() : 0;
  return TextureBytes(this->SamplesColorTexture, colorBytes * samples) +
    TextureBytes(this->SamplesDepthTexture, 4 * samples) +
    TextureBytes(this->SampleTexture, colorBytes) + TextureBytes(this->AccumulationTexture, 16);
}
