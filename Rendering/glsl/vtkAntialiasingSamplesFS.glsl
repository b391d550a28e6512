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
//   SAMPLES_PLAIN       writes the plain average of the pixel's samples of `samplesColor` and the
//                       nearest of their depths: the multisampled render as multisampling
//                       resolves it, which temporal antialiasing with samples blends and clamps
//                       to (SetTemporal with SetMultiSamples);
//   SAMPLES_ACCUMULATE  writes `source` (one antialiased sample image) scaled by `scale` (1 / N),
//                       added to the accumulation target by blending (one, one);
//   SAMPLES_RESOLVE     writes `source` (the accumulated average) and, as depth, the nearest of
//                       the pixel's samples in `samplesDepth`, into the renderer's viewport.
//                       Where the pixel's samples differ (a geometric edge crosses it, which
//                       multisampling resolves), the result is mixed with the plain average of
//                       the samples (multisampling's own resolve) by `resolveWeight` (0.5; 0 for
//                       vtkOpenGLAntialiasingPass::DebugSample and for the method's debug images,
//                       such as MLAA's edges): each sample image is antialiased
//                       as if each of its pixels covered a whole pixel, and their average blurs
//                       once more by the spread of the sample positions; the plain average has
//                       no such blur, only the coarse steps of N coverage levels. Where the
//                       samples agree (texture and colour-band edges, flat regions) the method's
//                       average is kept as it is.
// Exact texel reads.

in vec2 texCoord; // over the viewport, which is the size of the textures

#if defined(SAMPLES_COPY) || defined(SAMPLES_RESOLVE) || defined(SAMPLES_PLAIN)
uniform sampler2DMS samplesColor;
uniform sampler2DMS samplesDepth;
#endif
#if defined(SAMPLES_PLAIN) || defined(SAMPLES_RESOLVE)
uniform int numberOfSamples;

// The plain average of the samples of pixel p (multisampling's own resolve), the nearest of their
// depths, and whether they differ.
vec4 PlainAverage(ivec2 p, out float depth, out bool differ)
{
  vec4 first = texelFetch(samplesColor, p, 0);
  vec4 sum = first;
  differ = false;
  depth = texelFetch(samplesDepth, p, 0).r;
  for (int s = 1; s < numberOfSamples; ++s)
  {
    vec4 sample = texelFetch(samplesColor, p, s);
    sum += sample;
    differ = differ || any(notEqual(sample, first));
    depth = min(depth, texelFetch(samplesDepth, p, s).r);
  }
  return sum / float(numberOfSamples);
}
#endif
#ifdef SAMPLES_RESOLVE
uniform float resolveWeight;
#endif
#ifdef SAMPLES_COPY
uniform int sampleIndex;
#elif !defined(SAMPLES_PLAIN)
uniform sampler2D source;
#endif
#ifdef SAMPLES_ACCUMULATE
uniform float scale;
#endif

void main()
{
#if defined(SAMPLES_COPY)
  ivec2 p = ivec2(texCoord * vec2(textureSize(samplesColor)));
  gl_FragData[0] = texelFetch(samplesColor, p, sampleIndex);
  gl_FragDepth = texelFetch(samplesDepth, p, sampleIndex).r;
#elif defined(SAMPLES_PLAIN)
  ivec2 p = ivec2(texCoord * vec2(textureSize(samplesColor)));
  float depth;
  bool differ;
  gl_FragData[0] = PlainAverage(p, depth, differ);
  gl_FragDepth = depth;
#else
  ivec2 p = ivec2(texCoord * vec2(textureSize(source, 0)));
  vec4 c = texelFetch(source, p, 0);
#ifdef SAMPLES_ACCUMULATE
  gl_FragData[0] = c * scale;
#else
  float depth;
  bool differ;
  vec4 plain = PlainAverage(p, depth, differ);
  gl_FragData[0] = differ ? mix(c, plain, resolveWeight) : c;
  gl_FragDepth = depth;
#endif
#endif
}
