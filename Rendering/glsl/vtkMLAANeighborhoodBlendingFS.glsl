//VTK::System::Dec
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// MLAA pass 3 of 3: blending with the four-neighbourhood (Jimenez et al., "Practical
// Morphological Antialiasing", GPU Pro 2, section 4.4, Listing 4.5), drawn into the renderer's
// viewport of the target framebuffer.
//
// The pixel's own texel holds the weights of its top and left edgels; the weight of its bottom
// edgel is the green of the pixel below, that of its right edgel the alpha of the pixel to the
// right. Each neighbour k is mixed in as mix(c, c_k, a_k), and the mixes are averaged with weights
// a_k (a pixel may lie on up to four lines). With MLAA_DOMINANT_DIRECTION
// (vtkMLAAOptions::DominantDirectionBlending), a pixel on both a horizontal and a vertical line
// keeps only the direction with the larger weight (both on a tie), as SMAA does. The published
// shader makes each mix with one bilinear fetch; exact fetches and mix() give the same result
// without the filtering's rounding, and let a zero weight skip a neighbour entirely (so a NaN
// next door cannot leak in).
// With MLAA_STRAIGHT_ALPHA (vtkOpenGLMLAAPass::KeepAlpha with straight alpha), the colours are
// premultiplied by their alpha before they are mixed and the result is divided by its alpha:
// coverage blending, so the colour stored under alpha 0 (VTK's background colour behind a
// transparent background) never leaks into a silhouette as a fringe. Otherwise the four
// channels are mixed as they are (opaque images, and premultiplied ones, for which that is the
// coverage blend).
// The depth of the delegate's render is written too, so that passes and layers drawn after this
// one see the scene's depth.
//
// Compile-time variants (#defines prepended by vtkOpenGLMLAAPass in place of
// //VTK::Antialiasing::Dec; the program is rebuilt when the options change):
//   MLAA_DEBUG_OUTPUT        0 the antialiased image, 1 edges, 2 blending weights
//                            (vtkMLAAOptions::DebugOutput)
//   MLAA_DOMINANT_DIRECTION  defined: vtkMLAAOptions::DominantDirectionBlending
//   MLAA_STRAIGHT_ALPHA      defined: premultiply before mixing, divide after
//   MLAA_IN_PLACE            defined: the target already holds the delegate's image and depth
//                            (vtkOpenGLMLAAPass renders the delegate into it and copies it into
//                            colorTexture): the pixels blending leaves alone are discarded and
//                            no depth is written. Otherwise every pixel and its depth are
//                            written.
//
// Must match vtkImageMLAA's blending (BlendRow in Filters/vtkMLAAStages.h).

in vec2 texCoord;

uniform sampler2D colorTexture;   // the delegate's image
uniform sampler2D depthTexture;   // the delegate's depth
uniform sampler2D edgesTexture;   // pass 1 output, for the debug output
uniform sampler2D weightsTexture; // pass 2 output

// A colour, premultiplied when the image holds straight alpha.
vec4 premultiplied(vec4 c)
{
#ifdef MLAA_STRAIGHT_ALPHA
  return vec4(c.rgb * c.a, c.a);
#else
  return c;
#endif
}

// The four neighbours: above, below, left, right.
const ivec2 offsets[4] = ivec2[4](ivec2(0, 1), ivec2(0, -1), ivec2(-1, 0), ivec2(1, 0));

vec4 neighbor(ivec2 q)
{
  return premultiplied(texelFetch(colorTexture, q, 0));
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  ivec2 p = ivec2(texCoord * vec2(size)); // this fragment's pixel (texCoord is at its centre)
#ifndef MLAA_IN_PLACE
  gl_FragDepth = texelFetch(depthTexture, p, 0).r;
#endif

#if MLAA_DEBUG_OUTPUT == 1
  gl_FragData[0] = vec4(texelFetch(edgesTexture, p, 0).rg, 0.0, 1.0);
#elif MLAA_DEBUG_OUTPUT == 2
  gl_FragData[0] = texelFetch(weightsTexture, p, 0);
#else
  // Weights towards the neighbour above, below, to the left and to the right.
  vec4 w = texelFetch(weightsTexture, p, 0);
  vec4 a = vec4(w.r, p.y > 0 ? texelFetch(weightsTexture, p - ivec2(0, 1), 0).g : 0.0, w.b,
    p.x < size.x - 1 ? texelFetch(weightsTexture, p + ivec2(1, 0), 0).a : 0.0);
#ifdef MLAA_DOMINANT_DIRECTION
  float vertical = max(a.x, a.y);
  float horizontal = max(a.z, a.w);
  if (vertical > horizontal)
  {
    a.zw = vec2(0.0);
  }
  else if (horizontal > vertical)
  {
    a.xy = vec2(0.0);
  }
#endif
  float sum = a.x + a.y + a.z + a.w;
  if (sum <= 0.0)
  {
#ifdef MLAA_IN_PLACE
    discard; // no edge: the target keeps the pixel as rendered
#else
    gl_FragData[0] = texelFetch(colorTexture, p, 0); // no edge: exactly as rendered
    return;
#endif
  }
  vec4 original = texelFetch(colorTexture, p, 0);
  vec4 c = premultiplied(original);
  vec4 blended = vec4(0.0);
  // The neighbours with a weight, in the order above, below, left, right: a loop over the range
  // [first, last) of them rather than four conditional blocks, because a loop runs only as many
  // times as its pixels need, where both sides of a branch may be executed (rasterisers that
  // shade pixels in lock-step, llvmpipe among them). The range is empty for the pixels no line
  // crosses (most of them), and has two entries when one direction dominates.
  int first = a.x + a.y > 0.0 ? 0 : 2;
  int last = a.z + a.w > 0.0 ? 4 : 2;
  for (int k = first; k < last; ++k)
  {
    float ak = a[k];
    if (ak > 0.0)
    {
      blended += ak * mix(c, neighbor(p + offsets[k]), ak);
    }
  }
  c = blended / sum;
#ifdef MLAA_STRAIGHT_ALPHA
  // Back to straight colour; where nothing covers the pixel, its colour is kept as it was.
  c.rgb = c.a > 0.0 ? c.rgb / c.a : original.rgb;
#endif
  gl_FragData[0] = c;
#endif
}
