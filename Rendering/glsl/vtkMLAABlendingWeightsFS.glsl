//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA pass 2 of 3: blending weights (Jimenez et al., "Practical Morphological Antialiasing",
// GPU Pro 2, section 4.3, Listing 4.2).
//
// Runs on pixels with an edge only (see the edge-detection pass). For the top edgel of the pixel
// (a horizontal line) and for its left edgel (a vertical line):
// 1. the distances to both ends of the line, stopping at crossing edges (section 4.3.1,
//    Listing 4.3), and
// 2. the crossing edges at both ends (section 4.3.2, Figure 4.4), both from one bilinear fetch
//    per two pixels of the line, placed so that it tells each of the eight edgels it weighs
//    (searchLine; the chapter reads two edgels per fetch and the crossing edges with more);
// 3. the two areas of the precomputed area texture (section 4.3.3, Listing 4.4).
// Output: red = weight with which this pixel takes the colour of the pixel above it, green =
// weight with which the pixel above takes this pixel's colour, blue and alpha = the same for
// the left neighbour. GL's y grows upwards, so "above" is y + 1 and the published shader's -0.25
// offset towards the upper row becomes +0.25 here.
//
// Compile-time variants (#defines prepended by vtkOpenGLMLAAPass in place of //VTK::Antialiasing::Dec;
// the program is rebuilt when the options change):
//   MLAA_MAX_SEARCH_STEPS         vtkMLAAOptions::MaxSearchSteps (a constant loop bound)
//   MLAA_DIAGONAL_DETECTION       defined: vtkMLAAOptions::DiagonalDetection
//   MLAA_MINIMUM_DIAGONAL_LENGTH  vtkMLAAOptions::MinimumDiagonalLength
//   MLAA_CORNER_EXTRAPOLATION     defined: vtkMLAAOptions::CornerExtrapolation (see
//                                 extrapolateCorners)
//   MLAA_RECURSIVE_DOUBLING       defined: the distances to the ends of orthogonal lines are read
//                                 from the line lengths of vtkMLAALineLengthsFS.glsl (Biri et
//                                 al., section 3.3) instead of being searched here; they are the
//                                 same integers (vtkOpenGLMLAAPass::LineLengths)
//   MLAA_SAMPLE_AREAS             defined: the image is sample `sampleIndex` of a multisampled
//                                 render (vtkOpenGLMLAAPass::SampleAreas): orthogonal lines whose
//                                 edgel has, on either side, a pixel whose samples differ read
//                                 their areas from that sample's tables of sampleAreaTexture (the
//                                 line moved by the sample's offset from the pixel centre,
//                                 vtkMLAAAreaTexture::ComputeAreas); no CPU twin
//   MLAA_SAMPLES_SHADED           the number of samples (with MLAA_SAMPLE_AREAS), where every
//                                 sample was shaded at its own position
//                                 (vtkOpenGLAntialiasingPass::SampleShading, nothing blended
//                                 per pixel), so samples that agree bound every edge, not only
//                                 geometric ones (see lineArea)
//   MLAA_STAIRCASE_REACH          defined (with MLAA_DIAGONAL_DETECTION and
//                                 MLAA_RECURSIVE_DOUBLING): the units of staircases are counted
//                                 beforehand, up to this reach each way; a count below it is
//                                 final, a count equal to it goes on at the unit that far
//                                 (followStaircase); the same integers as the search
//
// With MLAA_DIAGONAL_DETECTION, edgels that belong to a staircase of one-pixel steps (at least
// minimumDiagonalLength units) take their weights from the 45-degree line through it instead,
// from the diagonal area table (vtkMLAAAreaTexture::ComputeDiagonalAreas). Exact texel reads are
// used there; the staircase is searched one unit per step, or followed through the counts of
// vtkMLAALineLengthsInitFS.glsl, one read per reach; vtkImageMLAA counts the same lengths
// (WeightsComputer::ComputeDiagonalLengths).
//
// Must match vtkImageMLAA's blending weights (ComputeBlendingWeights in Filters/vtkMLAABlendingWeights.cxx);
// the distances of searchLine must equal the line lengths of
// ComputeRowLineLengths/ComputeColumnLineLengths there and of vtkMLAALineLengthsFS.glsl.

in vec2 texCoord;

uniform sampler2D edgesTexture; // RG8, red = left edgel, green = top edgel; LINEAR, clamp to edge
uniform sampler2D areaTexture;  // vtkMLAAAreaTexture's table, RG32F (texelFetch only)
uniform sampler2D diagonalAreaTexture; // vtkMLAAAreaTexture's diagonal table, RGB32F
#ifdef MLAA_SAMPLE_AREAS
// Per sample s, the area table of horizontal lines (rows 2 s T...) then of vertical lines,
// T = 5 D texels high each; RG32F (texelFetch only).
uniform sampler2D sampleAreaTexture;
uniform int sampleIndex;
uniform float sampleGap; // 1/2 less the largest |offset| of a sample from the pixel centre
#ifdef MLAA_SAMPLES_SHADED
// MLAA_SAMPLES_SHADED is the number of samples (a constant bound: the loops below unroll).
uniform vec2 sampleOffsets[MLAA_SAMPLES_SHADED]; // from the pixel centre, x right, y up, pixels
#endif
#endif
#ifdef MLAA_RECURSIVE_DOUBLING
// Line lengths (left, right, down, up), RGBA16F integers, exact up to 4^passes >= maxDistance.
uniform sampler2D lengthsTexture;
#endif
#ifdef MLAA_STAIRCASE_REACH
// Counts of the units of staircases that follow each unit, up to MLAA_STAIRCASE_REACH: rising
// towards (-1, -1), (+1, +1), falling towards (-1, +1), (+1, -1); RG8, two to a byte
// (vtkMLAALineLengthsInitFS.glsl, countsAt).
uniform sampler2D staircaseCountsTexture;
#endif

