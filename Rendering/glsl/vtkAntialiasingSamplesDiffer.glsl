// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The samples of a multisampled render (vtkOpenGLAntialiasingPass::SetMultiSamples), as the
// method's shaders read them while they antialias one sample image, and whether a pixel's samples
// differ. Put in place of //VTK::Antialiasing::SamplesDiffer by vtkOpenGLAntialiasingPass.

uniform sampler2DMS samplesColor; // the multisampled render
uniform int numberOfSamples;

// Whether the samples of pixel q differ (an edge crosses it: a geometric one, or any edge when
// every sample was shaded on its own); none outside the image.
bool samplesDiffer(ivec2 q)
{
  if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, textureSize(samplesColor))))
  {
    return false;
  }
  vec4 first = texelFetch(samplesColor, q, 0);
  for (int s = 1; s < numberOfSamples; ++s)
  {
    if (any(notEqual(texelFetch(samplesColor, q, s), first)))
    {
      return true;
    }
  }
  return false;
}
