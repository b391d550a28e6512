//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// Temporal antialiasing of vtkOpenGLAntialiasingPass (SetTemporal): blends the current frame
// with the history of the previous frames.
//
// Compile-time variants (#defines prepended by vtkOpenGLAntialiasingPass; at most one defined):
//   TEMPORAL_OUTPUT     writes the blended history (historyTexture) and the delegate's depth into
//                       the target viewport (nothing is blended here).
//   TEMPORAL_REPROJECT  the camera moved (currentTexture is the frame antialiased by the
//                       method): the history is read where this pixel's point was in the
//                       previous frame, `reprojection` taking the current normalised device
//                       coordinates to the previous ones, with the depth and motion of the
//                       nearest point of the 3 x 3 neighbourhood, by Catmull-Rom interpolation,
//                       and clamped per channel to the range of the 3 x 3 neighbourhood of this
//                       frame as the delegate rendered it, before the method (frameTexture; what
//                       the current frame does not support: disocclusions, changed shading); a
//                       point that was outside the previous view, or hidden at the previous
//                       render behind something nearer (previousDepthTexture: a disocclusion,
//                       WasOccluded), takes the current frame alone.
//                       The current frame's weight rises with the distance the history moved,
//                       from currentWeight at rest to MovingWeight at MovingPixels, and on to 1
//                       (the current frame alone) at HistoryPixels and more; and it rises with
//                       the angle the direction of view turned at the point, to 1 at
//                       HistoryDegrees.
//   TEMPORAL_MOTION_FRAME  (with TEMPORAL_REPROJECT) the method wrote a motion frame
//                       (motionTexture; vtkOpenGLAntialiasingPass::HasMotionFrame): where the
//                       history is read and moved a pixel or more, and the edges at the pixel a
//                       quarter of a pixel or more across themselves, the blend takes it instead
//                       of the method's frame (MotionFrameShare).
//   TEMPORAL_MASK       (with TEMPORAL_REPROJECT) copies the current frame into the new
//                       history at every pixel, and marks with depth 1 the pixels the
//                       reprojecting blend does not discard (flatFrame), 0 the others, so that
//                       the blend then runs on them only, the depth test dropping the others
//                       before their shader runs (TemporalHistories::MarkBlendedPixels in
//                       vtkOpenGLAntialiasingPassTemporal.cxx).
//                       One pass for both: every pixel writes the same, with no discard.
//   TEMPORAL_KEEP_UNCHANGED  actors moved under a still camera (currentTexture is the frame
//                       antialiased by the method): nothing is reprojected; a pixel whose 3 x 3
//                       neighbourhood in the method's frame equals the last unjittered render's
//                       (previousTexture) keeps its history as it is, any other takes the
//                       current frame.
//   none                (a still camera; currentTexture is the delegate's jittered render): the
//                       history is read at this pixel, exactly, and not clamped: weighing the
//                       current frame 1 / N, N the pixel's count, the blend is the running average
//                       of the N renders it holds.
// The variants are separate programs rather than branches on a uniform: rasterisers that shade
// pixels in lock-step (llvmpipe among them) run both sides of a branch, so every pixel would pay
// for the reads of the other modes.
// currentWeight: the weight of the current frame (1: the current frame alone, the history is not
// read). Besides the history (gl_FragData[0]) the blend writes each pixel's count of frames in it
// (gl_FragData[1], from countTexture): 1 where the current frame replaces or mostly replaces the
// history (a reset, a moving camera, a pixel moving actors reached), the count plus one in a still
// accumulation, whose running average weighs the current frame 1 / count: a pixel that kept its
// history while actors moved goes on from its own count when they stop.

in vec2 texCoord; // over the viewport, which is the size of the textures
uniform sampler2D historyTexture; // RGBA, floating point
uniform sampler2D depthTexture;   // the delegate's depth
#ifndef TEMPORAL_OUTPUT
uniform sampler2D currentTexture; // this frame
uniform sampler2D countTexture;   // the frames the history holds, per pixel
uniform float currentWeight;
#endif
#ifdef TEMPORAL_REPROJECT
uniform mat4 reprojection;
uniform sampler2D frameTexture; // this frame as the delegate rendered it (not antialiased)
#ifdef TEMPORAL_MOTION_FRAME
uniform sampler2D motionTexture; // the method's motion frame
#endif
// Current normalised device coordinates to the point's world coordinates relative to the current
// eye; the eyes of this frame and the previous one in that frame, homogeneous (a parallel
// projection's is a point at infinity, w = 0, opposite its direction of projection).
uniform mat4 toPoint;
uniform vec4 currentEye;
uniform vec4 previousEye;
// The delegate's depth at the previous render, and the entries (2, 2), (2, 3), (3, 2), (3, 3) of
// that render's projection, which take its depth to the distance from the eye (EyeDistance).
uniform sampler2D previousDepthTexture;
uniform vec4 previousDepthToEye;
uniform vec2 previousJitter;
#endif
#ifdef TEMPORAL_KEEP_UNCHANGED
uniform sampler2D previousTexture; // the last unjittered render's frame, antialiased by the method
#endif

