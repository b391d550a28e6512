// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAAAreaTexture.h"

#include "vtkAntialiasingTableCache.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <utility>

vtkStandardNewMacro(vtkMLAAAreaTexture);

namespace
{
// Height, in pixels, of the revectorised line at an end with crossing-edge code `code`
// (section 4.3.2): positive towards the pixel opposite the owning one, negative into the owning
// pixel, zero where no slope can be told (no crossing edge, or crossing edges on both sides).
double EndHeight(int code)
{
  switch (code)
  {
    case 1:
      return 0.5; // crossing edge on the opposite side only
    case 3:
      return -0.5; // crossing edge on the owning pixel's side only
    default:
      return 0.0;
  }
}

// Integral over [a, b] of the linear function h * (1 - x / m), which falls from h at x = 0 to 0
// at x = m. Its sign is that of h over the whole interval.
double IntegrateFallingRamp(double h, double m, double a, double b)
{
  return h * ((b - a) - (b * b - a * a) / (2.0 * m));
}

using SharedTable = std::shared_ptr<const std::vector<float>>;

// The offsets of a table's line (vtkMLAAAreaTexture::ComputeAreas): across, along.
using Offset = std::pair<double, double>;

// The caches of the two kinds of table, by maximum distance and offset: a table is kept while a
// filter or pass holds it, and the last one asked for while it takes at most 1 MB (search lengths
// up to 35 steps for the plain areas, 48 for the diagonal ones; longer ones are built again when
// no one holds them, in milliseconds).
using TableCache = vtkAntialiasingTableCache<std::pair<int, Offset>, std::vector<float>>;
constexpr std::size_t KeptTables = 1;
}

//------------------------------------------------------------------------------
void vtkMLAAAreaTexture::ComputeAreas(
  int e1, int e2, int left, int right, double areas[2], double across, double along)
{
  areas[0] = areas[1] = 0.0;
  if (left < 0 || right < 0)
  {
    return;
  }
  // The line runs along the edge from x = 0 (its left or top end) to x = L; the pixel covers
  // [left, left + 1]. The first half of the line goes from height h1 at x = 0 to 0 at x = L / 2,
  // the second half from 0 at L / 2 to h2 at x = L (L, U and Z shapes alike).
  const double length = left + right + 1.0;
  const double middle = 0.5 * length;
  const double x0 = left;
  const double x1 = left + 1.0;
  // Crossing edges on both sides at both ends (code 4 at both): the run of a one-pixel-thin
  // feature between two of its diagonal steps (the apex of a thin curve, or thin lines and gaps
  // side by side), read only where one of the two pixels is that thin (the weights stages test
  // it). The pixels cannot tell which of the two is the feature stepping on, so both take the
  // area of the U shape that would be its (the heights 1/2 at both ends): the sum of the
  // readings into either side, each at most one pixel.
  if (e1 == 4 && e2 == 4)
  {
    double opposite[2], owning[2];
    ComputeAreas(1, 1, left, right, opposite, across, along);
    ComputeAreas(3, 3, left, right, owning, across, along);
    areas[0] = std::min(1.0, opposite[0] + owning[0]);
    areas[1] = std::min(1.0, opposite[1] + owning[1]);
    return;
  }
  double h1 = EndHeight(e1);
  double h2 = EndHeight(e2);
  // Crossing edges on both sides at one end (code 4) and on one side at the other: the line
  // continues diagonally past that end (a one-pixel-wide line or gap), so its boundary leaves
  // the edge there on the side opposite the other end's: a Z shape.
  if (e1 == 4 && h2 != 0.0)
  {
    h1 = -h2;
  }
  if (e2 == 4 && h1 != 0.0)
  {
    h2 = -h1;
  }

  if (across == 0.0 && along == 0.0)
  {
    double signedAreas[2] = { 0.0, 0.0 }; // first half, second half
    if (h1 != 0.0 && x0 < middle)
    {
      signedAreas[0] = IntegrateFallingRamp(h1, middle, x0, std::min(x1, middle));
    }
    if (h2 != 0.0 && x1 > middle)
    {
      // Mirror the second half onto the first: x -> L - x.
      signedAreas[1] = IntegrateFallingRamp(h2, middle, length - x1, length - std::max(x0, middle));
    }
    for (double a : signedAreas)
    {
      if (a < 0.0)
      {
        areas[0] -= a; // below the edge: the owning pixel takes the opposite colour
      }
      else
      {
        areas[1] += a; // above the edge: the opposite pixel takes the owning pixel's colour
      }
    }
    return;
  }

  // The line raised by `across` and moved by `along` relative to the pixel: its height at x
  // (measured in the pixel's frame) is h(x - along) + across, where h continues each half's
  // slope past its end (a straight staircase goes on beyond its step). The pixel's areas are
  // the parts of [x0, x1] between the edge and the line, below it (owning pixel) or above it
  // (opposite pixel), at most one pixel high. The height is linear between the breakpoints
  // (the middle of the line, and where it crosses -1, 0 and 1), so each piece is a trapezoid.
  auto height = [&](double x) {
    const double t = x - along;
    return across + (t < middle ? h1 * (1.0 - t / middle) : h2 * (1.0 - (length - t) / middle));
  };
  std::vector<double> cuts = { x0, x1 };
  const double kink = middle + along;
  if (kink > x0 && kink < x1)
  {
    cuts.push_back(kink);
  }
  std::sort(cuts.begin(), cuts.end());
  std::vector<double> pieces;
  for (size_t i = 0; i + 1 < cuts.size(); ++i)
  {
    const double a = cuts[i], b = cuts[i + 1];
    const double ha = height(a), hb = height(b);
    pieces.push_back(a);
    for (double level : { -1.0, 0.0, 1.0 })
    {
      if ((ha - level) * (hb - level) < 0.0)
      {
        pieces.push_back(a + (b - a) * (ha - level) / (ha - hb));
      }
    }
  }
  pieces.push_back(x1);
  std::sort(pieces.begin(), pieces.end());
  for (size_t i = 0; i + 1 < pieces.size(); ++i)
  {
    const double a = pieces[i], b = pieces[i + 1];
    const double area = 0.5 * (std::min(1.0, std::max(-1.0, height(a))) +
                          std::min(1.0, std::max(-1.0, height(b)))) * (b - a);
    (area < 0.0 ? areas[0] : areas[1]) += std::abs(area);
  }
}

