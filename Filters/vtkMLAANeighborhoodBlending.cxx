// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAANeighborhoodBlending.h"

#include <array>

namespace vtkMLAAStages
{

const float* WeightValues()
{
  static const std::array<float, 256> values = [] {
    std::array<float, 256> v{};
    for (int i = 0; i < 256; ++i)
    {
      v[i] = static_cast<float>(i) / 255.0f;
    }
    return v;
  }();
  return values.data();
}

//------------------------------------------------------------------------------
void WriteDebugImage(int debugOutput, const EdgesBuffer& edges, const WeightsBuffer& weights,
  const Rect& out, unsigned char* rgba)
{
  for (int y = out.Y0; y <= out.Y1; ++y)
  {
    unsigned char* o = rgba + static_cast<size_t>(y - out.Y0) * out.Width() * 4;
    for (int x = out.X0; x <= out.X1; ++x, o += 4)
    {
      if (debugOutput == vtkMLAAOptions::EDGES)
      {
        const unsigned char* e = edges.At(x, y);
        o[0] = e[0];
        o[1] = e[1];
        o[2] = 0;
        o[3] = 255;
      }
      else
      {
        // Pixels without edgels have no weights (and their entries are never written).
        const unsigned char* e = edges.At(x, y);
        const unsigned char* w = weights.At(x, y);
        for (int k = 0; k < 4; ++k)
        {
          o[k] = (e[0] | e[1]) ? w[k] : 0;
        }
      }
    }
  }
}
}