const int maxSearchSteps = MLAA_MAX_SEARCH_STEPS;
const int cellSize = 2 * MLAA_MAX_SEARCH_STEPS + 1; // D, the area texture's cell size

// The edges texture's size, set by main before any read. (Initialised here only so that
// compilers that check globals in source order, as Mesa's does, see it set.)
vec2 edgesSize = vec2(0.0);

// Bilinear read of the edges texture at a position in texels (texel i covers [i, i + 1]). At
// level 0 explicitly: the reads are made in loops and branches that differ between neighbouring
// pixels, where the derivatives an implicit level of detail needs are undefined (GLSL 4.50,
// section 8.9).
vec2 edgesAt(vec2 position)
{
  return textureLod(edgesTexture, position / edgesSize, 0.0).rg;
}

// The edgels of a square of 2 x 2 pixels, from one bilinear fetch at `position`, which lies
// 1/3 of a texel from the centre of the square's pixel a towards its pixel b on one axis and
// 1/5 of a texel from a's centre towards its pixel c on the other: the fetch weighs a, b, c and
// the fourth pixel d 8/15, 4/15, 2/15 and 1/15, so that round(15 v) holds each pixel's edgel as
// one bit (a 8, b 4, c 2, d 1) in each channel. That needs the filtering's weights to within
// 1/30, which the 8 bits of sub-texel precision of GPUs (and llvmpipe) give.
ivec2 edgelBits(vec2 position)
{
  return ivec2(round(15.0 * edgesAt(position)));
}

// The crossing-edge code (section 4.3.2) of a boundary of a line whose two crossing edgels are
// the bits `lineSide` (on the side of the pixels that own the line's edgels) and `opposite` of
// edgelBits: 3 for the first, plus 1 for the second (0, 1, 3 or 4).
int crossingCode(int bits, int lineSide, int opposite)
{
  return ((bits & lineSide) != 0 ? 3 : 0) + ((bits & opposite) != 0 ? 1 : 0);
}

// Distance from the pixel centred at `center` to the end of its line in `direction` (section
// 4.3.1): a line of top edgels (green) along its row, -1 left, +1 right, or (vertical) one of
// left edgels (red) along its column, -1 down, +1 up. The crossing edgels are the other kind:
// left edgels of this row and the one above, or top edgels of this column and the one to the
// left. The line ends before the first pixel without an edgel or at the first boundary with a
// crossing edgel. (The chapter's search does not stop at crossing edges; stopping keeps the two
// outlines of one-pixel-wide lines apart.)
//
// Each step covers a pair of pixels, first (2 i + 1 pixels away) and second (one further), with
// one fetch (edgelBits: a = first, b = second, c and d their neighbours across the line), where
// the chapter reads two edgels per fetch and the crossing edges with more (section 4.3.2).
// Going right or down, the pair's first pixel owns the crossing edgels of the boundary before
// it ("near") and the second those between the two ("mid"); going left or up, the first pixel
// owns the mid ones and the second those of the boundary after the pair, which is the next
// pair's near one (for the first pair, the pixel's own edgels, read before).
//
// `code` is the crossing-edge code of the boundary where the line ends: the codes of the pair's
// boundaries are at hand, so that the ends need no reads of their own.
// A line that goes on past the last step ends at the next pair's near boundary: one more step
// reads it.
int searchLine(vec2 center, bool vertical, float direction, out int code)
{
  bool shifted = vertical ? direction > 0.0 : direction < 0.0;
  int near = 0;
  if (shifted)
  {
    // This pixel (8) and the pixel above it (2) for its left edgels, this pixel (8) and the one
    // to its left (4) for its top edgels.
    ivec2 own = edgelBits(center + vec2(-1.0 / 3.0, 0.2));
    near = vertical ? crossingCode(own.g, 8, 4) : crossingCode(own.r, 8, 2);
  }
  // The first pair's fetch position along the line; each step moves it two pixels. (Written
  // as the same sum inside the loop, Mesa 26.1's llvmpipe dropped the 1/3 at one pixel of
  // TestMLAAPassLongLines, whose fetches then read the pair's first pixel alone: the line came
  // out one pixel longer there. Hoisted, every driver tested reads the pairs as written.)
  float first = (vertical ? center.y : center.x) + direction * (4.0 / 3.0);
  for (int i = 0; i <= maxSearchSteps; ++i)
  {
    float along = first + direction * float(2 * i);
    ivec2 bits = edgelBits(vertical ? vec2(center.x - 0.2, along) : vec2(along, center.y + 0.2));
    int edgels = vertical ? bits.r : bits.g;
    int crossings = vertical ? bits.g : bits.r;
    int firstCode = crossingCode(crossings, 8, 2);
    int secondCode = crossingCode(crossings, 4, 1);
    if (!shifted)
    {
      near = firstCode;
    }
    if (near != 0 || (edgels & 8) == 0 || i == maxSearchSteps)
    {
      code = near;
      return 2 * i;
    }
    int mid = shifted ? firstCode : secondCode;
    if (mid != 0 || (edgels & 4) == 0)
    {
      code = mid;
      return 2 * i + 1;
    }
    near = secondCode;
  }
  return 2 * maxSearchSteps; // not reached
}

