//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// Antialiasing of a multisampled render (vtkOpenGLAntialiasingPass::SetMultiSamples), the idea
// of SMAA's S2x mode (Jimenez et al., "SMAA: Enhanced Subpixel Morphological Antialiasing",
// 2012): the delegate renders into an N-sample target; each sample set (sample s of every pixel,
// an image of the scene shifted by that sample's sub-pixel position) is copied into the
// single-sample textures that the method's passes read, antialiased by them unchanged, and
// accumulated; the N antialiased images are averaged, as a multisample resolve averages the
// samples (the values as stored, no conversion: what MSAA's resolve and the supersampled
// reference of MEASURING.md average).
//
// Compile-time variants (#defines prepended by vtkOpenGLAntialiasingPass):
//   SAMPLES_COPY        writes sample `sampleIndex` of `samplesColor` and its depth (of
//                       `samplesDepth`) unchanged: the image the method's passes read;
//   SAMPLES_ACCUMULATE  writes `source` (one antialiased sample image) scaled by `scale` (1 / N),
//                       added to the accumulation target by blending (one, one);
//   SAMPLES_RESOLVE     writes `source` (the accumulated average) and, as depth, the nearest of
//                       the pixel's samples in `samplesDepth`, into the renderer's viewport.
// Exact texel reads.

in vec2 texCoord; // over the viewport, which is the size of the textures

#if defined(SAMPLES_COPY) || defined(SAMPLES_RESOLVE)
uniform sampler2DMS samplesDepth;
#endif
#ifdef SAMPLES_RESOLVE
uniform int numberOfSamples;
#endif
#ifdef SAMPLES_COPY
uniform sampler2DMS samplesColor;
uniform int sampleIndex;
#else
uniform sampler2D source;
#endif
#ifdef SAMPLES_ACCUMULATE
uniform float scale;
#endif

void main()
{
#ifdef SAMPLES_COPY
  ivec2 p = ivec2(texCoord * vec2(textureSize(samplesColor)));
  gl_FragData[0] = texelFetch(samplesColor, p, sampleIndex);
  gl_FragDepth = texelFetch(samplesDepth, p, sampleIndex).r;
#else
  ivec2 p = ivec2(texCoord * vec2(textureSize(source, 0)));
  vec4 c = texelFetch(source, p, 0);
#ifdef SAMPLES_ACCUMULATE
  gl_FragData[0] = c * scale;
#else
  gl_FragData[0] = c;
  float depth = 1.0;
  for (int s = 0; s < numberOfSamples; ++s)
  {
    depth = min(depth, texelFetch(samplesDepth, p, s).r);
  }
  gl_FragDepth = depth;
#endif
#endif
}
