//VTK::System::Dec
//VTK::Output::Dec

// MLAA pass 2 of 3: blending weights (Jimenez et al., "Practical Morphological Antialiasing",
// GPU Pro 2, section 4.3, Listing 4.2).
//
// Runs on pixels with an edge only (see the edge-detection pass). For the top edgel of the pixel
// (a horizontal line) and for its left edgel (a vertical line):
// 1. the distances to both ends of the line, reading two edgels per bilinear fetch
//    (section 4.3.1, Listing 4.3);
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
// `direction` (-1 left, +1 right). The first read sits between the first and the second pixel in
// that direction, so it returns the mean of two edgels: 1 (both set: go on two pixels), 0.5 (one
// set: taken to be the nearer one) or 0 (the line has ended). We compare with 0.9, not 1, to stay
// clear of the filtering's rounding.
float searchTopEdges(vec2 center, float direction)
{
  vec2 position = center + vec2(1.5 * direction, 0.0);
  float e = 0.0;
  int i;
  for (i = 0; i < maxSearchSteps; ++i)
  {
    e = edgesAt(position).g;
    if (e < 0.9)
    {
      break;
    }
    position.x += 2.0 * direction;
  }
  return min(2.0 * float(i) + 2.0 * e, 2.0 * float(maxSearchSteps));
}

// The same along a column of left edgels (red), -1 down, +1 up.
float searchLeftEdges(vec2 center, float direction)
{
  vec2 position = center + vec2(0.0, 1.5 * direction);
  float e = 0.0;
  int i;
  for (i = 0; i < maxSearchSteps; ++i)
  {
    e = edgesAt(position).r;
    if (e < 0.9)
    {
      break;
    }
    position.y += 2.0 * direction;
  }
  return min(2.0 * float(i) + 2.0 * e, 2.0 * float(maxSearchSteps));
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
