/**
 * @file   vtkMLAAStages.h
 * @brief  The CPU MLAA of vtkImageMLAA as the stages of the GPU pass (internal header).
 *
 * vtkImageMLAA runs, on each z slice, the same stages as vtkOpenGLMLAAPass runs as full-screen
 * passes (Rendering/glsl/), each a small unit with its own buffer:
 *
 * | stage                  | reads                  | writes                              | GPU pass |
 * |------------------------|------------------------|-------------------------------------|----------|
 * | reconstruction (typed, optional) | the slice's pixels | a reconstructed copy of them, read by every later stage | vtkMLAAReconstructionFS |
 * | features (typed)       | the slice's pixels     | a few rows of normalised features   | (fetches in the edge shader) |
 * | edges                  | features               | EdgesBuffer, 2 x 8 bit per pixel    | vtkMLAAEdgeDetectionFS |
 * | blending weights       | edges, area tables     | WeightsBuffer, 4 x 8 bit per pixel  | vtkMLAABlendingWeightsFS |
 * | neighbourhood blending (typed) | pixels, weights | the output slice                   | vtkMLAANeighborhoodBlendingFS |
 *
 * Only the features and the blending depend on the scalar type; the edges and weights buffers
 * are laid out as the pass's RG8 edges and RGBA8 blending-weights textures, with the same 8-bit
 * quantisation, so the two back ends compute the same numbers. Features are read row by row into
 * per-task buffers (never a full-size copy of the image); the edges and weights buffers (with,
 * from RunLengthSteps search steps on, the weights' scratch of 16-bit line lengths: 4 bytes per
 * pixel, 12 with DiagonalDetection) are the only full-size buffers besides the output.
 *
 * How far each stage reads beyond the pixels it produces (its halo) is derived from the options
 * in one place, Halo (below); vtkImageMLAA pads its input request by Halo::Total().
 *
 * Rows and columns follow VTK's image layout: y grows towards the top of the displayed image,
 * so "top" is the next row. All coordinates are those of the image's extent.
 *
 * This header is internal to MLAA::FiltersMLAA (the tests include it); it is not installed.
 */

#ifndef vtkMLAAStages_h
#define vtkMLAAStages_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAAOptions.h"
#include "vtkMLAATopology.h"
#include "vtkSMPTools.h"
#include "vtkType.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

namespace vtkMLAAStages
{
/** Rows per task of the stages' threaded loops. */
constexpr int RowsPerTask = 32;

//------------------------------------------------------------------------------
/** A rectangle of pixels of one slice, bounds included. */
struct Rect
{
  int X0 = 0, X1 = -1, Y0 = 0, Y1 = -1;
  int Width() const { return this->X1 - this->X0 + 1; }
  int Height() const { return this->Y1 - this->Y0 + 1; }
  bool Empty() const { return this->X1 < this->X0 || this->Y1 < this->Y0; }
  bool Contains(int x, int y) const
  {
    return x >= this->X0 && x <= this->X1 && y >= this->Y0 && y <= this->Y1;
  }
  Rect Intersect(const Rect& o) const
  {
    return { std::max(this->X0, o.X0), std::min(this->X1, o.X1), std::max(this->Y0, o.Y0),
      std::min(this->Y1, o.Y1) };
  }
  Rect Grown(int by) const
  {
    return { this->X0 - by, this->X1 + by, this->Y0 - by, this->Y1 + by };
  }
};

//------------------------------------------------------------------------------
/**
 * How far, in pixels along x and y, each stage reads beyond the pixels it produces, for given
 * options. An output pixel depends on input pixels up to Total() away; vtkImageMLAA pads its
 * input request by that much, which makes streamed results equal unstreamed ones.
 * - Blending: 1. A pixel blends with its four neighbours, by its own weights and by those of
 *   its right and lower neighbours.
 * - Search: the blending weights of a pixel read edgels along its line up to 2 * MaxSearchSteps
 *   pixels away and the crossing edge one further (section 4.3.1): 2 * MaxSearchSteps + 1. The
 *   diagonal search follows up to 2 * MaxSearchSteps units and reads the edgels two pixels past
 *   the last one: 2 * MaxSearchSteps + 3.
 * - Edges: an edgel compares its two pixels, which the search reach above already counts; local
 *   contrast adaptation also looks at the other boundaries of those pixels, one pixel further,
 *   which is padded by 2.
 * - Reconstruction: 1 with vtkMLAAOptions::Reconstruction (a reconstructed pixel depends on its
 *   eight neighbours, Biri et al. section 4.3), else 0.
 */
struct Halo
{
  int Blending = 1;
  int Search = 17;
  int Edges = 2;
  int Reconstruction = 0;
  int Total() const
  {
    return this->Blending + this->Search + this->Edges + this->Reconstruction;
  }
};
VTKFILTERSMLAA_EXPORT Halo ComputeHalo(vtkMLAAOptions* options);

//------------------------------------------------------------------------------
/**
 * Progress and cancellation of the stages' threaded loops. Rows are counted from every thread;
 * the report callback (vtkAlgorithm::UpdateProgress) and the abort query (GetAbortExecute) are
 * only called from the thread that created the object, between tasks, so observers of a
 * ProgressEvent run where they expect to. Once aborted, the remaining tasks return at once.
 */
class VTKFILTERSMLAA_EXPORT Progress
{
public:
  Progress(std::function<void(double)> report, std::function<bool()> aborted, vtkIdType totalRows);
  Progress();

