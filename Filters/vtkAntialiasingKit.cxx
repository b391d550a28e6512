// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAntialiasingKit.h"

#include "vtkDataArray.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>
#include <thread>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace vtkAntialiasingKit
{
//------------------------------------------------------------------------------
int BandRowsPerTask(int rows)
{
  const int threads = std::max(1, vtkSMPTools::GetEstimatedNumberOfThreads());
  return std::max(RowsPerTask, std::min(128, rows / (4 * threads)));
}

//------------------------------------------------------------------------------
void PreferHugePages(void* data, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge = std::uintptr_t(2) << 20;
  const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(data);
  const std::uintptr_t begin = (start + huge - 1) & ~(huge - 1);
  const std::uintptr_t end = (start + bytes) & ~(huge - 1);
  if (data && end > begin)
  {
    // Advice only: where it is refused (no transparent huge pages), the pages stay small.
    (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  }
#else
  (void)data;
  (void)bytes;
#endif
}

//------------------------------------------------------------------------------
void PreferHugePages(vtkDataArray* array)
{
  if (array && array->GetNumberOfValues() > 0)
  {
    PreferHugePages(array->GetVoidPointer(0),
      static_cast<std::size_t>(array->GetNumberOfValues()) * array->GetDataTypeSize());
  }
}

//------------------------------------------------------------------------------
Progress::Progress(
  std::function<void(double)> report, std::function<bool()> aborted, vtkIdType totalRows)
  : Report(std::move(report))
  , AbortQuery(std::move(aborted))
  , Total(totalRows > 0 ? totalRows : 1)
  , Owner(std::this_thread::get_id())
{
}

Progress::Progress()
  : Owner(std::this_thread::get_id())
{
}

void Progress::RowsDone(vtkIdType rows)
{
  const vtkIdType done = this->Done.fetch_add(rows, std::memory_order_relaxed) + rows;
  if (std::this_thread::get_id() != this->Owner)
  {
    return;
  }
  const double fraction = std::min(1.0, static_cast<double>(done) / this->Total);
  if (this->Report && fraction - this->LastReported >= 0.01)
  {
    this->LastReported = fraction;
    this->Report(fraction);
  }
  this->CheckAbort();
}

bool Progress::CheckAbort()
{
  if (std::this_thread::get_id() == this->Owner && this->AbortQuery && this->AbortQuery())
  {
    this->AbortFlag.store(true, std::memory_order_relaxed);
  }
  return this->Aborted();
}

//------------------------------------------------------------------------------
namespace
{
// Inlined into each clone below, so that each compiles the loops for its own target.
template <typename Acc>
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline void FromRelativeXYZPlanes(Acc* x, Acc* y, Acc* z, int n)
{
  Acc* planes[3] = { x, y, z };
  for (Acc* plane : planes)
  {
    for (int i = 0; i < n; ++i)
    {
      plane[i] = Lab::F(plane[i]);
    }
  }
  for (int i = 0; i < n; ++i)
  {
    Lab::FinishLab(x[i], y[i], z[i]);
  }
}
}

// An AVX2 clone beside the baseline (VTKMLAA_TARGET_CLONES, vtkAntialiasingKit.h).
namespace Lab
{
VTKMLAA_TARGET_CLONES void FromRelativeXYZ(float* x, float* y, float* z, int n)
{
  FromRelativeXYZPlanes(x, y, z, n);
}
VTKMLAA_TARGET_CLONES void FromRelativeXYZ(double* x, double* y, double* z, int n)
{
  FromRelativeXYZPlanes(x, y, z, n);
}
}

//------------------------------------------------------------------------------
namespace
{
template <int C>
inline void NormaliseChannels(
  const unsigned char* p, int width, float lo, float inverseRange, float* planes, int stride)
{
  for (int x = 0; x < width; ++x)
  {
    for (int k = 0; k < C; ++k)
    {
      planes[k * stride + x] = (static_cast<float>(p[C * x + k]) - lo) * inverseRange;
    }
  }
}
}

VTKMLAA_TARGET_CLONES void NormaliseBytes(const unsigned char* p, int width, int components,
  float lo, float inverseRange, float* planes, int planeStride)
{
  switch (components)
  {
    case 1:
      NormaliseChannels<1>(p, width, lo, inverseRange, planes, planeStride);
      break;
    case 2:
      NormaliseChannels<2>(p, width, lo, inverseRange, planes, planeStride);
      break;
    case 3:
      NormaliseChannels<3>(p, width, lo, inverseRange, planes, planeStride);
      break;
    default:
      NormaliseChannels<4>(p, width, lo, inverseRange, planes, planeStride);
      break;
  }
}

//------------------------------------------------------------------------------
FeatureLayout MakeFeatureLayout(int mode, int components)
{
  FeatureLayout layout;
  layout.Mode = mode;
  layout.Components = components;
  layout.HasAlpha = components == 2 || components == 4;
  layout.Count = mode == vtkMLAAOptions::COLOR
    ? components
    : (mode == vtkMLAAOptions::LAB ? 3 : 1) + (layout.HasAlpha ? 1 : 0);
  return layout;
}

}
