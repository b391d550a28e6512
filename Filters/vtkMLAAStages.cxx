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

namespace vtkMLAAStages
{
//------------------------------------------------------------------------------
Halo ComputeHalo(vtkMLAAOptions* options)
{
  Halo halo;
  halo.Blending = 1;
  // The diagonal search reads the edgels two pixels past the last unit it follows.
  halo.Search = options->GetSearchReach() + (options->GetDiagonalDetection() ? 2 : 0);
  halo.Edges = options->GetLocalContrastFactor() > 0.0 ? 2 : 0;
  halo.Reconstruction = options->GetReconstruction() ? 1 : 0;
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
