// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The multisampled rendering of vtkOpenGLAntialiasingPass (SetMultiSamples): the targets the
// delegate renders into, and the antialiasing of each sample set and their resolve. Private
// header.
#ifndef vtkOpenGLAntialiasingPassSamples_h
#define vtkOpenGLAntialiasingPassSamples_h

#include "vtkOpenGLAntialiasingPass.h"

#include <vector>

// The owner of the GL objects of multisampled renders: the multisampled colour and depth targets
// the delegate renders into, the image of one antialiased sample set, the accumulation of their
// average, the two framebuffer objects that bind them and the shaders of
// vtkAntialiasingSamplesFS.glsl. Prepare makes or resizes them, Release frees them (the pass calls
// it when a render uses no samples, when it releases its resources and when it is destroyed).
class vtkOpenGLAntialiasingPass::SampleTargets
{
public:
  explicit SampleTargets(vtkOpenGLAntialiasingPass* pass)
    : Pass(pass)
  {
  }
  ~SampleTargets() { this->Release(nullptr); }
  SampleTargets(const SampleTargets&) = delete;
  SampleTargets& operator=(const SampleTargets&) = delete;

  // The supported count nearest to the pass's MultiSamples (warning once when it differs), 0 for
  // none.
  int Choose(vtkOpenGLRenderWindow* renWin, bool floatColor);
  // Creates or resizes the multisampled targets and the sample and accumulation textures.
  void Prepare(const Frame& frame, int samples);
  // Renders the delegate into the multisampled targets (see RenderDelegateToTextures), every
  // sample shaded at its own position where SampleShading asks for it and the context has it;
  // returns whether it was.
  bool RenderDelegate(const vtkRenderState* s, const Frame& frame);
  // Copies each sample set into the pass's ColorTexture and DepthTexture, antialiases it with the
  // method (Antialias) into SampleTexture, accumulates the average and writes it with the nearest
  // depth into the target viewport (premultiplied "over" when compositing).
  bool Antialias(const Frame& frame, int samples);
  // Writes the plain average of each pixel's samples (multisampling's own resolve) into the
  // pass's ColorTexture and the nearest of their depths into its DepthTexture: the frame that
  // temporal antialiasing with samples blends and clamps to.
  bool ResolvePlain(const Frame& frame, int samples);
  // Frees the GL objects (only deletes them where `w` is null: their context is gone).
  void Release(vtkWindow* w);
  // Forgets the sample counts the context offered (the next context may offer others).
  void ForgetContext();
  // Bytes of the targets, colorBytes a texel of a colour target.
  vtkIdType TargetBytes(int colorBytes) const;

private:
  // Whether the multisampled render shades every sample: SampleShading, where the context has
  // it (warning once where it has not).
  bool UsesSampleShading(vtkOpenGLRenderWindow* renWin);
  // Copies sample `sample` of the multisampled targets into the pass's ColorTexture and
  // DepthTexture; with `sample` -1, the samples' plain average and nearest depth.
  bool CopySample(vtkOpenGLRenderWindow* renWin, int sample, int samples, int width, int height);

  vtkOpenGLAntialiasingPass* const Pass;                    // not held: the pass holds this
  vtkOpenGLFramebufferObject* SamplesFramebuffer = nullptr; // the delegate's, multisampled
  vtkOpenGLFramebufferObject* SampleFramebuffer = nullptr;  // one sample's result, accumulation
  vtkTextureObject* SamplesColorTexture = nullptr;
  vtkTextureObject* SamplesDepthTexture = nullptr;
  vtkTextureObject* SampleTexture = nullptr;       // one antialiased sample image
  vtkTextureObject* AccumulationTexture = nullptr; // the average of the antialiased samples
  ShaderVariant SampleCopyQuad, PlainQuad, AccumulateQuad, ResolveQuad;
  // Whether the last render's samples were all shaded on their own (SampleSet::Shaded).
  bool Shaded = false;
  bool WarnedSampleShading = false; // sample shading unavailable, said once
  int WarnedMultiSamples = 0;       // the count asked for that the last warning was about
  // The sample counts the driver offers for the colour and depth formats of the targets, largest
  // first, queried once per colour type (index 1: floating point) and context.
  std::vector<int> SupportedCounts[2];
};

#endif
