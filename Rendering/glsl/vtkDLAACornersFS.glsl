//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// DLAA, between its two passes: the sides of corners (vtkDLAAOptions, step 3; issue 50), into an
// RGBA8 texture the size of the image, which vtkDLAAFS reads. For pixel p:
//   r: the boundary between p and its right neighbour is the side of a corner;
//   g: the boundary between p and the pixel above it is.
// The short-edge blur along an edge reads two pixels each way, the long-edge step a window of up
// to 8; where they cross a side that meets the edge at a corner (the end of a bar, a junction of
// voxels), they bring the next shape's colour into a side that was exact. A boundary is such a
// side when its colours differ by more than `sideContrast` in some channel the luminosity reads,
// the pair of luminosities it separates runs on across it for cornerRun (4) pixels or more (within
// half their difference, looked at up to 8 pixels each way) and, at each end within those 8, the
// pair does not go on one pixel over (as a staircase's run goes on at each of its steps) and the
// side crossing there goes on for 4 pixels (a shorter one, such as the end of a line one pixel
// wide, is a step as well). The test is the same seen from either pixel. Exact texel reads,
// clamped to the border: a boundary with the border is none.
//
// Drawn twice, over flags cleared to 0 and a depth mask cleared to 0. First with
// DLAA_CORNER_CANDIDATES: the pixels with a boundary the masks would see (the test's first step,
// sideSeen) write the quad's depth, and the others are discarded. Then the whole test, tested
// against that mask, runs on the candidates only: a rasteriser that shades pixels in groups in
// lock-step (llvmpipe, which runs both sides of every branch for the group and ends no group on
// a discard) skips the groups without a candidate before shading them, as the MLAA pass's change
// mask does; most of a picture has none. With long edges both are drawn only over the squares of
// tiles near a mask other than 0 (vtkDLAATilesVS, two tiles around): pass 2 reads no others.
//
// Compile-time variants (#defines prepended by vtkOpenGLDLAAPass):
//   DLAA_LUMA               0 Rec. 709 luma, 1 green (vtkDLAAOptions::LumaFunction)
//   DLAA_TILED              defined: drawn by squares (vtkDLAATilesVS), with long edges
//   DLAA_CORNER_CANDIDATES  defined: the depth mask of candidates (no colour is written)
//
// Must match vtkDLAAStages::CornerSide.

in vec2 texCoord;

uniform sampler2D colorTexture; // the delegate's image
// vtkDLAAOptions::SideContrast: 2 Epsilon / Lambda, the contrast at which the blend masks see an
// edge (a step of that height gives the pixel beside it a high-pass of half of it).
uniform float sideContrast;
// vtkDLAAOptions::CornerSearch (8), the 2 ends of a run, vtkDLAAOptions::CornerCrossing (4), as
// uniforms: the GLSL compiler unrolls loops of a constant length, and llvmpipe, whose branches
// run for every pixel shaded with this one, then runs all of their bodies; a loop with a uniform
// bound ends as soon as none of those pixels needs it (most pixels have no boundary, and most
// boundaries a run shorter than 4).
uniform int cornerSearch;
uniform int runEnds;
uniform int crossingLength;
uniform int cornerRun; // vtkDLAAOptions::CornerRun (4): the shortest run of a corner's side

//VTK::DLAA::Luma

// The last pixel of the image, set by main before any read. (Initialised here only so that
// compilers that check globals in source order, as Mesa's does, see it set.)
ivec2 last = ivec2(0);

vec4 colorAt(ivec2 q)
{
  return texelFetch(colorTexture, clamp(q, ivec2(0), last), 0);
}

bool finiteLuma(float l)
{
  return !isnan(l) && !isinf(l);
}

// The luminosity d pixels from p along `along` and i pixels across it.
float lumaAt(ivec2 p, ivec2 along, ivec2 across, int d, int i)
{
  return luma(colorAt(p + d * along + i * across));
}

