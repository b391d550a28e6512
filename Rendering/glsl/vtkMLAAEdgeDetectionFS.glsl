//VTK::System::Dec
//VTK::Output::Dec

// MLAA pass 1 of 3: edge detection (Jimenez et al., "Practical Morphological Antialiasing",
// GPU Pro 2, section 4.2, Listing 4.1; luma as in section 4.2.1).
//
// Writes, for the pixel under this fragment, whether its left boundary (red) and its top
// boundary (green) are edges. "Top" is the next row up (GL's y + 1, the top of the displayed
// image). Pixels with no edge are discarded: the edges texture was cleared to 0, and the depth
// buffer, cleared to 1, keeps the quad's depth only where an edge was written. The
// blending-weights pass tests depth for equality, so it runs on edge pixels only: the chapter's
// stencil trick, done with a depth buffer.
//
// Must match vtkImageMLAA's edge detection (Filters/vtkImageMLAA.cxx).

in vec2 texCoord;

uniform sampler2D colorTexture; // the delegate's image (texelFetch only)
uniform sampler2D depthTexture; // its depth buffer, for depth edges
uniform int edgeDetection;      // vtkMLAAOptions: 0 luma, 1 colour, 2 depth
uniform float threshold;        // vtkMLAAOptions::Threshold
uniform bool useAlpha;          // also an edge where alpha alone changes

// Rec. 709 luma weights.
const vec3 lumaWeights = vec3(0.2126, 0.7152, 0.0722);

bool isFiniteColor(vec4 c)
{
  return !any(isnan(c)) && !any(isinf(c));
}

// An edge: a difference of at least the threshold, and of more than nothing (so that a zero
// threshold means "any difference"). NaN differences are never edges.
bool differs(float a, float b)
{
  float d = abs(a - b);
  return d >= threshold && d > 0.0;
}

// Whether the boundary between this pixel (colour a, depth da) and pixel q is an edge.
bool isEdge(vec4 a, float da, ivec2 q)
{
  vec4 b = texelFetch(colorTexture, q, 0);
  // Non-finite pixels (float buffers) never take part in an edge, so they never spread.
  if (!isFiniteColor(a) || !isFiniteColor(b))
  {
    return false;
  }
  if (useAlpha && differs(a.a, b.a))
  {
    return true;
  }
  if (edgeDetection == 1)
  {
    return differs(a.r, b.r) || differs(a.g, b.g) || differs(a.b, b.b);
  }
  if (edgeDetection == 2)
  {
    return differs(da, texelFetch(depthTexture, q, 0).r);
  }
  return differs(dot(a.rgb, lumaWeights), dot(b.rgb, lumaWeights));
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
  // The image border is never an edge (as reads clamped to the border would compare a pixel
  // with itself).
  vec4 color = texelFetch(colorTexture, p, 0);
  float depth = edgeDetection == 2 ? texelFetch(depthTexture, p, 0).r : 0.0;
  float left = (p.x > 0 && isEdge(color, depth, p - ivec2(1, 0))) ? 1.0 : 0.0;
  float top = (p.y < size.y - 1 && isEdge(color, depth, p + ivec2(0, 1))) ? 1.0 : 0.0;
  if (left == 0.0 && top == 0.0)
  {
    discard;
  }
  gl_FragData[0] = vec4(left, top, 0.0, 0.0);
}