#ifdef TEMPORAL_REPROJECT
// The weight of the current frame for a pixel whose history moved MovingPixels or more since the
// last frame. Reading the history between texels blurs it a little (Catmull-Rom is close to exact
// only near texel centres), and a pixel's history has been read again at every frame it carries:
// the farther it moves a frame, the shorter the history it keeps. Measured on mlaa-temporal's five
// orbit scenes at 0.2 and 0.5 degrees a frame (docs/measurements.md).
const float MovingWeight = 0.7;
const float MovingPixels = 1.0;
// Beyond MovingPixels the weight goes on rising, to 1 at HistoryPixels: the farther a point moved
// since the last frame, the more of its reprojected history is error the clamp cannot see (the
// depth's precision, the nearest point's motion lent to its neighbours, shading and silhouettes
// that change with the view), and the less of the picture it still has in common with the
// current frame. Measured on the orbit scenes at 0.2 to 2 degrees a frame (background pixels
// move about 2.7 pixels a frame at 0.2 degree, 27 at 2): no change at 0.2 and 0.5 degree, better
// at 1 and 2 degrees, where a fixed 0.7 fell below the single-frame method (docs/measurements.md).
const float HistoryPixels = 16.0;
// Shading that depends on the direction of view (specular highlights, a headlight) and the
// silhouettes of curved surfaces move over the surface as the view turns, which reprojecting the
// surface's points does not follow, and across a silhouette or a highlight the 3 x 3 range holds
// both colours, so the clamp keeps such history. The current frame's weight therefore also rises
// with the angle between the directions the point was seen from in the two frames, to 1 at
// HistoryDegrees: a camera orbiting its focal point turns the view there by the orbit's angle
// while those points hardly move on the screen. Measured on the orbit scenes at 0.2 to 2 degrees
// a frame (docs/measurements.md).
const float HistoryDegrees = 8.0;

// The angle, in degrees, between the directions from which the point `ndc` (normalised device
// coordinates of this frame) was seen in the previous frame and in this one.
float ViewTurn(vec3 ndc)
{
  vec4 point = toPoint * vec4(ndc, 1.0);
  vec3 x = point.xyz / point.w;
  vec3 now = x * currentEye.w - currentEye.xyz;
  vec3 before = x * previousEye.w - previousEye.xyz;
  float lengths = length(now) * length(before);
  return lengths > 0.0 ? degrees(acos(clamp(dot(now, before) / lengths, -1.0, 1.0))) : 0.0;
}

// The distance from the eye, along the direction of view, of the window depth `depth` under a
// projection whose entries (2, 2), (2, 3), (3, 2), (3, 3) are `m`.
float EyeDistance(float depth, vec4 m)
{
  float z = 2.0 * depth - 1.0;
  return -(m.y - z * m.w) / (z * m.z - m.x);
}

