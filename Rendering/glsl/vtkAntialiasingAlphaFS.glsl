//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// The alpha of a composited renderer's image kept across order-independent translucency
// (vtkOpenGLAntialiasingPass): vtkOrderIndependentTranslucentPass leaves the right premultiplied
// colour but not the coverage alpha, so the alpha before it is kept and written back, and the
// translucent geometry's coverage is then blended into it.
//
// Compile-time variants (#defines prepended by vtkOpenGLAntialiasingPass):
//   ANTIALIASING_KEEP_ALPHA  defined: writes the alpha of `source` (the delegate's colour) into a
//                            one-channel texture. Otherwise writes channel r of `source` (the
//                            kept alpha) as alpha; the colour mask keeps the colour.
// Exact texel reads.

in vec2 texCoord; // over the viewport, which is the size of `source`
uniform sampler2D source;

void main()
{
  vec4 texel = texelFetch(source, ivec2(texCoord * vec2(textureSize(source, 0))), 0);
#ifdef ANTIALIASING_KEEP_ALPHA
  gl_FragData[0] = vec4(texel.a, 0.0, 0.0, 1.0);
#else
  gl_FragData[0] = vec4(0.0, 0.0, 0.0, texel.r);
#endif
}