// Line coordinates (WeightsComputer::Line in vtkMLAABlendingWeights.cxx): the lines of top edgels
// (horizontal) and of left edgels (vertical) are followed by the same code. u runs along the line
// towards its second end (right, or down: a vertical line's first end is the upper one, as in the
// area table) and v across it, towards the pixels on the line's other side (up, or left). The
// line's own edgel of a pixel then lies between the pixel and its neighbour at v + 1, and the
// crossing edgel between the pixel and its neighbour at u - 1, for either orientation;
// crossing-edge codes count the edgel at v = 0 three times.
ivec2 lineToImage(ivec2 p, bool vertical, int u, int v)
{
  return p + (vertical ? ivec2(-v, -u) : ivec2(u, v));
}

// How many pixels the image holds past pixel p in direction s (-1 or +1) of u.
int toBorder(ivec2 p, bool vertical, int s)
{
  ivec2 last = ivec2(edgesSize) - 1;
  if (vertical)
  {
    return s < 0 ? last.y - p.y : p.y;
  }
  return s < 0 ? p.x : last.x - p.x;
}

// The crossing-edge code of the end of p's line whose crossing edgels belong to the pixel at u:
// none outside the image (where the clamped reads repeat the border's edgels).
int insideCode(int code, ivec2 p, bool vertical, int u)
{
  return (u < -toBorder(p, vertical, -1) || u > toBorder(p, vertical, 1)) ? 0 : code;
}

vec2 area(int e1, int e2, int d1, int d2)
{
  return texelFetch(areaTexture, ivec2(cellSize * e1 + d1, cellSize * e2 + d2), 0).rg;
}

#ifdef MLAA_SAMPLE_AREAS
// samplesColor, numberOfSamples and samplesDiffer (vtkAntialiasingSamplesDiffer.glsl).
//VTK::Antialiasing::SamplesDiffer
#endif

#ifdef MLAA_SAMPLES_SHADED
// Whether the edge between p's colour and q's crosses the sample pattern of pixel e (a step of
// that edge): e has samples of both colours, and every sample of q's colour lies farther towards
// q than every sample of p's colour (q is above p for a horizontal edge, left of it for a
// vertical one). At a corner, where another edge crosses e, the two colours split along that
// edge instead, and samples of a third colour are left out.
bool stepsAcross(ivec2 e, vec4 colorP, vec4 colorQ, bool vertical)
{
  if (any(lessThan(e, ivec2(0))) || any(greaterThanEqual(e, textureSize(samplesColor))))
  {
    return false;
  }
  float farthestP = -1.0;
  float nearestQ = 1.0;
  bool hasP = false;
  bool hasQ = false;
  for (int s = 0; s < MLAA_SAMPLES_SHADED; ++s)
  {
    vec4 c = texelFetch(samplesColor, e, s);
    float towardsQ = vertical ? -sampleOffsets[s].x : sampleOffsets[s].y;
    if (all(equal(c, colorP)))
    {
      farthestP = max(farthestP, towardsQ);
      hasP = true;
    }
    else if (all(equal(c, colorQ)))
    {
      nearestQ = min(nearestQ, towardsQ);
      hasQ = true;
    }
  }
  return hasP && hasQ && nearestQ > farthestP;
}
#endif

// The areas of the line through the edgel between pixels p and q (vertical: a vertical line),
// from the area texture; with MLAA_SAMPLE_AREAS:
// - where either pixel's samples differ (a geometric edge crosses it), from this sample's
//   tables (the line moved by the sample's offset), except for U shapes (both ends step to the
//   same side: the outline of a bump, a dot or the end of a thin line, whose reconstruction
//   does not place the feature; moving them lowered the scenes of points and thin lines);
// - where neither does but a pixel at an end of the line does (the line is a staircase of a
//   geometric edge), the edge passes between the two pixels' sample patterns: within
//   `sampleGap` (1/2 less the largest offset of a sample from the pixel centre) of the pixel
//   boundary, so neither pixel takes more than that of the other's colour;
// - with MLAA_SAMPLES_SHADED, where neither pixel's samples differ, whatever drew the edge:
//   each sample image is then the scene point-sampled at its sample's position, so the edge
//   lies within `sampleGap` of the pixel boundary here. The same bound applies where a pixel
//   at an end of the line has the edge across its samples (stepsAcross: a step of this edge);
//   where none has, no step is seen and the edge stays within the gap all along (a side on a
//   pixel border ending at corners, or a line whose steps lie beyond the search): no ramp, the
//   estimate of an offset known only to lie in [-sampleGap, sampleGap]. Without sample shading,
//   lines whose ends' samples agree are mostly edges inside a primitive (texture, colour
//   bands), shaded once per pixel, whose samples agree wherever the edge lies: they keep the
//   usual table.
vec2 lineArea(ivec2 p, ivec2 q, bool vertical, int e1, int e2, int d1, int d2)
{
#ifdef MLAA_SAMPLE_AREAS
  bool bump = e1 == e2 && (e1 == 1 || e1 == 3); // a U shape: both ends step the same way
  if (!bump && (samplesDiffer(p) || samplesDiffer(q)))
  {
    int size = 5 * cellSize;
    int row = (2 * sampleIndex + (vertical ? 1 : 0)) * size;
    return texelFetch(sampleAreaTexture, ivec2(cellSize * e1 + d1, row + cellSize * e2 + d2), 0).rg;
  }
  ivec2 along = vertical ? ivec2(0, 1) : ivec2(-1, 0); // towards the first end
#ifdef MLAA_SAMPLES_SHADED
  vec4 colorP = texelFetch(samplesColor, p, 0);
  vec4 colorQ = texelFetch(samplesColor, q, 0);
  if (!(stepsAcross(p + d1 * along, colorP, colorQ, vertical) ||
        stepsAcross(q + d1 * along, colorP, colorQ, vertical) ||
        stepsAcross(p - d2 * along, colorP, colorQ, vertical) ||
        stepsAcross(q - d2 * along, colorP, colorQ, vertical)))
  {
    return vec2(0.0);
  }
  return min(area(e1, e2, d1, d2), vec2(sampleGap));
#else
  if (samplesDiffer(p + d1 * along) || samplesDiffer(q + d1 * along) ||
    samplesDiffer(p - d2 * along) || samplesDiffer(q - d2 * along))
  {
    return min(area(e1, e2, d1, d2), vec2(sampleGap));
  }
#endif
#endif
  return area(e1, e2, d1, d2);
}

