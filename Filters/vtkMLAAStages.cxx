// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAAStages.h"

#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkSMPTools.h"

#include <array>
#include <map>
#include <mutex>
#include <cstdint>
#include <cstring>
#include <memory>
#include <vector>

namespace vtkMLAAStages
{
//------------------------------------------------------------------------------
namespace
{
// The buffers given back and not yet taken again, the most recent last.
struct SliceBuffersPool
{
  std::mutex Mutex;
  std::vector<std::unique_ptr<SliceBuffers>> Free;
  size_t Bytes = 0;
};
SliceBuffersPool& Pool()
{
  static SliceBuffersPool pool;
  return pool;
}
}

SliceBuffersLease AcquireSliceBuffers()
{
  SliceBuffersPool& pool = Pool();
  std::lock_guard<std::mutex> lock(pool.Mutex);
  if (pool.Free.empty())
  {
    return SliceBuffersLease(new SliceBuffers);
  }
  std::unique_ptr<SliceBuffers> buffers = std::move(pool.Free.back());
  pool.Free.pop_back();
  pool.Bytes -= buffers->GetCapacity();
  return SliceBuffersLease(buffers.release());
}

void ReturnSliceBuffers::operator()(SliceBuffers* returned) const
{
  std::unique_ptr<SliceBuffers> buffers(returned);
  const size_t bytes = buffers->GetCapacity();
  if (bytes > RetainedBytes)
  {
    return; // freed
  }
  SliceBuffersPool& pool = Pool();
  std::vector<std::unique_ptr<SliceBuffers>> dropped; // freed after the lock is released
  std::lock_guard<std::mutex> lock(pool.Mutex);
  // Make room by freeing the buffers returned longest ago.
  while (pool.Bytes + bytes > RetainedBytes && !pool.Free.empty())
  {
    pool.Bytes -= pool.Free.front()->GetCapacity();
    dropped.push_back(std::move(pool.Free.front()));
    pool.Free.erase(pool.Free.begin());
  }
  pool.Free.push_back(std::move(buffers));
  pool.Bytes += bytes;
}

size_t GetRetainedSliceBufferBytes()
{
  SliceBuffersPool& pool = Pool();
  std::lock_guard<std::mutex> lock(pool.Mutex);
  return pool.Bytes;
}

//------------------------------------------------------------------------------
Halo ComputeHalo(vtkMLAAOptions* options)
{
  Halo halo;
  halo.Blending = 1;
  // The diagonal search reads the edgels two pixels past the last unit it follows; corner
  // extrapolation counts the next run past a line's end, which lies up to the search's reach
  // away, as far again.
  halo.Search = options->GetSearchReach() * (options->GetCornerExtrapolation() ? 2 : 1) +
    (options->GetDiagonalDetection() ? 2 : 0);
  halo.Edges = options->GetLocalContrastFactor() > 0.0 ? 2 : 0;
  // A reconstructed pixel depends on its neighbours' neighbours and their coverage windows
  // (vtkMLAATopology::ReconstructionReach).
  halo.Reconstruction = options->GetReconstruction() ? vtkMLAATopology::ReconstructionReach : 0;
  return halo;
}

//------------------------------------------------------------------------------
void ConfigureSlice(vtkMLAAOptions* options, int components, double lo, double hi, SliceSetup& setup)
{
  setup.DebugOutput = options->GetDebugOutput();
  setup.Layout = MakeFeatureLayout(options->GetEdgeDetection(), components);
  setup.Edges.Threshold = options->GetThreshold();
  setup.Edges.LocalContrastFactor = options->GetLocalContrastFactor();
  setup.Edges.EuclideanFeatures = setup.Layout.Mode == vtkMLAAOptions::LAB ? 3 : 1;
  setup.Reconstruction = options->GetReconstruction();
  MakeWeightSettings(options, setup.Weights);
  setup.Dominant = options->GetDominantDirectionBlending();
  setup.PremultipliedAlpha = options->GetPremultipliedAlpha();
  setup.Lo = lo;
  setup.Hi = hi;
}
}
