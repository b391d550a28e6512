#include "vtkImageMLAA.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkImageMLAA);

namespace
{
// Bits of the edges image: an edgel at the left or at the top boundary of the pixel. "Top" is
// the side of the next row (higher y), which is the top of the displayed image.
constexpr unsigned char LeftEdge = 1;
constexpr unsigned char TopEdge = 2;

// Rows handled by one task of the threaded loops.
constexpr vtkIdType RowsPerTask = 32;

// A rectangle of pixels, bounds included.
struct Rect
{
  int X0, X1, Y0, Y1;
  int Width() const { return this->X1 - this->X0 + 1; }
  int Height() const { return this->Y1 - this->Y0 + 1; }
  bool Contains(int x, int y) const
  {
    return x >= this->X0 && x <= this->X1 && y >= this->Y0 && y <= this->Y1;
  }
};

// Edge detection of 8- and 16-bit and float images is done in float, as on the GPU; wider
// types use double.
template <typename T>
using AccumulatorType = typename std::conditional<(sizeof(T) <= 2 ||
                                                    std::is_same<T, float>::value),
  float, double>::type;

// Normalisation of a scalar type for edge detection: value -> (value - lo) / (hi - lo).
template <typename T>
void NormalisationRange(const double valueRange[2], double& lo, double& hi)
{
  if (std::is_floating_point<T>::value)
  {
    lo = valueRange[0];
    hi = valueRange[1];
  }
  else
  {
    lo = static_cast<double>(std::numeric_limits<T>::lowest());
    hi = static_cast<double>(std::numeric_limits<T>::max());
  }
}

template <typename T>
bool IsFinite(T v)
{
  return !std::is_floating_point<T>::value || std::isfinite(static_cast<double>(v));
}

template <typename T, typename Acc>
T ConvertBlended(Acc v)
{
  if (std::is_floating_point<T>::value)
  {
    return static_cast<T>(v);
  }
  // Round to nearest and saturate, as a GPU stores a normalised value.
  const Acc r = std::floor(v + Acc(0.5));
  if (r <= static_cast<Acc>(std::numeric_limits<T>::lowest()))
  {
    return std::numeric_limits<T>::lowest();
  }
  if (r >= static_cast<Acc>(std::numeric_limits<T>::max()))
  {
    return std::numeric_limits<T>::max();
  }
  return static_cast<T>(r);
}

// Everything one z slice needs: where its pixels are, the settings, and the area table.
struct SliceSetup
{
  Rect Whole;  // the image: reads beyond it are clamped to it, as GPU texture reads are
  Rect Input;  // the pixels available (the requested extent, padded)
  Rect Output; // the pixels to produce
  int Mode = vtkMLAAOptions::LUMA;
  int DebugOutput = vtkMLAAOptions::NO_DEBUG_OUTPUT;
  int SearchSteps = 8;
  double Threshold = 0.1;
  double LocalContrastFactor = 2.0; // vtkMLAAOptions::LocalContrastFactor, 0 = off
  const float* Area = nullptr; // 8-bit quantised area texture
  int CellSize = 17;           // D
  int AreaSize = 85;           // 5 D
  bool Diagonals = true;                // vtkMLAAOptions::DiagonalDetection
  bool Dominant = true;                 // vtkMLAAOptions::DominantDirectionBlending
  const float* DiagonalArea = nullptr;  // 8-bit quantised diagonal areas
  int DiagonalAreaSize = 51;            // 3 D
};

//------------------------------------------------------------------------------
// The three passes on one slice of an image of type T.
template <typename T>
class MLAASlice
{
public:
  using Acc = AccumulatorType<T>;

  // The contrast across the left and the top boundary of a pixel (0: not an edge).
  struct Boundary
  {
    Acc Left;
    Acc Top;
  };

  MLAASlice(const SliceSetup& setup, const T* input, vtkIdType inputRowStride, int components,
    double lo, double hi, const double* depth)
    : S(setup)
    , In(input)
    , InRowStride(inputRowStride)
    , C(components)
    , Depth(depth)
  {
    this->Lo = static_cast<Acc>(lo);
    this->InvRange = static_cast<Acc>(1.0 / (hi - lo));
    this->Threshold = static_cast<Acc>(setup.Threshold);
    this->ContrastFactor = static_cast<Acc>(setup.LocalContrastFactor);
    this->HasAlpha = (components == 2 || components == 4);
    this->F = (setup.Mode == vtkMLAAOptions::COLOR) ? components : 1 + (this->HasAlpha ? 1 : 0);
    this->Edges.resize(static_cast<size_t>(setup.Input.Width()) * setup.Input.Height());
  }

