//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA pass 1 of 3: edge detection (Jimenez et al., "Practical Morphological Antialiasing",
// GPU Pro 2, section 4.2, Listing 4.1; luma as in section 4.2.1).
//
// Compile-time variants (vtkOpenGLMLAAPass prepends the #defines in place of //VTK::Antialiasing::Dec
// and rebuilds the program when the options change, so no pixel pays for a run-time branch):
//   MLAA_EDGE_DETECTION   0 luma, 1 colour, 2 depth, 3 CIELAB (vtkMLAAOptions::EdgeDetection;
//                         Lab: Delta E / 100 of Biri et al., section 3.2, vtkMLAALab.glsl)
//   MLAA_USE_ALPHA        defined: a change in alpha alone is an edge too (the result keeps
//                         alpha: vtkOpenGLMLAAPass::KeepAlpha, or a composited layer)
//   MLAA_LOCAL_CONTRAST   defined: the local contrast adaptation pass (below)
//   MLAA_CHANGE_MASK      defined: the change mask pass (below)
//   MLAA_MARK_BLENDED     defined (with MLAA_CHANGE_MASK): also mark, with depth 1/4, the pixels
//                         that differ from their right or lower neighbour only (below)
//
// Detection (the default build): writes, for the pixel under this fragment, whether its left
// boundary (red) and its top boundary (green) are edges. "Top" is the next row up (GL's y + 1,
// the top of the displayed image). Pixels with no edge are discarded: the edges texture was
// cleared to 0, and the depth buffer (0 where the change mask left a pixel unmarked, 1 where it
// marked it) takes the quad's depth only where an edge was written. The later passes test depth
// for equality, so they run on edge pixels only: the chapter's stencil trick, done with a depth
// buffer.
//
// The change mask (built with MLAA_CHANGE_MASK defined, run first on every pixel): marks, with
// depth 1 over a mask cleared to 0, the pixels that differ from their left neighbour or from the
// pixel above (colour and alpha, and depth in depth mode); the detection then runs with the
// quad's depth (1/2) tested LESS, on the marked pixels only. A pixel equal to both neighbours
// has no edge whatever the threshold, and the depth test drops it before its shader runs: most
// of a picture is such pixels (backgrounds, flat colour), and the detection's conversions (Lab:
// three per pixel) are its cost. Rasterisers that shade pixels in lock-step skip a group only
// when none of its pixels passes the test, which an early depth test decides before shading
// and a discard in the shader does not (measured: docs/measurements.md, issue 20). With
// MLAA_MARK_BLENDED, the pixels that differ from their right or lower neighbour only are marked
// too, with depth 1/4, which the detection's test (1/2 LESS) leaves out: the blending, drawn with
// the quad at depth 0 tested LESS, then runs on every pixel next to an edge (a pixel across an
// edge differs from the pixel on the other side) and on no unmarked one.
//
// Local contrast adaptation (built with MLAA_LOCAL_CONTRAST defined, run when
// vtkMLAAOptions::LocalContrastFactor > 0 on the edge pixels only): rewrites the edges of each
// edge pixel, dropping an edge when the factor times its contrast is below the contrast of one
// of the six other boundaries of the two pixels it separates, or when it lies inside a ramp
// (insideRamp). Doing this in a pass of its own
// keeps its extra reads off the pixels without edges (the depth test rejects them before the
// shader runs), which matters on rasterisers that run both sides of every branch.
//
// Must match vtkImageMLAA's edge detection (DetectEdges in Filters/vtkMLAAEdgeDetection.cxx).

in vec2 texCoord;

uniform sampler2D colorTexture;    // the delegate's image (texelFetch only)
uniform sampler2D depthTexture;    // its depth buffer, for depth edges
uniform float threshold;           // vtkMLAAOptions::Threshold
uniform float localContrastFactor; // vtkMLAAOptions::LocalContrastFactor (> 0 here)

// Rec. 709 luma weights.
const vec3 lumaWeights = vec3(0.2126, 0.7152, 0.0722);

//VTK::MLAA::Lab

bool isFiniteColor(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}

// The difference of two values if it is at least the threshold (and more than nothing, so that
// a zero threshold means "any difference"), else 0. NaN differences are never edges.
float kept(float d)
{
  return (d >= threshold && d > 0.0) ? d : 0.0;
}