// Whether, at d pixels along `along` from p, the pixels i0 and i1 across it differ and the pixels
// 1 to crossingLength - 1 further along (in the direction `away`) keep their luminosities within
// half that difference: a side crossing the line between i0 and i1 that goes on for
// crossingLength pixels.
bool crossingGoesOn(ivec2 p, ivec2 along, ivec2 across, int d, int i0, int i1, int away)
{
  float l0 = lumaAt(p, along, across, d, i0);
  float l1 = lumaAt(p, along, across, d, i1);
  float difference = abs(l0 - l1);
  if (!(difference > 0.0))
  {
    return false;
  }
  float tolerance = 0.5 * difference;
  for (int m = 1; m < crossingLength; ++m)
  {
    if (!(abs(lumaAt(p, along, across, d + m * away, i0) - l0) <= tolerance &&
          abs(lumaAt(p, along, across, d + m * away, i1) - l1) <= tolerance))
    {
      return false;
    }
  }
  return true;
}

// Whether the run of the pair (lP, lQ) across the boundary between p and p + along, which stops
// i pixels across (i = side * end), ends in a step: the pair goes on one pixel over along
// `along`, or the side crossing there is shorter than 4 pixels, or a luminosity there is not
// finite.
bool endIsStep(ivec2 p, ivec2 along, ivec2 across, float lP, float lQ, float tolerance, int i,
  int side)
{
  if (!finiteLuma(lumaAt(p, along, across, 0, i)) || !finiteLuma(lumaAt(p, along, across, 1, i)))
  {
    return true;
  }
  for (int n = 0; n < runEnds; ++n)
  {
    int shift = 2 * n - 1;
    if (abs(lumaAt(p, along, across, shift, i) - lP) <= tolerance &&
      abs(lumaAt(p, along, across, 1 + shift, i) - lQ) <= tolerance)
    {
      return true;
    }
  }
  return !(crossingGoesOn(p, along, across, 0, i - side, i, -1) ||
    crossingGoesOn(p, along, across, 1, i - side, i, 1));
}

// Whether the masks would see the boundary between colours a and b as an edge (false where a
// value is not finite).
bool sideSeen(vec4 a, vec4 b)
{
  return abs(luma(a) - luma(b)) > 0.0 && lumaChannelsContrast(a, b) > sideContrast;
}

// Whether the boundary between p and p + along is the side of a corner: a side the masks see,
// then the run (most boundaries, the steps of staircases, are shorter than 4), then its ends
// within 8 pixels.
bool cornerSide(ivec2 p, ivec2 along, ivec2 across)
{
  vec4 a = colorAt(p);
  vec4 b = colorAt(p + along);
  if (!sideSeen(a, b))
  {
    return false;
  }
  float lP = luma(a);
  float lQ = luma(b);
  float difference = abs(lP - lQ);
  float tolerance = 0.5 * difference;
  int ends[2];
  for (int n = 0; n < 2; ++n)
  {
    int side = 2 * n - 1;
    int end = 1;
    for (; end <= cornerSearch; ++end)
    {
      if (!(abs(lumaAt(p, along, across, 0, side * end) - lP) <= tolerance &&
            abs(lumaAt(p, along, across, 1, side * end) - lQ) <= tolerance))
      {
        break;
      }
    }
    ends[n] = end;
  }
  bool corner = ends[0] + ends[1] - 1 >= cornerRun;
  for (int n = 0; corner && n < runEnds; ++n)
  {
    int side = 2 * n - 1;
    corner = ends[n] > cornerSearch ||
      !endIsStep(p, along, across, lP, lQ, tolerance, side * ends[n], side);
  }
  return corner;
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  last = size - ivec2(1);
  ivec2 p = ivec2(texCoord * vec2(size));
#ifdef DLAA_CORNER_CANDIDATES
  vec4 c = colorAt(p);
  if (!sideSeen(c, colorAt(p + ivec2(1, 0))) && !sideSeen(c, colorAt(p + ivec2(0, 1))))
  {
    discard;
  }
  gl_FragData[0] = vec4(0.0); // (colour writes are off)
#else
  bool right = cornerSide(p, ivec2(1, 0), ivec2(0, 1));
  bool up = cornerSide(p, ivec2(0, 1), ivec2(1, 0));
  gl_FragData[0] = vec4(right ? 1.0 : 0.0, up ? 1.0 : 0.0, 0.0, 0.0);
#endif
}