  // Pass 1 (section 4.2): the left and top edgels of every available pixel. First the contrast
  // across every boundary (0 where it is not an edge), then the edgels that local contrast
  // adaptation keeps.
  void DetectEdges()
  {
    const Rect& in = this->S.Input;
    const int w = in.Width();
    const int h = in.Height();
    // A ring of zero contrasts around the available pixels: boundaries outside them are not
    // edges. Every other entry is written below, so the grid is left uninitialised.
    const int stride = w + 2;
    std::unique_ptr<Boundary[]> contrasts(new Boundary[static_cast<size_t>(stride) * (h + 2)]);
    Boundary* grid = contrasts.get();
    std::fill(grid, grid + stride, Boundary{});
    std::fill(grid + static_cast<size_t>(h + 1) * stride, grid + static_cast<size_t>(h + 2) * stride,
      Boundary{});
    vtkSMPTools::For(0, h, RowsPerTask, [this, grid, stride](vtkIdType begin, vtkIdType end) {
      const Rect& r = this->S.Input;
      const int w = r.Width();
      std::vector<Acc> current(static_cast<size_t>(w) * this->F);
      std::vector<Acc> above(current.size());
      this->ComputeFeatures(r.Y0 + static_cast<int>(begin), current.data());
      for (vtkIdType row = begin; row < end; ++row)
      {
        const int y = r.Y0 + static_cast<int>(row);
        // The top row of the image has no top edge; the top row of a piece has one that is
        // never read (the padding covers every read), so it is left out.
        const bool hasAbove = y < r.Y1;
        if (hasAbove)
        {
          this->ComputeFeatures(y + 1, above.data());
        }
        Boundary* b = grid + static_cast<size_t>(row + 1) * stride;
        b[0] = b[w + 1] = Boundary{};
        if (this->F == 1)
        {
          this->RowContrasts<1>(current.data(), hasAbove ? above.data() : nullptr, b + 1, w);
        }
        else
        {
          this->RowContrasts<0>(current.data(), hasAbove ? above.data() : nullptr, b + 1, w);
        }
        std::swap(current, above);
      }
    });
    vtkSMPTools::For(0, h, RowsPerTask, [this, grid, stride](vtkIdType begin, vtkIdType end) {
      const int w = this->S.Input.Width();
      for (vtkIdType row = begin; row < end; ++row)
      {
        this->KeepEdgels(grid + static_cast<size_t>(row + 1) * stride + 1, stride,
          this->Edges.data() + static_cast<size_t>(row) * w, w);
      }
    });
  }

  // Passes 2 and 3 (sections 4.3 and 4.4), fused per group of rows: the blending weights of the
  // rows (and of the row below them and the column right of them, which the blending reads),
  // then the blended pixels, or one of the debug images.
  void BlendOrDebug(T* output, unsigned char* debug)
  {
    const Rect& out = this->S.Output;
    vtkSMPTools::For(0, out.Height(), RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
      const Rect& o = this->S.Output;
      // Weights of the rows [y0 - 1, y1] and columns [X0, X1 + 1]; only the entries of pixels
      // with edgels are written, and only those are read.
      const int y0 = o.Y0 + static_cast<int>(begin);
      const int y1 = o.Y0 + static_cast<int>(end) - 1;
      const Rect weightsRect = { o.X0, o.X1 + 1, y0 - 1, y1 };
      const size_t rowLength = static_cast<size_t>(weightsRect.Width()) * 4;
      std::unique_ptr<float[]> weights(new float[rowLength * weightsRect.Height()]);
      auto weightsAt = [&](int x, int y) {
        return weights.get() + (y - weightsRect.Y0) * rowLength + (x - weightsRect.X0) * 4;
      };
      for (int y = weightsRect.Y0; y <= weightsRect.Y1; ++y)
      {
        for (int x = weightsRect.X0; x <= weightsRect.X1; ++x)
        {
          if (this->S.Whole.Contains(x, y) && this->EdgesAt(x, y))
          {
            this->ComputeWeights(x, y, weightsAt(x, y));
          }
        }
      }

      for (int y = y0; y <= y1; ++y)
      {
        if (debug)
        {
          this->WriteDebugRow(y, weightsAt, debug);
        }
        else
        {
          this->BlendRow(y, weightsAt, output);
        }
      }
    });
  }

private:
  // The values compared across a boundary, normalised to [0, 1]: luma or the colour channels
  // or the depth, then alpha. A pixel with a non-finite value gets NaN features, which are
  // never an edge.
  void ComputeFeatures(int y, Acc* features) const
  {
    const Rect& r = this->S.Input;
    const T* p = this->In + static_cast<vtkIdType>(y - r.Y0) * this->InRowStride;
    const int w = r.Width();
    const int c = this->C;
    const Acc lo = this->Lo;
    const Acc inv = this->InvRange;
    const double* depth =
      this->Depth ? this->Depth + static_cast<size_t>(y - r.Y0) * w : nullptr;
    for (int x = 0; x < w; ++x, p += c, features += this->F)
    {
      bool finite = true;
      if (std::is_floating_point<T>::value)
      {
        for (int k = 0; k < c; ++k)
        {
          finite = finite && IsFinite(p[k]);
        }
      }
      if (!finite)
      {
        std::fill(features, features + this->F, std::numeric_limits<Acc>::quiet_NaN());
        continue;
      }
      int f = 0;
      switch (this->S.Mode)
      {
        case vtkMLAAOptions::COLOR:
          for (int k = 0; k < c; ++k)
          {
            features[f++] = (static_cast<Acc>(p[k]) - lo) * inv;
          }
          continue; // alpha is one of the channels
        case vtkMLAAOptions::DEPTH:
          features[f++] = static_cast<Acc>(depth[x]);
          break;
        default: // LUMA, Rec. 709 weights (section 4.2.1)
          if (c >= 3)
          {
            features[f++] = Acc(0.2126) * ((static_cast<Acc>(p[0]) - lo) * inv) +
              Acc(0.7152) * ((static_cast<Acc>(p[1]) - lo) * inv) +
              Acc(0.0722) * ((static_cast<Acc>(p[2]) - lo) * inv);
          }
          else
          {
            features[f++] = (static_cast<Acc>(p[0]) - lo) * inv;
          }
          break;
      }
      if (this->HasAlpha)
      {
        features[f] = (static_cast<Acc>(p[c - 1]) - lo) * inv;
      }
    }
  }