// What edge detection compares of pixel p (colour a), as a vector computed once for all the
// boundaries of the pixel: luma (red), the colour channels (rgb), its depth (red) or CIELAB
// (rgb), and alpha where it counts (the CPU filter's features, FeatureReader).
vec4 featuresAt(ivec2 p, vec4 a)
{
#if MLAA_EDGE_DETECTION == 1
  vec4 v = vec4(a.rgb, 0.0);
#elif MLAA_EDGE_DETECTION == 2
  vec4 v = vec4(texelFetch(depthTexture, p, 0).r, 0.0, 0.0, 0.0);
#elif MLAA_EDGE_DETECTION == 3
  vec4 v = vec4(labFeatures(a.rgb), 0.0);
#else
  vec4 v = vec4(dot(a.rgb, lumaWeights), 0.0, 0.0, 0.0);
#endif
#ifdef MLAA_USE_ALPHA
  v.a = a.a;
#endif
  return v;
}

// The contrast across the boundary between two pixels, given their colours a, b and features
// fa, fb (featuresAt): the largest difference of what edge detection compares that is at least
// the threshold, else 0; CIELAB's three features count as one, their Euclidean distance. Pixels
// with a non-finite colour (float buffers) take part in no edge, so they never spread.
float contrastOf(vec4 a, vec4 fa, vec4 b, vec4 fb)
{
  if (!isFiniteColor(a) || !isFiniteColor(b))
  {
    return 0.0;
  }
  vec4 d = abs(fa - fb);
#ifdef MLAA_USE_ALPHA
  float c = kept(d.a);
#else
  float c = 0.0;
#endif
#if MLAA_EDGE_DETECTION == 1
  return max(c, max(kept(d.r), max(kept(d.g), kept(d.b))));
#elif MLAA_EDGE_DETECTION == 3
  return max(c, kept(length(fa.rgb - fb.rgb)));
#else
  return max(c, kept(d.r));
#endif
}

// The colour of pixel q and its features, read clamped to the image (the callers count no
// contrast across the image border). Each pixel's features are computed once per fragment (Lab:
// a conversion each).
void pixelAt(ivec2 q, ivec2 size, out vec4 color, out vec4 features)
{
  ivec2 inside = clamp(q, ivec2(0), size - 1);
  color = texelFetch(colorTexture, inside, 0);
  features = featuresAt(inside, color);
}

#ifdef MLAA_LOCAL_CONTRAST
// Whether an edge whose compared values change by d across it lies inside a ramp: the
// boundaries before and after it along the same axis change them the same way, by at least half
// as much (the projections of their changes on d are at least |d| / 2). Sampled shading, not a
// step between two regions (vtkMLAAEdgeDetection.cxx, EdgeDetector::InsideRamp). `seen`: whether
// the pixels before and after the edge's two are inside the image; at its border the side seen
// decides alone. `finite`: whether their colours are finite (the edge's own two are, or it would
// not be one); a pixel seen that is not finite makes no ramp.
bool insideRamp(vec4 before, vec4 d, vec4 after, bvec2 seen, bvec2 finite)
{
  float dd = dot(d, d);
  return any(seen) && (!seen.x || (finite.x && 2.0 * dot(d, before) >= dd)) &&
    (!seen.y || (finite.y && 2.0 * dot(d, after) >= dd));
}

// The contrast between pixels p and q (q = p + (1, 0) or p + (0, 1)), given their colours and
// features; 0 where either is outside the image, whose border is never an edge.
float between(ivec2 p, ivec2 q, ivec2 size, vec4 a, vec4 fa, vec4 b, vec4 fb)
{
  if (any(lessThan(p, ivec2(0))) || any(greaterThanEqual(q, size)))
  {
    return 0.0;
  }
  return contrastOf(a, fa, b, fb);
}
#endif

#ifdef MLAA_CHANGE_MASK
// Whether pixel q (inside the image) holds what pixel p holds: colour and alpha, and depth in
// depth mode. Outside the image, yes (the border is never an edge).
bool sameAs(ivec2 p, vec4 color, ivec2 q, ivec2 size)
{
  if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size)))
  {
    return true;
  }
#if MLAA_EDGE_DETECTION == 2
  if (texelFetch(depthTexture, q, 0).r != texelFetch(depthTexture, p, 0).r)
  {
    return false;
  }
