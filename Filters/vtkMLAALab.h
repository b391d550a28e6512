// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAALab.h
 * @brief  sRGB to CIELAB for the CPU stages (internal header); the twin of
 *         Rendering/glsl/vtkMLAALab.glsl.
 *
 * Used by the features (vtkAntialiasingKit.h: LAB edges) and by topological reconstruction
 * (vtkMLAAReconstruction.h). Internal to MLAA::FiltersMLAA; not installed.
 */

// (The guard differs from the file name: the shader Rendering/glsl/vtkMLAALab.glsl becomes a
// generated vtkMLAALab.h guarded by vtkMLAALab_h, and vtkOpenGLMLAAPass.cxx includes both.)
#ifndef vtkMLAALabCPU_h
#define vtkMLAALabCPU_h

#include "vtkFiltersMLAAModule.h" // For export macro

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace vtkAntialiasingKit
{
//------------------------------------------------------------------------------
// CIELAB (Biri et al., "Morphological antialiasing and topological reconstruction", section
// 3.2), for vtkMLAAOptions::LAB edges and for reconstruction. A normalised colour is taken as
// sRGB, linearised, converted to CIE XYZ (D65) and to L*a*b*; the features are L/100, a/100
// and b/100, so that their Euclidean distance is Delta E (CIE 1976) / 100.
// Must match labFeatures() in Rendering/glsl/vtkMLAAEdgeDetectionFS.glsl and
// Rendering/glsl/vtkMLAAReconstructionFS.glsl.
namespace Lab
{
/** sRGB transfer function inverted: a normalised channel (clamped at 0) to linear light. */
template <typename Acc>
Acc Linearise(Acc c)
{
  c = c > Acc(0) ? c : Acc(0);
  return c <= Acc(0.04045) ? c / Acc(12.92) : std::pow((c + Acc(0.055)) / Acc(1.055), Acc(2.4));
}

/**
 * Cube root of a positive finite x, without division or branches, so that loops over rows
 * vectorise (several times faster than std::cbrt): a first guess of x^(-1/3) from the bits of
 * the float (a magic constant minus a third of the bits, which divides the exponent by -3;
 * under 7% off), Newton steps for the inverse cube root, y <- y (4 - x y^3) / 3, each of which
 * doubles the correct digits (three in float, four in double: within 4e-7 and 1e-15 relative),
 * then cbrt(x) = x y^2.
 */
template <typename Acc>
Acc FastCbrt(Acc x)
{
  const float xf = static_cast<float>(x);
  std::int32_t bits;
  std::memcpy(&bits, &xf, sizeof(bits));
  bits = 0x54a21d2a - static_cast<std::int32_t>(static_cast<float>(bits) * (1.0f / 3.0f));
  float guess;
  std::memcpy(&guess, &bits, sizeof(guess));
  Acc y = static_cast<Acc>(guess);
  constexpr int steps = sizeof(Acc) <= 4 ? 3 : 4;
  for (int i = 0; i < steps; ++i)
  {
    y = y * (Acc(4) - x * y * y * y) * Acc(1.0 / 3.0);
  }
  return x * y * y;
}

/**
 * a where c holds, else b, by the bits of the values: a select that compilers keep as one (a
 * conditional expression around a float-to-integer conversion becomes a branch under the
 * default floating-point trapping rules, which stops a loop from vectorising).
 */
template <typename Acc>
Acc Select(bool c, Acc a, Acc b)
{
  using Bits = typename std::conditional<sizeof(Acc) == 4, std::uint32_t, std::uint64_t>::type;
  Bits ba, bb;
  std::memcpy(&ba, &a, sizeof(a));
  std::memcpy(&bb, &b, sizeof(b));
  const Bits mask = Bits(0) - static_cast<Bits>(c);
  const Bits r = (ba & mask) | (bb & ~mask);
  Acc out;
  std::memcpy(&out, &r, sizeof(out));
  return out;
}

/**
 * The f of the L*a*b* definition. Both sides are computed and one is selected, so that a loop
 * vectorises (the cube root of a value under the knee, never negative here, is finite and
 * unused).
 */
template <typename Acc>
Acc F(Acc t)
{
  constexpr double delta = 6.0 / 29.0;
  const Acc root = FastCbrt(t);
  const Acc linear = t * Acc(1.0 / (3.0 * delta * delta)) + Acc(4.0 / 29.0);
  return Select(t > Acc(delta * delta * delta), root, linear);
}

/**
 * Row k of the matrix from linear sRGB (D65) to CIE XYZ, divided by the white point's
 * component k (0.95047, 1, 1.08883): XYZ relative to white.
 */
inline double RelativeXYZ(int k, int channel)
{
  static const double m[3][3] = { { 0.4124564, 0.3575761, 0.1804375 },
    { 0.2126729, 0.7151522, 0.0721750 }, { 0.0193339, 0.1191920, 0.9503041 } };
  static const double white[3] = { 0.95047, 1.0, 1.08883 };
  return m[k][channel] / white[k];
}

/** From f(X), f(Y), f(Z) to the features L/100, a/100, b/100 (in place). */
template <typename Acc>
void FinishLab(Acc& fx, Acc& fy, Acc& fz)
{
  const Acc l = Acc(1.16) * fy - Acc(0.16);
  const Acc a = Acc(5) * (fx - fy);
  const Acc b = Acc(2) * (fy - fz);
  fx = l;
  fy = a;
  fz = b;
}

/**
 * XYZ relative to white to the features L/100, a/100, b/100, in place, for n values in each of
 * the three planes (f, then FinishLab). Compiled for AVX2 besides the baseline where the compiler
 * can pick at run time (the same operations, no fused multiply-add: the same results), since this
 * loop is most of the cost of LAB edges.
 */
VTKFILTERSMLAA_EXPORT void FromRelativeXYZ(float* x, float* y, float* z, int n);
VTKFILTERSMLAA_EXPORT void FromRelativeXYZ(double* x, double* y, double* z, int n);

/** Linear sRGB (D65) to the features L/100, a/100, b/100. */
template <typename Acc>
void FromLinear(Acc r, Acc g, Acc b, Acc& l, Acc& a, Acc& bb)
{
  Acc xyz[3];
  for (int k = 0; k < 3; ++k)
  {
    xyz[k] = F(static_cast<Acc>(RelativeXYZ(k, 0)) * r + static_cast<Acc>(RelativeXYZ(k, 1)) * g +
      static_cast<Acc>(RelativeXYZ(k, 2)) * b);
  }
  FinishLab(xyz[0], xyz[1], xyz[2]);
  l = xyz[0];
  a = xyz[1];
  bb = xyz[2];
}
}
}

#endif