  /** Count rows as done; from the creating thread, report progress and poll for an abort. */
  void RowsDone(vtkIdType rows);
  /** Whether the work was aborted (any thread). */
  bool Aborted() const { return this->AbortFlag.load(std::memory_order_relaxed); }
  /** Poll the abort query now (creating thread only). */
  bool CheckAbort();

private:
  std::function<void(double)> Report;
  std::function<bool()> AbortQuery;
  vtkIdType Total = 1;
  std::atomic<vtkIdType> Done{ 0 };
  double LastReported = -1.0;
  std::atomic<bool> AbortFlag{ false };
  std::thread::id Owner;
};

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

//------------------------------------------------------------------------------
// Stage 1: features (typed). The values compared across each pixel boundary, normalised so that
// the value range of the image is [0, 1].

/** What each pixel contributes to edge detection, from the options and the components. */
struct FeatureLayout
{
  int Mode = vtkMLAAOptions::LUMA; // vtkMLAAOptions::EdgeDetectionModes
  int Components = 3;              // of the image
  bool HasAlpha = false;           // 2 or 4 components
  int Count = 1;                   // features per pixel
};
VTKFILTERSMLAA_EXPORT FeatureLayout MakeFeatureLayout(int mode, int components);

/**
 * Edge detection of 8- and 16-bit and float images is done in float, as on the GPU; wider types
 * use double.
 */
template <typename T>
using AccumulatorType = typename std::conditional<(sizeof(T) <= 2 ||
                                                    std::is_same<T, float>::value),
  float, double>::type;

/**
 * Reads the features of rows of pixels of type T: normalised as (value - lo) * inverseRange,
 * luma (Rec. 709, section 4.2.1; the first component of grey images), every channel (COLOR,
 * alpha included), the depth (given per row, already normalised) or CIELAB (LAB: L/100, a/100,
 * b/100, namespace Lab), then alpha. A pixel holding
 * NaN or infinity gets NaN features, which are never an edge. For one-byte types the normalised
 * values (and their products with the luma weights) come from tables built once, which give the
 * same floats as the arithmetic.
 */
template <typename T, typename Acc>
class FeatureReader
{
public:
  FeatureReader(const FeatureLayout& layout, Acc lo, Acc inverseRange)
    : Layout(layout)
    , Lo(lo)
    , InverseRange(inverseRange)
  {
    if (UseTables)
    {
      for (int i = 0; i < 256; ++i)
      {
        const Acc v = (static_cast<Acc>(static_cast<T>(i)) - lo) * inverseRange;
        const unsigned char index = static_cast<unsigned char>(static_cast<T>(i));
        this->Normalised[index] = v;
        this->Luma[0][index] = Acc(0.2126) * v;
        this->Luma[1][index] = Acc(0.7152) * v;
        this->Luma[2][index] = Acc(0.0722) * v;
        const Acc linear = Lab::Linearise(v);
        for (int k = 0; k < 3; ++k)
        {
          for (int channel = 0; channel < 3; ++channel)
          {
            this->XYZ[k][channel][index] =
              static_cast<Acc>(Lab::RelativeXYZ(k, channel)) * linear;
          }
        }
      }
    }
  }

  /**
   * The features of `width` pixels at `p` (components interleaved) into `features`, one plane of
   * `width` values per feature (feature k of pixel x at features[k * width + x]).
   */
  void Row(const T* p, int width, const double* depth, Acc* features) const
  {
    const int c = this->Layout.Components;
    if (this->Layout.Mode == vtkMLAAOptions::LAB)
    {
      this->LabRow(p, width, features);
      return;
    }
    if (std::is_floating_point<T>::value)
    {
      // Non-finite pixels: NaN features.
      for (int x = 0; x < width; ++x)
      {
        bool finite = true;
        for (int k = 0; k < c; ++k)
        {
          finite = finite && std::isfinite(static_cast<double>(p[x * c + k]));
        }
        if (finite)
        {
          this->Pixel(p + x * c, depth ? depth + x : nullptr, features + x, width);
        }
        else
        {
          for (int k = 0; k < this->Layout.Count; ++k)
          {
            features[k * width + x] = std::numeric_limits<Acc>::quiet_NaN();
          }
        }
      }
      return;
    }
    if (this->Layout.Mode == vtkMLAAOptions::LUMA && c == 3)
    {
      // The common cases without per-pixel branches: RGB luma, and every channel.
      for (int x = 0; x < width; ++x, p += 3)
      {
        features[x] = this->LumaOf(p);
      }
      return;
    }
    if (this->Layout.Mode == vtkMLAAOptions::COLOR)
    {
      for (int k = 0; k < c; ++k)
      {
        Acc* plane = features + k * width;
        for (int x = 0; x < width; ++x)
        {
          plane[x] = this->Normalise(p[x * c + k]);
        }
      }
      return;
    }
    for (int x = 0; x < width; ++x)
    {
      this->Pixel(p + x * c, depth ? depth + x : nullptr, features + x, width);
    }
  }

private:
  static constexpr bool UseTables = sizeof(T) == 1;

  // The first pixel of each run of equal pixels (all C components) of a row, in runStart;
  // returns the number of runs.
  template <int C>
  static int FindRuns(const T* p, int width, int* runStart)
  {
    int runs = 0;
    for (int x = 0; x < width; ++x)
    {
      const T* q = p + x * C;
      bool same = x > 0;
      for (int k = 0; k < C; ++k)
      {
        same = same && q[k] == q[k - C];
      }
      runStart[runs] = x;
      runs += same ? 0 : 1;
    }
    return runs;
  }