// Disocclusion. Where a point was hidden at the previous render behind something nearer (a
// camera moving past an object uncovers what was behind it), the history at its previous position
// is the hiding object's, and the clamp does not always see it: over a textured or edged surface
// the 3 x 3 range spans colours between which the hiding object's may lie. So the previous render's
// depth is read where the point was (bilinearly over the 2 x 2 texels around it: a plane's window
// depth is linear across the screen, so a surface seen at a grazing angle matches its own
// reprojected depth, with no allowance for its slope) and, if it is nearer than the point by
// OccludedShare of the point's distance or more, the pixel takes the current frame alone. The
// point is the nearest of the 3 x 3 neighbourhood, as for the motion: a silhouette pixel, which
// holds some of the object, finds the object where it was. The share allows for the depth
// buffer's precision and for the nearest point changing places with its neighbours as the view
// turns.
const float OccludedShare = 0.02;
// Whether the point whose window depth at the previous render is `expected` was hidden then; `uv`:
// where it was (texture coordinates, unjittered). The previous render may have been a jittered one
// of a still accumulation (`previousJitter`, in pixels: the window centre moved by it, which moves
// the picture by minus that much).
bool WasOccluded(vec2 uv, ivec2 size, float expected)
{
  vec2 position = uv * vec2(size) - 0.5 - previousJitter;
  ivec2 base = ivec2(floor(position));
  vec2 t = position - floor(position);
  float d[4];
  for (int k = 0; k < 4; ++k)
  {
    ivec2 q = clamp(base + ivec2(k % 2, k / 2), ivec2(0), size - 1);
    d[k] = texelFetch(previousDepthTexture, q, 0).r;
  }
  float was = EyeDistance(mix(mix(d[0], d[1], t.x), mix(d[2], d[3], t.x), t.y), previousDepthToEye);
  float is = EyeDistance(expected, previousDepthToEye);
  return was < is - OccludedShare * abs(is);
}

// The current frame's weight for a pixel whose history moved `moved` pixels since the last frame
// and whose direction of view turned `turned` degrees.
float CurrentWeight(float moved, float turned)
{
  float weight =
    mix(currentWeight, max(currentWeight, MovingWeight), clamp(moved / MovingPixels, 0.0, 1.0));
  weight =
    mix(weight, 1.0, clamp((moved - MovingPixels) / (HistoryPixels - MovingPixels), 0.0, 1.0));
  return mix(weight, 1.0, clamp(turned / HistoryDegrees, 0.0, 1.0));
}

#ifdef TEMPORAL_MOTION_FRAME
// How much of the method's motion frame replaces its frame, for a pixel whose history moved
// `moved` pixels, whose edge moved `across` pixels across itself (AcrossEdge) and whose current
// frame weighs `weight`. A method's filtering along an edge (DLAA's short-edge blur) spreads each
// jump of the edge's staircase over the pixels beside it, and re-forms with every move of the
// edge, which a single frame needs and a blend of frames does not: a history that moves a pixel
// or more a frame holds the edge seen at other positions of the pixel grid, so its blend with the
// frame smooths the jumps by itself, and the filtering only adds its own flicker. So the motion
// frame (the method without that filtering) is taken in full where the history moved
// MovingPixels or more and the edge AcrossPixels or more across itself, and not at all where the
// history is not read (weight 1: it then is the result alone, and needs the filtering), at rest
// (a still or slow edge's samples do not move across pixels) nor where the edge slid along itself
// (a long, nearly horizontal edge under a camera turning about the vertical: the history holds
// its staircase where the frame has it): there the jumps do not average out. Nor on a thin
// line (`line`, from CurrentRange: the pixel is a ridge or a valley of the luma, one pixel wide):
// a history that moves across a line holds it one pixel wide at other rows, not the share of the
// pixel it covers, so its jumps do not average out either, and the blur is what softens them.
// Measured with DLAA on the orbit scenes of mlaa-temporal at 0.2 to 2 degrees a frame, and the
// thin line's rule on its other motions (elevation, roll, dolly; docs/measurements.md).
const float AcrossPixels = 0.25;
float MotionFrameShare(float moved, float across, float line, float weight)
{
  float motion =
    min(clamp(moved / MovingPixels, 0.0, 1.0), clamp(across / AcrossPixels, 0.0, 1.0));
  return (1.0 - line) * motion * clamp((1.0 - weight) / (1.0 - MovingWeight), 0.0, 1.0);
}

// Whether `x` is a positive finite number (not 0, infinite or NaN: a floating-point frame may hold
// such pixels, and the measures of their neighbours that divide by a sum of steps stay finite).
bool PositiveFinite(float x)
{
  return x > 0.0 && x < 1.0e38;
}

// How far, in pixels, the edges at a pixel moved across themselves when the picture moved by
// `motion` (pixels): the motion's horizontal and vertical parts, weighed by how much the rendered
// luma (Rec. 709) varies along each axis over the 3 x 3 neighbourhood (`variation`, from
// CurrentRange: the sums of the absolute differences between neighbours, along x and along y); the
// whole motion where the neighbourhood is one luma, or where its variation is not a finite
// number (a floating-point frame with an infinite or NaN pixel: the pixels beside it stay finite).
// A nearly horizontal edge, or a thin horizontal line, varies along y only, and moves across
// itself by the motion's vertical part.
// (Per axis, as DLAA filters: a signed gradient, Sobel's, cancels across a thin line and took the
// direction of the colour's noise there: measured worse, and dependent on the luma's weights.)
float AcrossEdge(vec2 motion, vec2 variation)
{
  float sum = variation.x + variation.y;
  return PositiveFinite(sum) ? dot(abs(motion), variation) / sum : length(motion);
}
#endif

