// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkAntialiasingKit.h
 * @brief  What the CPU stages of both methods (MLAA and DLAA) are built from (internal header).
 *
 * - Rect: a rectangle of pixels of one slice; RowsPerTask: the rows of one threaded task.
 * - Progress: rows done, counted from every thread, reported and polled for abort on the calling
 *   thread only (vtkImageAntialiasingAlgorithm makes one per update).
 * - AccumulatorType: the floating-point type the typed stages compute in for a scalar type.
 * - FeatureLayout, FeatureReader: the only typed step on the way in. One row of pixels of any
 *   scalar type into planes of normalised features (luma, colour, CIELAB, depth, alpha), in
 *   [0, 1] over the image's value range, NaN for non-finite values. MLAA's edge detection and
 *   reconstruction read them; DLAA reads the colour features.
 * - ByteBuffer: an uninitialised, reusable full-size buffer.
 * - ConvertBlended: a blended value back to the scalar type, rounded and clamped.
 *
 * Rows and columns follow VTK's image layout: y grows towards the top of the displayed image,
 * so "top" is the next row. All coordinates are those of the image's extent.
 *
 * Internal to MLAA::FiltersMLAA (tests, benchmarks and the mlaa tool include it); not
 * installed.
 */

#ifndef vtkAntialiasingKit_h
#define vtkAntialiasingKit_h

#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAALab.h"
#include "vtkMLAAOptions.h"
#include "vtkType.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <new>
#include <thread>
#include <type_traits>

class vtkDataArray;

/**
 * VTKMLAA_TARGET_CLONES before a (non-template) function definition: an AVX2 clone of it beside
 * the baseline, chosen at load time, where GCC or Clang on x86-64 can make one; nothing elsewhere.
 * Not FMA: a fused multiply-add would round differently from the baseline, and the results must
 * not depend on the processor. For the few loops where wider vectors pay (vtkAntialiasingKit.cxx,
 * vtkMLAAEdgeDetection.cxx).
 */
#if defined(__x86_64__) && defined(__GNUC__) && defined(__ELF__) &&                             \
  (defined(__clang__) ? __clang_major__ >= 14 : __GNUC__ >= 6)
#define VTKMLAA_TARGET_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define VTKMLAA_TARGET_CLONES
#endif