  // LAB features (section 3.2 of Biri et al.): L/100, a/100, b/100 planes, then alpha. Grey
  // images are grey sRGB (R = G = B). Plane by plane: XYZ relative to white (from tables for
  // one-byte types), then f in branch-free loops, which vectorise, then L, a and b.
  void LabRow(const T* p, int width, Acc* features) const
  {
    const int c = this->Layout.Components;
    Acc* planes[3] = { features, features + width, features + 2 * static_cast<size_t>(width) };
    const int second = c >= 3 ? 1 : 0; // grey: the one channel is R, G and B
    const int third = c >= 3 ? 2 : 0;
    // A pixel equal to the one before it takes its features: only the first pixel of each run
    // of one colour (most of a rendered image is such runs) is converted, into the first
    // `runs` entries of the planes, and the rows are expanded at the end. Run i starts at
    // pixel runStart[i].
    static thread_local std::vector<int> runStartStorage;
    runStartStorage.resize(static_cast<size_t>(width) + 1);
    int* runStart = runStartStorage.data();
    int runs = 0;
    switch (c)
    {
      case 1:
        runs = this->FindRuns<1>(p, width, runStart);
        break;
      case 2:
        runs = this->FindRuns<2>(p, width, runStart);
        break;
      case 3:
        runs = this->FindRuns<3>(p, width, runStart);
        break;
      default:
        runs = this->FindRuns<4>(p, width, runStart);
        break;
    }
    runStart[runs] = width;
    for (int i = 0; i < runs; ++i)
    {
      const T* q = p + static_cast<size_t>(runStart[i]) * c;
      if (UseTables)
      {
        for (int k = 0; k < 3; ++k)
        {
          planes[k][i] = this->XYZ[k][0][static_cast<unsigned char>(q[0])] +
            this->XYZ[k][1][static_cast<unsigned char>(q[second])] +
            this->XYZ[k][2][static_cast<unsigned char>(q[third])];
        }
      }
      else
      {
        const Acc r = Lab::Linearise(this->Normalise(q[0]));
        const Acc g = c >= 3 ? Lab::Linearise(this->Normalise(q[second])) : r;
        const Acc b = c >= 3 ? Lab::Linearise(this->Normalise(q[third])) : r;
        for (int k = 0; k < 3; ++k)
        {
          planes[k][i] = static_cast<Acc>(Lab::RelativeXYZ(k, 0)) * r +
            static_cast<Acc>(Lab::RelativeXYZ(k, 1)) * g +
            static_cast<Acc>(Lab::RelativeXYZ(k, 2)) * b;
        }
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      Acc* plane = planes[k];
      for (int i = 0; i < runs; ++i)
      {
        plane[i] = Lab::F(plane[i]);
      }
    }
    for (int i = 0; i < runs; ++i)
    {
      Lab::FinishLab(planes[0][i], planes[1][i], planes[2][i]);
    }
    if (runs < width)
    {
      // Backwards, so that no run is overwritten before it is read (run i starts at or after
      // pixel i).
      for (int k = 0; k < 3; ++k)
      {
        Acc* plane = planes[k];
        for (int i = runs - 1; i >= 0; --i)
        {
          std::fill(plane + runStart[i], plane + runStart[i + 1], plane[i]);
        }
      }
    }
    if (this->Layout.HasAlpha)
    {
      Acc* alpha = features + 3 * static_cast<size_t>(width);
      for (int x = 0; x < width; ++x)
      {
        alpha[x] = this->Normalise(p[x * c + c - 1]);
      }
    }
    if (std::is_floating_point<T>::value)
    {
      // Non-finite pixels: NaN features, which are never an edge and never unlike anything.
      for (int x = 0; x < width; ++x)
      {
        bool finite = true;
        for (int k = 0; k < c; ++k)
        {
          finite = finite && std::isfinite(static_cast<double>(p[x * c + k]));
        }
        if (!finite)
        {
          for (int k = 0; k < this->Layout.Count; ++k)
          {
            features[k * static_cast<size_t>(width) + x] = std::numeric_limits<Acc>::quiet_NaN();
          }
        }
      }
    }
  }

  Acc Normalise(T v) const
  {
    if (UseTables)
    {
      return this->Normalised[static_cast<unsigned char>(v)];
    }
    return (static_cast<Acc>(v) - this->Lo) * this->InverseRange;
  }
  Acc LumaOf(const T* p) const
  {
    if (UseTables)
    {
      return this->Luma[0][static_cast<unsigned char>(p[0])] +
        this->Luma[1][static_cast<unsigned char>(p[1])] +
        this->Luma[2][static_cast<unsigned char>(p[2])];
    }
    return Acc(0.2126) * this->Normalise(p[0]) + Acc(0.7152) * this->Normalise(p[1]) +
      Acc(0.0722) * this->Normalise(p[2]);
  }
  // The features of one pixel, `plane` values apart.
  void Pixel(const T* p, const double* depth, Acc* features, int plane) const
  {
    const int c = this->Layout.Components;
    int f = 0;
    switch (this->Layout.Mode)
    {
      case vtkMLAAOptions::COLOR:
        for (int k = 0; k < c; ++k)
        {
          features[plane * f++] = this->Normalise(p[k]);
        }
        return; // alpha is one of the channels
      case vtkMLAAOptions::DEPTH:
        features[plane * f++] = static_cast<Acc>(*depth);
        break;
      default:
        features[plane * f++] = c >= 3 ? this->LumaOf(p) : this->Normalise(p[0]);
        break;
    }
    if (this->Layout.HasAlpha)
    {
      features[plane * f] = this->Normalise(p[c - 1]);
    }
  }

  FeatureLayout Layout;
  Acc Lo;
  Acc InverseRange;
  Acc Normalised[UseTables ? 256 : 1];
  Acc Luma[3][UseTables ? 256 : 1];
  Acc XYZ[3][3][UseTables ? 256 : 1]; // [XYZ component][channel][value]: contributions
};

//------------------------------------------------------------------------------
/**
 * Bytes that the stages write in full before reading them: allocated without being cleared, and
 * kept when a later slice or update needs no more.
 */
class ByteBuffer
{
public:
  void Reserve(size_t size)
  {
    if (size > this->Capacity)
    {
      this->Bytes.reset(new unsigned char[size]);
      this->Capacity = size;
    }
    this->Size = size;
  }
  unsigned char* Get() { return this->Bytes.get(); }
  const unsigned char* Get() const { return this->Bytes.get(); }
  size_t GetSize() const { return this->Size; }

private:
  std::unique_ptr<unsigned char[]> Bytes;
  size_t Capacity = 0;
  size_t Size = 0;
};

//------------------------------------------------------------------------------
// Stage 2: edges (section 4.2).

/**
 * The edges of a rectangle of pixels, laid out as the pass's RG8 edges texture: two bytes per
 * pixel, [0] = 255 where the pixel has an edgel at its left boundary, [1] = 255 at its top
 * boundary (towards the next row); 0 elsewhere.
 */
struct EdgesBuffer
{
  Rect Extent;
  ByteBuffer Data;

  void Allocate(const Rect& extent);
  const unsigned char* At(int x, int y) const
  {
    return this->Data.Get() +
      2 * (static_cast<size_t>(y - this->Extent.Y0) * this->Extent.Width() + (x - this->Extent.X0));
  }
  unsigned char* At(int x, int y)
  {
    return const_cast<unsigned char*>(static_cast<const EdgesBuffer*>(this)->At(x, y));
  }
  bool Left(int x, int y) const { return this->At(x, y)[0] != 0; }
  bool Top(int x, int y) const { return this->At(x, y)[1] != 0; }
  bool Any(int x, int y) const { return (this->At(x, y)[0] | this->At(x, y)[1]) != 0; }
};

/** Settings of edge detection, from vtkMLAAOptions. */
struct EdgeSettings
{
  double Threshold = 0.1;
  double LocalContrastFactor = 2.0; // 0: off
  // How many leading features are compared together, by their Euclidean distance: 3 in LAB
  // mode (Delta E / 100 from L, a, b, Biri et al. section 3.2), 1 otherwise (a plain
  // difference); no other value is used.
  int EuclideanFeatures = 1;
};

/**
 * The edgels of every pixel of edges.Extent (already allocated), from the features that
 * `readRow(y, features)` gives for each row y of it (layout.Count planes of
 * edges.Extent.Width() values, FeatureReader::Row). The contrast across a boundary is the
 * largest of the Euclidean distance of the first settings.EuclideanFeatures features and the
 * differences of the others; the boundary is an edge where it is at least the threshold (and
 * more than 0); with local contrast adaptation, only if factor
 * times that contrast is at least the contrast of every other boundary of its two pixels.
 * Boundaries outside the extent are not edges. Acc is float or double (AccumulatorType).
 */
template <typename Acc>
VTKFILTERSMLAA_EXPORT void DetectEdges(const std::function<void(int, Acc*)>& readRow, int features,
  const EdgeSettings& settings, EdgesBuffer& edges, Progress& progress);

//------------------------------------------------------------------------------
// Stage 3: blending weights (section 4.3).

/**
 * The blending weights of a rectangle of pixels, laid out as the pass's RGBA8 blending-weights
 * texture (8-bit, value / 255): [0] the weight with which the pixel takes the colour above it,
 * [1] the pixel above takes this one's, [2] the pixel takes its left neighbour's, [3] the left
 * neighbour takes this one's. Only the pixels with an edgel are written ([0] and [1] are 0
 * unless the pixel has a top edgel, [2] and [3] unless it has a left one); the others are left
 * as they were and never read, which spares clearing the whole buffer.
 */
struct WeightsBuffer
{
  Rect Extent;
  ByteBuffer Data;
  // Scratch of ComputeBlendingWeights: the down and up line lengths of the extent's pixels (two
  // LineLength per pixel), kept with the weights so that it is not allocated (and its pages not
  // faulted in afresh) on every run.
  ByteBuffer ColumnLengths;
  // The same for the staircase lengths of DiagonalDetection: four LineLength per pixel.
  ByteBuffer DiagonalLengths;

