//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// DLAA pass 2 of 2: short and long edges (vtkDLAAOptions, steps 1 and 2), drawn into the
// renderer's viewport of the target framebuffer, from the delegate's image and the masks of
// pass 1 (vtkDLAAMasksFS: mx, my; -1 where the pixel's 5-pixel cross holds a colour that is not
// finite).
//   s = lerp(lerp(c, Bx, mx), By, my / 2);
// with DLAA_LONG_EDGES, Mx = saturate(2 a - 1) for a the mean of mx over p - 8 .. p + 8 along x,
// My likewise along y; where exactly one of them is positive, the pixel is moved towards one of
// its two neighbours across the edge until its luminosity is that of the mean colour along the
// edge over p - h .. p + h (the first neighbour, above or left, on a tie), and mixed into s by
// that mask. h, from 1 to 8, is half the length of the step the pixel is on (stepHalfLength).
// Pixels that read a colour that is not finite are left as they are: those whose 5-pixel cross
// holds one and, with long edges, those with such a cross within 8 pixels along x or y. Exact
// texel reads, clamped to the border.
//
// Compile-time variants (#defines prepended by vtkOpenGLDLAAPass):
//   DLAA_LUMA        0 Rec. 709 luma, 1 green (vtkDLAAOptions::LumaFunction)
//   DLAA_LONG_EDGES  defined: vtkDLAAOptions::LongEdges
//   DLAA_IN_PLACE    defined: the target already holds the delegate's image and depth; pixels
//                    the method leaves alone are discarded and no depth is written. Otherwise
//                    every pixel and its depth are written.
//   DLAA_MOTION_FRAME  defined: temporal antialiasing with a moving camera
//                    (vtkOpenGLAntialiasingPass::HasMotionFrame); the second draw buffer takes the
//                    motion frame: the same without the short-edge blur (c where s is, then the
//                    same long-edge step), which the temporal blend uses where the history moved
//                    a pixel or more.
//   DLAA_NO_SHORT_EDGES  defined: a sample image of a multisampled render whose samples were
//                    each shaded on its own (vtkOpenGLDLAAPass::ShortEdgesFromSamples): no
//                    short-edge blur (s = c), the long-edge step alone; the average of the sample
//                    images measures the coverage that the blur estimates. The long-edge step is
//                    taken only where the samples see a step within its window (stepSeen).
//
// Must match vtkImageDLAA.

in vec2 texCoord;

uniform sampler2D colorTexture; // the delegate's image
uniform sampler2D depthTexture; // the delegate's depth (not in place)
uniform sampler2D masksTexture; // pass 1 output, `padding` pixels larger each side
#ifdef DLAA_LONG_EDGES
uniform sampler2D tilesTexture; // which tiles of 8 x 8 masks hold one other than 0
#endif
uniform int padding;
uniform sampler2D cornersTexture; // the sides of corners (vtkDLAACornersFS)
//VTK::DLAA::Luma

// The last pixel of the image, set by main before any read. (Initialised here only so that
// compilers that check globals in source order, as Mesa's does, see it set.)
ivec2 last = ivec2(0);

vec4 colorAt(ivec2 q)
{
  return texelFetch(colorTexture, clamp(q, ivec2(0), last), 0);
}

// The pixel c moved towards the neighbour n0 or n1 (n0 first on a tie) until its luminosity is
// t; c itself when neither reaches t within one step.
vec4 towards(vec4 c, vec4 n0, vec4 n1, float t)
{
  float lc = luma(c);
  float best = 2.0;
  vec4 q = c;
  float l0 = luma(n0) - lc;
  if (l0 != 0.0)
  {
    float k = (t - lc) / l0;
    if (k > 0.0 && k <= 1.0)
    {
      best = k;
      q = mix(c, n0, k);
    }
  }
  float l1 = luma(n1) - lc;
  if (l1 != 0.0)
  {
    float k = (t - lc) / l1;
    if (k > 0.0 && k <= 1.0 && k < best)
    {
      q = mix(c, n1, k);
    }
  }
  return q;
}