namespace vtkAntialiasingKit
{
/**
 * Asks the kernel to back the 2 MiB pages that lie wholly inside [data, data + bytes) with
 * transparent huge pages (Linux's madvise MADV_HUGEPAGE; nothing elsewhere, or when the
 * system does not offer them). For a large buffer that is about to be written for the first
 * time: its fresh memory then faults once per 2 MiB instead of once per 4 KiB, which costs
 * several microseconds each on virtual machines (up to 12 per 4 KiB measured here).
 */
VTKFILTERSMLAA_EXPORT void PreferHugePages(void* data, std::size_t bytes);
/** The same for the values of an array just allocated (vtkImageData::AllocateScalars). */
VTKFILTERSMLAA_EXPORT void PreferHugePages(vtkDataArray* array);

/**
 * The channels of `width` pixels of `components` bytes each at p, normalised as
 * (value - lo) * inverseRange, into one plane per channel, planeStride values apart: the same
 * floats as that expression per value (FeatureReader's COLOR features of 8-bit images), with an
 * AVX2 clone (VTKMLAA_TARGET_CLONES) that takes the channels apart eight pixels at a time.
 */
VTKFILTERSMLAA_EXPORT void NormaliseBytes(const unsigned char* p, int width, int components,
  float lo, float inverseRange, float* planes, int planeStride);

/** Rows per task of the stages' threaded loops. */
constexpr int RowsPerTask = 32;

/**
 * Rows per task for a stage whose tasks also work on rows beyond their own (halos, scans that
 * start before the band): tasks of more rows do less of that work again, as long as every
 * thread has several tasks to balance the load (four each, between RowsPerTask and 128 rows,
 * for an extent of `rows` rows).
 */
VTKFILTERSMLAA_EXPORT int BandRowsPerTask(int rows);

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
// Features: the values compared across each pixel boundary, normalised so that the value range
// of the image is [0, 1]. They mirror the texture fetches of the edge detection shader
// (Rendering/glsl/vtkMLAAEdgeDetectionFS.glsl).
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
      std::fill(&this->XYZ[0][0][0], &this->XYZ[0][0][0] + sizeof(this->XYZ) / sizeof(Acc), Acc(0));
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
            this->XYZ[channel][index][k] =
              static_cast<Acc>(Lab::RelativeXYZ(k, channel)) * linear;
          }
        }
      }
    }
  }

  /**
   * The features of `width` pixels at `p` (components interleaved) into `features`, one plane
   * per feature, planeStride values apart (feature k of pixel x at features[k * planeStride + x];
   * 0: width apart).
   */
  void Row(const T* p, int width, const double* depth, Acc* features, int planeStride = 0) const
  {
    const int c = this->Layout.Components;
    const int stride = planeStride > 0 ? planeStride : width;
    if (this->Layout.Mode == vtkMLAAOptions::LAB)
    {
      this->LabRow(p, width, features, stride);
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
          this->Pixel(p + x * c, depth ? depth + x : nullptr, features + x, stride);
        }
        else
        {
          for (int k = 0; k < this->Layout.Count; ++k)
          {
            features[k * stride + x] = std::numeric_limits<Acc>::quiet_NaN();
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
      if (std::is_same<T, unsigned char>::value && std::is_same<Acc, float>::value)
      {
        // (The table holds these values; the arithmetic vectorises.)
        NormaliseBytes(reinterpret_cast<const unsigned char*>(p), width, c,
          static_cast<float>(this->Lo), static_cast<float>(this->InverseRange),
          reinterpret_cast<float*>(features), stride);
        return;
      }
      for (int k = 0; k < c; ++k)
      {
        Acc* plane = features + static_cast<size_t>(k) * stride;
        for (int x = 0; x < width; ++x)
        {
          plane[x] = this->Normalise(p[x * c + k]);
        }
      }
      return;
    }
    for (int x = 0; x < width; ++x)
    {
      this->Pixel(p + x * c, depth ? depth + x : nullptr, features + x, stride);
    }
  }

private:
  static constexpr bool UseTables = sizeof(T) == 1;

  // Whether the B bytes at a and b differ, read in the widest pieces that fit (B is a constant:
  // a few loads, no branches). Equal bytes give equal features.
  template <std::size_t B>
  static bool BytesDiffer(const void* a, const void* b)
  {
    const unsigned char* u = static_cast<const unsigned char*>(a);
    const unsigned char* v = static_cast<const unsigned char*>(b);
    std::uint64_t d = 0;
    std::size_t i = 0;
    for (; i + 8 <= B; i += 8)
    {
      std::uint64_t x, y;
      std::memcpy(&x, u + i, 8);
      std::memcpy(&y, v + i, 8);
      d |= x ^ y;
    }
    if (B - i >= 4)
    {
      std::uint32_t x, y;
      std::memcpy(&x, u + i, 4);
      std::memcpy(&y, v + i, 4);
      d |= x ^ y;
      i += 4;
    }
    if (B - i >= 2)
    {
      std::uint16_t x, y;
      std::memcpy(&x, u + i, 2);
      std::memcpy(&y, v + i, 2);
      d |= static_cast<std::uint16_t>(x ^ y);
      i += 2;
    }
    if (B - i >= 1)
    {
      d |= static_cast<unsigned char>(u[i] ^ v[i]);
    }
    return d != 0;
  }

  // The first pixel of each run of equal pixels (all C components) of a row, in runStart;
  // returns the number of runs. Most of a rendered image is long runs: eight pixels at a time
  // that each equal the one before (their bytes equal those one pixel earlier) are passed over
  // with one comparison of their bytes. (Not inlined: inlined into a caller with a short constant
  // row, GCC warns of reads in the branch that the row's length rules out.)
  template <int C>
#if defined(__GNUC__)
  __attribute__((noinline))
#endif
  static int FindRuns(const T* p, int width, int* runStart)
  {
    constexpr std::size_t chunk = 8 * C * sizeof(T);
    int runs = 0;
    for (int x = 0; x < width;)
    {
      if (x > 0 && x + 8 <= width && std::memcmp(p + x * C, p + (x - 1) * C, chunk) == 0)
      {
        x += 8;
        continue;
      }
      // Then pixel by pixel, eight of them before the next try. Branch-free, by the bytes:
      // where runs are short, a branch per pixel would mostly be mispredicted.
      const int end = std::min(width, x + 8);
      if (x == 0)
      {
        runStart[runs++] = x++;
      }
      for (; x < end; ++x)
      {
        runStart[runs] = x;
        runs += BytesDiffer<C * sizeof(T)>(p + x * C, p + (x - 1) * C) ? 1 : 0;
      }
    }
    return runs;
  }

  // LAB features (section 3.2 of Biri et al.): L/100, a/100, b/100 planes, then alpha. Grey
  // images are grey sRGB (R = G = B). Plane by plane: XYZ relative to white (from tables for
  // one-byte types), then f in branch-free loops, which vectorise, then L, a and b.
  void LabRow(const T* p, int width, Acc* features, int stride) const
  {
    const int c = this->Layout.Components;
    Acc* planes[3] = { features, features + stride, features + 2 * static_cast<size_t>(stride) };
    const int second = c >= 3 ? 1 : 0; // grey: the one channel is R, G and B
    const int third = c >= 3 ? 2 : 0;
    // A pixel equal to the one before it takes its features: only the first pixel of each run
    // of one colour (most of a rendered image is such runs) is converted, into `runs` values
    // per plane kept apart (unless every pixel is a run), and the rows are expanded at the end.
    // Run i starts at pixel runStart[i].
    static thread_local std::vector<int> runStartStorage;
    static thread_local std::vector<Acc> runValueStorage;
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
    // Where fewer than a quarter of the pixels repeat the one before, expanding the runs would
    // cost more than converting every pixel.
    const bool compact = runs <= width - width / 4;
    const int n = compact ? runs : width;
    Acc* values[3] = { planes[0], planes[1], planes[2] };
    if (compact)
    {
      runValueStorage.resize(3 * static_cast<size_t>(runs));
      for (int k = 0; k < 3; ++k)
      {
        values[k] = runValueStorage.data() + k * static_cast<size_t>(runs);
      }
    }
    for (int i = 0; i < n; ++i)
    {
      const T* q = p + static_cast<size_t>(compact ? runStart[i] : i) * c;
      if (UseTables)
      {
        const Acc* r = this->XYZ[0][static_cast<unsigned char>(q[0])];
        const Acc* g = this->XYZ[1][static_cast<unsigned char>(q[second])];
        const Acc* b = this->XYZ[2][static_cast<unsigned char>(q[third])];
        for (int k = 0; k < 3; ++k)
        {
          values[k][i] = r[k] + g[k] + b[k];
        }
      }
      else
      {
        const Acc r = Lab::Linearise(this->Normalise(q[0]));
        const Acc g = c >= 3 ? Lab::Linearise(this->Normalise(q[second])) : r;
        const Acc b = c >= 3 ? Lab::Linearise(this->Normalise(q[third])) : r;
        for (int k = 0; k < 3; ++k)
        {
          values[k][i] = static_cast<Acc>(Lab::RelativeXYZ(k, 0)) * r +
            static_cast<Acc>(Lab::RelativeXYZ(k, 1)) * g +
            static_cast<Acc>(Lab::RelativeXYZ(k, 2)) * b;
        }
      }
    }
    Lab::FromRelativeXYZ(values[0], values[1], values[2], n);
    if (compact)
    {
      // Each run from its start on, four pixels first whatever its length (one vector store;
      // what falls beyond a short run is overwritten by the runs after it), except near the
      // end of the row.
      for (int k = 0; k < 3; ++k)
      {
        Acc* plane = planes[k];
        const Acc* value = values[k];
        for (int i = 0; i < runs; ++i)
        {
          const int start = runStart[i];
          const int end = runStart[i + 1];
          const Acc v = value[i];
          int x = start;
          if (start + 4 <= width)
          {
            plane[start] = plane[start + 1] = plane[start + 2] = plane[start + 3] = v;
            x = start + 4;
          }
          for (; x < end; ++x)
          {
            plane[x] = v;
          }
        }
      }
    }
    if (this->Layout.HasAlpha)
    {
      Acc* alpha = features + 3 * static_cast<size_t>(stride);
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
            features[k * static_cast<size_t>(stride) + x] = std::numeric_limits<Acc>::quiet_NaN();
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
  // [channel][value][XYZ component]: contributions (the fourth entry pads a value's three to a
  // vector).
  Acc XYZ[3][UseTables ? 256 : 1][4];
};

//------------------------------------------------------------------------------
/**
 * Values that the stages write in full before reading them: allocated without being cleared,
 * and kept when a later slice, task or update needs no more. Growing drops the contents. A new
 * buffer's memory is fresh: from HugePageSize up, it is allocated on a huge page's boundary, in
 * whole huge pages, with PreferHugePages (T must be trivial).
 */
template <typename T>
class ScratchBuffer
{
  static_assert(std::is_trivially_default_constructible<T>::value &&
      std::is_trivially_destructible<T>::value,
    "ScratchBuffer holds plain values");

public:
  static constexpr std::size_t HugePageSize = std::size_t(2) << 20;

  void Reserve(size_t size)
  {
    if (size > this->Capacity)
    {
      this->Values.reset();
      std::size_t bytes = size * sizeof(T);
      std::size_t alignment = alignof(std::max_align_t);
      if (bytes >= HugePageSize)
      {
        bytes = (bytes + HugePageSize - 1) / HugePageSize * HugePageSize;
        alignment = HugePageSize;
      }
      this->Values.reset(static_cast<T*>(::operator new(bytes, std::align_val_t(alignment))));
      this->Values.get_deleter().Alignment = alignment;
      this->Capacity = size; // (the allocation may be up to a huge page larger)
      PreferHugePages(this->Values.get(), bytes);
    }
    this->Size = size;
  }
  T* Get() { return this->Values.get(); }
  const T* Get() const { return this->Values.get(); }
  size_t GetSize() const { return this->Size; }
  size_t GetCapacity() const { return this->Capacity; }

private:
  struct Free
  {
    std::size_t Alignment = alignof(std::max_align_t);
    void operator()(T* p) const { ::operator delete(p, std::align_val_t(this->Alignment)); }
  };
  std::unique_ptr<T, Free> Values;
  size_t Capacity = 0;
  size_t Size = 0;
};
using ByteBuffer = ScratchBuffer<unsigned char>;

//------------------------------------------------------------------------------
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
}

#endif
