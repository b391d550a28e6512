//VTK::System::Dec
//VTK::Output::Dec

// MLAA pass 2 of 3: blending weights (Jimenez et al., "Practical Morphological Antialiasing",
// GPU Pro 2, section 4.3, Listing 4.2).
//
// Runs on pixels with an edge only (see the edge-detection pass). For the top edgel of the pixel
// (a horizontal line) and for its left edgel (a vertical line):
// 1. the distances to both ends of the line, reading two edgels per bilinear fetch
//    (section 4.3.1, Listing 4.3) and stopping at crossing edges;
// 2. the crossing edges at both ends, read a quarter pixel off the line so that one bilinear
//    fetch tells which of the two possible edgels are set (section 4.3.2, Figure 4.4);
// 3. the two areas of the precomputed area texture (section 4.3.3, Listing 4.4).
// Output: red = weight with which this pixel takes the colour of the pixel above it, green =
// weight with which the pixel above takes this pixel's colour, blue and alpha = the same for
// the left neighbour. GL's y grows upwards, so "above" is y + 1 and the published shader's -0.25
// offset towards the upper row becomes +0.25 here.
//
// Must match vtkImageMLAA's blending weights (Filters/vtkImageMLAA.cxx).

in vec2 texCoord;

uniform sampler2D edgesTexture; // RG8, red = left edgel, green = top edgel; LINEAR, clamp to edge
uniform sampler2D areaTexture;  // vtkMLAAAreaTexture's table, RG32F (texelFetch only)
uniform int maxSearchSteps;     // vtkMLAAOptions::MaxSearchSteps
uniform int cellSize;           // D = 2 * maxSearchSteps + 1, the area texture's cell size

vec2 edgesSize;

// Bilinear read of the edges texture at a position in texels (texel i covers [i, i + 1]).
vec2 edgesAt(vec2 position)
{
  return texture(edgesTexture, position / edgesSize).rg;
}

// Distance from the pixel centred at `center` to the end of its line of top edgels (green) in
// `direction` (-1 left, +1 right). Each step covers the next two pixels with two bilinear fetches
// (section 4.3.1 reads two edgels per fetch; the quarter-texel offsets of section 4.3.2 make
// every edgel of a fetch readable):
// - along the line, a quarter texel from the first pixel's centre towards the second: 3/4 of the
//   first edgel plus 1/4 of the second, so round(4 v) = 3 e1 + e2;
// - the crossing edgels (left edgels, red) at the boundary before the first pixel ("near") and
//   between the two ("mid"), on this row and the one above: a fetch on the row boundary, a
//   quarter texel from the mid boundary's owner towards the near one's, so round(8 v) =
//   3 n_mid + n_near with n the number of crossing edgels (0 to 2) at each boundary.
// The line ends before the first pixel without an edgel or at the first boundary with a crossing
// edgel. (The chapter's search does not stop at crossing edges; stopping keeps the two outlines
// of one-pixel-wide lines apart.)
float searchTopEdges(vec2 center, float direction)
{
  for (int i = 0; i < maxSearchSteps; ++i)
  {
    float first = center.x - 0.5 + direction * float(2 * i + 1); // the first pixel's index
    int along = int(round(4.0 * edgesAt(vec2(first + 0.5 + 0.25 * direction, center.y)).g));
    // The mid boundary belongs to the right pixel of the pair, the near one to the right pixel
    // of (previous, first).
    float crossingX = direction < 0.0 ? first + 0.75 : first + 1.25;
    int crossing = int(round(8.0 * edgesAt(vec2(crossingX, center.y + 0.5)).r));
    if (crossing % 3 != 0 || along < 3)
    {
      return float(2 * i);
    }
    if (crossing >= 3 || (along != 1 && along != 4))
    {
      return float(2 * i + 1);
    }
  }
  return float(2 * maxSearchSteps);
}

// The same along a column of left edgels (red), -1 down, +1 up; the crossing edgels are top
// edgels (green) of this column and the one to the left.
float searchLeftEdges(vec2 center, float direction)
{
  for (int i = 0; i < maxSearchSteps; ++i)
  {
    float first = center.y - 0.5 + direction * float(2 * i + 1);
    int along = int(round(4.0 * edgesAt(vec2(center.x, first + 0.5 + 0.25 * direction)).r));
    // The mid boundary belongs to the lower pixel of the pair, the near one to the lower pixel of
    // (previous, first).
    float crossingY = direction > 0.0 ? first + 0.25 : first - 0.25;
    int crossing = int(round(8.0 * edgesAt(vec2(center.x - 0.5, crossingY)).g));
    if (crossing % 3 != 0 || along < 3)
    {
      return float(2 * i);
    }
    if (crossing >= 3 || (along != 1 && along != 4))
    {
      return float(2 * i + 1);
    }
  }
  return float(2 * maxSearchSteps);
}

// The crossing-edge code 0, 1, 3 or 4 of a fetch weighted 3:1 between the owning pixel's row
// (or column) and the opposite one. An end outside the image has no crossing edge.
int crossingCode(float fetched, int endPixel, int size)
{
  return (endPixel < 0 || endPixel >= size) ? 0 : int(round(4.0 * fetched));
}

vec2 area(int e1, int e2, int d1, int d2)
{
  return texelFetch(areaTexture, ivec2(cellSize * e1 + d1, cellSize * e2 + d2), 0).rg;
}

void main()
{
  ivec2 size = textureSize(edgesTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  edgesSize = vec2(size);
  vec2 center = vec2(p) + 0.5;
  vec2 e = texelFetch(edgesTexture, p, 0).rg;
  vec4 weights = vec4(0.0);

  if (e.g > 0.5) // edge at the top: a horizontal line, ends to the left and to the right
  {
    int left = int(round(searchTopEdges(center, -1.0)));
    int right = int(round(searchTopEdges(center, 1.0)));
    float fetchY = center.y + 0.25; // 3:1 between this row and the row above
    int e1 = crossingCode(edgesAt(vec2(center.x - float(left), fetchY)).r, p.x - left, size.x);
    int e2 = crossingCode(
      edgesAt(vec2(center.x + float(right + 1), fetchY)).r, p.x + right + 1, size.x);
    weights.rg = area(e1, e2, left, right);
  }

  if (e.r > 0.5) // edge at the left: a vertical line, its first end is the upper one
  {
    int up = int(round(searchLeftEdges(center, 1.0)));
    int down = int(round(searchLeftEdges(center, -1.0)));
    float fetchX = center.x - 0.25; // 3:1 between this column and the column to the left
    int e1 = crossingCode(edgesAt(vec2(fetchX, center.y + float(up))).g, p.y + up, size.y);
    int e2 = crossingCode(
      edgesAt(vec2(fetchX, center.y - float(down + 1))).g, p.y - down - 1, size.y);
    weights.ba = area(e1, e2, up, down);
  }

  gl_FragData[0] = weights;
}