// The sides of corners (vtkDLAACornersFS, vtkDLAAOptions step 3): whether the boundary between q
// and q + step (one pixel along x or y, either way) is one. Boundaries with the border are none.
bool cornerBetween(ivec2 q, ivec2 step)
{
  ivec2 r = step.x + step.y < 0 ? q + step : q; // the pixel left of or below the boundary
  if (any(lessThan(r, ivec2(0))) || any(greaterThan(r, last)))
  {
    return false;
  }
  vec4 flags = texelFetch(cornersTexture, r, 0);
  return (step.x != 0 ? flags.r : flags.g) > 0.5;
}

// How many pixels, 0 to 2, the short-edge blur of p reads along `along` before a corner's side.
int blurReach(ivec2 p, ivec2 along)
{
  return cornerBetween(p, along) ? 0 : (cornerBetween(p + along, along) ? 1 : 2);
}

// The short-edge blur of p along `along`: its 5 pixels, each read no farther than the blur
// reaches on its side.
vec4 shortBlur(ivec2 p, vec4 c, ivec2 along)
{
  int ahead = blurReach(p, along);
  int behind = blurReach(p, -along);
  return (colorAt(p - min(2, behind) * along) + colorAt(p - min(1, behind) * along) +
           colorAt(p + min(1, ahead) * along) + colorAt(p + min(2, ahead) * along) + 2.0 * c) /
    6.0;
}

// How far the step of a long edge that the pixel p is on reaches from p in the direction
// `along`, at most `limit` pixels: as far as the two neighbours across the edge (p - across and
// p + across) keep their luminosity, within half their difference. One exception: where the
// pixel has one of them on its side of the edge (within that tolerance) and the other not, the
// step may go on once through the place where the pixel's row (or column) and the other
// neighbour swap luminosities, which is where a line one pixel wide moves into the pixel's row:
// without it, the pixels beside such a line would see its step end at the very place where the
// line reaches them. vtkDLAAStages::StepReach computes the same.
bool near(float x, float y, float tolerance)
{
  return abs(x - y) <= tolerance;
}

// Whether the luminosities m (this side's neighbour, the pixel's row, the other side's) are those
// the step had, e, with this side's neighbour and the pixel's row swapped; if so, e takes them.
bool swapped(inout float side, inout float middle, float other, float mSide, float mMiddle,
  float mOther, float tolerance)
{
  if (near(mSide, middle, tolerance) && near(mMiddle, side, tolerance) &&
    near(mOther, other, tolerance))
  {
    float t = side;
    side = middle;
    middle = t;
    return true;
  }
  return false;
}

int stepReach(ivec2 p, ivec2 along, ivec2 across, int limit, out bool corner)
{
  corner = false;
  float e0 = luma(colorAt(p - across));
  float e1 = luma(colorAt(p));
  float e2 = luma(colorAt(p + across));
  float tolerance = 0.5 * abs(e0 - e2);
  bool swap = near(e0, e1, tolerance) != near(e2, e1, tolerance);
  float row = e1; // the luminosity of the pixel's row (or column) at i - 1
  for (int i = 1; i <= limit; ++i)
  {
    ivec2 q = p + i * along;
    float m0 = luma(colorAt(q - across));
    float m1 = luma(colorAt(q));
    float m2 = luma(colorAt(q + across));
    if (m1 != row && cornerBetween(p + (i - 1) * along, along))
    {
      corner = true;
      return i - 1; // the window stops before a corner's side
    }
    row = m1;
    if (near(m0, e0, tolerance) && near(m2, e2, tolerance))
    {
      continue;
    }
    if (swap &&
      (swapped(e0, e1, e2, m0, m1, m2, tolerance) || swapped(e2, e1, e0, m2, m1, m0, tolerance)))
    {
      swap = false;
      continue;
    }
    return i - 1;
  }
  return limit;
}

