// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkImageDLAA against a plain transcription of the method in vtkDLAAOptions: every pixel
// computed on its own in double precision, reading its neighbours through a clamped accessor,
// with no shared intermediate buffers. On random block images (edges of every contrast, long
// and short, in 1 to 4 components, with REC709 and GREEN, with and without long edges) the two
// agree within the rounding of the 8-bit output, except where float and double fall on
// different sides of one of the method's thresholds (rare; they are counted and bounded).
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkAntialiasingTestUtilities.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>

using namespace vtkMLAATest;

namespace
{
struct Reference
{
  vtkImageData* Image;
  int W, H, C;
  double Epsilon, Lambda;
  bool LongEdges;
  double Weights[4] = { 0, 0, 0, 0 };

  double V(int x, int y, int k) const
  {
    x = std::min(std::max(x, 0), this->W - 1);
    y = std::min(std::max(y, 0), this->H - 1);
    return GetValue(this->Image, x, y, k) / 255.0;
  }
  double L(int x, int y) const
  {
    double l = 0;
    for (int k = 0; k < this->C; ++k)
    {
      l += this->Weights[k] * this->V(x, y, k);
    }
    return l;
  }
  // Blend mask of a horizontal edge (along = x) or of a vertical one (along = y).
  double Mask(int x, int y, bool horizontalEdge) const
  {
    const int ax = horizontalEdge ? 1 : 0, ay = horizontalEdge ? 0 : 1; // blur direction
    double high = 0, blur = 0;
    for (int k = 0; k < this->C; ++k)
    {
      // High-pass across the edge, i.e. along the other direction.
      const double sum = this->V(x - 2 * ay, y - 2 * ax, k) + this->V(x - ay, y - ax, k) +
        this->V(x + ay, y + ax, k) + this->V(x + 2 * ay, y + 2 * ax, k);
      high += this->Weights[k] * std::abs(sum - 4 * this->V(x, y, k)) / 4;
      const double b = this->V(x - 2 * ax, y - 2 * ay, k) + this->V(x - ax, y - ay, k) +
        this->V(x + ax, y + ay, k) + this->V(x + 2 * ax, y + 2 * ay, k);
      blur += this->Weights[k] * (b + 2 * this->V(x, y, k)) / 6;
    }
    const double n = this->Lambda * high - this->Epsilon;
    if (n <= 0)
    {
      return 0;
    }
    if (blur == 0)
    {
      return 1;
    }
    return std::min(std::max(n / blur, 0.0), 1.0);
  }
  // The luminosity d pixels from (x, y) in the direction (ax, ay) and i pixels across it, as a
  // float, as both back ends compare them: the tests of corners compare differences with half of
  // other differences, and in one-component images of 64 random grey levels exact midpoints
  // (a + c = 2 b) are frequent; double and float put them on either side.
  double At(int x, int y, int ax, int ay, int d, int i) const
  {
    return static_cast<float>(this->L(x + d * ax + i * ay, y + d * ay + i * ax));
  }
  // Whether, d pixels along, the pixels i0 and i1 across differ, and do alike (each within half
  // the difference) for 3 more pixels in the direction `away`.
  bool CrossingGoesOn(int x, int y, int ax, int ay, int d, int i0, int i1, int away) const
  {
    const double l0 = this->At(x, y, ax, ay, d, i0);
    const double l1 = this->At(x, y, ax, ay, d, i1);
    const double tolerance = std::abs(l0 - l1) / 2;
    if (!(tolerance > 0))
    {
      return false;
    }
    for (int m = 1; m <= 3; ++m)
    {
      if (std::abs(this->At(x, y, ax, ay, d + m * away, i0) - l0) > tolerance ||
        std::abs(this->At(x, y, ax, ay, d + m * away, i1) - l1) > tolerance)
      {
        return false;
      }
    }
    return true;
  }
  // Whether the boundary between the pixels k - 1 and k from (x, y) in the direction (ax, ay)
  // is the side of a corner (vtkDLAAOptions, "Corners").
  bool CornerSide(int x, int y, int ax, int ay, int k, double minimum) const
  {
    const double p = this->At(x, y, ax, ay, k - 1, 0);
    const double q = this->At(x, y, ax, ay, k, 0);
    // The largest difference of the two colours in a channel the luminosity reads.
    double contrast = 0;
    for (int c = 0; c < this->C; ++c)
    {
      if (this->Weights[c] != 0)
      {
        contrast = std::max(contrast,
          static_cast<double>(static_cast<float>(std::abs(
            this->V(x + (k - 1) * ax, y + (k - 1) * ay, c) - this->V(x + k * ax, y + k * ay, c)))));
      }
    }
    if (!(std::abs(p - q) > 0) || !(contrast > minimum))
    {
      return false;
    }
    const double tolerance = std::abs(p - q) / 2;
    auto pair = [&](int d, int i) {
      return std::abs(this->At(x, y, ax, ay, d - 1, i) - p) <= tolerance &&
        std::abs(this->At(x, y, ax, ay, d, i) - q) <= tolerance;
    };
    int length = 1;
    for (int side : { -1, 1 })
    {
      int i = side;
      while (std::abs(i) <= 8 && pair(k, i))
      {
        i += side;
        ++length;
      }
      if (std::abs(i) <= 8 &&
        (pair(k - 1, i) || pair(k + 1, i) ||
          !(this->CrossingGoesOn(x, y, ax, ay, k - 1, i - side, i, -1) ||
            this->CrossingGoesOn(x, y, ax, ay, k, i - side, i, 1))))
      {
        return false; // a step
      }
    }
    return length >= 4;
  }
  // 2 Epsilon / Lambda, as a float: the contrast at which the masks see an edge.
  double SideContrast() const { return static_cast<float>(2 * this->Epsilon / this->Lambda); }
  // How far, 0 to 2 pixels, the short-edge blur reads in the direction (ax, ay).
  int BlurReach(int x, int y, int ax, int ay) const
  {
    const double minimum = this->SideContrast();
    return this->CornerSide(x, y, ax, ay, 1, minimum)
      ? 0
      : (this->CornerSide(x, y, ax, ay, 2, minimum) ? 1 : 2);
  }
  void Pixel(int x, int y, double* out) const
  {
    const double mx = this->Mask(x, y, true);
    const double my = this->Mask(x, y, false);
    const int right = this->BlurReach(x, y, 1, 0), left = this->BlurReach(x, y, -1, 0);
    const int up = this->BlurReach(x, y, 0, 1), down = this->BlurReach(x, y, 0, -1);
    for (int k = 0; k < this->C; ++k)
    {
      const double c = this->V(x, y, k);
      const double bx =
        (this->V(x - std::min(2, left), y, k) + this->V(x - std::min(1, left), y, k) +
          this->V(x + std::min(1, right), y, k) + this->V(x + std::min(2, right), y, k) + 2 * c) /
        6;
      const double by =
        (this->V(x, y - std::min(2, down), k) + this->V(x, y - std::min(1, down), k) +
          this->V(x, y + std::min(1, up), k) + this->V(x, y + std::min(2, up), k) + 2 * c) /
        6;
      const double h = c + (bx - c) * mx;
      out[k] = h + (by - h) * my / 2;
    }
    if (!this->LongEdges)
    {
      return;
    }
    double sx = 0, sy = 0;
    for (int d = -8; d <= 8; ++d)
    {
      sx += this->Mask(x + d, y, true);
      sy += this->Mask(x, y + d, false);
    }
    const double MX = std::min(std::max(2 * sx / 17 - 1, 0.0), 1.0);
    const double MY = std::min(std::max(2 * sy / 17 - 1, 0.0), 1.0);
    if ((MX > 0) == (MY > 0))
    {
      return;
    }
    const bool alongX = MX > 0;
    // The mean along the edge over the step the pixel is on: as far each way (the shorter of the
    // two, 1 to 8 pixels) as both neighbours across the edge keep within half their difference
    // of their luminosity beside the pixel, or, once, where the pixel's row and one neighbour
    // swap (a line one pixel wide moving into the row of a pixel on the other side).
    auto at = [&](int d, int k) {
      return alongX ? this->L(x + d, y + k) : this->L(x + k, y + d);
    };
    const double tolerance = std::abs(at(0, -1) - at(0, 1)) / 2;
    auto same = [&](double u, double v) { return std::abs(u - v) <= tolerance; };
    // The window also stops before a corner's side that the masks would see as an edge, and is
    // empty where one lies next to the pixel.
    const double sideContrast = this->SideContrast();
    int reach[2] = { 8, 8 };
    bool cornerNext = false;
    for (int way = 0; way < 2; ++way)
    {
      double e[3] = { at(0, -1), at(0, 0), at(0, 1) };
      bool swapLeft = same(e[0], e[1]) != same(e[2], e[1]);
      double row = e[1];
      for (int d = 1; d <= 8; ++d)
      {
        const int along = way ? -d : d;
        const double m[3] = { at(along, -1), at(along, 0), at(along, 1) };
        const int sign = way ? -1 : 1;
        if (m[1] != row &&
          this->CornerSide(x, y, alongX ? sign : 0, alongX ? 0 : sign, d, sideContrast))
        {
          reach[way] = d - 1;
          cornerNext = cornerNext || d == 1;
          break;
        }
        row = m[1];
        if (same(m[0], e[0]) && same(m[2], e[2]))
        {
          continue;
        }
        bool swapped = false;
        for (int side : { 0, 2 })
        {
          const int other = 2 - side;
          if (swapLeft && !swapped && same(m[side], e[1]) && same(m[1], e[side]) &&
            same(m[other], e[other]))
          {
            std::swap(e[side], e[1]);
            swapLeft = false;
            swapped = true;
          }
        }
        if (!swapped)
        {
          reach[way] = d - 1;
          break;
        }
      }
    }
    const int half = cornerNext ? 0 : std::max(1, std::min(reach[0], reach[1]));
    double t = 0;
    for (int d = -half; d <= half; ++d)
    {
      t += alongX ? this->L(x + d, y) : this->L(x, y + d);
    }
    t /= 2 * half + 1;
    const int n[2][2] = { { alongX ? x : x - 1, alongX ? y + 1 : y },
      { alongX ? x : x + 1, alongX ? y - 1 : y } };
    const double lc = this->L(x, y);
    double best = -1;
    int pick = -1;
    for (int i = 0; i < 2; ++i)
    {
      const double ln = this->L(n[i][0], n[i][1]);
      if (ln == lc)
      {
        continue;
      }
      const double kk = (t - lc) / (ln - lc);
      if (kk > 0 && kk <= 1 && (pick < 0 || kk < best))
      {
        best = kk;
        pick = i;
      }
    }
    const double m = alongX ? MX : MY;
    for (int k = 0; k < this->C; ++k)
    {
      const double c = this->V(x, y, k);
      const double q = pick < 0 ? c : c + (this->V(n[pick][0], n[pick][1], k) - c) * best;
      out[k] += (q - out[k]) * m;
    }
  }
};
}

