//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause

// DLAA pass 2 (vtkDLAAFS) drawn in place with long edges: one instance of VTK's screen quad per
// square of drawTiles x drawTiles tiles of 8 x 8 pixels of the image (instance k: square column
// k % columns, row k / columns), placed over its pixels where some of them may change, collapsed
// to nothing elsewhere. A pixel may change only where one of the five tiles of masks that its
// 17-pixel windows touch holds a mask other than 0 (vtkDLAATilesFS; vtkDLAAFS makes the same
// test per pixel): the pixels of image tile t lie in tile t + 1 of the masks (whose texture has
// 8 pixels of padding), and their windows touch that tile and its four neighbours. The square
// reads the tiles of masks around its own (corners included, which only draws a little more).
// A rasteriser then shades only the squares near edges; the pixels of the others keep the
// delegate's image, as the fragment shader would have left them. The pass of the sides of corners
// (vtkDLAACornersFS) is drawn the same way, reading tiles two further (`margin`), over a texture
// cleared to 0.

in vec4 ndCoordIn;  // a corner of VTK's screen quad, in [-1, 1]^2
in vec2 texCoordIn; // the same corner in [0, 1]^2
out vec2 texCoord;  // over the image, as the screen quad gives it

uniform sampler2D colorTexture; // the delegate's image (its size)
uniform sampler2D tilesTexture;
uniform int drawTiles; // tiles a side of a square
// Tiles of masks around the square's own that are read: 1 for pass 2; 2 for the sides of corners
// (vtkDLAACornersFS), whose flags pass 2 reads up to 8 pixels from the pixels it shades.
uniform int margin;

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  ivec2 last = textureSize(tilesTexture, 0) - ivec2(1);
  int side = 8 * drawTiles; // pixels
  int columns = (size.x + side - 1) / side;
  ivec2 square = ivec2(gl_InstanceID % columns, gl_InstanceID / columns);
  // Image tiles square * drawTiles + (0 .. drawTiles - 1) lie in tiles of masks one further;
  // with their neighbours, masks tiles square * drawTiles + (0 .. drawTiles + 1).
  ivec2 first = square * drawTiles;
  bool changes = false;
  for (int j = 1 - margin; j <= drawTiles + margin; ++j)
  {
    for (int i = 1 - margin; i <= drawTiles + margin; ++i)
    {
      ivec2 t = clamp(first + ivec2(i, j), ivec2(0), last);
      changes = changes || texelFetch(tilesTexture, t, 0).r != 0.0;
    }
  }
  // The square's pixels (the last row and column of squares may reach past the image).
  vec2 lo = vec2(square * side);
  vec2 hi = min(vec2(square * side + ivec2(side)), vec2(size));
  vec2 corner = mix(lo, hi, ndCoordIn.xy * 0.5 + 0.5) / vec2(size);
  texCoord = mix(lo, hi, texCoordIn) / vec2(size);
  // A square whose pixels all stay as they are: every corner at one point outside the view.
  gl_Position = changes ? vec4(corner * 2.0 - 1.0, 0.0, 1.0) : vec4(2.0, 2.0, 0.0, 1.0);
}