// The history at `uv` (texture coordinates), interpolated by Catmull-Rom over the 4 x 4 texels
// around it: a bilinear read would blur the history a little more at every frame of a moving
// camera, and the blur would add up.
vec4 CatmullRom(sampler2D image, vec2 uv, ivec2 size)
{
  vec2 position = uv * vec2(size) - 0.5;
  vec2 t = fract(position);
  ivec2 base = ivec2(floor(position)) - 1;
  vec2 w[4];
  w[0] = t * (-0.5 + t * (1.0 - 0.5 * t));
  w[1] = 1.0 + t * t * (-2.5 + 1.5 * t);
  w[2] = t * (0.5 + t * (2.0 - 1.5 * t));
  w[3] = t * t * (-0.5 + 0.5 * t);
  vec4 sum = vec4(0.0);
  for (int j = 0; j < 4; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      ivec2 texel = clamp(base + ivec2(i, j), ivec2(0), size - 1);
      sum += w[i].x * w[j].y * texelFetch(image, texel, 0);
    }
  }
  return sum;
}

// The range, per channel, of this frame as rendered (before the method) over the 3 x 3
// neighbourhood of `p`, rather than of the method's frame: the rendered samples are what the
// history has to agree with. Measured a little better (or equal) for both methods on every scene
// of mlaa-temporal at 0.2 and 0.5 degree a frame (docs/measurements.md). With a motion frame, also
// the luma's variation along x and y (AcrossEdge) and how much the pixel is a thin line
// (MotionFrameShare), from the same reads.
void CurrentRange(ivec2 p, ivec2 size, out vec4 lo, out vec4 hi, out vec2 variation, out float line)
{
  lo = texelFetch(frameTexture, p, 0);
  hi = lo;
  float luma[9]; // row by row, from (-1, -1)
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      vec4 c = texelFetch(frameTexture, clamp(p + ivec2(i, j), ivec2(0), size - 1), 0);
      lo = min(lo, c);
      hi = max(hi, c);
#ifdef TEMPORAL_MOTION_FRAME
      luma[3 * j + i + 4] = dot(c.rgb, vec3(0.2126, 0.7152, 0.0722));
#endif
    }
  }
  variation = vec2(0.0);
  line = 0.0;
#ifdef TEMPORAL_MOTION_FRAME
  for (int k = 0; k < 3; ++k)
  {
    variation.x += abs(luma[3 * k + 1] - luma[3 * k]) + abs(luma[3 * k + 2] - luma[3 * k + 1]);
    variation.y += abs(luma[k + 3] - luma[k]) + abs(luma[k + 6] - luma[k + 3]);
  }
  // A thin line: along x or along y, the pixel's steps to its two neighbours have opposite signs
  // (a ridge or a valley); the smaller of the two, over the pixel's largest step, says how much.
  // The side of an edge steps one way only, and a smooth shading's steps are small on both sides.
  float a = luma[4] - luma[3], b = luma[5] - luma[4];
  float c = luma[4] - luma[1], d = luma[7] - luma[4];
  float ridge =
    max(a * b < 0.0 ? min(abs(a), abs(b)) : 0.0, c * d < 0.0 ? min(abs(c), abs(d)) : 0.0);
  float largest = max(max(abs(a), abs(b)), max(abs(c), abs(d)));
  line = PositiveFinite(largest) ? clamp(ridge / largest, 0.0, 1.0) : 0.0;
#endif
}

// Where the rendered 3 x 3 neighbourhood is one colour and the method left the pixel at that
// colour, the clamp takes any history to that colour: the result is the current frame, which
// the pass has already copied into the new history (with a count of 1), so the history is
// neither located nor read there (flat regions, most of a background).
bool flatFrame(
  ivec2 p, ivec2 size, vec4 current, out vec4 lo, out vec4 hi, out vec2 variation, out float line)
{
  CurrentRange(p, size, lo, hi, variation, line);
  return lo == hi && current == lo;
}

