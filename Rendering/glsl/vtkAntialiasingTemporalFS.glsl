//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// Temporal antialiasing of vtkOpenGLAntialiasingPass (SetTemporal): blends the current frame,
// jittered and antialiased by the method, with the history of the previous frames.
//
// Compile-time variants (#defines prepended by vtkOpenGLAntialiasingPass):
//   TEMPORAL_OUTPUT     defined: writes the blended history (historyTexture) and the delegate's
//                       depth into the target viewport (nothing is blended here).
//   TEMPORAL_REPROJECT  defined (the camera moved): the history is read where this pixel's point
//                       (its depth) was in the previous frame, `reprojection` taking the current
//                       normalised device coordinates to the previous ones (both unjittered), and
//                       clamped per channel to the range of the current frame's 3 x 3
//                       neighbourhood; a point that was outside the previous view takes the current
//                       frame alone. Otherwise (a still camera) the history is read at this pixel,
//                       exactly, and not clamped: the blend is then a running average.
// currentWeight: the weight of the current frame (1: the current frame alone, the history is not
// read).

in vec2 texCoord; // over the viewport, which is the size of the textures
uniform sampler2D historyTexture; // RGBA, floating point, linear filtering
uniform sampler2D depthTexture;   // the delegate's depth
#ifndef TEMPORAL_OUTPUT
uniform sampler2D currentTexture; // this frame, antialiased
uniform float currentWeight;
uniform mat4 reprojection;
#endif

void main()
{
  ivec2 size = textureSize(depthTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
  float depth = texelFetch(depthTexture, p, 0).r;
#ifdef TEMPORAL_OUTPUT
  gl_FragData[0] = texelFetch(historyTexture, p, 0);
  gl_FragDepth = depth;
#else
  vec4 current = texelFetch(currentTexture, p, 0);
  if (currentWeight >= 1.0)
  {
    gl_FragData[0] = current;
    return;
  }
#ifdef TEMPORAL_REPROJECT
  vec4 ndc = vec4((vec2(p) + 0.5) / vec2(size) * 2.0 - 1.0, depth * 2.0 - 1.0, 1.0);
  vec4 previous = reprojection * ndc;
  vec2 uv = previous.xy / previous.w * 0.5 + 0.5;
  if (previous.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
  {
    gl_FragData[0] = current;
    return;
  }
  vec4 history = texture(historyTexture, uv);
  vec4 lo = current;
  vec4 hi = current;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      vec4 c = texelFetch(currentTexture, clamp(p + ivec2(i, j), ivec2(0), size - 1), 0);
      lo = min(lo, c);
      hi = max(hi, c);
    }
  }
  history = clamp(history, lo, hi);
#else
  vec4 history = texelFetch(historyTexture, p, 0);
#endif
  gl_FragData[0] = mix(history, current, currentWeight);
#endif
}
