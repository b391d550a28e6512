//VTK::System::Dec
// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA pass 0 (with vtkMLAAOptions::Reconstruction only): topological reconstruction (Biri et
// al., "Morphological antialiasing and topological reconstruction", section 4), before edge
// detection. Writes the reconstructed colour of every pixel into a texture of the colour
// texture's format, which the edge detection and the blending then read instead of the
// delegate's image.
//
// For the pixel A under this fragment, each of its eight neighbours is unlike A when the CIELAB
// difference Delta E / 100 reaches the threshold (and is more than 0), or, with MLAA_USE_ALPHA,
// the alpha difference does: the two would have a Lab edge before local contrast adaptation.
// Non-finite colours (float buffers) are never unlike anything. The unlike neighbours X form an
// 8-bit mask (bit 0 E, 1 NE, 2 N, 3 NW, 4 W, 5 SW, 6 S, 7 SE; N is the next row up). A is
// selected when the selection table (T8(X) == 2 and T8(complement) == 1, section 4.2, uploaded
// from vtkMLAATopology::GetSelectionBits: the one generator) has the mask's bit and the X
// pixels are pairwise alike (one colour: the shape). The pixels of the square window of radius
// coverageRadius around A that are alike the shape (not unlike its first pixel) measure the
// thin shape's density; coverageTable (vtkMLAATopology::GetCoverageTable, the coverage rule)
// turns their count into the share of the shape that covers A (0: A is not a gap in a thin
// line and keeps its colour). A selected pixel then moves by that share towards the mean of
// the X pixels, alpha included. A pixel that is not a gap but lies in the shape of a gap among
// its neighbours (the thin line rule), where the gap's window holds more shape pixels than the
// gap's eight neighbours, keeps lineShareTable's share (vtkMLAATopology::GetLineShareTable) of
// its colour and moves the rest of the way to the gap's. Reads beyond the image are clamped to
// its border.
//
// Compile-time variants (#defines prepended by vtkOpenGLMLAAPass in place of //VTK::Antialiasing::Dec):
//   MLAA_USE_ALPHA     defined: a change in alpha alone makes a neighbour unlike too
//   MLAA_WRITE_BACK    defined: only the changed pixels are written (the others are
//                      discarded): the pass draws this into the target when the blending works
//                      in place and writes back only the pixels it blends.
//
// Must match Reconstruct and Unlike in Filters/vtkMLAAReconstruction.h (vtkImageMLAA), and the
// neighbour order of vtkMLAATopology.

in vec2 texCoord;

uniform sampler2D colorTexture; // the delegate's image (texelFetch only)
uniform float threshold;        // vtkMLAAOptions::Threshold
uniform int selectionTable[8];  // 256 bits: bit (m & 31) of word m >> 5 selects mask m
uniform int coverageRadius;     // vtkMLAATopology::CoverageRadius
uniform float coverageTable[49]; // vtkMLAATopology::GetCoverageTable(), by shape pixels
uniform float lineShareTable[49]; // vtkMLAATopology::GetLineShareTable(), by shape pixels

//VTK::MLAA::Lab

// The neighbours in mask bit order (vtkMLAATopology::GetNeighborOffset).
const ivec2 offsets[8] = ivec2[8](ivec2(1, 0), ivec2(1, 1), ivec2(0, 1), ivec2(-1, 1),
  ivec2(-1, 0), ivec2(-1, -1), ivec2(0, -1), ivec2(1, -1));

bool isFiniteColor(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}

// Lab features (xyz) and alpha (w) of a colour.
vec4 features(vec4 c)
{
  return vec4(labFeatures(c.rgb), c.a);
}

// Whether two pixels (features f, g; finiteness) are unlike; distances compared squared.
bool unlike(vec4 f, bool finiteF, vec4 g, bool finiteG)
{
  if (!finiteF || !finiteG)
  {
    return false;
  }
  float t2 = threshold * threshold;
  vec3 d = f.xyz - g.xyz;
  float e2 = dot(d, d);
  if (e2 >= t2 && e2 > 0.0)
  {
    return true;
  }
#ifdef MLAA_USE_ALPHA
  float da = f.w - g.w;
  float a2 = da * da;
  return a2 >= t2 && a2 > 0.0;
#else
  return false;
#endif
}

// The colour of pixel q, its reads clamped to the image.
vec4 colorAt(ivec2 q, ivec2 size)
{
  return texelFetch(colorTexture, clamp(q, ivec2(0), size - 1), 0);
}

