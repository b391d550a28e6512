// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The selection rule of topological reconstruction (vtkMLAATopology, Biri et al. section 4):
// the connexity number of every one of the 256 neighbourhood masks equals the number of
// 8-connected components that a flood fill finds on the 3 x 3 grid (centre left out); the
// selection table follows the class's rule, recomputed here from the flood fill's pieces (two
// pieces of at most two neighbours, at least 135 degrees apart, the complement one piece or a
// straight line's two); the packed bits for the GPU hold the
// same table; and a few masks named by hand have the expected answers.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkMLAATopology.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <sstream>

using namespace vtkMLAATest;

namespace
{
// A piece found by the flood fill: its size and the sums of its cells' offsets from the centre.
struct FilledPiece
{
  int Size = 0;
  int X = 0;
  int Y = 0;
};

// Components of the set cells of a 3 x 3 grid (grid[y][x], centre never set) by flood fill, and
// the size of the largest.
int FloodFillComponents(bool grid[3][3], int& largest, std::vector<FilledPiece>* pieces = nullptr)
{
  largest = 0;
  bool seen[3][3] = {};
  int components = 0;
  for (int y = 0; y < 3; ++y)
  {
    for (int x = 0; x < 3; ++x)
    {
      if (!grid[y][x] || seen[y][x])
      {
        continue;
      }
      ++components;
      int size = 1;
      FilledPiece piece;
      piece.X = x - 1;
      piece.Y = y - 1;
      int stack[9][2];
      int top = 0;
      stack[top][0] = x;
      stack[top][1] = y;
      ++top;
      seen[y][x] = true;
      while (top > 0)
      {
        --top;
        const int cx = stack[top][0];
        const int cy = stack[top][1];
        for (int dy = -1; dy <= 1; ++dy)
        {
          for (int dx = -1; dx <= 1; ++dx)
          {
            const int nx = cx + dx;
            const int ny = cy + dy;
            if (nx >= 0 && nx < 3 && ny >= 0 && ny < 3 && grid[ny][nx] && !seen[ny][nx])
            {
              seen[ny][nx] = true;
              ++size;
              piece.X += nx - 1;
              piece.Y += ny - 1;
              stack[top][0] = nx;
              stack[top][1] = ny;
              ++top;
            }
          }
        }
      }
      largest = std::max(largest, size);
      piece.Size = size;
      if (pieces)
      {
        pieces->push_back(piece);
      }
    }
  }
  return components;
}

int Components(int mask, int& largest, std::vector<FilledPiece>* pieces = nullptr)
{
  bool grid[3][3] = {};
  for (int bit = 0; bit < 8; ++bit)
  {
    if ((mask >> bit) & 1)
    {
      int dx, dy;
      vtkMLAATopology::GetNeighborOffset(bit, dx, dy);
      grid[1 + dy][1 + dx] = true;
    }
  }
  return FloodFillComponents(grid, largest, pieces);
}

// The selection rule of vtkMLAATopology, from the flood fill.
bool Rule(int m)
{
  int largest;
  std::vector<FilledPiece> pieces;
  if (Components(m, largest, &pieces) != 2 || largest > 2)
  {
    return false;
  }
  const double ax = double(pieces[0].X) / pieces[0].Size, ay = double(pieces[0].Y) / pieces[0].Size;
  const double bx = double(pieces[1].X) / pieces[1].Size, by = double(pieces[1].Y) / pieces[1].Size;
  const double cosine =
    (ax * bx + ay * by) / (std::sqrt(ax * ax + ay * ay) * std::sqrt(bx * bx + by * by));
  if (cosine > -0.7)
  {
    return false;
  }
  int complementLargest;
  const int complement = Components(~m & 255, complementLargest);
  const bool straight = pieces[0].Size == 1 && pieces[1].Size == 1 && cosine < -0.999;
  return complement == 1 || (complement == 2 && straight);
}

int Components(int mask)
{
  int largest;
  return Components(mask, largest);
}
}