int TestImageDLAAReference(int, char*[])
{
  std::mt19937 random(2011);
  for (int components = 1; components <= 4; ++components)
  {
    for (int luma : { vtkDLAAOptions::REC709, vtkDLAAOptions::GREEN })
    {
      for (bool longEdges : { true, false })
      {
        // Blocks of random sizes and colours, and long shallow bands.
        const int w = 83, h = 61;
        auto image = MakeImage(w, h, components);
        std::uniform_int_distribution<int> value(0, 255);
        std::vector<int> colours(64 * components);
        for (auto& v : colours)
        {
          v = value(random);
        }
        const int shift = value(random) % 7;
        FillImage(image, [&](int x, int y, int, int k) {
          const int block = ((x + shift) / 9 + 3 * ((y + x / 23) / 7)) % 64;
          return static_cast<double>(colours[block * components + k]);
        });
        vtkNew<vtkDLAAOptions> options;
        options->SetLumaFunction(luma);
        options->SetLongEdges(longEdges);
        vtkNew<vtkImageDLAA> filter;
        filter->SetOptions(options);
        filter->SetInputData(image);
        filter->Update();
        vtkImageData* out = filter->GetOutput();

        Reference ref{ image, w, h, components, options->GetEpsilon(), options->GetLambda(),
          longEdges };
        if (components < 3)
        {
          ref.Weights[0] = 1;
        }
        else if (luma == vtkDLAAOptions::GREEN)
        {
          ref.Weights[1] = 1;
        }
        else
        {
          ref.Weights[0] = 0.2126;
          ref.Weights[1] = 0.7152;
          ref.Weights[2] = 0.0722;
        }
        int off = 0, changed = 0;
        double worst = 0;
        for (int y = 0; y < h; ++y)
        {
          for (int x = 0; x < w; ++x)
          {
            double expected[4];
            ref.Pixel(x, y, expected);
            bool pixelOff = false;
            for (int k = 0; k < components; ++k)
            {
              const double e = std::min(std::max(std::floor(expected[k] * 255 + 0.5), 0.0), 255.0);
              const double d = std::abs(GetValue(out, x, y, k) - e);
              pixelOff = pixelOff || d > 1;
              worst = std::max(worst, d);
              changed += GetValue(out, x, y, k) != GetValue(image, x, y, k) ? 1 : 0;
            }
            off += pixelOff ? 1 : 0;
          }
        }
        {
          std::cout << components << " components, luma " << luma << ", long edges " << longEdges
                    << ": " << off << " pixels more than 1/255 from the reference (largest "
                    << worst << "/255), " << changed << " values changed" << std::endl;
        }
        MLAA_CHECK(off <= w * h / 500);
        MLAA_CHECK(changed > 100);
      }
    }
  }
  return Result();
}