//------------------------------------------------------------------------------
std::shared_ptr<const std::vector<float>> vtkMLAAAreaTexture::GetSharedTable(int maxDistance)
{
  return GetSharedTable(maxDistance, 0.0, 0.0);
}

//------------------------------------------------------------------------------
std::shared_ptr<const std::vector<float>> vtkMLAAAreaTexture::GetSharedTable(
  int maxDistance, double across, double along)
{
  static TableCache cache(KeptTables);
  const int distance = std::max(1, maxDistance);
  const Offset shift = { std::min(0.5, std::max(-0.5, across)),
    std::min(0.5, std::max(-0.5, along)) };
  return cache.Get({ distance, shift }, [distance, shift]() {
    const int d = distance + 1;
    const int size = NumberOfCodes * d;
    auto table =
      std::make_shared<std::vector<float>>(static_cast<size_t>(size) * size * 2, 0.0f);
    for (int e2 = 0; e2 < NumberOfCodes; ++e2)
    {
      for (int e1 = 0; e1 < NumberOfCodes; ++e1)
      {
        if (e1 == 2 || e2 == 2)
        {
          continue; // code 2 cannot occur: its cells stay empty
        }
        for (int right = 0; right < d; ++right)
        {
          for (int left = 0; left < d; ++left)
          {
            double areas[2];
            ComputeAreas(e1, e2, left, right, areas, shift.first, shift.second);
            const size_t texel = static_cast<size_t>(d * e2 + right) * size + (d * e1 + left);
            (*table)[2 * texel] = static_cast<float>(areas[0]);
            (*table)[2 * texel + 1] = static_cast<float>(areas[1]);
          }
        }
      }
    }
    return SharedTable(table);
  });
}

//------------------------------------------------------------------------------
void vtkMLAAAreaTexture::ComputeDiagonalAreas(int e1, int e2, int d1, int d2, double areas[3])
{
  areas[0] = areas[1] = areas[2] = 0.0;
  if (d1 < 0 || d2 < 0)
  {
    return;
  }
  auto endShift = [](int code) { return code == 1 ? -0.5 : (code == 2 ? 0.5 : 0.0); };
  const double h1 = endShift(e1);
  const double h2 = endShift(e2);
  const double length = d1 + d2 + 1.0;
  const double middle = 0.5 * length;
  // The revectorised line's shift at t along the staircase: h1 at t = 0, 0 at the middle, h2 at
  // t = length.
  auto shift = [&](double t) {
    const double s = (t < middle) ? h1 * (1.0 - t / middle) : h2 * (1.0 - (length - t) / middle);
    return std::min(0.5, std::max(-0.5, s));
  };
  const double in = 0.5 + shift(d1 + 0.5);
  const double before = 0.5 - shift(d1);
  const double after = 0.5 - shift(d1 + 1.0);
  areas[0] = 0.5 * in * in;
  areas[1] = 0.5 * before * before;
  areas[2] = 0.5 * after * after;
}