  // The contrast across a boundary: the largest difference of a feature, if it is at least the
  // threshold (and more than nothing, so that a zero threshold means "any difference"), else 0.
  // NaN differences are never edges. FixedF is the number of features when known at compile
  // time (the common single-feature case), else 0.
  template <int FixedF>
  Acc Contrast(const Acc* a, const Acc* b) const
  {
    const int features = FixedF > 0 ? FixedF : this->F;
    Acc contrast = 0;
    for (int k = 0; k < features; ++k)
    {
      const Acc d = std::abs(a[k] - b[k]);
      if (d >= this->Threshold && d > contrast)
      {
        contrast = d;
      }
    }
    return contrast;
  }

  // The contrasts of one row of w pixels with features f, and the row above with features g
  // (null for the top row of the available pixels: no top edges).
  template <int FixedF>
  void RowContrasts(const Acc* f, const Acc* g, Boundary* b, int w) const
  {
    const int features = FixedF > 0 ? FixedF : this->F;
    b[0].Left = Acc(0);
    for (int x = 1; x < w; ++x)
    {
      b[x].Left = this->Contrast<FixedF>(f + x * features, f + (x - 1) * features);
    }
    for (int x = 0; x < w; ++x)
    {
      b[x].Top = g ? this->Contrast<FixedF>(f + x * features, g + x * features) : Acc(0);
    }
  }

  // The edgels of one row that local contrast adaptation keeps (vtkMLAAOptions::
  // LocalContrastFactor), from the contrasts of the row (`b`, w entries of a grid with the given
  // stride) and of the rows below and above it: an edge whose contrast, times the factor, is
  // below the contrast of one of the six other boundaries of the two pixels it separates is
  // dropped.
  void KeepEdgels(const Boundary* b, int stride, unsigned char* edges, int w) const
  {
    const Boundary* below = b - stride;
    const Boundary* above = b + stride;
    const Acc factor = this->ContrastFactor;
    for (int x = 0; x < w; ++x)
    {
      const Acc left = b[x].Left;
      const Acc top = b[x].Top;
      unsigned char e = 0;
      if (left > Acc(0) &&
        (factor == Acc(0) ||
          factor * left >= std::max({ b[x - 1].Left, b[x + 1].Left, b[x - 1].Top, top,
                             below[x - 1].Top, below[x].Top })))
      {
        e |= LeftEdge;
      }
      if (top > Acc(0) &&
        (factor == Acc(0) ||
          factor * top >= std::max({ below[x].Top, above[x].Top, left, b[x + 1].Left,
                            above[x].Left, above[x + 1].Left })))
      {
        e |= TopEdge;
      }
      edges[x] = e;
    }
  }

  // The edgels of an available pixel.
  unsigned char EdgesAt(int x, int y) const
  {
    const Rect& r = this->S.Input;
    return this->Edges[static_cast<size_t>(y - r.Y0) * r.Width() + (x - r.X0)];
  }

  // The edgels at (x, y) clamped to the image, as a GPU reads a texture with clamp-to-edge.
  unsigned char ClampedEdgesAt(int x, int y) const
  {
    const Rect& r = this->S.Input;
    return this->EdgesAt(std::min(std::max(x, r.X0), r.X1), std::min(std::max(y, r.Y0), r.Y1));
  }
  int TopAt(int x, int y) const { return (this->ClampedEdgesAt(x, y) & TopEdge) ? 1 : 0; }
  int LeftAt(int x, int y) const { return (this->ClampedEdgesAt(x, y) & LeftEdge) ? 1 : 0; }

  // Section 4.3.1: distance from (x, y) to the end of its line of top edgels in direction dx
  // (-1 left, +1 right), or of left edgels in direction dy (-1 down, +1 up). Each step looks at
  // the next two pixels along the line, as the GPU does with two bilinear fetches:
  // - the two edgels along the line (weighted 3:1, so that each can be told apart);
  // - the crossing edgels (perpendicular ones, on either side of the line) at the boundary
  //   before the first pixel and at the boundary between the two.
  // The line ends before the first pixel without an edgel, or at the first boundary with a
  // crossing edgel. Stopping at crossing edges (which the chapter's search does not, section
  // 4.3.1 and 4.6) keeps the top and bottom outlines of one-pixel-wide lines apart.
  int SearchTopEdges(int x, int y, int dx) const
  {
    for (int i = 0; i < this->S.SearchSteps; ++i)
    {
      const int first = x + dx * (2 * i + 1);
      const int second = first + dx;
      // Left edgels of the pixels right of the two boundaries, on this row and the one above.
      const int nearOwner = std::max(first, first - dx);
      const int midOwner = std::max(first, second);
      if (this->LeftAt(nearOwner, y) || this->LeftAt(nearOwner, y + 1) || !this->TopAt(first, y))
      {
        return 2 * i;
      }
      if (this->LeftAt(midOwner, y) || this->LeftAt(midOwner, y + 1) || !this->TopAt(second, y))
      {
        return 2 * i + 1;
      }
    }
    return 2 * this->S.SearchSteps;
  }
  int SearchLeftEdges(int x, int y, int dy) const
  {
    for (int i = 0; i < this->S.SearchSteps; ++i)
    {
      const int first = y + dy * (2 * i + 1);
      const int second = first + dy;
      // Top edgels of the pixels below the two boundaries, in this column and the one left.
      const int nearOwner = std::min(first, first - dy);
      const int midOwner = std::min(first, second);
      if (this->TopAt(x, nearOwner) || this->TopAt(x - 1, nearOwner) || !this->LeftAt(x, first))
      {
        return 2 * i;
      }
      if (this->TopAt(x, midOwner) || this->TopAt(x - 1, midOwner) || !this->LeftAt(x, second))
      {
        return 2 * i + 1;
      }
    }
    return 2 * this->S.SearchSteps;
  }

