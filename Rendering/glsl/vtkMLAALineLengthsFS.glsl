//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA line lengths by recursive doubling, one pass (Biri et al., "Practical morphological
// antialiasing on the GPU", section 3.3, equation 1 and Algorithm 2).
//
// Each channel (red = left, green = right, blue = down, alpha = up) holds d(X), a count of the
// pixels that continue X's line in that direction. It starts as the 0/1 flag of
// vtkMLAALineLengthsInitFS.glsl, and each pass applies equation 1 three times,
//   d(X) := d(X) + d(X - d(X))        (X - d(X): d(X) pixels further in the channel's direction),
// reading the previous pass's texture: the count jumps over the stretch that the pixel it lands
// on has counted already. If the previous pass left every count exact below `level` and equal to
// `level` otherwise, three jumps of at most `level` make them exact below 4 level (Figure 4):
// after the passes for levels 1, 4, 16 and 64 the counts are exact up to 256, the longest
// distance vtkMLAAOptions allows (2 x 128 steps). A pixel whose count is below `level` is final
// and is only copied (the paper's early-out). vtkOpenGLMLAAPass runs ceil(log4(maximum
// distance)) passes, ping-ponging two RGBA16F textures (16-bit floats hold integers up to 2048
// exactly; the 8-bit texture of the paper stops at 255), and the blending-weights shader clamps
// the counts to the maximum distance.
//
// Reads are clamped to the texture: past the border, the border pixel's count repeats, which is
// exact because a line that continues across the border continues for ever there (the
// initialisation reads its edgels clamped too).
//
// Must match the line lengths of vtkImageMLAA (ComputeRowLineLengths and
// ComputeColumnLineLengths in Filters/vtkMLAALineLengths.cxx).

in vec2 texCoord;

uniform sampler2D lengthsTexture; // RGBA16F, the previous pass's counts (texelFetch only)
uniform float level;              // 1, 4, 16 or 64

// Equation 1 three times for each channel of `lengths` at p, along `directions`.
vec4 doubled(sampler2D lengths, ivec2 p, ivec2 size, ivec2 directions[4])
{
  vec4 d = texelFetch(lengths, p, 0);
  vec4 result = d;
  for (int c = 0; c < 4; ++c)
  {
    if (d[c] >= level)
    {
      // Three jumps from d(X) pixels away (Algorithm 2).
      ivec2 q = p + directions[c] * int(d[c]);
      for (int k = 0; k < 3; ++k)
      {
        float jump = texelFetch(lengths, clamp(q, ivec2(0), size - 1), 0)[c];
        result[c] += jump;
        q += directions[c] * int(jump);
      }
    }
  }
  return result;
}

void main()
{
  ivec2 size = textureSize(lengthsTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  gl_FragData[0] = doubled(lengthsTexture, p, size,
    ivec2[4](ivec2(-1, 0), ivec2(1, 0), ivec2(0, -1), ivec2(0, 1)));
}
