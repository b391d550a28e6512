// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The luminosity function of directionally localized antialiasing (vtkDLAAOptions::LumaFunction),
// shared by the DLAA shaders: DLAA_LUMA 0 is Rec. 709 luma, 1 the green channel alone.
float luma(vec4 c)
{
#if DLAA_LUMA == 1
  return c.g;
#else
  return dot(c.rgb, vec3(0.2126, 0.7152, 0.0722));
#endif
}

// The largest difference between two colours in the channels the luminosity reads.
float lumaChannelsContrast(vec4 a, vec4 b)
{
#if DLAA_LUMA == 1
  return abs(a.g - b.g);
#else
  vec3 d = abs(a.rgb - b.rgb);
  return max(max(d.r, d.g), d.b);
#endif
}

// Whether every channel of a colour is a finite number.
bool finite(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}