  // Section 4.3.2: the crossing-edge code at an end of a line, 3 * (edgel on the owning pixel's
  // side) + (edgel on the opposite side), as the bilinear fetch a quarter pixel off the edge
  // reads it. Ends outside the image have no crossing edge.
  int CrossingLeftEdges(int x, int ownY, int oppositeY) const
  {
    if (x < this->S.Whole.X0 || x > this->S.Whole.X1)
    {
      return 0;
    }
    return 3 * this->LeftAt(x, ownY) + this->LeftAt(x, oppositeY);
  }
  int CrossingTopEdges(int ownX, int oppositeX, int y) const
  {
    if (y < this->S.Whole.Y0 || y > this->S.Whole.Y1)
    {
      return 0;
    }
    return 3 * this->TopAt(ownX, y) + this->TopAt(oppositeX, y);
  }

  // Section 4.3: the four blending weights of a pixel with edgels.
  // w[0]: this pixel takes the colour above it; w[1]: the pixel above takes this one's;
  // w[2]: this pixel takes its left neighbour's; w[3]: the left neighbour takes this one's.
  // With DiagonalDetection, an edgel that is part of a 45-degree staircase takes its weights
  // from the diagonal line instead (ComputeDiagonalWeights).
  void ComputeWeights(int x, int y, float* w) const
  {
    const unsigned char e = this->EdgesAt(x, y);
    w[0] = w[1] = w[2] = w[3] = 0.0f;
    bool top = (e & TopEdge) != 0;
    bool left = (e & LeftEdge) != 0;
    if (this->S.Diagonals)
    {
      this->ComputeDiagonalWeights(x, y, top, left, w);
    }
    if (top)
    {
      // A horizontal line: its ends lie to the left and to the right.
      const int leftEnd = this->SearchTopEdges(x, y, -1);
      const int rightEnd = this->SearchTopEdges(x, y, +1);
      const int e1 = this->CrossingLeftEdges(x - leftEnd, y, y + 1);
      const int e2 = this->CrossingLeftEdges(x + rightEnd + 1, y, y + 1);
      this->LookUpArea(e1, e2, leftEnd, rightEnd, w);
    }
    if (left)
    {
      // A vertical line: its first end is the upper one.
      const int up = this->SearchLeftEdges(x, y, +1);
      const int down = this->SearchLeftEdges(x, y, -1);
      const int e1 = this->CrossingTopEdges(x, x - 1, y + up);
      const int e2 = this->CrossingTopEdges(x, x - 1, y - down - 1);
      this->LookUpArea(e1, e2, up, down, w + 2);
    }
  }

  // Edgels for the diagonal search: none outside the image.
  int DiagonalTopAt(int x, int y) const
  {
    return this->S.Whole.Contains(x, y) ? this->TopAt(x, y) : 0;
  }
  int DiagonalLeftAt(int x, int y) const
  {
    return this->S.Whole.Contains(x, y) ? this->LeftAt(x, y) : 0;
  }
  // A unit of a rising staircase: a pixel with both edgels. A unit of a falling one, named by its
  // pixel q: q's top edgel and its right neighbour's left edgel.
  bool IsRisingUnit(int x, int y) const
  {
    return this->DiagonalTopAt(x, y) && this->DiagonalLeftAt(x, y);
  }
  bool IsFallingUnit(int x, int y) const
  {
    return this->DiagonalTopAt(x, y) && this->DiagonalLeftAt(x + 1, y);
  }

  // Number of further units of the staircase through the unit at (x, y) in direction
  // (dx, dy), at most the maximum distance; `reachedEnd` tells whether the staircase ended
  // within it.
  template <typename IsUnit>
  int SearchDiagonal(int x, int y, int dx, int dy, IsUnit isUnit, bool& reachedEnd) const
  {
    const int maxDistance = this->S.CellSize - 1;
    for (int k = 1; k <= maxDistance; ++k)
    {
      if (!isUnit(x + k * dx, y + k * dy))
      {
        reachedEnd = true;
        return k - 1;
      }
    }
    reachedEnd = false;
    return maxDistance;
  }

  // End code of vtkMLAAAreaTexture::ComputeDiagonalAreas from what the staircase does past its
  // end: a run along x ("flatter") or along y ("steeper"), each of which shifts the line into or
  // out of the unit's pixel depending on the end and on the slope. Both or neither: nothing.
  static int DiagonalEndCode(bool reachedEnd, bool flatter, bool steeper, int flatterCode)
  {
    if (!reachedEnd || flatter == steeper)
    {
      return 0;
    }
    return flatter ? flatterCode : 3 - flatterCode;
  }