// The areas with the heights of the ends flagged in `halved` halved (CornerExtrapolation): each
// end's part of the areas is read on its own, (e1, 0) and (0, e2), and the halved one weighted
// by 1/2 (WeightsComputer::LookUpArea).
vec2 area(int e1, int e2, int d1, int d2, bvec2 halved)
{
  if (!any(halved))
  {
    return area(e1, e2, d1, d2);
  }
  return (halved.x ? 0.5 : 1.0) * area(e1, 0, d1, d2) +
    (halved.y ? 0.5 : 1.0) * area(0, e2, d1, d2);
}

// Whether pixel p lies inside the image.
bool insideImage(ivec2 p)
{
  return all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, ivec2(edgesSize)));
}

// Exact edgels of a pixel; none outside the image.
vec2 edgelsAt(ivec2 p)
{
  if (!insideImage(p))
  {
    return vec2(0.0);
  }
  return texelFetch(edgesTexture, p, 0).rg;
}
bool topAt(ivec2 p) { return edgelsAt(p).g > 0.5; }
bool leftAt(ivec2 p) { return edgelsAt(p).r > 0.5; }

// The edgels at (u, v) of p's line coordinates: along the line, or crossing it; none outside the
// image.
bool alongAt(ivec2 p, bool vertical, int u, int v)
{
  vec2 e = edgelsAt(lineToImage(p, vertical, u, v));
  return (vertical ? e.r : e.g) > 0.5;
}
bool crossingAt(ivec2 p, bool vertical, int u, int v)
{
  vec2 e = edgelsAt(lineToImage(p, vertical, u, v));
  return (vertical ? e.g : e.r) > 0.5;
}

// Whether the crossing edge of code `code` (1 or 3: on one side) of the line at row (column) v,
// whose edgels belong to the pixel at u = crossing, goes on for a second pixel away from the
// line: the side of a shape or a region, not a one-pixel step. The test of a corner (lineEnd,
// runEndsUnseen) and of a T junction (junctionGoesOn); WeightsComputer::CrossingGoesOn.
bool crossingGoesOn(ivec2 p, bool vertical, int crossing, int v, int code)
{
  return crossingAt(p, vertical, crossing, code == 3 ? v - 1 : v + 2);
}

// Whether the end of p's line whose crossing edgels belong to the pixel at u = crossing, of
// crossing-edge code `code`, is a T junction that the line goes on past: crossing edgels on one
// side, the line's own edgel going on straight past the end (at u = beyond) and the crossing edge
// going on for a second pixel away from the line. The line has no step there, and the end is read
// as one without crossing edges (WeightsComputer::JunctionGoesOn, issue 20).
bool junctionGoesOn(int code, ivec2 p, bool vertical, int crossing, int beyond)
{
  return (code == 1 || code == 3) && alongAt(p, vertical, beyond, 0) &&
    crossingGoesOn(p, vertical, crossing, 0, code);
}

// Whether the end of p's line in direction s (-1 or +1), `distance` pixels away with crossing code
// `code`, is the corner of a shape: a crossing edge on one side only that goes on for a second
// pixel away from the line, and no line going on one row (column) over past it. Issue 50;
// WeightsComputer::CornerEnd.
bool cornerEnd(ivec2 p, bool vertical, int s, int code, int distance)
{
  if (code != 1 && code != 3)
  {
    return false;
  }
  int beyond = s * (distance + 1); // the pixel just past the end
  int crossing = s < 0 ? beyond + 1 : beyond;
  return !alongAt(p, vertical, beyond, code == 3 ? -1 : 1) &&
    crossingGoesOn(p, vertical, crossing, 0, code);
}

// Whether a run of crossing edgels of the pixels at u = crossing begins at v, where the run one
// column (row) over ended, for two pixels or more away from the line: none at v - away, beside
// that run (WeightsComputer::CrossingEndsInStep).
bool nextRunFrom(ivec2 p, bool vertical, int crossing, int v, int away)
{
  return crossingAt(p, vertical, crossing, v) && crossingAt(p, vertical, crossing, v + away) &&
    !crossingAt(p, vertical, crossing, v - away);
}

// Whether the crossing edge of such a corner, followed away from the line within the reach, ends
// in a step of its own (the next run one column (row) over, for two pixels or more, beginning
// where it ends: a side meeting a steep staircase); `run` counts its pixels
// (WeightsComputer::CrossingEndsInStep).
bool crossingEndsInStep(ivec2 p, bool vertical, int s, int code, int distance, out int run)
{
  int crossing = s < 0 ? -distance : distance + 1;
  // The crossing edge covers v = 0 and -1 (code 3) or v = 1 and 2 (code 1); follow it on.
  int away = code == 3 ? -1 : 1;
  run = 2;
  for (int v = code == 3 ? -2 : 3; abs(v) <= cellSize - 1; v += away, ++run)
  {
    if (!crossingAt(p, vertical, crossing, v))
    {
      return nextRunFrom(p, vertical, crossing - 1, v, away) ||
        nextRunFrom(p, vertical, crossing + 1, v, away);
    }
  }
  return false;
}