#endif
  return all(equal(texelFetch(colorTexture, q, 0), color));
}
#endif

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
#ifdef MLAA_CHANGE_MASK
  // The change mask: pixels equal to their left neighbour and to the pixel above have no edge
  // whatever the threshold; the others are marked (depth 1) for the edge detection, which the
  // depth test then runs on them only.
  vec4 here = texelFetch(colorTexture, p, 0);
  if (sameAs(p, here, p - ivec2(1, 0), size) && sameAs(p, here, p + ivec2(0, 1), size))
  {
#ifdef MLAA_MARK_BLENDED
    // No edge of its own, but the pixel across an edge of its right or lower neighbour: the
    // blending may change it (a lower mark, which the edge detection's test leaves out).
    if (sameAs(p, here, p + ivec2(1, 0), size) && sameAs(p, here, p - ivec2(0, 1), size))
    {
      discard;
    }
    gl_FragDepth = 0.25;
    gl_FragData[0] = vec4(0.0);
    return;
#else
    discard;
#endif
  }
  gl_FragDepth = 1.0;
  gl_FragData[0] = vec4(0.0); // not written (colour writes are off)
  return;
#endif

  // The two boundaries this pixel owns: with its left neighbour l and with the pixel above, t.
  ivec2 dx = ivec2(1, 0);
  ivec2 dy = ivec2(0, 1);
  ivec2 l = p - dx;
  ivec2 t = p + dy;
  vec4 color = texelFetch(colorTexture, p, 0);
  vec4 features = featuresAt(p, color);
  vec4 colorL, featuresL, colorT, featuresT;
  pixelAt(l, size, colorL, featuresL);
  pixelAt(t, size, colorT, featuresT);
  float left = p.x > 0 ? contrastOf(color, features, colorL, featuresL) : 0.0;
  float top = p.y < size.y - 1 ? contrastOf(color, features, colorT, featuresT) : 0.0;
  bool keepLeft = left > 0.0;
  bool keepTop = top > 0.0;

#ifdef MLAA_LOCAL_CONTRAST
  // This pixel's other two boundaries, shared by both edges (contrast is symmetric).
  vec4 colorQ, featuresQ, colorR, featuresR;
  pixelAt(p + dx, size, colorQ, featuresQ);
  pixelAt(p - dy, size, colorR, featuresR);
  float right = p.x < size.x - 1 ? contrastOf(color, features, colorQ, featuresQ) : 0.0;
  float bottom = p.y > 0 ? contrastOf(color, features, colorR, featuresR) : 0.0;
  float around = max(right, bottom);
  // For the ramp test: the compared values of the right and lower neighbours, kept because
  // featuresQ and featuresR are reused for other pixels below.
  vec4 rightOf = featuresQ;
  vec4 below = featuresR;
  bool rightFinite = isFiniteColor(colorQ);
  bool belowFinite = isFiniteColor(colorR);
  // The pixel above l (left of t) is a neighbour of both l and t.
  vec4 colorLT, featuresLT;
  pixelAt(l + dy, size, colorLT, featuresLT);
  if (keepLeft)
  {
    pixelAt(l - dx, size, colorQ, featuresQ);
    pixelAt(l - dy, size, colorR, featuresR);
    float strongest = max(max(around, top),
      max(between(l - dx, l, size, colorQ, featuresQ, colorL, featuresL),
        max(between(l, l + dy, size, colorL, featuresL, colorLT, featuresLT),
          between(l - dy, l, size, colorR, featuresR, colorL, featuresL))));
    keepLeft = localContrastFactor * left >= strongest &&
      !insideRamp(featuresL - featuresQ, features - featuresL, rightOf - features,
        bvec2(p.x >= 2, p.x + 1 < size.x), bvec2(isFiniteColor(colorQ), rightFinite));
  }
  if (keepTop)
  {
    pixelAt(t + dy, size, colorQ, featuresQ);
    pixelAt(t + dx, size, colorR, featuresR);
    float strongest = max(max(around, left),
      max(between(t, t + dy, size, colorT, featuresT, colorQ, featuresQ),
        max(between(t - dx, t, size, colorLT, featuresLT, colorT, featuresT),
          between(t, t + dx, size, colorT, featuresT, colorR, featuresR))));
    keepTop = localContrastFactor * top >= strongest &&
      !insideRamp(features - below, featuresT - features, featuresQ - featuresT,
        bvec2(p.y >= 1, p.y + 2 < size.y), bvec2(belowFinite, isFiniteColor(colorQ)));
  }
#else
  if (!keepLeft && !keepTop)
  {
    discard;
  }
#endif
  gl_FragData[0] = vec4(keepLeft ? 1.0 : 0.0, keepTop ? 1.0 : 0.0, 0.0, 0.0);
}
