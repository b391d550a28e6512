//VTK::System::Dec
//VTK::Output::Dec
//VTK::Antialiasing::Dec

// DLAA pass 1 of 2: the short-edge blend masks of every pixel (vtkDLAAOptions, step 1), into an
// RG32F texture (full floats, so that their 17-pixel means follow the CPU's arithmetic) that
// the second pass reads at the pixel itself and, for long edges, over 17-pixel windows. The
// texture extends `padding` pixels (8 with long edges, else 0) beyond each side of the image:
// the masks of the pixels beyond the border, which the 17-pixel windows of the pixels near it
// average, are computed by the same formulas from colour reads clamped to the border (as
// vtkImageDLAA computes them). Per pixel p with colour c and its four neighbours at distance
// 1 and 2 along x (reads clamped to the image's border):
//   Hx = |sum - 4 c| / 4 (per channel), Bx = (sum + 2 c) / 6, and Hy, By along y;
//   mx = saturate((lambda * l(Hy) - epsilon) / l(Bx)) (a horizontal edge: blurred along x),
//   my = saturate((lambda * l(Hx) - epsilon) / l(By)) (a vertical edge: blurred along y),
// 0 where the numerator is not positive, 1 where it is positive and the divisor is 0.
// Output: (mx, my); (-1, -1) where the 5-pixel cross holds a colour that is not finite (the
// method's masks of such a pixel are 0, and the pixels that read them are left as they are).
//
// Compile-time variants (#defines prepended by vtkOpenGLDLAAPass):
//   DLAA_LUMA  0 Rec. 709 luma, 1 green (vtkDLAAOptions::LumaFunction)
//
// Must match vtkImageDLAA.

in vec2 texCoord; // over the masks texture

uniform sampler2D colorTexture; // the delegate's image
uniform float lambda;
uniform float epsilon;
uniform int padding; // pixels of the masks texture beyond each side of the image

//VTK::DLAA::Luma

// The blend mask from a high-pass luminosity and the luminosity of the blur it goes with.
float blendMask(float highPass, float blur)
{
  float numerator = lambda * highPass - epsilon;
  if (!(numerator > 0.0))
  {
    return 0.0;
  }
  return blur == 0.0 ? 1.0 : clamp(numerator / blur, 0.0, 1.0);
}

void main()
{
  ivec2 size = textureSize(colorTexture, 0);
  // The fragment's pixel of the masks texture is the image pixel p shifted by the padding.
  ivec2 p = ivec2(texCoord * vec2(size + ivec2(2 * padding))) - ivec2(padding);
  ivec2 last = size - ivec2(1);
  vec4 c = texelFetch(colorTexture, clamp(p, ivec2(0), last), 0);
  vec4 sumX = texelFetch(colorTexture, clamp(p - ivec2(2, 0), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p - ivec2(1, 0), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p + ivec2(1, 0), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p + ivec2(2, 0), ivec2(0), last), 0);
  vec4 sumY = texelFetch(colorTexture, clamp(p - ivec2(0, 2), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p - ivec2(0, 1), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p + ivec2(0, 1), ivec2(0), last), 0) +
    texelFetch(colorTexture, clamp(p + ivec2(0, 2), ivec2(0), last), 0);
  // A sum is finite exactly when its terms are (an overflow to infinity counts as not finite).
  if (!finite(c) || !finite(sumX) || !finite(sumY))
  {
    gl_FragData[0] = vec4(-1.0, -1.0, 0.0, 0.0);
    return;
  }
  vec4 highX = abs(sumX - 4.0 * c) / 4.0;
  vec4 highY = abs(sumY - 4.0 * c) / 4.0;
  vec4 blurX = (sumX + 2.0 * c) / 6.0;
  vec4 blurY = (sumY + 2.0 * c) / 6.0;
  gl_FragData[0] =
    vec4(blendMask(luma(highY), luma(blurX)), blendMask(luma(highX), luma(blurY)), 0.0, 0.0);
}