// Whether that end has crossing edges on both sides (code 4) that both go on for a second pixel
// away from the line: a junction of shapes at least two pixels wide (WeightsComputer::WideJunction).
bool wideJunction(ivec2 p, bool vertical, int s, int code, int distance)
{
  int crossing = s < 0 ? -distance : distance + 1;
  return code == 4 && crossingGoesOn(p, vertical, crossing, 0, 1) &&
    crossingGoesOn(p, vertical, crossing, 0, 3);
}

// Whether p's line is the side of a shape that shows no step of a staircase (a shape shorter than
// four pixels in both directions, a rendered point, excepted): a corner at one end, and no step
// at the other (a corner, a junction of wider shapes, the image border, no crossing edge, or
// beyond the reach). It is left alone: nothing seen tells that it leaves the pixel boundary
// (issue 50; WeightsComputer::SideWithoutSteps).
bool sideWithoutSteps(ivec2 p, bool vertical, int e1, int e2, int d1, int d2)
{
  int length = d1 + d2 + 1;
  if (length == 1)
  {
    return false; // a step of the staircase across it, or the end of a one-pixel bar
  }
  bool corner1 = cornerEnd(p, vertical, -1, e1, d1);
  bool corner2 = cornerEnd(p, vertical, 1, e2, d2);
  if (!((corner1 || corner2) && (corner1 || e1 == 0 || wideJunction(p, vertical, -1, e1, d1)) &&
        (corner2 || e2 == 0 || wideJunction(p, vertical, 1, e2, d2))))
  {
    return false;
  }
  int run1 = 0, run2 = 0;
  if ((corner1 && crossingEndsInStep(p, vertical, -1, e1, d1, run1)) ||
    (corner2 && crossingEndsInStep(p, vertical, 1, e2, d2, run2)))
  {
    return false;
  }
  // A small shape, short in both directions (a rendered point), keeps the chapter's reading.
  return length >= 4 || d1 >= cellSize - 1 || d2 >= cellSize - 1 || max(run1, run2) >= 4;
}

// Whether one of the two pixels across the edgel of p's line (p and the pixel at v + 1) is one
// pixel thin across it: it has an edgel on its far side too. A line with code 4 at both ends is
// read as a thin feature's run only there (vtkMLAAAreaTexture); between the junctions of wider
// shapes it keeps no slope (WeightsComputer::ThinAcross).
bool thinAcross(ivec2 p, bool vertical)
{
  return alongAt(p, vertical, 0, -1) || alongAt(p, vertical, 0, 1);
}
// Whether such runs are read at all: not with the sample areas of a multisampled render, whose
// samples resolve how much of a pixel thin features cover, where the single-sample reading can
// only share it out evenly.
#ifdef MLAA_SAMPLE_AREAS
const bool readThinRuns = false;
#else
const bool readThinRuns = true;
#endif

#ifdef MLAA_DIAGONAL_DETECTION
#ifdef MLAA_STAIRCASE_REACH
// With recursive doubling, the units of staircases were counted beforehand
// (vtkMLAALineLengthsInitFS.glsl): a unit of a rising staircase (up and to the right) is a pixel
// with both edgels; a unit of a falling one, named by its pixel q, is q's top edgel and its right
// neighbour's left edgel.
// The four counts of pixel q: rising towards -x and +x, then falling towards -x and +x.
vec4 countsAt(ivec2 q)
{
  // RG8: two counts to a byte, the count towards -x plus 16 times the count towards +x.
  vec2 v = round(255.0 * texelFetch(staircaseCountsTexture, q, 0).rg);
  vec2 high = floor(v / 16.0);
  return vec4(v.r - 16.0 * high.r, high.r, v.g - 16.0 * high.g, high.g);
}

// The counts of units that follow unit q along its staircase, towards its first end (-x) and
// towards its second, each up to the reach (0 where q is no unit of that kind).
ivec2 unitCounts(ivec2 q, bool rising)
{
  vec4 counts = countsAt(clamp(q, ivec2(0), ivec2(edgesSize) - 1)); // whole numbers
  return ivec2(rising ? counts.rg : counts.ba);
}

// Number of further units of the staircase through unit q in `direction` (counts' `channel`),
// at most the maximum distance, given its unitCounts that way; reachedEnd tells whether the
// staircase ended within it. A count that equals the reach goes on at the unit that far, which is
// counted too: one read per reach units.
int followStaircase(ivec2 q, ivec2 direction, int channel, int count, out bool reachedEnd)
{
  int maxDistance = cellSize - 1;
  int last = count;
  while (last == MLAA_STAIRCASE_REACH && count < maxDistance)
  {
    last = int(countsAt(q + count * direction)[channel]);
    count += last;
  }
  reachedEnd = count < maxDistance;
  return min(count, maxDistance);
}
#else
// Otherwise they are searched here, one unit per step. A unit of a rising staircase (up and to
// the right) is a pixel with both edgels; a unit of a falling one, named by its pixel q, is q's
// top edgel and its right neighbour's left edgel. The unchecked tests read without the image's
// bounds: their caller keeps every pixel they read inside it; the checked ones find no unit
// outside it.
bool risingUnitInside(ivec2 p)
{
  return all(greaterThan(texelFetch(edgesTexture, p, 0).rg, vec2(0.5)));
}
bool fallingUnitInside(ivec2 q)
{
  return texelFetch(edgesTexture, q, 0).g > 0.5 &&
    texelFetch(edgesTexture, q + ivec2(1, 0), 0).r > 0.5;
}
bool isRisingUnit(ivec2 p) { return insideImage(p) && risingUnitInside(p); }
bool isFallingUnit(ivec2 q)
{
  return insideImage(q) && insideImage(q + ivec2(1, 0)) && fallingUnitInside(q);
}