//------------------------------------------------------------------------------
std::shared_ptr<const std::vector<float>> vtkMLAAAreaTexture::GetSharedDiagonalTable(
  int maxDistance)
{
  static TableCache cache(KeptTables);
  const int distance = std::max(1, maxDistance);
  return cache.Get({ distance, Offset() }, [distance]() {
    const int d = distance + 1;
    const int size = NumberOfDiagonalCodes * d;
    auto table =
      std::make_shared<std::vector<float>>(static_cast<size_t>(size) * size * 3, 0.0f);
    for (int t = 0; t < size; ++t)
    {
      for (int s = 0; s < size; ++s)
      {
        double areas[3];
        ComputeDiagonalAreas(s / d, t / d, s % d, t % d, areas);
        float* texel = table->data() + 3 * (static_cast<size_t>(t) * size + s);
        for (int c = 0; c < 3; ++c)
        {
          texel[c] = static_cast<float>(areas[c]);
        }
      }
    }
    return SharedTable(table);
  });
}

//------------------------------------------------------------------------------
vtkMLAAAreaTexture::vtkMLAAAreaTexture() = default;

//------------------------------------------------------------------------------
vtkMLAAAreaTexture::~vtkMLAAAreaTexture()
{
  if (this->Image)
  {
    this->Image->Delete();
  }
}

//------------------------------------------------------------------------------
const float* vtkMLAAAreaTexture::GetTable()
{
  if (!this->Table || this->TableMaxDistance != this->MaxDistance)
  {
    this->Table = GetSharedTable(this->MaxDistance);
    this->TableMaxDistance = this->MaxDistance;
  }
  return this->Table->data();
}

//------------------------------------------------------------------------------
float vtkMLAAAreaTexture::GetArea(int e1, int e2, int left, int right, int channel)
{
  const int d = this->GetCellSize();
  if (e1 < 0 || e1 >= NumberOfCodes || e2 < 0 || e2 >= NumberOfCodes || left < 0 || left >= d ||
    right < 0 || right >= d || channel < 0 || channel > 1)
  {
    return 0.0f;
  }
  const size_t texel =
    static_cast<size_t>(d * e2 + right) * this->GetTextureSize() + (d * e1 + left);
  return this->GetTable()[2 * texel + channel];
}

//------------------------------------------------------------------------------
vtkImageData* vtkMLAAAreaTexture::GetImage()
{
  if (this->Image && this->ImageMaxDistance == this->MaxDistance)
  {
    return this->Image;
  }
  const int size = this->GetTextureSize();
  const float* table = this->GetTable();
  if (!this->Image)
  {
    this->Image = vtkImageData::New();
  }
  this->Image->Initialize();
  this->Image->SetDimensions(size, size, 1);
  this->Image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  this->Image->GetPointData()->GetScalars()->SetName("Areas");
  auto* pixels = static_cast<unsigned char*>(this->Image->GetScalarPointer());
  for (int t = 0; t < size; ++t)
  {
    const int row = size - 1 - t; // texel row 0 is the top of the picture
    for (int s = 0; s < size; ++s)
    {
      const float* areas = table + 2 * (static_cast<size_t>(t) * size + s);
      unsigned char* out = pixels + 3 * (static_cast<size_t>(row) * size + s);
      for (int c = 0; c < 2; ++c)
      {
        const long v = std::lround(255.0 * areas[c]);
        out[c] = static_cast<unsigned char>(std::min(255L, std::max(0L, v)));
      }
      out[2] = 0;
    }
  }
  this->ImageMaxDistance = this->MaxDistance;
  return this->Image;
}

//------------------------------------------------------------------------------
void vtkMLAAAreaTexture::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MaxDistance: " << this->MaxDistance << "\n";
  os << indent << "CellSize: " << this->GetCellSize() << "\n";
  os << indent << "TextureSize: " << this->GetTextureSize() << "\n";
}
