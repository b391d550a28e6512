// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAATopology.h"

#include <algorithm>
#include <cmath>

#include "vtkObjectFactory.h"

#include <array>
#include <cstdlib>

vtkStandardNewMacro(vtkMLAATopology);

namespace
{
// The neighbours in bit order: E, NE, N, NW, W, SW, S, SE (y grows towards the next row).
constexpr int Offsets[8][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { -1, -1 },
  { 0, -1 }, { 1, -1 } };
}

//------------------------------------------------------------------------------
void vtkMLAATopology::GetNeighborOffset(int bit, int& dx, int& dy)
{
  dx = Offsets[bit & 7][0];
  dy = Offsets[bit & 7][1];
}

//------------------------------------------------------------------------------
double vtkMLAATopology::GetCoverage(int shapePixels)
{
  const int columns = 2 * CoverageRadius + 1;
  if (shapePixels <= 0 || shapePixels > columns)
  {
    return 0.0;
  }
  return static_cast<double>(shapePixels) / (2.0 * columns);
}

//------------------------------------------------------------------------------
double vtkMLAATopology::GetLineShare(int shapePixels)
{
  const int columns = 2 * CoverageRadius + 1;
  if (shapePixels <= 0 || 2 * shapePixels > columns)
  {
    return 1.0;
  }
  return static_cast<double>(shapePixels) / columns;
}

//------------------------------------------------------------------------------
const float* vtkMLAATopology::GetCoverageTable()
{
  static const std::array<float, CoverageTableSize> table = [] {
    std::array<float, CoverageTableSize> t{};
    for (int n = 0; n < CoverageTableSize; ++n)
    {
      t[n] = static_cast<float>(GetCoverage(n));
    }
    return t;
  }();
  return table.data();
}

//------------------------------------------------------------------------------
const float* vtkMLAATopology::GetLineShareTable()
{
  static const std::array<float, CoverageTableSize> table = [] {
    std::array<float, CoverageTableSize> t{};
    for (int n = 0; n < CoverageTableSize; ++n)
    {
      t[n] = static_cast<float>(GetLineShare(n));
    }
    return t;
  }();
  return table.data();
}

//------------------------------------------------------------------------------
int vtkMLAATopology::ConnexityNumber(int mask)
{
  return static_cast<int>(FindPieces(mask).size());
}

//------------------------------------------------------------------------------
int vtkMLAATopology::LargestComponent(int mask)
{
  int largest = 0;
  for (const Piece& piece : FindPieces(mask))
  {
    largest = std::max(largest, piece.Size);
  }
  return largest;
}

//------------------------------------------------------------------------------
std::vector<vtkMLAATopology::Piece> vtkMLAATopology::FindPieces(int mask)
{
  // Union-find over the positions in the mask; two positions are 8-adjacent when they are at
  // most one apart along x and along y (section 4.1, N8).
  int parent[8];
  for (int i = 0; i < 8; ++i)
  {
    parent[i] = i;
  }
  auto root = [&parent](int i) {
    while (parent[i] != i)
    {
      i = parent[i];
    }
    return i;
  };
  for (int i = 0; i < 8; ++i)
  {
    for (int j = i + 1; j < 8; ++j)
    {
      if (((mask >> i) & 1) && ((mask >> j) & 1) &&
        std::abs(Offsets[i][0] - Offsets[j][0]) <= 1 &&
        std::abs(Offsets[i][1] - Offsets[j][1]) <= 1)
      {
        parent[root(j)] = root(i);
      }
    }
  }
  std::vector<Piece> pieces;
  int index[8];
  for (int i = 0; i < 8; ++i)
  {
    if (!((mask >> i) & 1))
    {
      continue;
    }
    const int r = root(i);
    if (r == i)
    {
      index[r] = static_cast<int>(pieces.size());
      pieces.push_back(Piece{});
    }
  }
  for (int i = 0; i < 8; ++i)
  {
    if ((mask >> i) & 1)
    {
      Piece& piece = pieces[index[root(i)]];
      ++piece.Size;
      piece.X += Offsets[i][0];
      piece.Y += Offsets[i][1];
    }
  }
  return pieces;
}

//------------------------------------------------------------------------------
double vtkMLAATopology::PiecesCosine(const Piece& a, const Piece& b)
{
  const double ax = static_cast<double>(a.X) / a.Size, ay = static_cast<double>(a.Y) / a.Size;
  const double bx = static_cast<double>(b.X) / b.Size, by = static_cast<double>(b.Y) / b.Size;
  const double na = std::sqrt(ax * ax + ay * ay), nb = std::sqrt(bx * bx + by * by);
  return (na > 0.0 && nb > 0.0) ? (ax * bx + ay * by) / (na * nb) : 1.0;
}

//------------------------------------------------------------------------------
bool vtkMLAATopology::ComputeSelection(int mask)
{
  // Section 4.2: two pieces of the shape X, one piece of its complement. Ours: pieces no larger
  // than a thin line's cross-section, on opposite sides of the pixel; and a gap in a straight
  // line (two single pixels exactly opposite, the complement cut in two by the line) is closed
  // too.
  mask &= 255;
  const std::vector<Piece> shape = FindPieces(mask);
  if (shape.size() != 2 || shape[0].Size > MaximumPieceSize || shape[1].Size > MaximumPieceSize)
  {
    return false;
  }
  const double cosine = PiecesCosine(shape[0], shape[1]);
  if (cosine > OppositeCosine)
  {
    return false;
  }
  const size_t complement = FindPieces(~mask & 255).size();
  const bool straightGap = shape[0].Size == 1 && shape[1].Size == 1 && cosine < -0.999;
  return complement == 1 || (complement == 2 && straightGap);
}

//------------------------------------------------------------------------------
const unsigned char* vtkMLAATopology::GetSelectionTable()
{
  static const std::array<unsigned char, 256> table = [] {
    std::array<unsigned char, 256> t{};
    for (int m = 0; m < 256; ++m)
    {
      t[m] = ComputeSelection(m) ? 1 : 0;
    }
    return t;
  }();
  return table.data();
}

//------------------------------------------------------------------------------
void vtkMLAATopology::GetSelectionBits(unsigned int bits[8])
{
  const unsigned char* table = GetSelectionTable();
  for (int word = 0; word < 8; ++word)
  {
    bits[word] = 0;
    for (int b = 0; b < 32; ++b)
    {
      bits[word] |= table[32 * word + b] ? (1u << b) : 0u;
    }
  }
}

//------------------------------------------------------------------------------
void vtkMLAATopology::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  int selected = 0;
  for (int m = 0; m < 256; ++m)
  {
    selected += GetSelectionTable()[m];
  }
  os << indent << "Selected neighbourhood masks: " << selected << " of 256\n";
}
