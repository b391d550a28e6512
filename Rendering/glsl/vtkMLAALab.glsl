// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// CIELAB features for the MLAA shaders (Biri et al., "Morphological antialiasing and
// topological reconstruction", section 3.2). vtkOpenGLMLAAPass puts this file in place of
// //VTK::MLAA::Lab in the shaders that compare colours in CIELAB (the edge detection in Lab
// mode, and the reconstruction pass), so there is one GLSL copy of the conversion.
//
// A normalised colour is taken as sRGB, linearised, converted to CIE XYZ (D65) and to L*a*b*;
// the features are L/100, a/100 and b/100, so that their Euclidean distance is Delta E
// (CIE 1976) / 100.
//
// Must match namespace Lab in Filters/vtkMLAALab.h (vtkImageMLAA).

// The sRGB transfer function inverted: a channel (clamped at 0) to linear light.
#ifdef MLAA_SRGB_TABLE
// An 8-bit source (each channel k / 255): its 256 values, from the CPU filter's conversion
// (vtkMLAALab.h, whose tables for 8-bit images hold the same), instead of a pow per channel.
uniform float srgbToLinear[256];
float labLinear(float c)
{
  return srgbToLinear[int(clamp(c, 0.0, 1.0) * 255.0 + 0.5)];
}
#else
float labLinear(float c)
{
  c = max(c, 0.0);
  return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}
#endif

// The f of the L*a*b* definition, (6/29)^3 = 0.008856452, 3 (6/29)^2 = 0.12841855.
float labF(float t)
{
  return t > 0.008856452 ? pow(t, 1.0 / 3.0) : t / 0.12841855 + 4.0 / 29.0;
}

// (L, a, b) / 100 of a normalised sRGB colour.
vec3 labFeatures(vec3 srgb)
{
  vec3 rgb = vec3(labLinear(srgb.r), labLinear(srgb.g), labLinear(srgb.b));
  // XYZ divided by the white point (0.95047, 1, 1.08883).
  float x = dot(vec3(0.4124564, 0.3575761, 0.1804375), rgb) / 0.95047;
  float y = dot(vec3(0.2126729, 0.7151522, 0.0721750), rgb);
  float z = dot(vec3(0.0193339, 0.1191920, 0.9503041), rgb) / 1.08883;
  float fx = labF(x);
  float fy = labF(y);
  float fz = labF(z);
  return vec3(1.16 * fy - 0.16, 5.0 * (fx - fy), 2.0 * (fy - fz));
}
