// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAntialiasingKit.h"

#include <thread>

namespace vtkAntialiasingKit
{
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