  void Allocate(const Rect& extent);
  const unsigned char* At(int x, int y) const
  {
    return this->Data.Get() +
      4 * (static_cast<size_t>(y - this->Extent.Y0) * this->Extent.Width() + (x - this->Extent.X0));
  }
  unsigned char* At(int x, int y)
  {
    return const_cast<unsigned char*>(static_cast<const WeightsBuffer*>(this)->At(x, y));
  }
};

/**
 * The search length (vtkMLAAOptions::MaxSearchSteps) from which the weights stage counts line
 * lengths as run lengths instead of searching from every edge pixel (measured, 1920 x 1080, one
 * thread, vtkImageMLAA time / vtkImageGaussianSmooth time): searching stops at each line's end,
 * so on images of short lines it is cheaper (0.30 against 0.44 at 8 steps on the "mixed" scene:
 * counting reads every pixel a few times) but its cost grows with the lines' length, up to 6.3
 * at 32 steps and 11 at 128 on a screen of long 0.3-degree stripes, and 6.2 and 14 on 45-degree
 * stripes (staircases), where run lengths stay at 1.5 to 2.3. From 16 steps on (32 pixels each
 * way) run lengths bound that cost; below, the search's reads are bounded by the short distance.
 */
constexpr int RunLengthSteps = 16;

/**
 * The area tables of vtkMLAAAreaTexture for one maximum distance, quantised to 8 bits as the
 * blending weights are stored (the pass's RGBA8 texture), and the search settings.
 */
struct WeightSettings
{
  int SearchSteps = 8;     // vtkMLAAOptions::MaxSearchSteps
  bool Diagonals = true;   // vtkMLAAOptions::DiagonalDetection
  // How lines and staircases are measured: true, by run lengths counted over the extent
  // beforehand (ComputeRowLineLengths, ComputeColumnLineLengths, and the staircases' likewise);
  // false, by searching from every pixel with an edgel, step by step, as the GPU's SEARCH_LOOP.
  // The same numbers either way; MakeWeightSettings picks run lengths from RunLengthSteps
  // search steps on.
  bool RunLengths = false;
  int CellSize = 17;       // D = 2 * SearchSteps + 1
  int AreaSize = 85;       // 5 D
  int DiagonalAreaSize = 51; // 3 D
  // Quantised once per maximum distance and shared (quantising the tables of 128 steps, 5 million
  // texels, costs more than the rest of the weights stage).
  std::shared_ptr<const std::vector<unsigned char>> Area;         // 2 per texel
  std::shared_ptr<const std::vector<unsigned char>> DiagonalArea; // 3 per texel; null without diagonals
};
VTKFILTERSMLAA_EXPORT void MakeWeightSettings(vtkMLAAOptions* options, WeightSettings& settings);

/**
 * Line lengths (section 4.3.1's distance search, done as run lengths): for a pixel p, the number
 * of further pixels along its row (left or right) or its column (down or up) that continue its
 * line, at most maxDistance (vtkMLAAOptions::GetMaxDistance()). Pixel q continues the line from
 * its neighbour p towards q when q has the line's edgel (a top edgel for a row, a left edgel for
 * a column) and no crossing edgel lies at the boundary between p and q: no left edgel there on
 * p's row or the row above (rows), no top edgel there in p's column or the column to the left
 * (columns). Edgels are read clamped to edges.Extent, as a GPU reads with clamp-to-edge, so a
 * line that reaches the border of the extent and continues across it (by that rule applied to
 * the clamped edgels) runs on to maxDistance.
 *
 * These equal, for every pixel, the distances of a search that steps pixel by pixel up to
 * maxDistance (the chapter's loop, vtkOpenGLMLAAPass's SEARCH_LOOP), but cost one linear scan
 * per row and per column instead of up to maxDistance reads per pixel and direction: each length
 * is 0 where the next pixel does not continue the line, else 1 plus the next pixel's length,
 * capped (the recursion that the GPU's recursive doubling, Rendering/glsl/
 * vtkMLAALineLengthsFS.glsl, evaluates in log4(maxDistance) passes instead; Biri et al., section
 * 3.3). 16-bit lengths hold maxDistance up to 256.
 */
using LineLength = std::uint16_t;

/**
 * The left and right lengths of the pixels of row y of edges.Extent that have a top edgel (one
 * entry per column of the extent, from edges.Extent.X0; the entries of pixels without a top
 * edgel are not all written: they are never needed).
 */
VTKFILTERSMLAA_EXPORT void ComputeRowLineLengths(
  const EdgesBuffer& edges, int y, int maxDistance, LineLength* left, LineLength* right);

/**
 * The down and up lengths of the pixels of `extent` (within edges.Extent) that have a left
 * edgel, row by row, one entry per pixel of `extent` in each array (those of pixels without a
 * left edgel are not all written). Threaded over strips of columns.
 */
VTKFILTERSMLAA_EXPORT void ComputeColumnLineLengths(const EdgesBuffer& edges, const Rect& extent,
  int maxDistance, LineLength* down, LineLength* up);

/**
 * The blending weights of the pixels of weights.Extent (already allocated, within edges.Extent)
 * that have an edgel, from the edges; the entries of the others are not written. `whole` is the image: edgels are read clamped to edges.Extent,
 * as a GPU clamps texture reads, and the image border is not a crossing edge. The distances to
 * the ends of orthogonal lines are line lengths (ComputeRowLineLengths, per row of each task,
 * and ComputeColumnLineLengths, held for the whole weights extent: two 16-bit values per pixel);
 * with DiagonalDetection, the lengths of staircases are counted the same way beforehand (four
 * 16-bit values per pixel). Below RunLengthSteps search steps they are searched from each pixel
 * instead (WeightSettings::RunLengths), which needs none of these buffers.
 */
VTKFILTERSMLAA_EXPORT void ComputeBlendingWeights(const EdgesBuffer& edges, const Rect& whole,
  const WeightSettings& settings, WeightsBuffer& weights, Progress& progress);

//------------------------------------------------------------------------------
// Stage 4: neighbourhood blending (section 4.4, typed).

/** The 8-bit weights as the blending reads them: value / 255 in float. */
VTKFILTERSMLAA_EXPORT const float* WeightValues();

/** Settings of the blending, from vtkMLAAOptions and the image. */
struct BlendSettings
{
  bool Dominant = true;          // vtkMLAAOptions::DominantDirectionBlending
  bool StraightAlpha = false;    // alpha present and not premultiplied
  double AlphaLo = 0.0;          // normalisation of the alpha channel
  double AlphaInverseRange = 1.0;
};

template <typename T, typename Acc>
T ConvertBlended(Acc v)
{
  if (std::is_floating_point<T>::value)
  {
    return static_cast<T>(v);
  }
  // Round to nearest and saturate, as a GPU stores a normalised value.
  const Acc r = std::floor(v + Acc(0.5));
  if (r <= static_cast<Acc>(std::numeric_limits<T>::lowest()))
  {
    return std::numeric_limits<T>::lowest();
  }
  if (r >= static_cast<Acc>(std::numeric_limits<T>::max()))
  {
    return std::numeric_limits<T>::max();
  }
  return static_cast<T>(r);
}

/**
 * Row y of the output: each pixel of `out` (columns out.X0..X1) mixed with its four neighbours
 * by the weights, c' = sum_k a_k ((1 - a_k) c + a_k c_k) / sum_k a_k, which for a single edge is
 * equation 4.1; pixels without weights are copied. `pixel(x, y)` gives the input pixel (all
 * components); only neighbours with a weight are read, and those lie within the weights' extent.
 * With DominantDirectionBlending, a pixel on both a horizontal and a vertical line blends along
 * the one with the larger weight only. With straight alpha, the colour channels are averaged
 * weighted by alpha as well (premultiply, blend, divide by the blended alpha), so the colour of
 * transparent pixels never leaks into their neighbours; where the alphas that take part are all
 * equal, that changes nothing and the plain formula is used.
 */
template <typename T, typename Acc, typename PixelAt>
void BlendRow(int y, const Rect& out, int components, const EdgesBuffer& edges,
  const WeightsBuffer& weights, const BlendSettings& settings, PixelAt pixel, T* output)
{
  const float* value = WeightValues();
  const Rect& wr = weights.Extent;
  const int c = components;
  std::copy(pixel(out.X0, y), pixel(out.X0, y) + static_cast<size_t>(out.Width()) * c, output);
  if (y < wr.Y0 || y > wr.Y1)
  {
    return;
  }
  const bool hasBelow = y - 1 >= wr.Y0;
  const int x0 = std::max(out.X0, wr.X0);
  const int x1 = std::min(out.X1, wr.X1);
  const unsigned char* e = edges.At(x0, y);
  const unsigned char* eBelow = hasBelow ? edges.At(x0, y - 1) : nullptr;
  const unsigned char* w = weights.At(x0, y);
  const unsigned char* wBelow = hasBelow ? weights.At(x0, y - 1) : nullptr;
  // A pixel is blended where it has an edgel of its own, where the pixel below has a top edgel
  // or where the pixel on its right has a left edgel; only then are the weights read (the
  // weights of pixels without edgels are never written). Most pixels have none: four pixels
  // at a time are skipped with one test on the edges.
  constexpr std::uint64_t topMask = 0xFF00FF00FF00FF00ull;
  constexpr std::uint64_t leftMask = 0x00FF00FF00FF00FFull;
  const bool littleEndian = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first == 1;
  }();
  for (int x = x0; x <= x1; ++x, e += 2, w += 4, eBelow = eBelow ? eBelow + 2 : nullptr,
           wBelow = wBelow ? wBelow + 4 : nullptr)
  {
    if (littleEndian && x + 3 <= x1 && x + 4 <= wr.X1)
    {
      // Pixels x to x + 3: their edgels, the top edgels below them and the left edgels of the
      // pixels right of them (x + 1 to x + 4, all within the weights).
      std::uint64_t own, below = 0, right;
      std::memcpy(&own, e, 8);
      std::memcpy(&right, e + 2, 8);
      if (eBelow)
      {
        std::memcpy(&below, eBelow, 8);
      }
      if ((own | (below & topMask) | (right & leftMask)) == 0)
      {
        x += 3;
        e += 6;
        w += 12;
        eBelow = eBelow ? eBelow + 6 : nullptr;
        wBelow = wBelow ? wBelow + 12 : nullptr;
        continue;
      }
    }
    const bool top = e[1] != 0;
    const bool left = e[0] != 0;
    const bool fromBelow = eBelow && eBelow[1];
    const bool fromRight = x < wr.X1 && e[2];
    if (!top && !left && !fromBelow && !fromRight)
    {
      continue;
    }
    Acc a[4] = { top ? static_cast<Acc>(value[w[0]]) : Acc(0),
      fromBelow ? static_cast<Acc>(value[wBelow[1]]) : Acc(0),
      left ? static_cast<Acc>(value[w[2]]) : Acc(0),
      fromRight ? static_cast<Acc>(value[w[4 + 3]]) : Acc(0) };
    if (settings.Dominant)
    {
      // DominantDirectionBlending: on a corner, only the line with the larger weight counts.
      const Acc vertical = std::max(a[0], a[1]);
      const Acc horizontal = std::max(a[2], a[3]);
      if (vertical > horizontal)
      {
        a[2] = a[3] = Acc(0);
      }
      else if (horizontal > vertical)
      {
        a[0] = a[1] = Acc(0);
      }
    }
    const Acc sum = a[0] + a[1] + a[2] + a[3];
    if (!(sum > Acc(0)))
    {
      continue;
    }
    const T* p = pixel(x, y);
    // Neighbours that are not blended in are never read (they may lie outside the input).
    const T* neighbours[4] = { a[0] > Acc(0) ? pixel(x, y + 1) : p,
      a[1] > Acc(0) ? pixel(x, y - 1) : p, a[2] > Acc(0) ? pixel(x - 1, y) : p,
      a[3] > Acc(0) ? pixel(x + 1, y) : p };
    T* q = output + static_cast<size_t>(x - out.X0) * c;
    int first = 0; // the first channel blended by the plain formula
    if (settings.StraightAlpha)
    {
      // Straight alpha: blend the colours premultiplied, unless all alphas taking part agree.
      const Acc alpha = static_cast<Acc>(p[c - 1]);
      bool equal = true;
      for (int n = 0; n < 4; ++n)
      {
        equal = equal && (!(a[n] > Acc(0)) || static_cast<Acc>(neighbours[n][c - 1]) == alpha);
      }
      if (!equal)
      {
        first = c - 1;
        auto coverage = [&settings, c](const T* px) {
          const double v =
            (static_cast<double>(px[c - 1]) - settings.AlphaLo) * settings.AlphaInverseRange;
          return static_cast<Acc>(std::min(1.0, std::max(0.0, v)));
        };
        const Acc ownCoverage = coverage(p);
        Acc mixedAlpha = 0;
        Acc mixed[3] = { 0, 0, 0 };
        for (int n = 0; n < 4; ++n)
        {
          if (a[n] > Acc(0))
          {
            const Acc selfShare = a[n] * (Acc(1) - a[n]) * ownCoverage;
            const Acc otherShare = a[n] * a[n] * coverage(neighbours[n]);
            mixedAlpha += selfShare + otherShare;
            for (int k = 0; k < c - 1; ++k)
            {
              mixed[k] += selfShare * static_cast<Acc>(p[k]) +
                otherShare * static_cast<Acc>(neighbours[n][k]);
            }
          }
        }
        if (mixedAlpha > Acc(0))
        {
          for (int k = 0; k < c - 1; ++k)
          {
            q[k] = ConvertBlended<T>(mixed[k] / mixedAlpha);
          }
        }
        // else: everything that takes part is fully transparent; the colour stays.
      }
    }
    for (int k = first; k < c; ++k)
    {
      const Acc v = static_cast<Acc>(p[k]);
      Acc blended = 0;
      for (int n = 0; n < 4; ++n)
      {
        if (a[n] > Acc(0))
        {
          blended += a[n] * ((Acc(1) - a[n]) * v + a[n] * static_cast<Acc>(neighbours[n][k]));
        }
      }
      q[k] = ConvertBlended<T>(blended / sum);
    }
  }
}

/**
 * One of the debug images of vtkMLAAOptions (8-bit RGBA, rows of out.Width() pixels) for the
 * pixels of `out`: the edges or the blending weights.
 */
VTKFILTERSMLAA_EXPORT void WriteDebugImage(int debugOutput, const EdgesBuffer& edges,
  const WeightsBuffer& weights, const Rect& out, unsigned char* rgba);

//------------------------------------------------------------------------------
// The stages on one slice.

// Normalised depth values of one row of the depth image, for depth edges: floating-point depths
// as they are (a z-buffer in [0, 1]), integer ones by the range of their type.
template <typename T>
void NormaliseDepthRow(const void* row, vtkIdType pixelStride, int width, double* out)
{
  double lo = 0.0;
  double hi = 1.0;
  if (!std::is_floating_point<T>::value)
  {
    lo = static_cast<double>(std::numeric_limits<T>::lowest());
    hi = static_cast<double>(std::numeric_limits<T>::max());
  }
  const T* p = static_cast<const T*>(row);
  for (int x = 0; x < width; ++x, p += pixelStride)
  {
    out[x] = (static_cast<double>(*p) - lo) / (hi - lo);
  }
}

// The depth image of one slice, read row by row.
struct DepthRows
{
  const char* Origin = nullptr; // the first available pixel of the slice
  vtkIdType RowBytes = 0;
  vtkIdType PixelStride = 0; // in values
  void (*Normalise)(const void*, vtkIdType, int, double*) = nullptr;
};

/** Everything one z slice of any type needs. */
struct SliceSetup
{
  Rect Whole;  // the image: reads beyond it are clamped to it, as GPU texture reads are
  Rect Input;  // the pixels available (the requested extent, padded, within the input)
  Rect Output; // the pixels to produce
  int DebugOutput = vtkMLAAOptions::NO_DEBUG_OUTPUT;
  FeatureLayout Layout;
  EdgeSettings Edges;
  WeightSettings Weights;
  bool Dominant = true;
  bool PremultipliedAlpha = false;
  bool Reconstruction = false; // vtkMLAAOptions::Reconstruction (stage 0)
  double Lo = 0.0; // normalisation: value -> (value - Lo) / (Hi - Lo)
  double Hi = 1.0;

