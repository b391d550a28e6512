// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkDLAAStages.h"

namespace vtkDLAAStages
{
//------------------------------------------------------------------------------
VTKMLAA_TARGET_CLONES void SameNeighbours(int planes, const float* const* here,
  const float* const* above, int n, unsigned char* right, unsigned char* up)
{
  SameNeighbours<float>(planes, here, above, n, right, up);
}

//------------------------------------------------------------------------------
Settings MakeSettings(vtkDLAAOptions* options, int components, double lo, double hi)
{
  Settings s;
  s.Epsilon = options->GetEpsilon();
  s.Lambda = options->GetLambda();
  s.LongEdges = options->GetLongEdges();
  s.Components = components;
  s.Lo = lo;
  s.Hi = hi;
  std::fill(s.LumaWeights, s.LumaWeights + 4, 0.0);
  if (components < 3)
  {
    s.LumaWeights[0] = 1.0; // grey (and alpha)
  }
  else if (options->GetLumaFunction() == vtkDLAAOptions::GREEN)
  {
    s.LumaWeights[1] = 1.0;
  }
  else
  {
    s.LumaWeights[0] = 0.2126;
    s.LumaWeights[1] = 0.7152;
    s.LumaWeights[2] = 0.0722;
  }
  return s;
}
}