// The mask of the neighbours of pixel q (features f, finite) unlike it, with their colours,
// features and finiteness.
int neighborMask(ivec2 q, ivec2 size, vec4 f, bool finite, out vec4 colors[8],
  out vec4 featureList[8], out bool finiteList[8])
{
  int mask = 0;
  for (int i = 0; i < 8; ++i)
  {
    colors[i] = colorAt(q + offsets[i], size);
    featureList[i] = features(colors[i]);
    finiteList[i] = isFiniteColor(colors[i]);
    if (unlike(f, finite, featureList[i], finiteList[i]))
    {
      mask |= 1 << i;
    }
  }
  return mask;
}

// Whether pixel q (its unlike neighbours `mask`, their features and finiteness) is a gap: the
// number of the pixels of its coverage window alike the shape when it is selected, its shape
// is one colour and the coverage rule gives it a share above 0; else 0.
int gapShapePixels(ivec2 q, ivec2 size, int mask, vec4 featureList[8], bool finiteList[8])
{
  if (((selectionTable[mask >> 5] >> (mask & 31)) & 1) == 0)
  {
    return 0;
  }
  // The shape is one colour: its pixels are pairwise alike.
  for (int i = 0; i < 8; ++i)
  {
    for (int j = i + 1; j < 8; ++j)
    {
      if (((mask >> i) & (mask >> j) & 1) != 0 &&
        unlike(featureList[i], finiteList[i], featureList[j], finiteList[j]))
      {
        return 0;
      }
    }
  }
  // The coverage rule: the window's pixels alike the shape (its first pixel stands for it).
  int first = 0;
  while (((mask >> first) & 1) == 0)
  {
    ++first;
  }
  int shapePixels = 0;
  for (int dy = -coverageRadius; dy <= coverageRadius; ++dy)
  {
    for (int dx = -coverageRadius; dx <= coverageRadius; ++dx)
    {
      if (dx != 0 || dy != 0)
      {
        vec4 c = colorAt(q + ivec2(dx, dy), size);
        if (!unlike(features(c), isFiniteColor(c), featureList[first], finiteList[first]))
        {
          ++shapePixels;
        }
      }
    }
  }
  return coverageTable[shapePixels] > 0.0 ? shapePixels : 0;
}

// The number of bits set in an 8-bit mask.
int bitsSet(int mask)
{
  int n = 0;
  for (int i = 0; i < 8; ++i)
  {
    n += (mask >> i) & 1;
  }
  return n;
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  vec4 color = texelFetch(colorTexture, p, 0);
  bool finite = isFiniteColor(color);

  vec4 neighbors[8];
  vec4 neighborFeatures[8];
  bool neighborFinite[8];
  int mask = neighborMask(p, size, features(color), finite, neighbors, neighborFeatures,
    neighborFinite);
  int shapePixels = gapShapePixels(p, size, mask, neighborFeatures, neighborFinite);
  bool changed = false;
  if (shapePixels > 0)
  {
    // A gap: it moves by the coverage's share towards the mean of its unlike neighbours.
    vec4 sum = vec4(0.0);
    float n = 0.0;
    for (int i = 0; i < 8; ++i)
    {
      if (((mask >> i) & 1) != 0)
      {
        sum += neighbors[i];
        n += 1.0;
      }
    }
    color += coverageTable[shapePixels] * (sum / n - color);
    changed = true;
  }
  else if (mask != 0)
  {
    // The thin line rule: a pixel of the shape of a gap among its unlike neighbours, whose
    // window holds more shape pixels than its eight neighbours, keeps lineShareTable's share
    // of its colour and takes the rest from the gap (the gap with the most shape pixels, the
    // first in bit order among equals).
    int best = 0;
    vec4 gapColor = color;
    for (int i = 0; i < 8; ++i)
    {
      if (((mask >> i) & 1) != 0)
      {
        ivec2 g = clamp(p + offsets[i], ivec2(0), size - 1);
        vec4 gapNeighbors[8];
        vec4 gapFeatures[8];
        bool gapFinite[8];
        int gapMask = neighborMask(g, size, neighborFeatures[i], neighborFinite[i], gapNeighbors,
          gapFeatures, gapFinite);
        int gapPixels = gapShapePixels(g, size, gapMask, gapFeatures, gapFinite);
        if (gapPixels > best && gapPixels > bitsSet(gapMask))
        {
          best = gapPixels;
          gapColor = neighbors[i];
        }
      }
    }
    if (best > 0 && lineShareTable[best] < 1.0)
    {
      color += (1.0 - lineShareTable[best]) * (gapColor - color);
      changed = true;
    }
  }
#ifdef MLAA_WRITE_BACK
  if (!changed)
  {
    discard; // the target keeps the pixel as rendered
  }
#endif
  gl_FragData[0] = color;
}