// The nearest point of the 3 x 3 neighbourhood of `p` (its depth `depth` on entry): its motion
// moves this pixel. An antialiased silhouette pixel, which holds some of the object, moves with
// the object, not with what is behind it (the background, whose depth is the far plane, moves
// otherwise under a rotation).
ivec2 Nearest(ivec2 p, ivec2 size, inout float depth)
{
  ivec2 nearest = p;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 q = clamp(p + ivec2(i, j), ivec2(0), size - 1);
      float d = texelFetch(depthTexture, q, 0).r;
      if (d < depth)
      {
        depth = d;
        nearest = q;
      }
    }
  }
  return nearest;
}
#endif

void main()
{
  ivec2 size = textureSize(depthTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size));
#ifdef TEMPORAL_MASK
  vec4 copied = texelFetch(currentTexture, p, 0);
  vec4 range[2];
  vec2 unused;
  float unusedLine;
  gl_FragDepth = flatFrame(p, size, copied, range[0], range[1], unused, unusedLine) ? 0.0 : 1.0;
  gl_FragData[0] = copied;
  return;
#endif
  float depth = texelFetch(depthTexture, p, 0).r;
#ifdef TEMPORAL_OUTPUT
  gl_FragData[0] = texelFetch(historyTexture, p, 0);
  gl_FragDepth = depth;
#else
  vec4 current = texelFetch(currentTexture, p, 0);
  gl_FragData[1] = vec4(1.0);
  if (currentWeight >= 1.0)
  {
    gl_FragData[0] = current;
    return;
  }
#if defined(TEMPORAL_KEEP_UNCHANGED)
  // A pixel whose 3 x 3 neighbourhood in the method's frame is the one of the last unjittered
  // render was not reached by the motion and keeps its history; any other takes the current frame
  // alone. (The neighbourhood, not the pixel alone: a pixel that an edge crossed holds part of the
  // actor in its history while its own sample may be the background before and after; a
  // neighbour across the edge changed.)
  bool unchanged = true;
  for (int j = -1; j <= 1; ++j)
  {
    for (int i = -1; i <= 1; ++i)
    {
      ivec2 q = clamp(p + ivec2(i, j), ivec2(0), size - 1);
      unchanged = unchanged && texelFetch(currentTexture, q, 0) == texelFetch(previousTexture, q, 0);
    }
  }
  gl_FragData[0] = unchanged ? texelFetch(historyTexture, p, 0) : current;
  gl_FragData[1] = unchanged ? texelFetch(countTexture, p, 0) : vec4(1.0);
#elif defined(TEMPORAL_REPROJECT)
  // The mask pass (TEMPORAL_MASK) left out the pixels discarded here; the test stays, so that
  // the blend is the same without the mask.
  vec4 lo, hi;
  vec2 variation;
  float line;
  if (flatFrame(p, size, current, lo, hi, variation, line))
  {
    discard;
  }
  ivec2 nearest = Nearest(p, size, depth);
  vec2 here = (vec2(nearest) + 0.5) / vec2(size);
  vec3 ndc = vec3(here * 2.0 - 1.0, depth * 2.0 - 1.0);
  vec4 previous = reprojection * vec4(ndc, 1.0);
  vec2 motion = previous.xy / previous.w * 0.5 + 0.5 - here; // in texture coordinates
  vec2 uv = (vec2(p) + 0.5) / vec2(size) + motion;
  if (previous.w <= 0.0 || any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))))
  {
    gl_FragData[0] = current; // a point outside the previous view: the current frame alone
    return;
  }
  float moved = length(motion * vec2(size));
  float weight = CurrentWeight(moved, ViewTurn(ndc));
  if (weight >= 1.0 || WasOccluded(uv, size, previous.z / previous.w * 0.5 + 0.5))
  {
    // Moved HistoryPixels or turned HistoryDegrees or more, or hidden at the previous render: the
    // history is not read.
    gl_FragData[0] = current;
    return;
  }
#ifdef TEMPORAL_MOTION_FRAME
  float across = AcrossEdge(motion * vec2(size), variation);
  current =
    mix(current, texelFetch(motionTexture, p, 0), MotionFrameShare(moved, across, line, weight));
#endif
  vec4 history = clamp(CatmullRom(historyTexture, uv, size), lo, hi);
  gl_FragData[0] = mix(history, current, weight);
#else
  vec4 history = texelFetch(historyTexture, p, 0);
  float count = texelFetch(countTexture, p, 0).r + 1.0;
  gl_FragData[0] = mix(history, current, 1.0 / count);
  gl_FragData[1] = vec4(count);
#endif
#endif
}