// Whether the neighbours of unit q along its staircase, towards its first end (-x) and towards
// its second, are units (1) or not (0): the first step of each search.
ivec2 unitCounts(ivec2 q, bool rising)
{
  ivec2 direction = rising ? ivec2(1) : ivec2(1, -1); // towards the second end
  bvec2 next = rising ? bvec2(isRisingUnit(q - direction), isRisingUnit(q + direction))
                      : bvec2(isFallingUnit(q - direction), isFallingUnit(q + direction));
  return ivec2(next);
}

// Number of further units of the staircase through unit p in `direction` (rising for `channel`
// 0 and 1), at most the maximum distance, given whether the first of them is a unit (`count`,
// unitCounts); reachedEnd tells whether the staircase ended within it.
int followStaircase(ivec2 p, ivec2 direction, int channel, int count, out bool reachedEnd)
{
  int maxDistance = cellSize - 1;
  if (count == 0)
  {
    reachedEnd = true;
    return 0;
  }
  // A loop per kind, each reading what its kind needs: where pixels shaded in lock-step run
  // both sides of a branch, the loop of the other kind ends at once, where a read that depends on
  // the kind would read for both on every step.
  // The loops read the edgels without the image's bounds: they stop at the last unit inside it
  // (a falling unit also reads the pixel right of it), where the reads would find none.
  bool rising = channel < 2;
  ivec2 last = ivec2(edgesSize) - ivec2(rising ? 1 : 2, 1);
  ivec2 room = ivec2(direction.x > 0 ? last.x - p.x : p.x, direction.y > 0 ? last.y - p.y : p.y);
  int reach = min(maxDistance, min(room.x, room.y));
  int k = 2;
  if (rising)
  {
    while (k <= reach && risingUnitInside(p + k * direction))
    {
      ++k;
    }
  }
  else
  {
    while (k <= reach && fallingUnitInside(p + k * direction))
    {
      ++k;
    }
  }
  if (k <= maxDistance)
  {
    reachedEnd = true;
    return k - 1;
  }
  reachedEnd = false;
  return maxDistance;
}
#endif
#endif

// End code of the diagonal table (0 nothing, 1 out of the unit's pixel, 2 into it) from what the
// staircase does past its end: a run along x (flatter) or along y (steeper).
int diagonalEndCode(bool reachedEnd, bool flatter, bool steeper, int flatterCode)
{
  if (!reachedEnd || flatter == steeper)
  {
    return 0;
  }
  return flatter ? flatterCode : 3 - flatterCode;
}

vec3 diagonalArea(int e1, int e2, int d1, int d2)
{
  return texelFetch(diagonalAreaTexture, ivec2(cellSize * e1 + d1, cellSize * e2 + d2), 0).rgb;
}

#ifdef MLAA_CORNER_EXTRAPOLATION
// Distance from pixel q to the end of its line (of top edgels, or of left edgels if vertical) in
// direction s of u, as the distances of lineWeights are found.
int runDistance(ivec2 q, bool vertical, int s)
{
#ifdef MLAA_RECURSIVE_DOUBLING
  // lengthsTexture: left, right, down, up.
  int component = vertical ? (s < 0 ? 3 : 2) : (s < 0 ? 0 : 1);
  return min(int(round(texelFetch(lengthsTexture, q, 0)[component])), 2 * maxSearchSteps);
#else
  int code;
  return searchLine(vec2(q) + 0.5, vertical, vertical ? float(-s) : float(s), code);
#endif
}

// CornerExtrapolation (WeightsComputer::ExtrapolateCorners in vtkMLAABlendingWeights.cxx says
// why): ends = (code, distance) of the first and of the second end of a line; unseen: whether the
// line's course past each end is not seen (a corner of a shape, or the image border); next: the
// length of the staircase's next run past each end that is a step (0: none). Where exactly one
// end is unseen and the other is a step whose next run can belong to one straight staircase with
// this line, the unseen end becomes a virtual step one whole run from the step (a Z shape), or
// beyond the reach (code 0 at the maximum distance); where that next run ends unseen as well
// (nextUnseen: the side's only step), one run of twice the longer of the two. Where the other
// end, within the reach and of code 0, 1 or 3, gives no such run, an unseen end of code 1 or 3
// keeps its code and takes half its ramp instead (halved: which end; its height is unknown).
// Returns whether it changed the ends.
bool extrapolateCorners(
  inout ivec4 ends, bvec2 unseen, ivec2 next, bvec2 nextUnseen, out bvec2 halved)
{
  halved = bvec2(false);
  if (unseen.x == unseen.y)
  {
    return false;
  }
  ivec2 step = unseen.x ? ends.zw : ends.xy;
  ivec2 unseenEnd = unseen.x ? ends.xy : ends.zw;
  int stepNext = unseen.x ? next.y : next.x;
  int length = ends.y + ends.w + 1;
  int maxDistance = cellSize - 1;
  int run = max(length, stepNext);
  if (unseen.x ? nextUnseen.y : nextUnseen.x)
  {
    run *= 2; // the step is the side's only one: the expected run is twice the longer one seen
  }
  else if (stepNext < 2 || stepNext + 1 < length)
  {
    if (step.x == 4 || step.y >= maxDistance || (unseenEnd.x != 1 && unseenEnd.x != 3))
    {
      return false;
    }
    halved = unseen;
    return true;
  }
  int distance = run - 1 - step.y;
  ivec2 corner = ivec2(4 - step.x, distance);
  if (stepNext > maxDistance || distance > maxDistance)
  {
    corner = ivec2(0, maxDistance);
  }
  if (unseen.x)
  {
    ends.xy = corner;
  }
  else
  {
    ends.zw = corner;
  }
  return true;
}