// Half the length, from 1 to 8 pixels, of the window along the edge over which the long-edge
// step takes its mean: the shorter of the step's two reaches from p. The mean along the edge over
// a window longer than the step would spread the step's transition over the whole window: on an
// edge a few pixels from vertical or horizontal (steps of 2 to 16 pixels) that blurs it across
// more than the pixels it covers, and as the edge moves the steps' windows flicker. 0 where a
// corner's side lies next to p: the window would cross it, and the mean of p alone leaves p as it
// is.
int stepHalfLength(ivec2 p, ivec2 along, ivec2 across)
{
  bool cornerAhead;
  bool cornerBehind;
  int ahead = stepReach(p, along, across, 8, cornerAhead);
  // (At least 1 pixel behind: a corner's side there sets 0 whatever the reach ahead.)
  int behind = stepReach(p, -along, across, max(ahead, 1), cornerBehind);
  return (cornerAhead && ahead == 0) || (cornerBehind && behind == 0) ? 0
                                                                      : max(1, min(ahead, behind));
}

#ifdef DLAA_NO_SHORT_EDGES
// samplesColor, numberOfSamples and samplesDiffer (vtkAntialiasingSamplesDiffer.glsl).
//VTK::Antialiasing::SamplesDiffer

// Whether the samples see a step of the long edge that the pixel p is on, within the window of
// its long-edge step (h pixels each way along it): some pixel of the window, on the pixel's row
// (or column) or on either side across, has samples that differ. Where none has, every sample
// of those pixels agrees, so the edge lies within the gap between the sample pattern and the
// pixel border all along the window: a side that lies on pixel borders and ends at a corner or a
// junction of other sides (voxels, bars), which the step would ramp from that end. A step of a
// real staircase crosses the sample patterns of the pixels where it is.
// (From the pixel outwards: the nearest pixels are read first.)
bool stepSeen(ivec2 p, ivec2 along, ivec2 across, int h)
{
  for (int d = 0; d <= h; ++d)
  {
    for (int j = -1; j <= 1; ++j)
    {
      if (samplesDiffer(p + d * along + j * across) || samplesDiffer(p - d * along + j * across))
      {
        return true;
      }
    }
  }
  return false;
}
#endif