  /**
   * The pixels whose blending weights the output needs: its own, and those of the row below it
   * and the column right of it, which its blending reads; within the available pixels.
   */
  Rect WeightsExtent() const
  {
    return Rect{ this->Output.X0, this->Output.X1 + 1, this->Output.Y0 - 1, this->Output.Y1 }
      .Intersect(this->Input);
  }
  /**
   * The rows the stages go through on one slice (reconstruction, edges, weights, blending), for
   * progress.
   */
  vtkIdType RowsOfWork() const
  {
    return static_cast<vtkIdType>(this->Input.Height()) * (this->Reconstruction ? 2 : 1) +
      this->WeightsExtent().Height() + this->Output.Height();
  }
};

//------------------------------------------------------------------------------
// Stage 0 (optional): topological reconstruction (Biri et al., section 4), typed; runs before
// the features when vtkMLAAOptions::Reconstruction is on, and its output replaces the input of
// every later stage.

/**
 * Whether two pixels with LAB features (FeatureReader in LAB mode, `count` planes `plane`
 * values apart) are unlike for reconstruction: Delta E / 100 at least the threshold (and more
 * than 0), or, with alpha (count 4), the alpha difference likewise: the boundary between them
 * would be a LAB edge before local contrast adaptation. NaN features (non-finite pixels) are
 * never unlike anything. Distances are compared squared, which is the same test.
 * Must match unlike() in Rendering/glsl/vtkMLAAReconstructionFS.glsl.
 */
template <typename Acc>
bool Unlike(const Acc* p, const Acc* q, size_t plane, int count, Acc threshold2)
{
  const Acc d0 = p[0] - q[0];
  const Acc d1 = p[plane] - q[plane];
  const Acc d2 = p[2 * plane] - q[2 * plane];
  const Acc e2 = d0 * d0 + d1 * d1 + d2 * d2;
  if (e2 >= threshold2 && e2 > Acc(0))
  {
    return true;
  }
  if (count > 3)
  {
    const Acc da = p[3 * plane] - q[3 * plane];
    const Acc a2 = da * da;
    return a2 >= threshold2 && a2 > Acc(0);
  }
  return false;
}

/**
 * Unlike for pixels first..last - 1 of a row of features `a` against `b` (the same row, or the
 * one below or above, offset to the neighbour): `value` is or-ed into mask[x] where they are
 * unlike. One branch-free loop per direction.
 */
template <typename Acc, bool Alpha>
void UnlikeMasks(const Acc* a, const Acc* b, size_t plane, Acc threshold2, unsigned char value,
  int first, int last, unsigned char* mask)
{
  const Acc* a1 = a + plane;
  const Acc* a2 = a + 2 * plane;
  const Acc* a3 = a + 3 * plane;
  const Acc* b1 = b + plane;
  const Acc* b2 = b + 2 * plane;
  const Acc* b3 = b + 3 * plane;
  for (int x = first; x < last; ++x)
  {
    const Acc d0 = a[x] - b[x];
    const Acc d1 = a1[x] - b1[x];
    const Acc d2 = a2[x] - b2[x];
    const Acc e2 = d0 * d0 + d1 * d1 + d2 * d2;
    bool unlike = (e2 >= threshold2) & (e2 > Acc(0));
    if (Alpha)
    {
      const Acc da = a3[x] - b3[x];
      const Acc a2d = da * da;
      unlike = unlike | ((a2d >= threshold2) & (a2d > Acc(0)));
    }
    mask[x] |= unlike ? value : static_cast<unsigned char>(0);
  }
}

/**
 * The neighbour masks (bits as vtkMLAATopology) of pixels first..last - 1 of a row from the
 * comparisons of Reconstruct (1 where unlike): toE[x] with the pixel right of x, toN, toNE and
 * toNW[x] with the pixels above, and those of the row below, whose entries at x, x - 1 and
 * x + 1 are the comparisons of pixel x with its S, SW and SE neighbours.
 */
inline void CombineUnlike(const unsigned char* __restrict toE,
  const unsigned char* __restrict toNE, const unsigned char* __restrict toN,
  const unsigned char* __restrict toNW, const unsigned char* __restrict belowNE,
  const unsigned char* __restrict belowN, const unsigned char* __restrict belowNW, int first,
  int last, unsigned char* __restrict mask)
{
  for (int x = first; x < last; ++x)
  {
    mask[x] = static_cast<unsigned char>(toE[x] | (toNE[x] << 1) | (toN[x] << 2) |
      (toNW[x] << 3) | (toE[x - 1] << 4) | (belowNE[x - 1] << 5) | (belowN[x] << 6) |
      (belowNW[x + 1] << 7));
  }
}

/**
 * Section 4.3: the reconstructed pixels of setup.Input into `output` (rows of
 * setup.Input.Width() pixels, packed). `input` points at the first pixel of setup.Input (rows
 * `inputRowStride` values apart); reads beyond setup.Input are clamped to it (the halo keeps
 * those reads away from the output, and at the image border they are clamped as a GPU clamps
 * texture reads). For each pixel A, X is the mask of its neighbours unlike A (Unlike, threshold
 * setup.Edges.Threshold; bits as vtkMLAATopology). A is selected when
 * vtkMLAATopology::GetSelectionTable() says so and the X pixels are pairwise not unlike (one
 * colour: the shape); it then becomes the mean of its X pixels, every component, rounded to
 * nearest for integer types. Every other pixel is copied. All decisions read the original
 * pixels.
 * Must match Rendering/glsl/vtkMLAAReconstructionFS.glsl.
 */
template <typename T>
void Reconstruct(const SliceSetup& setup, const T* input, vtkIdType inputRowStride, T* output,
  Progress& progress)
{
  using Acc = AccumulatorType<T>;
  const Rect& in = setup.Input;
  if (in.Empty())
  {
    return;
  }
  const int w = in.Width();
  const int h = in.Height();
  const int c = setup.Layout.Components;
  const FeatureLayout layout = MakeFeatureLayout(vtkMLAAOptions::LAB, c);
  const int count = layout.Count;
  const size_t plane = static_cast<size_t>(w);
  const FeatureReader<T, Acc> reader(
    layout, static_cast<Acc>(setup.Lo), static_cast<Acc>(1.0 / (setup.Hi - setup.Lo)));
  const Acc threshold = static_cast<Acc>(setup.Edges.Threshold);
  const Acc threshold2 = threshold * threshold;
  const unsigned char* selected = vtkMLAATopology::GetSelectionTable();
  int offsets[8][2];
  for (int bit = 0; bit < 8; ++bit)
  {
    vtkMLAATopology::GetNeighborOffset(bit, offsets[bit][0], offsets[bit][1]);
  }
  auto pixel = [&](int x, int y) { return input + y * inputRowStride + static_cast<vtkIdType>(x) * c; };

  vtkSMPTools::For(0, h, RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    // The LAB features of rows begin - 1 .. end (clamped), row i at index i + 1 - begin.
    const int first = static_cast<int>(begin) - 1;
    const int rows = static_cast<int>(end - begin) + 2;
    const size_t rowSize = plane * count;
    std::unique_ptr<Acc[]> band(new Acc[rowSize * rows]);
    for (int i = 0; i < rows; ++i)
    {
      const int y = std::min(std::max(first + i, 0), h - 1);
      reader.Row(pixel(0, y), w, nullptr, band.get() + rowSize * i);
    }
    // Whether pixels are unlike their neighbours, each pair compared once (Unlike is
    // symmetric): along each band row (x, x + 1), and between band rows i and i + 1 (x with x,
    // x + 1 and x - 1 above it), over the columns where both pixels exist. Branch-free loops
    // that vectorise.
    const size_t uw = static_cast<size_t>(w);
    std::vector<unsigned char> along(rows * uw, 0);
    std::vector<unsigned char> up((rows - 1) * uw, 0);
    std::vector<unsigned char> upRight((rows - 1) * uw, 0);
    std::vector<unsigned char> upLeft((rows - 1) * uw, 0);
    auto compare = [&](const Acc* a, const Acc* b, int from, int to, unsigned char* out) {
      if (count > 3)
      {
        UnlikeMasks<Acc, true>(a, b, plane, threshold2, 1, from, to, out);
      }
      else
      {
        UnlikeMasks<Acc, false>(a, b, plane, threshold2, 1, from, to, out);
      }
    };
    for (int i = 0; i < rows; ++i)
    {
      const Acc* here = band.get() + rowSize * i;
      if (i > 0 && i < rows - 1)
      {
        compare(here, here + 1, 0, w - 1, along.data() + i * uw);
      }
      if (i < rows - 1)
      {
        const Acc* above = here + rowSize;
        compare(here, above, 0, w, up.data() + i * uw);
        compare(here, above + 1, 0, w - 1, upRight.data() + i * uw);
        compare(here, above - 1, 1, w, upLeft.data() + i * uw);
      }
    }
    std::vector<unsigned char> masks(uw);
    for (vtkIdType row = begin; row < end; ++row)
    {
      const int y = static_cast<int>(row);
      T* out = output + static_cast<size_t>(y) * w * c;
      std::copy(pixel(0, y), pixel(0, y) + static_cast<size_t>(w) * c, out);
      // The features of the rows below, at and above y.
      const int j = y - first; // band row of y
      const Acc* around[3] = { band.get() + rowSize * (j - 1), band.get() + rowSize * j,
        band.get() + rowSize * (j + 1) };
      // The masks of the unlike neighbours of the inner columns from the comparisons above
      // (bits as vtkMLAATopology: E, NE, N, NW, W, SW, S, SE), then those of the first and
      // last columns, whose reads are clamped.
      unsigned char* mask = masks.data();
      const unsigned char* toE = along.data() + j * uw;
      const unsigned char* toN = up.data() + j * uw;
      const unsigned char* toNE = upRight.data() + j * uw;
      const unsigned char* toNW = upLeft.data() + j * uw;
      const unsigned char* toS = up.data() + (j - 1) * uw;
      const unsigned char* toSW = upRight.data() + (j - 1) * uw; // from (x - 1, y - 1)
      const unsigned char* toSE = upLeft.data() + (j - 1) * uw;  // from (x + 1, y - 1)
      CombineUnlike(toE, toNE, toN, toNW, toSW, toS, toSE, 1, w - 1, mask);
      for (int x : { 0, w - 1 })
      {
        mask[x] = 0; // (a single column is done twice, to the same result)
        for (int bit = 0; bit < 8; ++bit)
        {
          const int nx = std::min(std::max(x + offsets[bit][0], 0), w - 1);
          mask[x] |= Unlike(around[1] + x, around[1 + offsets[bit][1]] + nx, plane, count, threshold2)
            ? static_cast<unsigned char>(1 << bit)
            : 0;
        }
      }
      for (int x = 0; x < w; ++x)
      {
        if ((x & 7) == 0 && x + 8 <= w)
        {
          // Most pixels have no unlike neighbour: eight at a time are skipped.
          std::uint64_t eight;
          std::memcpy(&eight, mask + x, sizeof(eight));
          if (eight == 0)
          {
            x += 7;
            continue;
          }
        }
        if (!selected[mask[x]])
        {
          continue;
        }
        int neighbourX[8];
        const Acc* features[8];
        for (int bit = 0; bit < 8; ++bit)
        {
          neighbourX[bit] = std::min(std::max(x + offsets[bit][0], 0), w - 1);
          features[bit] = around[1 + offsets[bit][1]] + neighbourX[bit];
        }
        const int unlike = mask[x];
        // The shape is one colour: its pixels are pairwise alike.
        bool oneColour = true;
        for (int i = 0; i < 8 && oneColour; ++i)
        {
          for (int j = i + 1; j < 8 && oneColour; ++j)
          {
            if (((unlike >> i) & (unlike >> j) & 1) &&
              Unlike(features[i], features[j], plane, count, threshold2))
            {
              oneColour = false;
            }
          }
        }
        if (!oneColour)
        {
          continue;
        }
        // The mean of the shape's pixels, every component.
        double sum[4] = { 0, 0, 0, 0 };
        int n = 0;
        for (int bit = 0; bit < 8; ++bit)
        {
          if ((unlike >> bit) & 1)
          {
            const int ny = std::min(std::max(y + offsets[bit][1], 0), h - 1);
            const T* q = pixel(neighbourX[bit], ny);
            for (int k = 0; k < c; ++k)
            {
              sum[k] += static_cast<double>(q[k]);
            }
            ++n;
          }
        }
        for (int k = 0; k < c; ++k)
        {
          out[static_cast<size_t>(x) * c + k] = ConvertBlended<T>(sum[k] / n);
        }
      }
    }
    progress.RowsDone(end - begin);
  });
}

