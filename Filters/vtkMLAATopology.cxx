#include "vtkMLAATopology.h"

#include <algorithm>

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
int vtkMLAATopology::ConnexityNumber(int mask)
{
  int largest;
  return CountComponents(mask, largest);
}

//------------------------------------------------------------------------------
int vtkMLAATopology::LargestComponent(int mask)
{
  int largest;
  CountComponents(mask, largest);
  return largest;
}

//------------------------------------------------------------------------------
int vtkMLAATopology::CountComponents(int mask, int& largest)
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
  int components = 0;
  int sizes[8] = { 0, 0, 0, 0, 0, 0, 0, 0 };
  for (int i = 0; i < 8; ++i)
  {
    if ((mask >> i) & 1)
    {
      components += root(i) == i ? 1 : 0;
      ++sizes[root(i)];
    }
  }
  largest = *std::max_element(sizes, sizes + 8);
  return components;
}

//------------------------------------------------------------------------------
const unsigned char* vtkMLAATopology::GetSelectionTable()
{
  // Section 4.2: T8(X) == 2 and T8(complement of X) == 1; and (ours) no piece of X larger than
  // the cross-section of a thin line.
  static const std::array<unsigned char, 256> table = [] {
    std::array<unsigned char, 256> t{};
    for (int m = 0; m < 256; ++m)
    {
      t[m] = (ConnexityNumber(m) == 2 && ConnexityNumber(~m & 255) == 1 &&
               LargestComponent(m) <= MaximumPieceSize)
        ? 1
        : 0;
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