// Whether the staircase's next run, at v from u of p's line coordinates and `length` pixels long
// in direction s, ends at a corner or the image border (WeightsComputer::RunEndsUnseen).
bool runEndsUnseen(ivec2 p, bool vertical, int u, int v, int s, int length)
{
  int last = u + s * (length - 1);
  if (s * last >= toBorder(p, vertical, s))
  {
    return true;
  }
  if (length - 1 >= 2 * maxSearchSteps)
  {
    return false;
  }
  int crossing = s < 0 ? last : last + 1;
  int code =
    3 * int(crossingAt(p, vertical, crossing, v)) + int(crossingAt(p, vertical, crossing, v + 1));
  if ((code != 1 && code != 3) || alongAt(p, vertical, last + s, code == 3 ? v - 1 : v + 1))
  {
    return false;
  }
  return crossingGoesOn(p, vertical, crossing, v, code);
}

// The end of p's line in direction s (-1: the first end, +1: the second), `distance` pixels
// away, with crossing-edge code `code` (WeightsComputer::LineEnd). Returns (unseen, next run
// length, whether the next run ends unseen).
ivec3 lineEnd(int code, ivec2 p, bool vertical, int s, int distance)
{
  if (code != 1 && code != 3)
  {
    return ivec3(0);
  }
  int beyond = s * (distance + 1); // the pixel just past the end
  int crossing = s < 0 ? beyond + 1 : beyond; // the crossing edge's pixel
  int next = code == 3 ? -1 : 1;
  if (alongAt(p, vertical, beyond, next))
  {
    int length = runDistance(lineToImage(p, vertical, beyond, next), vertical, s) + 1;
    return ivec3(0, length, runEndsUnseen(p, vertical, beyond, next, s, length) ? 1 : 0);
  }
  return ivec3(crossingGoesOn(p, vertical, crossing, 0, code) ? 1 : 0, 0, 0);
}
#endif

const int OUT = 1;
const int IN = 2;

#ifdef MLAA_DIAGONAL_DETECTION
// The diagonal areas (vtkMLAAAreaTexture::ComputeDiagonalAreas) of the staircase through unit q,
// rising or falling, if it has at least MLAA_MINIMUM_DIAGONAL_LENGTH units. `counts` are q's
// unitCounts. The ends' codes come from what the staircase does past them: a run along x
// (flatter) or along y (steeper).
bool staircaseAreas(ivec2 q, bool rising, ivec2 counts, out vec3 a)
{
  ivec2 direction = rising ? ivec2(1) : ivec2(1, -1); // towards the second end
  int channel = rising ? 0 : 2;
  bool end1, end2;
  int d1 = followStaircase(q, -direction, channel, counts.x, end1);
  int d2 = followStaircase(q, direction, channel + 1, counts.y, end2);
  if (d1 + d2 + 1 < MLAA_MINIMUM_DIAGONAL_LENGTH)
  {
    return false;
  }
  ivec2 q1 = q - d1 * direction;
  ivec2 q2 = q + d2 * direction;
  int e1 = rising
    ? diagonalEndCode(end1, topAt(q1 - ivec2(1)), leftAt(q1 - ivec2(0, 1)), OUT)
    : diagonalEndCode(end1, topAt(q1 - ivec2(1, 0)), leftAt(q1 + ivec2(0, 1)), IN);
  int e2 = rising
    ? diagonalEndCode(end2, topAt(q2 + ivec2(1, 0)), leftAt(q2 + ivec2(1)), IN)
    : diagonalEndCode(end2, topAt(q2 + ivec2(1, -1)), leftAt(q2 + ivec2(1, -1)), OUT);
  a = diagonalArea(e1, e2, d1, d2);
  return true;
}
#endif