//------------------------------------------------------------------------------
/** The full-size buffers of the stages, reused from slice to slice. */
struct SliceBuffers
{
  ByteBuffer Reconstructed; // the reconstructed pixels of the slice, with Reconstruction only
  EdgesBuffer Edges;
  WeightsBuffer Weights;
};

/** Wall-clock seconds spent in each stage, summed over the slices run with it. */
struct StageTimes
{
  double Reconstruction = 0.0;   // with vtkMLAAOptions::Reconstruction only
  double FeaturesAndEdges = 0.0; // features are read row by row inside edge detection
  double BlendingWeights = 0.0;
  double Blending = 0.0; // neighbourhood blending or the debug image
};

/**
 * The stages on one slice of an image of type T (reconstruction first, when
 * setup.Reconstruction): `input` points at the first pixel of
 * setup.Input (rows `inputRowStride` values apart), `output` (or `debug`, for a debug image) at
 * the first pixel of setup.Output (rows packed). `times`, if given, collects the stages' times.
 */
template <typename T>
void RunSlice(const SliceSetup& setup, const T* input, vtkIdType inputRowStride,
  const DepthRows& depth, T* output, unsigned char* debug, SliceBuffers& buffers,
  Progress& progress, StageTimes* times = nullptr)
{
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  auto lap = [&t0, times](double StageTimes::*stage) {
    const auto t1 = Clock::now();
    if (times)
    {
      times->*stage += std::chrono::duration<double>(t1 - t0).count();
    }
    t0 = t1;
  };
  using Acc = AccumulatorType<T>;
  const Rect& in = setup.Input;
  const int c = setup.Layout.Components;

  // Stage 0: reconstruction, into a copy of the available pixels that then replaces the input.
  if (setup.Reconstruction)
  {
    buffers.Reconstructed.Reserve(
      sizeof(T) * static_cast<size_t>(c) * in.Width() * std::max(in.Height(), 0));
    T* reconstructed = reinterpret_cast<T*>(buffers.Reconstructed.Get());
    Reconstruct<T>(setup, input, inputRowStride, reconstructed, progress);
    lap(&StageTimes::Reconstruction);
    if (progress.Aborted())
    {
      return;
    }
    input = reconstructed;
    inputRowStride = static_cast<vtkIdType>(in.Width()) * c;
  }
  auto pixel = [&](int x, int y) {
    return input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
      static_cast<vtkIdType>(x - in.X0) * c;
  };

  // Stages 1 and 2: features, read row by row, and edges.
  const FeatureReader<T, Acc> reader(
    setup.Layout, static_cast<Acc>(setup.Lo), static_cast<Acc>(1.0 / (setup.Hi - setup.Lo)));
  const std::function<void(int, Acc*)> readRow = [&](int y, Acc* features) {
    const double* depthRow = nullptr;
    if (depth.Normalise)
    {
      // One row of normalised depths per thread, kept from row to row.
      static thread_local std::vector<double> depthValues;
      depthValues.resize(in.Width());
      depth.Normalise(depth.Origin + (y - in.Y0) * depth.RowBytes, depth.PixelStride, in.Width(),
        depthValues.data());
      depthRow = depthValues.data();
    }
    reader.Row(pixel(in.X0, y), in.Width(), depthRow, features);
  };
  buffers.Edges.Allocate(in);
  DetectEdges<Acc>(readRow, setup.Layout.Count, setup.Edges, buffers.Edges, progress);
  lap(&StageTimes::FeaturesAndEdges);

  // Stage 3: blending weights of the output pixels and of the pixels whose weights their
  // blending reads (the row below and the column right of them).
  const Rect& out = setup.Output;
  buffers.Weights.Allocate(setup.WeightsExtent());
  if (progress.Aborted())
  {
    return;
  }
  ComputeBlendingWeights(buffers.Edges, setup.Whole, setup.Weights, buffers.Weights, progress);
  lap(&StageTimes::BlendingWeights);
  if (progress.Aborted())
  {
    return;
  }

  // Stage 4: neighbourhood blending, or a debug image.
  if (debug)
  {
    WriteDebugImage(setup.DebugOutput, buffers.Edges, buffers.Weights, out, debug);
    progress.RowsDone(out.Height());
    lap(&StageTimes::Blending);
    return;
  }
  BlendSettings blend;
  blend.Dominant = setup.Dominant;
  blend.StraightAlpha = setup.Layout.HasAlpha && !setup.PremultipliedAlpha;
  blend.AlphaLo = setup.Lo;
  blend.AlphaInverseRange = 1.0 / (setup.Hi - setup.Lo);
  vtkSMPTools::For(0, out.Height(), RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    for (vtkIdType i = begin; i < end; ++i)
    {
      BlendRow<T, Acc>(out.Y0 + static_cast<int>(i), out, c, buffers.Edges, buffers.Weights, blend, pixel,
        output + i * out.Width() * c);
    }
    progress.RowsDone(end - begin);
  });
  lap(&StageTimes::Blending);
}

/**
 * A SliceSetup's settings from the options, for an image of `components` components normalised
 * by [lo, hi]; the rectangles are left to the caller.
 */
VTKFILTERSMLAA_EXPORT void ConfigureSlice(
  vtkMLAAOptions* options, int components, double lo, double hi, SliceSetup& setup);
}

#endif