  // Weights of the edgels of (x, y) that belong to a staircase of at least
  // vtkMLAAOptions::MinimumDiagonalLength units; `top` and `left` are cleared for the edgels
  // handled here, which the orthogonal search then skips.
  //
  // Rising (up and to the right): units (x0 + k, y0 + k); the unit's pixel takes the colour above
  // and left of it, the pixels above and left of it take its colour. The first end is the
  // lower-left one.
  // Falling (down and to the right): units q = (x0 + k, y0 - k) with r = q + (1, 0); q takes the
  // colour above it (r of the unit before) and right of it (r); r takes q's colour. The first end
  // is the upper-left one.
  void ComputeDiagonalWeights(int x, int y, bool& top, bool& left, float* w) const
  {
    constexpr int minLength = vtkMLAAOptions::MinimumDiagonalLength;
    constexpr int Out = 1;
    constexpr int In = 2;
    if (top && left)
    {
      auto isUnit = [this](int u, int v) { return this->IsRisingUnit(u, v); };
      bool end1, end2;
      const int d1 = this->SearchDiagonal(x, y, -1, -1, isUnit, end1);
      const int d2 = this->SearchDiagonal(x, y, +1, +1, isUnit, end2);
      if (d1 + d2 + 1 >= minLength)
      {
        const int x1 = x - d1, y1 = y - d1; // first unit
        const int x2 = x + d2, y2 = y + d2; // last unit
        const int e1 = DiagonalEndCode(
          end1, this->DiagonalTopAt(x1 - 1, y1 - 1) != 0, this->DiagonalLeftAt(x1, y1 - 1) != 0, Out);
        const int e2 = DiagonalEndCode(
          end2, this->DiagonalTopAt(x2 + 1, y2) != 0, this->DiagonalLeftAt(x2 + 1, y2 + 1) != 0, In);
        float a[3];
        this->LookUpDiagonalArea(e1, e2, d1, d2, a);
        w[0] = w[2] = a[0];
        w[1] = a[2]; // the pixel above lies after this unit along the line
        w[3] = a[1]; // the pixel to the left lies before it
        top = left = false;
        return;
      }
    }
    auto isFalling = [this](int u, int v) { return this->IsFallingUnit(u, v); };
    // Falling staircases: this pixel as q (its top edgel) or as r (its left edgel).
    for (int role = 0; role < 2; ++role)
    {
      const bool asQ = role == 0;
      if (!(asQ ? top : left))
      {
        continue;
      }
      const int qx = asQ ? x : x - 1;
      if (!this->IsFallingUnit(qx, y))
      {
        continue;
      }
      bool end1, end2;
      const int d1 = this->SearchDiagonal(qx, y, -1, +1, isFalling, end1);
      const int d2 = this->SearchDiagonal(qx, y, +1, -1, isFalling, end2);
      if (d1 + d2 + 1 < minLength)
      {
        continue;
      }
      const int x1 = qx - d1, y1 = y + d1; // first unit (upper left)
      const int x2 = qx + d2, y2 = y - d2; // last unit (lower right)
      const int e1 = DiagonalEndCode(
        end1, this->DiagonalTopAt(x1 - 1, y1) != 0, this->DiagonalLeftAt(x1, y1 + 1) != 0, In);
      const int e2 = DiagonalEndCode(end2, this->DiagonalTopAt(x2 + 1, y2 - 1) != 0,
        this->DiagonalLeftAt(x2 + 1, y2 - 1) != 0, Out);
      float a[3];
      this->LookUpDiagonalArea(e1, e2, d1, d2, a);
      if (asQ)
      {
        w[0] = a[0]; // q takes the colour above it
        w[1] = a[1]; // the pixel above q is the r of the unit before
        top = false;
      }
      else
      {
        w[2] = a[2]; // r lies after q along the line
        w[3] = a[0]; // q takes r's colour
        left = false;
      }
    }
  }

  void LookUpDiagonalArea(int e1, int e2, int d1, int d2, float* a) const
  {
    const int d = this->S.CellSize;
    const size_t texel =
      static_cast<size_t>(d * e2 + d2) * this->S.DiagonalAreaSize + (d * e1 + d1);
    std::copy(this->S.DiagonalArea + 3 * texel, this->S.DiagonalArea + 3 * texel + 3, a);
  }

  void LookUpArea(int e1, int e2, int d1, int d2, float* w) const
  {
    const int d = this->S.CellSize;
    const size_t texel = static_cast<size_t>(d * e2 + d2) * this->S.AreaSize + (d * e1 + d1);
    w[0] = this->S.Area[2 * texel];
    w[1] = this->S.Area[2 * texel + 1];
  }

  const T* InputPixel(int x, int y) const
  {
    const Rect& r = this->S.Input;
    return this->In + static_cast<vtkIdType>(y - r.Y0) * this->InRowStride +
      static_cast<vtkIdType>(x - r.X0) * this->C;
  }

