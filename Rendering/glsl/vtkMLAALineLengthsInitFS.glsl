//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA line lengths by recursive doubling, initialisation (Biri et al., "Practical morphological
// antialiasing on the GPU", section 3.3: "we simply write 1 to the left and right distance of
// any pixel belonging to horizontal lines and 1 to up and down distance to the ones belonging to
// vertical lines"), with the crossing-edge rule of this project's search; and the counts of
// staircase units (below).
//
// Output (RGBA16F, one flag 0 or 1 per direction, red = left, green = right, blue = down,
// alpha = up): whether the neighbour in that direction continues this pixel's line:
// - left/right, for a pixel with a top edgel (a horizontal line): the neighbour has a top edgel
//   too and no left edgel (a crossing edge) lies at the boundary between them, on this row or
//   the row above;
// - down/up, for a pixel with a left edgel (a vertical line): the neighbour has a left edgel too
//   and no top edgel lies at the boundary between them, in this column or the column to the
//   left.
// Edgels are read clamped to the texture (as the bilinear search reads with clamp-to-edge), so a
// pixel at the border whose line continues across it gets the flag towards the outside, and the
// doubling passes (vtkMLAALineLengthsFS.glsl) then count the line on to the maximum distance.
// vtkOpenGLMLAAPass runs this on the pixels with an edge only (the depth mask); the others stay
// cleared to 0.
//
// With MLAA_STAIRCASE_COUNTS defined (vtkMLAAOptions::DiagonalDetection), a second output (RG8)
// counts the units of the staircases of one-pixel steps that follow each unit, up to
// MLAA_STAIRCASE_REACH units each way: how many of the next pixels that way are units of the
// same staircase,
// - for a unit of a rising staircase (a pixel with both its left and its top edgel), towards
//   (-1, -1) and (+1, +1), in red;
// - for a unit of a falling staircase (a pixel q with its top edgel whose right neighbour has its
//   left edgel), towards (-1, +1) and (+1, -1), in green;
// each byte the count towards -x plus 16 times the count towards +x (so a reach of at most 15).
// A count below the reach is exact; a count equal to it goes on at the unit that far away (a
// unit, and counted too). So the blending-weights shader follows a staircase with one read per
// reach units (followStaircase), where its search reads every unit (up to twice the maximum
// distance reads per unit on a long 45-degree edge), and no doubling pass counts staircases.
// Outside the image there are no edgels here (no clamping), so a staircase ends at the border.
//
// Must match the line lengths of vtkImageMLAA (ComputeRowLineLengths and
// ComputeColumnLineLengths in Filters/vtkMLAALineLengths.cxx) and searchLine in
// vtkMLAABlendingWeightsFS.glsl; the staircase counts the diagonal lengths of vtkImageMLAA
// (WeightsComputer::ComputeDiagonalLengths in Filters/vtkMLAABlendingWeights.cxx).

in vec2 texCoord;

uniform sampler2D edgesTexture; // RG8, red = left edgel, green = top edgel (texelFetch only)

// The edges texture's size, set by main before any read. (Initialised here only so that
// compilers that check globals in source order, as Mesa's does, see it set.)
ivec2 size = ivec2(0);

vec2 edgelsAt(ivec2 p)
{
  return texelFetch(edgesTexture, clamp(p, ivec2(0), size - 1), 0).rg;
}
bool topAt(ivec2 p) { return edgelsAt(p).g > 0.5; }
bool leftAt(ivec2 p) { return edgelsAt(p).r > 0.5; }

#ifdef MLAA_STAIRCASE_COUNTS
// Exact edgels, none outside the image.
vec2 unclampedEdgelsAt(ivec2 p)
{
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(p, size)))
  {
    return vec2(0.0);
  }
  return texelFetch(edgesTexture, p, 0).rg;
}
bool isRisingUnit(ivec2 p) { return all(greaterThan(unclampedEdgelsAt(p), vec2(0.5))); }
bool isFallingUnit(ivec2 q)
{
  return unclampedEdgelsAt(q).g > 0.5 && unclampedEdgelsAt(q + ivec2(1, 0)).r > 0.5;
}

// How many of the pixels after unit p in `direction` are units of its staircase, up to the
// reach. A loop per kind, each reading what its kind needs (where pixels shaded in lock-step run
// both sides of a branch, the loop of the other kind ends at once).
float risingUnitsAfter(ivec2 p, ivec2 direction)
{
  int k = 0;
  while (k < MLAA_STAIRCASE_REACH && isRisingUnit(p + (k + 1) * direction))
  {
    ++k;
  }
  return float(k);
}
float fallingUnitsAfter(ivec2 q, ivec2 direction)
{
  int k = 0;
  while (k < MLAA_STAIRCASE_REACH && isFallingUnit(q + (k + 1) * direction))
  {
    ++k;
  }
  return float(k);
}
#endif

void main()
{
  size = textureSize(edgesTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  bool top = topAt(p);
  bool left = leftAt(p);
  vec4 flags = vec4(0.0);
  if (top)
  {
    // The left boundary of a pixel is its own left edgel; that of the row above crosses too.
    flags.r = (topAt(p - ivec2(1, 0)) && !leftAt(p) && !leftAt(p + ivec2(0, 1))) ? 1.0 : 0.0;
    flags.g = (topAt(p + ivec2(1, 0)) && !leftAt(p + ivec2(1, 0)) && !leftAt(p + ivec2(1, 1)))
      ? 1.0 : 0.0;
  }
  if (left)
  {
    // The boundary between two rows is the lower pixel's top edgel; that of the column to the
    // left crosses too.
    flags.b = (leftAt(p - ivec2(0, 1)) && !topAt(p - ivec2(0, 1)) && !topAt(p - ivec2(1, 1)))
      ? 1.0 : 0.0;
    flags.a = (leftAt(p + ivec2(0, 1)) && !topAt(p) && !topAt(p - ivec2(1, 0))) ? 1.0 : 0.0;
  }
  gl_FragData[0] = flags;
#ifdef MLAA_STAIRCASE_COUNTS
  vec4 counts = vec4(0.0);
  // p is inside the image: its clamped edgels (top, left) are its own.
  if (top && left) // a rising unit
  {
    counts.r = risingUnitsAfter(p, ivec2(-1, -1));
    counts.g = risingUnitsAfter(p, ivec2(1, 1));
  }
  if (top && unclampedEdgelsAt(p + ivec2(1, 0)).r > 0.5) // a falling unit
  {
    counts.b = fallingUnitsAfter(p, ivec2(-1, 1));
    counts.a = fallingUnitsAfter(p, ivec2(1, -1));
  }
  gl_FragData[1] = vec4(counts.r + 16.0 * counts.g, counts.b + 16.0 * counts.a, 0.0, 0.0) / 255.0;
#endif
}