// The two weights of the line through p's top edgel (vertical false) or its left edgel (true),
// section 4.3: the distances to its ends, d1 before p and d2 after it along u (searched, or with
// MLAA_RECURSIVE_DOUBLING the given lengths), the crossing-edge codes there, and the area.
vec2 lineWeights(ivec2 p, bool vertical, ivec2 lengths)
{
  int e1, e2, d1, d2;
#ifdef MLAA_RECURSIVE_DOUBLING
  d1 = lengths.x;
  d2 = lengths.y;
  // The codes, read 3:1 between p's row (column) and the one across: round(4 v).
  vec2 center = vec2(p) + 0.5;
  vec2 along = vertical ? vec2(0.0, -1.0) : vec2(1.0, 0.0); // u in the image
  vec2 fetch = center + (vertical ? vec2(-0.25, 0.0) : vec2(0.0, 0.25));
  vec2 c1 = edgesAt(fetch - along * float(d1));
  vec2 c2 = edgesAt(fetch + along * float(d2 + 1));
  e1 = int(round(4.0 * (vertical ? c1.g : c1.r)));
  e2 = int(round(4.0 * (vertical ? c2.g : c2.r)));
#else
  // searchLine's direction: x right, y up.
  float first = vertical ? 1.0 : -1.0;
  d1 = searchLine(vec2(p) + 0.5, vertical, first, e1);
  d2 = searchLine(vec2(p) + 0.5, vertical, -first, e2);
#endif
  e1 = insideCode(e1, p, vertical, -d1);
  e2 = insideCode(e2, p, vertical, d2 + 1);
  if (junctionGoesOn(e1, p, vertical, -d1, -d1 - 1))
  {
    e1 = 0;
  }
  if (junctionGoesOn(e2, p, vertical, d2 + 1, d2 + 1))
  {
    e2 = 0;
  }
  // With sample areas, a pixel pair whose samples differ measures where the side lies instead
  // (read only for such sides: lineArea reads them for the others).
  if (sideWithoutSteps(p, vertical, e1, e2, d1, d2)
#ifdef MLAA_SAMPLE_AREAS
    && !(samplesDiffer(p) || samplesDiffer(lineToImage(p, vertical, 0, 1)))
#endif
  )
  {
    return vec2(0.0);
  }
  bvec2 halved = bvec2(false); // ends of half height (CornerExtrapolation)
#ifdef MLAA_CORNER_EXTRAPOLATION
  if (d1 + d2 > 0)
  {
    ivec3 end1 = lineEnd(e1, p, vertical, -1, d1);
    ivec3 end2 = lineEnd(e2, p, vertical, 1, d2);
    ivec4 ends = ivec4(e1, d1, e2, d2);
    bvec2 unseen = bvec2(end1.x != 0, end2.x != 0);
    ivec2 next = ivec2(end1.y, end2.y);
    bvec2 nextUnseen = bvec2(end1.z != 0, end2.z != 0);
    int border1 = toBorder(p, vertical, -1);
    int border2 = toBorder(p, vertical, 1);
    if (d1 >= border1) // the image border: the line's course beyond it is not seen
    {
      ends.xy = ivec2(0, border1);
      unseen.x = true;
      next.x = 0;
      nextUnseen.x = false;
    }
    if (d2 >= border2)
    {
      ends.zw = ivec2(0, border2);
      unseen.y = true;
      next.y = 0;
      nextUnseen.y = false;
    }
    if (extrapolateCorners(ends, unseen, next, nextUnseen, halved))
    {
      e1 = ends.x;
      d1 = ends.y;
      e2 = ends.z;
      d2 = ends.w;
    }
  }
#endif
  if (e1 == 4 && e2 == 4 && !(readThinRuns && thinAcross(p, vertical)))
  {
    e1 = e2 = 0; // junctions of wider shapes at both ends: no slope
  }
  return any(halved) ? area(e1, e2, d1, d2, halved)
                     : lineArea(p, lineToImage(p, vertical, 0, 1), vertical, e1, e2, d1, d2);
}

void main()
{
  ivec2 size = textureSize(edgesTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  edgesSize = vec2(size);
  vec2 e = texelFetch(edgesTexture, p, 0).rg;
  vec4 weights = vec4(0.0);
  bool top = e.g > 0.5;
  bool left = e.r > 0.5;

#ifdef MLAA_DIAGONAL_DETECTION
  {
    // The staircase units this pixel's edgels may belong to, as candidates: 1, a rising unit
    // (this pixel, both edgels; its first end is the lower-left one); 2, a falling unit q =
    // this pixel (its top edgel and the right neighbour's left edgel); 4, a falling unit q = the
    // left neighbour (its top edgel and this pixel's left edgel). Falling staircases' first end
    // is the upper-left one. A unit with a unit next to it along its diagonal may lie on a
    // staircase of MLAA_MINIMUM_DIAGONAL_LENGTH (2) units; the others are left out here, so that
    // the loop below runs only for pixels on staircases: a loop runs as many times as its
    // pixels need, where both sides of a branch may be executed (rasterisers that shade pixels in
    // lock-step, llvmpipe among them), and most edge pixels are on none.
    ivec2 dx = ivec2(1, 0);
    const bool single = MLAA_MINIMUM_DIAGONAL_LENGTH <= 1;
    ivec2 risingNext = unitCounts(p, true);
    ivec2 qNext = unitCounts(p, false);
    ivec2 rNext = unitCounts(p - dx, false);
    int candidates = (top && left && (any(greaterThan(risingNext, ivec2(0))) || single)) ? 1 : 0;
    candidates |= (top && leftAt(p + dx) && (any(greaterThan(qNext, ivec2(0))) || single)) ? 2 : 0;
    candidates |= (left && topAt(p - dx) && (any(greaterThan(rNext, ivec2(0))) || single)) ? 4 : 0;
    while (candidates != 0)
    {
      int c = (candidates & 1) != 0 ? 1 : ((candidates & 2) != 0 ? 2 : 4);
      candidates -= c;
      vec3 a;
      if (!staircaseAreas(c == 4 ? p - dx : p, c == 1,
            c == 1 ? risingNext : (c == 2 ? qNext : rNext), a))
      {
        continue;
      }
      if (c == 1)
      {
        // This pixel takes the colours above and left of it; the pixel above lies after it
        // along the line, the one to the left before it. Its edgels belong to this staircase:
        // no falling one is looked at.
        weights = vec4(a.x, a.z, a.x, a.y);
        top = false;
        left = false;
        candidates = 0;
      }
      else if (c == 2)
      {
        weights.rg = a.xy; // q takes the colour above it, the r of the unit before
        top = false;
      }
      else
      {
        weights.ba = a.zx; // r lies after q along the line; q takes r's colour
        left = false;
      }
    }
  }
#endif

#ifdef MLAA_RECURSIVE_DOUBLING
  // The same distances as the searches of lineWeights, counted for every pixel at once.
  ivec4 lengths = (top || left)
    ? min(ivec4(round(texelFetch(lengthsTexture, p, 0))), ivec4(2 * maxSearchSteps))
    : ivec4(0);
#else
  ivec4 lengths = ivec4(0); // searched
#endif

  if (top) // a horizontal line, its first end to the left
  {
    weights.rg = lineWeights(p, false, lengths.xy);
  }
  if (left) // a vertical line, its first end the upper one
  {
    weights.ba = lineWeights(p, true, lengths.wz);
  }

  gl_FragData[0] = weights;
}