  // Section 4.4: each pixel mixed with its four neighbours, c' = sum_k a_k ((1 - a_k) c +
  // a_k c_k) / sum_k a_k, which for a single edge is equation 4.1.
  template <typename WeightsAt>
  void BlendRow(int y, WeightsAt& weightsAt, T* output) const
  {
    const Rect& o = this->S.Output;
    const Rect& whole = this->S.Whole;
    const int c = this->C;
    T* out = output + static_cast<vtkIdType>(y - o.Y0) * o.Width() * c;
    std::copy(this->InputPixel(o.X0, y), this->InputPixel(o.X0, y) + o.Width() * c, out);
    const bool hasBelow = y > whole.Y0;
    for (int x = o.X0; x <= o.X1; ++x)
    {
      const unsigned char own = this->EdgesAt(x, y);
      const bool below = hasBelow && (this->EdgesAt(x, y - 1) & TopEdge);
      const bool right = x < whole.X1 && (this->EdgesAt(x + 1, y) & LeftEdge);
      if (!own && !below && !right)
      {
        continue;
      }
      const float* w = weightsAt(x, y);
      Acc a[4] = { (own & TopEdge) ? static_cast<Acc>(w[0]) : Acc(0),
        below ? static_cast<Acc>(weightsAt(x, y - 1)[1]) : Acc(0),
        (own & LeftEdge) ? static_cast<Acc>(w[2]) : Acc(0),
        right ? static_cast<Acc>(weightsAt(x + 1, y)[3]) : Acc(0) };
      if (this->S.Dominant)
      {
        // DominantDirectionBlending: on a corner, only the line with the larger weight counts.
        const Acc vertical = std::max(a[0], a[1]);
        const Acc horizontal = std::max(a[2], a[3]);
        if (vertical > horizontal)
        {
          a[2] = a[3] = Acc(0);
        }
        else if (horizontal > vertical)
        {
          a[0] = a[1] = Acc(0);
        }
      }
      const Acc sum = a[0] + a[1] + a[2] + a[3];
      if (!(sum > Acc(0)))
      {
        continue;
      }
      const T* neighbours[4] = { this->InputPixel(x, y + 1), this->InputPixel(x, y - 1),
        this->InputPixel(x - 1, y), this->InputPixel(x + 1, y) };
      const T* p = this->InputPixel(x, y);
      T* q = out + static_cast<vtkIdType>(x - o.X0) * c;
      for (int k = 0; k < c; ++k)
      {
        const Acc v = static_cast<Acc>(p[k]);
        Acc blended = 0;
        for (int n = 0; n < 4; ++n)
        {
          if (a[n] > Acc(0)) // never touch a neighbour that is not blended in
          {
            blended += a[n] * ((Acc(1) - a[n]) * v + a[n] * static_cast<Acc>(neighbours[n][k]));
          }
        }
        q[k] = ConvertBlended<T>(blended / sum);
      }
    }
  }

  template <typename WeightsAt>
  void WriteDebugRow(int y, WeightsAt& weightsAt, unsigned char* debug) const
  {
    const Rect& o = this->S.Output;
    unsigned char* out = debug + static_cast<vtkIdType>(y - o.Y0) * o.Width() * 4;
    for (int x = o.X0; x <= o.X1; ++x, out += 4)
    {
      const unsigned char e = this->EdgesAt(x, y);
      if (this->S.DebugOutput == vtkMLAAOptions::EDGES)
      {
        out[0] = (e & LeftEdge) ? 255 : 0;
        out[1] = (e & TopEdge) ? 255 : 0;
        out[2] = 0;
        out[3] = 255;
      }
      else
      {
        const float* w = weightsAt(x, y);
        for (int k = 0; k < 4; ++k)
        {
          out[k] = e ? static_cast<unsigned char>(std::lround(255.0f * w[k])) : 0;
        }
      }
    }
  }

  const SliceSetup& S;
  const T* In;
  vtkIdType InRowStride;
  int C;
  const double* Depth;
  Acc Lo = 0;
  Acc InvRange = 1;
  Acc Threshold = 0;
  Acc ContrastFactor = 0;
  bool HasAlpha = false;
  int F = 1; // features per pixel
  std::vector<unsigned char> Edges;
};

//------------------------------------------------------------------------------
// Normalised depth values of the available pixels of one slice.
template <typename T>
void NormaliseDepth(const T* depth, vtkIdType rowStride, vtkIdType pixelStride, const Rect& r,
  std::vector<double>& out)
{
  double lo = 0.0;
  double hi = 1.0;
  if (!std::is_floating_point<T>::value)
  {
    lo = static_cast<double>(std::numeric_limits<T>::lowest());
    hi = static_cast<double>(std::numeric_limits<T>::max());
  }
  out.resize(static_cast<size_t>(r.Width()) * r.Height());
  for (int y = 0; y < r.Height(); ++y)
  {
    const T* p = depth + y * rowStride;
    for (int x = 0; x < r.Width(); ++x, p += pixelStride)
    {
      out[static_cast<size_t>(y) * r.Width() + x] = (static_cast<double>(*p) - lo) / (hi - lo);
    }
  }
}

template <typename T>
void RunSlice(const SliceSetup& setup, const T* input, vtkIdType inputRowStride, int components,
  const double valueRange[2], const double* depth, T* output, unsigned char* debug)
{
  double lo, hi;
  NormalisationRange<T>(valueRange, lo, hi);
  MLAASlice<T> slice(setup, input, inputRowStride, components, lo, hi, depth);
  slice.DetectEdges();
  slice.BlendOrDebug(output, debug);
}