void leave(vec4 c)
{
#ifdef DLAA_IN_PLACE
  discard;
#else
  gl_FragData[0] = c;
#ifdef DLAA_MOTION_FRAME
  gl_FragData[1] = c;
#endif
#endif
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  last = size - ivec2(1);
  ivec2 p = ivec2(texCoord * vec2(size));
#ifndef DLAA_IN_PLACE
  gl_FragDepth = texelFetch(depthTexture, p, 0).r;
#endif
  ivec2 pm = p + ivec2(padding); // p in the masks texture
#ifdef DLAA_LONG_EDGES
  // The tiles of 8 x 8 masks (vtkDLAATilesFS) that the pixel's windows touch: texels pm.x - 8 to
  // pm.x + 8 of its row lie in three tiles whatever pm.x, the middle one pm / 8, which holds the
  // pixel itself; the column likewise. Where all five hold masks of 0 only, the pixel has no
  // short edge and both long masks are 0: the method leaves it as it is.
  ivec2 tile = pm / 8;
  if (texelFetch(tilesTexture, tile, 0).r == 0.0 &&
    texelFetch(tilesTexture, tile - ivec2(1, 0), 0).r == 0.0 &&
    texelFetch(tilesTexture, tile + ivec2(1, 0), 0).r == 0.0 &&
    texelFetch(tilesTexture, tile - ivec2(0, 1), 0).r == 0.0 &&
    texelFetch(tilesTexture, tile + ivec2(0, 1), 0).r == 0.0)
  {
    leave(texelFetch(colorTexture, p, 0));
    return;
  }
#endif
  vec4 c = texelFetch(colorTexture, p, 0);
  vec4 m = texelFetch(masksTexture, pm, 0);
  if (m.x < 0.0)
  {
    leave(c); // the 5-pixel cross holds a colour that is not finite
    return;
  }

#ifdef DLAA_LONG_EDGES
  // The long masks: means of mx along x and of my along y over 17 pixels, and whether a mask
  // they average read a colour that is not finite.
  // A pixel without a short edge changes only where a long mask is positive, which takes a sum
  // of 17 masks, each at most 1, above 8.5: once the masks still to be read (9 - i of them)
  // could not lift either sum above 8, the pixel is left as it is whatever they hold (a colour
  // that is not finite among them would leave it too). Such pixels near an edge read 9 pairs of
  // masks instead of 17, with the same result. (The bound is the uniform `padding`, 8 here, so
  // that the loop is not unrolled and ends once every pixel shaded with this one is done.)
#ifdef DLAA_NO_SHORT_EDGES
  bool shortEdge = false; // only a long mask changes the pixel
#else
  bool shortEdge = m.x > 0.0 || m.y > 0.0;
#endif
  float sumX = 0.0;
  float sumY = 0.0;
  bool bad = false;
  bool needed = true;
  for (int i = -padding; i <= padding; ++i)
  {
    if (!shortEdge && sumX <= float(i - 1) && sumY <= float(i - 1))
    {
      needed = false;
      break;
    }
    vec4 mX = texelFetch(masksTexture, pm + ivec2(i, 0), 0);
    vec4 mY = texelFetch(masksTexture, pm + ivec2(0, i), 0);
    sumX += mX.x;
    sumY += mY.y;
    bad = bad || mX.x < 0.0 || mY.x < 0.0;
  }
  if (bad || !needed)
  {
    leave(c);
    return;
  }
  float longX = clamp(2.0 * (sumX / 17.0) - 1.0, 0.0, 1.0);
  float longY = clamp(2.0 * (sumY / 17.0) - 1.0, 0.0, 1.0);
#else
  float longX = 0.0;
  float longY = 0.0;
#endif
  if (m.x <= 0.0 && m.y <= 0.0 && longX <= 0.0 && longY <= 0.0)
  {
    leave(c); // flat, or faint noise: exactly as rendered
    return;
  }

  // Short edges.
  vec4 left = colorAt(p - ivec2(1, 0));
  vec4 right = colorAt(p + ivec2(1, 0));
  vec4 below = colorAt(p - ivec2(0, 1));
  vec4 above = colorAt(p + ivec2(0, 1));
#ifdef DLAA_NO_SHORT_EDGES
  vec4 result = c;
#else
  vec4 blurX = m.x > 0.0 ? shortBlur(p, c, ivec2(1, 0)) : c;
  vec4 blurY = m.y > 0.0 ? shortBlur(p, c, ivec2(0, 1)) : c;
  vec4 result = mix(mix(c, blurX, m.x), blurY, m.y / 2.0);
#endif
  vec4 motionFrame = c; // (DLAA_MOTION_FRAME) no short-edge blur

#ifdef DLAA_LONG_EDGES
  // Long edges, unless both directions have one (noise, texture). One code path for either
  // direction: llvmpipe runs every branch that a pixel of its group takes, so two branches, one
  // a direction, would each cost every group with a long edge.
  if ((longX > 0.0) != (longY > 0.0))
  {
    bool horizontal = longX > 0.0; // the edge runs along x
    ivec2 along = horizontal ? ivec2(1, 0) : ivec2(0, 1);
    ivec2 across = horizontal ? ivec2(0, 1) : ivec2(1, 0);
    float longMask = horizontal ? longX : longY;
    int h = stepHalfLength(p, along, across);
    vec4 sum = vec4(0.0);
    for (int i = -h; i <= h; ++i)
    {
      sum += colorAt(p + i * along);
    }
    // Towards the neighbour across the edge: above or below, left or right.
    vec4 stepped = towards(c, horizontal ? above : left, horizontal ? below : right,
      luma(sum / float(2 * h + 1)));
#ifdef DLAA_NO_SHORT_EDGES
    stepped = stepped == c || stepSeen(p, along, across, h) ? stepped : c;
#endif
    result = mix(result, stepped, longMask);
    motionFrame = mix(motionFrame, stepped, longMask);
  }
#endif

#ifdef DLAA_IN_PLACE
  bool changed = result != c;
#ifdef DLAA_MOTION_FRAME
  changed = changed || motionFrame != c;
#endif
  if (!changed)
  {
    discard;
  }
#endif
  gl_FragData[0] = result;
#ifdef DLAA_MOTION_FRAME
  gl_FragData[1] = motionFrame;
#endif
}
