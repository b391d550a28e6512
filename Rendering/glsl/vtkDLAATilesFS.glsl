//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// DLAA, between passes 1 and 2, with long edges only: which tiles of 8 x 8 texels of the masks
// texture (vtkDLAAMasksFS) hold a mask other than 0, into an 8-bit texture of one texel a tile
// (1: some mask is positive, or marks a colour that is not finite; 0: every mask is 0).
//
// Not a step of the method (vtkImageDLAA has none): it lets pass 2 (vtkDLAAFS) leave at once
// the pixels whose two 17-pixel windows, and the pixel itself, lie in tiles of zeros. Those
// pixels have no short edge and long masks of 0, so the method leaves them as they are anyway;
// they are most of a picture, and would otherwise each read the 34 masks of their windows.

in vec2 texCoord; // over the tiles texture

uniform sampler2D masksTexture; // pass 1 output (with its padding)

void main()
{
  ivec2 size = textureSize(masksTexture, 0);
  ivec2 first = ivec2(texCoord * vec2((size + ivec2(7)) / 8)) * 8; // the tile's first texel
  bool marked = false;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      // The last tiles of a row or column may reach past the texture: those texels are not read.
      ivec2 q = first + ivec2(i, j);
      if (all(lessThan(q, size)))
      {
        marked = marked || any(notEqual(texelFetch(masksTexture, q, 0).xy, vec2(0.0)));
      }
    }
  }
  gl_FragData[0] = vec4(marked ? 1.0 : 0.0, 0.0, 0.0, 1.0);
}