// An area table quantised to 8 bits: blending weights are stored as 8-bit values, as in the
// chapter's RGBA8 blending-weights texture, so the CPU filter and the GPU pass use the same
// weights.
std::vector<float> Quantised(const std::vector<float>& table)
{
  std::vector<float> quantised(table.size());
  for (size_t i = 0; i < table.size(); ++i)
  {
    quantised[i] = std::nearbyint(table[i] * 255.0f) / 255.0f;
  }
  return quantised;
}
} // namespace

//------------------------------------------------------------------------------
vtkImageMLAA::vtkImageMLAA()
{
  this->SetNumberOfInputPorts(2);
  this->Options = vtkMLAAOptions::New();
}

//------------------------------------------------------------------------------
vtkImageMLAA::~vtkImageMLAA()
{
  this->Options->Delete();
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetOptions(vtkMLAAOptions* options)
{
  if (vtkMLAAOptions::Assign(this, this->Options, options))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkImageMLAA::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Options->GetMTime());
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetDepthInputData(vtkDataObject* depth)
{
  this->SetInputData(1, depth);
}

//------------------------------------------------------------------------------
void vtkImageMLAA::SetDepthInputConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkImageMLAA::GetInputPadding()
{
  // The blending reads the weights of the right and lower neighbours (1 pixel); a weight reads
  // edgels up to 2 * MaxSearchSteps pixels along its line and the crossing edge one further
  // (2 * MaxSearchSteps + 1); an edgel compares two pixels. The diagonal search reads up to
  // 2 * MaxSearchSteps units along x and y, and the edgels two pixels past the last one. Local
  // contrast adaptation decides an edgel from the other boundaries of its two pixels, which
  // reach one pixel further; two are padded.
  const int edgels =
    2 * this->Options->GetMaxSearchSteps() + (this->Options->GetDiagonalDetection() ? 4 : 2);
  return edgels + (this->Options->GetLocalContrastFactor() > 0.0 ? 2 : 0);
}

//------------------------------------------------------------------------------
int vtkImageMLAA::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (this->Options->GetDebugOutput() != vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_UNSIGNED_CHAR, 4);
  }
  else
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
      inInfo, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
    if (scalarInfo)
    {
      vtkDataObject::SetPointDataActiveScalarInfo(outInfo,
        scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE()),
        scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()));
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  const int pad = this->GetInputPadding();

  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* inInfo = inputVector[port]->GetInformationObject(0);
    if (!inInfo)
    {
      continue;
    }
    int whole[6];
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
    int padded[6];
    for (int axis = 0; axis < 3; ++axis)
    {
      const int p = axis < 2 ? pad : 0; // z slices are independent
      padded[2 * axis] = std::max(extent[2 * axis] - p, whole[2 * axis]);
      padded[2 * axis + 1] = std::min(extent[2 * axis + 1] + p, whole[2 * axis + 1]);
      if (extent[2 * axis] > extent[2 * axis + 1])
      {
        // An empty request stays empty.
        padded[2 * axis] = extent[2 * axis];
        padded[2 * axis + 1] = extent[2 * axis + 1];
      }
    }
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), padded, 6);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkImageMLAA::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  vtkImageData* input = vtkImageData::GetData(inInfo);
  if (!output)
  {
    vtkErrorMacro("No output image.");
    return 0;
  }
  auto fail = [output]() {
    output->Initialize();
    return 0;
  };
  if (!input)
  {
    vtkErrorMacro("No input image.");
    return fail();
  }

  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (!scalars)
  {
    vtkErrorMacro("The input image has no point scalars to antialias.");
    return fail();
  }
  const int components = scalars->GetNumberOfComponents();
  if (components < 1 || components > 4)
  {
    vtkErrorMacro("The input image has " << components
                                         << " components; vtkImageMLAA takes 1 to 4 (grey, grey "
                                            "+ alpha, RGB, RGBA).");
    return fail();
  }
  const int scalarType = scalars->GetDataType();
  switch (scalarType)
  {
    vtkTemplateMacro(break);
    default:
      vtkErrorMacro("The input scalars are of type " << scalars->GetDataTypeAsString()
                                                     << ", which vtkImageMLAA does not support "
                                                        "(it takes integer and floating-point "
                                                        "types).");
      return fail();
  }
  if (this->ValueRange[1] <= this->ValueRange[0] || !std::isfinite(this->ValueRange[0]) ||
    !std::isfinite(this->ValueRange[1]))
  {
    vtkErrorMacro("ValueRange must be finite with ValueRange[0] < ValueRange[1]; it is ["
      << this->ValueRange[0] << ", " << this->ValueRange[1] << "].");
    return fail();
  }

  int outExt[6], inExt[6], whole[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), outExt);
  input->GetExtent(inExt);
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), whole);
  if (outExt[0] > outExt[1] || outExt[2] > outExt[3] || outExt[4] > outExt[5] ||
    inExt[0] > inExt[1] || inExt[2] > inExt[3] || inExt[4] > inExt[5])
  {
    vtkErrorMacro("The input image is empty (extent " << inExt[0] << " " << inExt[1] << " "
                                                      << inExt[2] << " " << inExt[3] << " "
                                                      << inExt[4] << " " << inExt[5] << ").");
    return fail();
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    if (outExt[2 * axis] < inExt[2 * axis] || outExt[2 * axis + 1] > inExt[2 * axis + 1])
    {
      vtkErrorMacro("The input extent does not cover the requested output extent.");
      return fail();
    }
  }

  const int mode = this->Options->GetEdgeDetection();
  const int debugOutput = this->Options->GetDebugOutput();
  const int pad = this->GetInputPadding();

  SliceSetup setup;
  setup.Whole = { whole[0], whole[1], whole[2], whole[3] };
  setup.Output = { outExt[0], outExt[1], outExt[2], outExt[3] };
  setup.Input = { std::max(inExt[0], std::max(whole[0], outExt[0] - pad)),
    std::min(inExt[1], std::min(whole[1], outExt[1] + pad)),
    std::max(inExt[2], std::max(whole[2], outExt[2] - pad)),
    std::min(inExt[3], std::min(whole[3], outExt[3] + pad)) };
  setup.Mode = mode;
  setup.DebugOutput = debugOutput;
  setup.SearchSteps = this->Options->GetMaxSearchSteps();
  setup.Threshold = this->Options->GetThreshold();
  setup.LocalContrastFactor = this->Options->GetLocalContrastFactor();
  const int maxDistance = this->Options->GetMaxDistance();
  const std::vector<float> area = Quantised(*vtkMLAAAreaTexture::GetSharedTable(maxDistance));
  setup.Area = area.data();
  setup.CellSize = maxDistance + 1;
  setup.AreaSize = vtkMLAAAreaTexture::NumberOfCodes * setup.CellSize;
  setup.Diagonals = this->Options->GetDiagonalDetection();
  setup.Dominant = this->Options->GetDominantDirectionBlending();
  const std::vector<float> diagonalArea = setup.Diagonals
    ? Quantised(*vtkMLAAAreaTexture::GetSharedDiagonalTable(maxDistance))
    : std::vector<float>();
  setup.DiagonalArea = diagonalArea.data();
  setup.DiagonalAreaSize = vtkMLAAAreaTexture::NumberOfDiagonalCodes * setup.CellSize;

  // The depth image, for depth edges.
  vtkImageData* depth = nullptr;
  vtkDataArray* depthScalars = nullptr;
  if (mode == vtkMLAAOptions::DEPTH)
  {
    depth = vtkImageData::GetData(inputVector[1]);
    depthScalars = depth ? depth->GetPointData()->GetScalars() : nullptr;
    if (!depthScalars)
    {
      vtkErrorMacro("EdgeDetection is Depth but no depth image with scalars is connected to "
                    "input port 1 (SetDepthInputData / SetDepthInputConnection).");
      return fail();
    }
    int depthExt[6];
    depth->GetExtent(depthExt);
    if (depthExt[0] > setup.Input.X0 || depthExt[1] < setup.Input.X1 ||
      depthExt[2] > setup.Input.Y0 || depthExt[3] < setup.Input.Y1 || depthExt[4] > outExt[4] ||
      depthExt[5] < outExt[5])
    {
      vtkErrorMacro("The depth image does not cover the colour image's extent.");
      return fail();
    }
    switch (depthScalars->GetDataType())
    {
      vtkTemplateMacro(break);
      default:
        vtkErrorMacro("The depth scalars are of type " << depthScalars->GetDataTypeAsString()
                                                       << ", which is not supported.");
        return fail();
    }
  }

  output->SetExtent(outExt);
  if (debugOutput != vtkMLAAOptions::NO_DEBUG_OUTPUT)
  {
    output->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
    output->GetPointData()->GetScalars()->SetName(
      debugOutput == vtkMLAAOptions::EDGES ? "Edges" : "BlendingWeights");
  }
  else
  {
    output->AllocateScalars(scalarType, components);
    output->GetPointData()->GetScalars()->SetName(scalars->GetName());
  }

  vtkIdType inIncrements[3];
  input->GetIncrements(scalars, inIncrements);
  const vtkIdType outSliceSize =
    static_cast<vtkIdType>(setup.Output.Width()) * setup.Output.Height() *
    output->GetPointData()->GetScalars()->GetNumberOfComponents();

  std::vector<double> depthValues;
  for (int z = outExt[4]; z <= outExt[5]; ++z)
  {
    if (depth)
    {
      vtkIdType depthIncrements[3];
      depth->GetIncrements(depthScalars, depthIncrements);
      switch (depthScalars->GetDataType())
      {
        vtkTemplateMacro(NormaliseDepth(static_cast<const VTK_TT*>(depth->GetScalarPointer(
                                          setup.Input.X0, setup.Input.Y0, z)),
          depthIncrements[1], depthIncrements[0], setup.Input, depthValues));
      }
    }
    void* inPtr = input->GetScalarPointer(setup.Input.X0, setup.Input.Y0, z);
    void* outPtr = static_cast<char*>(output->GetScalarPointer()) +
      (z - outExt[4]) * outSliceSize * output->GetScalarSize();
    unsigned char* debug = debugOutput != vtkMLAAOptions::NO_DEBUG_OUTPUT
      ? static_cast<unsigned char*>(outPtr)
      : nullptr;
    switch (scalarType)
    {
      vtkTemplateMacro(RunSlice(setup, static_cast<const VTK_TT*>(inPtr), inIncrements[1],
        components, this->ValueRange, depth ? depthValues.data() : nullptr,
        debug ? nullptr : static_cast<VTK_TT*>(outPtr), debug));
    }
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkImageMLAA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ValueRange: " << this->ValueRange[0] << " " << this->ValueRange[1] << "\n";
  os << indent << "Options:\n";
  this->Options->PrintSelf(os, indent.GetNextIndent());
}