int TestMLAATopology(int, char*[])
{
  // The neighbour order: E, NE, N, NW, W, SW, S, SE with y up.
  const int expected[8][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { -1, -1 },
    { 0, -1 }, { 1, -1 } };
  for (int bit = 0; bit < 8; ++bit)
  {
    int dx, dy;
    vtkMLAATopology::GetNeighborOffset(bit, dx, dy);
    MLAA_CHECK(dx == expected[bit][0] && dy == expected[bit][1]);
  }

  const unsigned char* table = vtkMLAATopology::GetSelectionTable();
  unsigned int bits[8];
  vtkMLAATopology::GetSelectionBits(bits);
  int selected = 0;
  for (int m = 0; m < 256; ++m)
  {
    int largest;
    const int t = Components(m, largest);
    const int complement = Components(~m & 255);
    MLAA_CHECK(vtkMLAATopology::LargestComponent(m) == largest);
    if (!MLAA_CHECK(vtkMLAATopology::ConnexityNumber(m) == t))
    {
      std::cerr << "mask " << m << ": T8 " << vtkMLAATopology::ConnexityNumber(m)
                << ", flood fill " << t << std::endl;
    }
    (void)complement;
    const bool rule = Rule(m);
    MLAA_CHECK((table[m] != 0) == rule);
    MLAA_CHECK(vtkMLAATopology::IsSelected(m) == rule);
    MLAA_CHECK(((bits[m >> 5] >> (m & 31)) & 1u) == (rule ? 1u : 0u));
    selected += rule ? 1 : 0;
  }
  std::cout << selected << " of 256 masks are selected" << std::endl;
  MLAA_CHECK(selected > 0 && selected < 256);

  // By hand: a diagonal line with a pixel missing (NE and SW) is selected, and so is a knight's
  // bend (E and NW) and a straight horizontal gap (E and W; the paper's rule alone leaves it,
  // its like pixels being two pieces); the pixel beside such a gap (SW and SE, 90 degrees
  // apart) is not; neither is a line end (SW only), a corner (W, SW, S), a thin L's corner
  // (everything but E and N), nothing, everything, or the cross of a thin line's own pixel (NE,
  // N, S, SE unlike; E and W like).
  MLAA_CHECK(vtkMLAATopology::IsSelected((1 << 1) | (1 << 5)));
  MLAA_CHECK(vtkMLAATopology::IsSelected((1 << 0) | (1 << 3)));
  MLAA_CHECK(vtkMLAATopology::IsSelected((1 << 0) | (1 << 4)));
  MLAA_CHECK(vtkMLAATopology::IsSelected((1 << 2) | (1 << 6)));
  MLAA_CHECK(!vtkMLAATopology::IsSelected((1 << 5) | (1 << 7)));
  MLAA_CHECK(!vtkMLAATopology::IsSelected(255 & ~((1 << 0) | (1 << 2))));
  MLAA_CHECK(!vtkMLAATopology::IsSelected(1 << 5));
  MLAA_CHECK(!vtkMLAATopology::IsSelected((1 << 4) | (1 << 5) | (1 << 6)));
  MLAA_CHECK(!vtkMLAATopology::IsSelected(0));
  MLAA_CHECK(!vtkMLAATopology::IsSelected(255));
  MLAA_CHECK(!vtkMLAATopology::IsSelected((1 << 1) | (1 << 2) | (1 << 6) | (1 << 7)));
  // Two lines passing close by (N, NE, E on one side, SW on the other): the paper's rule alone
  // selects it, the size of the pieces does not.
  const int passing = (1 << 2) | (1 << 1) | (1 << 0) | (1 << 5);
  MLAA_CHECK(vtkMLAATopology::ConnexityNumber(passing) == 2);
  MLAA_CHECK(vtkMLAATopology::ConnexityNumber(~passing & 255) == 1);
  MLAA_CHECK(!vtkMLAATopology::IsSelected(passing));
  MLAA_CHECK(vtkMLAATopology::ConnexityNumber(0xAA) == 4); // the four corners
  MLAA_CHECK(vtkMLAATopology::ConnexityNumber(0x55) == 1); // the four sides touch diagonally

  vtkNew<vtkMLAATopology> topology;
  std::ostringstream print;
  topology->Print(print);
  MLAA_CHECK(print.str().find("of 256") != std::string::npos);
  return Result();
}
