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
  const int steps = options->GetMaxSearchSteps();
  halo.Blending = 1;
  halo.Search = 2 * steps + (options->GetDiagonalDetection() ? 3 : 1);
  halo.Edges = options->GetLocalContrastFactor() > 0.0 ? 2 : 0;
  halo.Reconstruction = options->GetReconstruction() ? 1 : 0;
  return halo;
}

//------------------------------------------------------------------------------
Progress::Progress(
  std::function<void(double)> report, std::function<bool()> aborted, vtkIdType totalRows)
  : Report(std::move(report))
  , AbortQuery(std::move(aborted))
  , Total(totalRows > 0 ? totalRows : 1)
  , Owner(std::this_thread::get_id())
{
}

Progress::Progress()
  : Owner(std::this_thread::get_id())
{
}

void Progress::RowsDone(vtkIdType rows)
{
  const vtkIdType done = this->Done.fetch_add(rows, std::memory_order_relaxed) + rows;
  if (std::this_thread::get_id() != this->Owner)
  {
    return;
  }
  const double fraction = std::min(1.0, static_cast<double>(done) / this->Total);
  if (this->Report && fraction - this->LastReported >= 0.01)
  {
    this->LastReported = fraction;
    this->Report(fraction);
  }
  this->CheckAbort();
}

bool Progress::CheckAbort()
{
  if (std::this_thread::get_id() == this->Owner && this->AbortQuery && this->AbortQuery())
  {
    this->AbortFlag.store(true, std::memory_order_relaxed);
  }
  return this->Aborted();
}

//------------------------------------------------------------------------------
FeatureLayout MakeFeatureLayout(int mode, int components)
{
  FeatureLayout layout;
  layout.Mode = mode;
  layout.Components = components;
  layout.HasAlpha = components == 2 || components == 4;
  layout.Count = mode == vtkMLAAOptions::COLOR
    ? components
    : (mode == vtkMLAAOptions::LAB ? 3 : 1) + (layout.HasAlpha ? 1 : 0);
  return layout;
}

//------------------------------------------------------------------------------
void EdgesBuffer::Allocate(const Rect& extent)
{
  this->Extent = extent;
  // Every entry is written by DetectEdges.
  this->Data.Reserve(extent.Empty() ? 0 : 2 * static_cast<size_t>(extent.Width()) * extent.Height());
}

void WeightsBuffer::Allocate(const Rect& extent)
{
  this->Extent = extent;
  // Every entry is written by ComputeBlendingWeights.
  this->Data.Reserve(extent.Empty() ? 0 : 4 * static_cast<size_t>(extent.Width()) * extent.Height());
}

//------------------------------------------------------------------------------
namespace
{
// The contrasts across the left and the top boundaries of the pixels of one row (0: not an
// edge), each with a zero entry before the first and after the last pixel ([-1] and [w]).
template <typename Acc>
struct ContrastRow
{
  Acc* Left;
  Acc* Top;
};

// The contrasts of rows and the edgels that local contrast adaptation keeps.
template <typename Acc>
class EdgeDetector
{
public:
  EdgeDetector(int features, const EdgeSettings& settings)
    : F(features)
    , E(settings.EuclideanFeatures == 3 && features >= 3 ? 3 : 1)
    , Threshold(static_cast<Acc>(settings.Threshold))
    , Factor(static_cast<Acc>(settings.LocalContrastFactor))
  {
  }

  // The contrast across a boundary: the largest difference of a feature that is at least the
  // threshold (and more than nothing, so that a zero threshold means "any difference"), else 0.
  // NaN differences are never edges.
  Acc Contrast(Acc a, Acc b) const { return this->Kept(std::abs(a - b)); }
  Acc Kept(Acc d) const { return (d >= this->Threshold && d > Acc(0)) ? d : Acc(0); }

  // The contrasts of one row of w pixels with features f, and the row above with features g
  // (null where there is no row above: no top edges); features in planes of w values. The
  // largest over the features is taken plane by plane, which vectorises.
  void Contrasts(const Acc* f, const Acc* g, ContrastRow<Acc> b, int w) const
  {
    b.Left[-1] = b.Left[w] = b.Top[-1] = b.Top[w] = Acc(0);
    b.Left[0] = Acc(0);
    if (this->E == 3)
    {
      // LAB: Delta E / 100, the Euclidean distance of (L, a, b) / 100 (Biri et al., 3.2).
      const Acc* f1 = f + w;
      const Acc* f2 = f + 2 * w;
      for (int x = 1; x < w; ++x)
      {
        const Acc d0 = f[x] - f[x - 1];
        const Acc d1 = f1[x] - f1[x - 1];
        const Acc d2 = f2[x] - f2[x - 1];
        b.Left[x] = this->Kept(std::sqrt(d0 * d0 + d1 * d1 + d2 * d2));
      }
    }
    else
    {
      for (int x = 1; x < w; ++x)
      {
        b.Left[x] = this->Contrast(f[x], f[x - 1]);
      }
    }
    for (int k = this->E; k < this->F; ++k)
    {
      const Acc* plane = f + k * w;
      for (int x = 1; x < w; ++x)
      {
        const Acc c = this->Contrast(plane[x], plane[x - 1]);
        b.Left[x] = c > b.Left[x] ? c : b.Left[x];
      }
    }
    if (!g)
    {
      std::fill(b.Top, b.Top + w, Acc(0));
      return;
    }
    if (this->E == 3)
    {
      const Acc* f1 = f + w;
      const Acc* f2 = f + 2 * w;
      const Acc* g1 = g + w;
      const Acc* g2 = g + 2 * w;
      for (int x = 0; x < w; ++x)
      {
        const Acc d0 = f[x] - g[x];
        const Acc d1 = f1[x] - g1[x];
        const Acc d2 = f2[x] - g2[x];
        b.Top[x] = this->Kept(std::sqrt(d0 * d0 + d1 * d1 + d2 * d2));
      }
    }
    else
    {
      for (int x = 0; x < w; ++x)
      {
        b.Top[x] = this->Contrast(f[x], g[x]);
      }
    }
    for (int k = this->E; k < this->F; ++k)
    {
      const Acc* plane = f + k * w;
      const Acc* planeAbove = g + k * w;
      for (int x = 0; x < w; ++x)
      {
        const Acc c = this->Contrast(plane[x], planeAbove[x]);
        b.Top[x] = c > b.Top[x] ? c : b.Top[x];
      }
    }
  }

  // The edgels of one row that local contrast adaptation (vtkMLAAOptions::LocalContrastFactor)
  // keeps, from the contrasts of the row (b) and of the rows below and above it: an edge whose
  // contrast, times the factor, is below the contrast of one of the six other boundaries of the
  // two pixels it separates is dropped.
  void KeepEdgels(ContrastRow<Acc> below, ContrastRow<Acc> b, ContrastRow<Acc> above,
    unsigned char* edges, int w) const
  {
    const Acc factor = this->Factor;
    // Most boundaries are not edges: clear the row, and skip runs of pixels whose contrasts are
    // all +0 (contrasts are never negative or NaN), 16 bytes of each at a time.
    std::fill(edges, edges + 2 * static_cast<size_t>(w), 0);
    constexpr int chunk = static_cast<int>(16 / sizeof(Acc));
    for (int x = 0; x < w; ++x)
    {
      if (x % chunk == 0 && x + chunk <= w)
      {
        std::uint64_t bits[4];
        std::memcpy(bits, b.Left + x, 16);
        std::memcpy(bits + 2, b.Top + x, 16);
        if ((bits[0] | bits[1] | bits[2] | bits[3]) == 0)
        {
          x += chunk - 1;
          continue;
        }
      }
      const Acc left = b.Left[x];
      const Acc top = b.Top[x];
      if (!(left > Acc(0)) && !(top > Acc(0)))
      {
        continue;
      }
      unsigned char* edge = edges + 2 * x;
      edge[0] = (left > Acc(0) &&
                   (factor == Acc(0) ||
                     factor * left >= std::max({ b.Left[x - 1], b.Left[x + 1], b.Top[x - 1], top,
                                        below.Top[x - 1], below.Top[x] })))
        ? 255
        : 0;
      edge[1] = (top > Acc(0) &&
                   (factor == Acc(0) ||
                     factor * top >= std::max({ below.Top[x], above.Top[x], left, b.Left[x + 1],
                                       above.Left[x], above.Left[x + 1] })))
        ? 255
        : 0;
    }
  }

private:
  int F;
  int E; // leading features compared by Euclidean distance (1 or 3)
  Acc Threshold;
  Acc Factor;
};
}

//------------------------------------------------------------------------------
// Section 4.2: the contrast across every boundary (0 where it is not an edge), then the edgels
// that local contrast adaptation keeps. Each task takes a band of rows and computes the
// contrasts of its rows and of the rows just below and above it (which adaptation reads) from
// the features of those rows, so no full-size buffer but the edges is needed.
template <typename Acc>
void DetectEdges(const std::function<void(int, Acc*)>& readRow, int features,
  const EdgeSettings& settings, EdgesBuffer& edges, Progress& progress)
{
  const Rect r = edges.Extent;
  if (r.Empty())
  {
    return;
  }
  const int w = r.Width();
  const int h = r.Height();
  const EdgeDetector<Acc> detector(features, settings);
  vtkSMPTools::For(0, h, RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    // Contrast rows begin - 1 .. end, row i at index i + 1 - begin.
    const int rows = static_cast<int>(end - begin) + 2;
    const size_t stride = static_cast<size_t>(w) + 2;
    std::unique_ptr<Acc[]> band(new Acc[2 * stride * rows]);
    auto contrastRow = [&](int i) {
      Acc* left = band.get() + 2 * stride * (i + 1 - begin);
      return ContrastRow<Acc>{ left + 1, left + stride + 1 };
    };
    std::vector<Acc> current(static_cast<size_t>(w) * features);
    std::vector<Acc> above(current.size());
    const int first = std::max(0, static_cast<int>(begin) - 1);
    const int last = std::min(h - 1, static_cast<int>(end));
    for (int i = static_cast<int>(begin) - 1; i <= static_cast<int>(end); ++i)
    {
      if (i < first || i > last)
      {
        // Outside the extent: no boundaries.
        const ContrastRow<Acc> b = contrastRow(i);
        std::fill(b.Left - 1, b.Left + w + 1, Acc(0));
        std::fill(b.Top - 1, b.Top + w + 1, Acc(0));
      }
    }
    readRow(r.Y0 + first, current.data());
    for (int i = first; i <= last; ++i)
    {
      // The top row of the extent has no top edge; the top row of a piece has one that is
      // never read (the padding covers every read), so it is left out.
      const bool hasAbove = i + 1 < h;
      if (hasAbove)
      {
        readRow(r.Y0 + i + 1, above.data());
      }
      detector.Contrasts(current.data(), hasAbove ? above.data() : nullptr, contrastRow(i), w);
      std::swap(current, above);
    }
    for (vtkIdType i = begin; i < end; ++i)
    {
      const int row = static_cast<int>(i);
      detector.KeepEdgels(contrastRow(row - 1), contrastRow(row), contrastRow(row + 1),
        edges.At(r.X0, r.Y0 + row), w);
    }
    progress.RowsDone(end - begin);
  });
}

template VTKFILTERSMLAA_EXPORT void DetectEdges<float>(const std::function<void(int, float*)>&,
  int, const EdgeSettings&, EdgesBuffer&, Progress&);
template VTKFILTERSMLAA_EXPORT void DetectEdges<double>(const std::function<void(int, double*)>&,
  int, const EdgeSettings&, EdgesBuffer&, Progress&);

//------------------------------------------------------------------------------
namespace
{
// An area table quantised to 8 bits: blending weights are stored as 8-bit values, as in the
// chapter's RGBA8 blending-weights texture, so the CPU filter and the GPU pass use the same
// weights.
std::vector<unsigned char> Quantised(const std::vector<float>& table)
{
  std::vector<unsigned char> quantised(table.size());
  for (size_t i = 0; i < table.size(); ++i)
  {
    quantised[i] = static_cast<unsigned char>(std::nearbyint(table[i] * 255.0f));
  }
  return quantised;
}

// The quantised table of one maximum distance, made once and shared, as vtkMLAAAreaTexture
// shares its float tables.
using QuantisedTable = std::shared_ptr<const std::vector<unsigned char>>;
QuantisedTable SharedQuantised(
  int maxDistance, bool diagonal, std::shared_ptr<const std::vector<float>> (*table)(int))
{
  static std::mutex mutex;
  static std::map<std::pair<int, bool>, QuantisedTable> cache;
  std::lock_guard<std::mutex> lock(mutex);
  QuantisedTable& entry = cache[{ maxDistance, diagonal }];
  if (!entry)
  {
    entry = std::make_shared<const std::vector<unsigned char>>(Quantised(*table(maxDistance)));
  }
  return entry;
}
}

void MakeWeightSettings(vtkMLAAOptions* options, WeightSettings& settings)
{
  const int maxDistance = options->GetMaxDistance();
  settings.SearchSteps = options->GetMaxSearchSteps();
  settings.Diagonals = options->GetDiagonalDetection();
  settings.RunLengths = settings.SearchSteps >= RunLengthSteps;
  settings.CellSize = maxDistance + 1;
  settings.AreaSize = vtkMLAAAreaTexture::NumberOfCodes * settings.CellSize;
  settings.DiagonalAreaSize = vtkMLAAAreaTexture::NumberOfDiagonalCodes * settings.CellSize;
  settings.Area = SharedQuantised(maxDistance, false, &vtkMLAAAreaTexture::GetSharedTable);
  settings.DiagonalArea = settings.Diagonals
    ? SharedQuantised(maxDistance, true, &vtkMLAAAreaTexture::GetSharedDiagonalTable)
    : nullptr;
}

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
// Line lengths (section 4.3.1 as run lengths; see the header). With C = maxDistance and "p
// continues to q" meaning that q has the line's edgel and no crossing edgel lies between p and
// q (edgels read clamped to the extent):
//   length(p) = continues(p, next(p)) ? min(C, 1 + length(next(p))) : 0,
// evaluated from the far end of each row or column towards its near end. Past the border of the
// extent the clamped edgels repeat the border pixel's, so the border pixel continues to its
// outer neighbour exactly when every further one does too: its length is C or 0.
namespace
{
// Whether any of the n pixels of an edges row at e has a left edgel (Which = 0) or a top one
// (Which = 1), eight bytes (four pixels) at a time. The masks select each pixel's first or
// second byte on little-endian machines (as BlendRow's skip assumes); elsewhere every byte
// counts, which only costs the skip.
template <int Which>
inline bool AnyEdgel(const unsigned char* e, int n)
{
  static const std::uint64_t mask = [] {
    const std::uint16_t one = 1;
    unsigned char first;
    std::memcpy(&first, &one, 1);
    return first != 1 ? ~0ull : Which == 0 ? 0x00FF00FF00FF00FFull : 0xFF00FF00FF00FF00ull;
  }();
  int k = 0;
  std::uint64_t any = 0;
  for (; k + 4 <= n; k += 4)
  {
    std::uint64_t four;
    std::memcpy(&four, e + 2 * k, sizeof(four));
    any |= four;
  }
  bool found = (any & mask) != 0;
  for (; k < n && !found; ++k)
  {
    found = e[2 * k + Which] != 0;
  }
  return found;
}
}

void ComputeRowLineLengths(
  const EdgesBuffer& edges, int y, int maxDistance, LineLength* left, LineLength* right)
{
  const Rect& r = edges.Extent;
  const int w = r.Width();
  const int cap = maxDistance;
  const unsigned char* e = edges.At(r.X0, y);
  // The row above, clamped: its left edgels cross the line too.
  const unsigned char* a = edges.At(r.X0, std::min(y + 1, r.Y1));
  // Whether pixel i has a top edgel, and whether its left boundary is open (no left edgel on
  // this row or the row above): then the line runs from i - 1 into i, or from i into i - 1.
  auto top = [e](int i) { return e[2 * i + 1] != 0; };
  auto open = [e, a](int i) { return (e[2 * i] | a[2 * i]) == 0; };
  // Only the lengths of pixels with a top edgel are used, by the weights and by the recursion
  // (a pixel's length is read by its neighbour only if it continues that neighbour's line, so
  // only if it has a top edgel): groups of eight pixels without one are skipped, their entries
  // left unwritten.
  auto noTopEdgels = [e, w](int i) { return i + 8 <= w && !AnyEdgel<1>(e + 2 * i, 8); };
  // Left: i - 1 continues i's line when it has a top edgel and i's left boundary is open. At the
  // extent's left border the clamped edgels repeat pixel 0's: C or 0.
  int length = (top(0) && open(0)) ? cap : 0;
  left[0] = static_cast<LineLength>(length);
  for (int i = 1; i < w; ++i)
  {
    if (noTopEdgels(i))
    {
      i += 7;
      length = 0; // pixel i + 7 has no top edgel: the next one's line does not run into it
      continue;
    }
    length = (top(i - 1) && open(i)) ? std::min(cap, length + 1) : 0;
    left[i] = static_cast<LineLength>(length);
  }
  // Right: i + 1 continues i's line when it has a top edgel and its left boundary is open.
  length = (top(w - 1) && open(w - 1)) ? cap : 0;
  right[w - 1] = static_cast<LineLength>(length);
  for (int i = w - 2; i >= 0; --i)
  {
    if (i >= 7 && noTopEdgels(i - 7))
    {
      i -= 7;
      length = 0;
      continue;
    }
    length = (top(i + 1) && open(i + 1)) ? std::min(cap, length + 1) : 0;
    right[i] = static_cast<LineLength>(length);
  }
}

void ComputeColumnLineLengths(const EdgesBuffer& edges, const Rect& extent, int maxDistance,
  LineLength* down, LineLength* up)
{
  const Rect& r = edges.Extent;
  if (extent.Empty())
  {
    return;
  }
  const int cap = maxDistance;
  const int w = extent.Width();
  // Strips of columns, each scanned row by row (contiguous reads and writes within a row); the
  // running lengths of a strip's columns are carried from row to row. As for rows, only the
  // lengths of pixels with a left edgel are used: a row of a strip without left edgels resets
  // the carried lengths and is not stored.
  constexpr int strip = 256;
  vtkSMPTools::For(0, (w + strip - 1) / strip, 1, [&](vtkIdType begin, vtkIdType end) {
    LineLength carry[strip];
    for (vtkIdType s = begin; s < end; ++s)
    {
      const int i0 = static_cast<int>(s) * strip;
      const int n = std::min(strip, w - i0);
      const int x0 = extent.X0 + i0;
      const int leftOfFirst = std::max(x0 - 1, r.X0);
      auto hasLeftEdgels = [&](int y) { return AnyEdgel<0>(edges.At(x0, y), n); };
      auto storeCarry = [&](LineLength* lengths, int y) {
        if (y >= extent.Y0 && y <= extent.Y1)
        {
          std::copy(carry, carry + n, lengths + static_cast<size_t>(y - extent.Y0) * w + i0);
        }
      };
      // The lengths of row lengthsRow from those carried: pixel k continues when edgelsRow's
      // pixel has a left edgel and the boundary above boundaryRow's pixel is open (no top edgel
      // on it in this column or the column to the left, clamped to the extent).
      auto scanRow = [&](int edgelsRow, int boundaryRow) {
        const unsigned char* e = edges.At(x0, edgelsRow);
        const unsigned char* b = edges.At(x0, boundaryRow);
        unsigned char previousTop = edges.At(leftOfFirst, boundaryRow)[1];
        for (int k = 0; k < n; ++k)
        {
          const unsigned char ownTop = b[2 * k + 1];
          const bool continues = e[2 * k] != 0 && (ownTop | previousTop) == 0;
          previousTop = ownTop;
          carry[k] = static_cast<LineLength>(continues ? std::min(cap, carry[k] + 1) : 0);
        }
      };
      // One direction (step -1: up, scanned downwards from the top; +1: down, scanned upwards
      // from the bottom). The scan starts at the extent's border, where the clamped edgels repeat
      // the border row's so that its length is C or 0, or C rows beyond the pixels wanted, where
      // it may start from 0: a line that reaches that row from a wanted pixel is C long already.
      auto scan = [&](int step, LineLength* lengths) {
        const int border = step < 0 ? r.Y1 : r.Y0;
        const int wanted = step < 0 ? extent.Y1 : extent.Y0;
        const int last = step < 0 ? extent.Y0 : extent.Y1;
        const int start = step < 0 ? std::min(border, wanted + cap) : std::max(border, wanted - cap);
        if (start == border)
        {
          // The border row's own edgels stand for every row beyond it (C - 1 + 1 = C).
          std::fill(carry, carry + n, static_cast<LineLength>(cap - 1));
          scanRow(border, border);
        }
        else
        {
          std::fill(carry, carry + n, static_cast<LineLength>(0));
        }
        bool zero = false;
        bool ownEdgels = hasLeftEdgels(start);
        if (ownEdgels)
        {
          storeCarry(lengths, start);
        }
        for (int y = start + step; step < 0 ? y >= last : y <= last; y += step)
        {
          // Up: y + 1 continues y's line when it has a left edgel and y's top boundary is open.
          // Down: y - 1 continues it when it has a left edgel and its own top boundary (the one
          // between the two) is open.
          const int previous = y - step;
          if (!ownEdgels)
          {
            if (!zero)
            {
              std::fill(carry, carry + n, static_cast<LineLength>(0));
              zero = true;
            }
          }
          else
          {
            scanRow(previous, step < 0 ? y : previous);
            zero = false;
          }
          ownEdgels = hasLeftEdgels(y);
          if (ownEdgels)
          {
            storeCarry(lengths, y);
          }
        }
      };
      scan(-1, up);
      scan(+1, down);
    }
  });
}

//------------------------------------------------------------------------------
namespace
{
// Section 4.3: the blending weights of one pixel from the edges around it.
class WeightsComputer
{
public:
  // The lengths of the staircases through the pixels of an extent, in each of their two
  // directions, as SearchDiagonal counts them (ComputeDiagonalLengths); the entries of pixels
  // that are not units of that kind of staircase are not written.
  struct DiagonalLengths
  {
    Rect Extent;
    LineLength* RisingDown = nullptr;  // rising units, towards (-1, -1)
    LineLength* RisingUp = nullptr;    // rising units, towards (+1, +1)
    LineLength* FallingUp = nullptr;   // falling units, towards (-1, +1)
    LineLength* FallingDown = nullptr; // falling units, towards (+1, -1)
    size_t Index(int x, int y) const
    {
      return static_cast<size_t>(y - this->Extent.Y0) * this->Extent.Width() + (x - this->Extent.X0);
    }
  };

  WeightsComputer(const EdgesBuffer& edges, const Rect& whole, const WeightSettings& settings,
    const DiagonalLengths* diagonalLengths = nullptr)
    : E(edges)
    , R(edges.Extent)
    , Whole(whole)
    , S(settings)
    , D(diagonalLengths)
  {
  }

  // The diagonal lengths of the columns x0..x1 of lengths.Extent, by the run-length recursion
  // of the orthogonal lines along each diagonal (ComputeRowLineLengths): a unit's count towards
  // a direction is 0 if the next pixel that way is no unit, else 1 plus that unit's count,
  // capped at the maximum distance. Rows are scanned upwards for the directions that go down and
  // downwards for those that go up. Where the next pixel lies outside the extent or the strip of
  // columns, the count is searched unit by unit instead (SearchDiagonal), so strips are
  // independent and the reads beyond the extent are those of the search. Must give the counts of
  // searchDiagonal in Rendering/glsl/vtkMLAABlendingWeightsFS.glsl, which searches from every
  // unit.
  void ComputeDiagonalLengths(const DiagonalLengths& lengths, int x0, int x1) const
  {
    const Rect& ext = lengths.Extent; // within the edges' extent and the image
    const int cap = this->S.CellSize - 1;
    auto rising = [this](int u, int v) { return this->IsRisingUnit(u, v); };
    auto falling = [this](int u, int v) { return this->IsFallingUnit(u, v); };
    // Rows upwards for the directions that go down (rising towards (-1, -1), falling towards
    // (+1, -1)), then downwards for those that go up ((+1, +1) and (-1, +1)).
    for (const int dy : { -1, +1 })
    {
      LineLength* risingOut = dy < 0 ? lengths.RisingDown : lengths.RisingUp;
      LineLength* fallingOut = dy < 0 ? lengths.FallingDown : lengths.FallingUp;
      const int risingDx = dy;
      const int fallingDx = -dy;
      for (int y = dy < 0 ? ext.Y0 : ext.Y1; dy < 0 ? y <= ext.Y1 : y >= ext.Y0; y -= dy)
      {
        const int ny = y + dy;
        const bool nextRow = ny >= ext.Y0 && ny <= ext.Y1;
        const unsigned char* e = this->E.At(x0, y);
        const unsigned char* n = nextRow ? this->E.At(x0, ny) : nullptr;
        // The count of the unit at (x, y) whose next unit would be at (nx, ny), given whether that
        // is a unit: from the next unit's count inside the strip, else searched.
        auto count = [&](int x, int nx, bool isRising, bool nextIsUnit, const LineLength* out) {
          if (!n || nx < x0 || nx > x1)
          {
            bool reachedEnd;
            return isRising ? this->SearchDiagonal(x, y, risingDx, dy, rising, reachedEnd)
                            : this->SearchDiagonal(x, y, fallingDx, dy, falling, reachedEnd);
          }
          return nextIsUnit ? std::min(cap, 1 + out[lengths.Index(nx, ny)]) : 0;
        };
        for (int x = x0; x <= x1; ++x)
        {
          const int i = x - x0;
          // Both kinds of unit have the pixel's top edgel: eight pixels without one are skipped.
          if (i % 8 == 0 && x + 7 <= x1 && !AnyEdgel<1>(e + 2 * i, 8))
          {
            x += 7;
            continue;
          }
          if (!e[2 * i + 1])
          {
            continue;
          }
          // A rising unit: the pixel's two edgels (inside the image: no clamping).
          if (e[2 * i])
          {
            const int nx = x + risingDx;
            const int ni = nx - x0;
            const bool next = n && nx >= x0 && nx <= x1 && n[2 * ni] && n[2 * ni + 1];
            risingOut[lengths.Index(x, y)] =
              static_cast<LineLength>(count(x, nx, true, next, risingOut));
          }
          // A falling unit: its top edgel and the left edgel of the pixel to its right (read
          // through the clamped accessors at the strip's last column).
          if (x < x1 ? e[2 * i + 2] != 0 : falling(x, y))
          {
            const int nx = x + fallingDx;
            const int ni = nx - x0;
            bool next = false;
            if (n && nx >= x0 && nx <= x1)
            {
              next = nx < x1 ? (n[2 * ni + 1] && n[2 * ni + 2]) : falling(nx, ny);
            }
            fallingOut[lengths.Index(x, y)] =
              static_cast<LineLength>(count(x, nx, false, next, fallingOut));
          }
        }
      }
    }
  }

  // The four weights of a pixel with edgels (see WeightsBuffer), given the lengths of its lines
  // (ComputeRowLineLengths, ComputeColumnLineLengths): leftEnd and rightEnd along its row,
  // up and down along its column; leftEnd -1: none given, they are searched. With DiagonalDetection, an edgel that is part of a 45-degree
  // staircase takes its weights from the diagonal line instead (ComputeDiagonalWeights).
  void Compute(int x, int y, int leftEnd, int rightEnd, int up, int down, unsigned char* w) const
  {
    w[0] = w[1] = w[2] = w[3] = 0;
    bool top = this->E.Top(x, y);
    bool left = this->E.Left(x, y);
    if (leftEnd < 0)
    {
      // No lengths counted beforehand: search.
      leftEnd = top ? this->SearchTopEdges(x, y, -1) : 0;
      rightEnd = top ? this->SearchTopEdges(x, y, +1) : 0;
      up = left ? this->SearchLeftEdges(x, y, +1) : 0;
      down = left ? this->SearchLeftEdges(x, y, -1) : 0;
    }
    if (this->S.Diagonals)
    {
      this->ComputeDiagonalWeights(x, y, top, left, w);
    }
    if (top)
    {
      // A horizontal line: its ends lie to the left and to the right.
      const int e1 = this->CrossingLeftEdges(x - leftEnd, y, y + 1);
      const int e2 = this->CrossingLeftEdges(x + rightEnd + 1, y, y + 1);
      this->LookUpArea(e1, e2, leftEnd, rightEnd, w);
    }
    if (left)
    {
      // A vertical line: its first end is the upper one.
      const int e1 = this->CrossingTopEdges(x, x - 1, y + up);
      const int e2 = this->CrossingTopEdges(x, x - 1, y - down - 1);
      this->LookUpArea(e1, e2, up, down, w + 2);
    }
  }

private:
  // The edgels at (x, y) clamped to the available pixels, as a GPU reads a texture with
  // clamp-to-edge.
  const unsigned char* Clamped(int x, int y) const
  {
    return this->E.At(std::min(std::max(x, this->R.X0), this->R.X1),
      std::min(std::max(y, this->R.Y0), this->R.Y1));
  }
  int TopAt(int x, int y) const { return this->Clamped(x, y)[1] ? 1 : 0; }
  int LeftAt(int x, int y) const { return this->Clamped(x, y)[0] ? 1 : 0; }

  // Section 4.3.1, searched (below WeightSettings::RunLengthSteps; the run lengths give the
  // same numbers): distance from (x, y) to the end of its line of top edgels in direction dx
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
    if (x < this->Whole.X0 || x > this->Whole.X1)
    {
      return 0;
    }
    return 3 * this->LeftAt(x, ownY) + this->LeftAt(x, oppositeY);
  }
  int CrossingTopEdges(int ownX, int oppositeX, int y) const
  {
    if (y < this->Whole.Y0 || y > this->Whole.Y1)
    {
      return 0;
    }
    return 3 * this->TopAt(ownX, y) + this->TopAt(oppositeX, y);
  }

  // Edgels for the diagonal search: none outside the image.
  int DiagonalTopAt(int x, int y) const
  {
    return this->Whole.Contains(x, y) ? this->TopAt(x, y) : 0;
  }
  int DiagonalLeftAt(int x, int y) const
  {
    return this->Whole.Contains(x, y) ? this->LeftAt(x, y) : 0;
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
  void ComputeDiagonalWeights(int x, int y, bool& top, bool& left, unsigned char* w) const
  {
    constexpr int minLength = vtkMLAAOptions::MinimumDiagonalLength;
    constexpr int Out = 1;
    constexpr int In = 2;
    if (top && left)
    {
      auto isUnit = [this](int u, int v) { return this->IsRisingUnit(u, v); };
      bool end1, end2;
      const int d1 = this->DiagonalLength(x, y, -1, -1, true, isUnit, end1);
      const int d2 = this->DiagonalLength(x, y, +1, +1, true, isUnit, end2);
      if (d1 + d2 + 1 >= minLength)
      {
        const int x1 = x - d1, y1 = y - d1; // first unit
        const int x2 = x + d2, y2 = y + d2; // last unit
        const int e1 = DiagonalEndCode(end1, this->DiagonalTopAt(x1 - 1, y1 - 1) != 0,
          this->DiagonalLeftAt(x1, y1 - 1) != 0, Out);
        const int e2 = DiagonalEndCode(end2, this->DiagonalTopAt(x2 + 1, y2) != 0,
          this->DiagonalLeftAt(x2 + 1, y2 + 1) != 0, In);
        const unsigned char* a = this->DiagonalArea(e1, e2, d1, d2);
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
      const int d1 = this->DiagonalLength(qx, y, -1, +1, false, isFalling, end1);
      const int d2 = this->DiagonalLength(qx, y, +1, -1, false, isFalling, end2);
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
      const unsigned char* a = this->DiagonalArea(e1, e2, d1, d2);
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

  const unsigned char* DiagonalArea(int e1, int e2, int d1, int d2) const
  {
    const int d = this->S.CellSize;
    const size_t texel = static_cast<size_t>(d * e2 + d2) * this->S.DiagonalAreaSize + (d * e1 + d1);
    return this->S.DiagonalArea->data() + 3 * texel;
  }

  void LookUpArea(int e1, int e2, int d1, int d2, unsigned char* w) const
  {
    const int d = this->S.CellSize;
    const size_t texel = static_cast<size_t>(d * e2 + d2) * this->S.AreaSize + (d * e1 + d1);
    const unsigned char* a = this->S.Area->data() + 2 * texel;
    w[0] = a[0];
    w[1] = a[1];
  }

  // SearchDiagonal from a unit, from the diagonal lengths where they were computed.
  template <typename IsUnit>
  int DiagonalLength(int x, int y, int dx, int dy, bool isRising, IsUnit isUnit,
    bool& reachedEnd) const
  {
    if (this->D && this->D->Extent.Contains(x, y))
    {
      const LineLength* lengths = isRising
        ? (dx < 0 ? this->D->RisingDown : this->D->RisingUp)
        : (dx < 0 ? this->D->FallingUp : this->D->FallingDown);
      const int d = lengths[this->D->Index(x, y)];
      reachedEnd = d < this->S.CellSize - 1;
      return d;
    }
    return this->SearchDiagonal(x, y, dx, dy, isUnit, reachedEnd);
  }

  const EdgesBuffer& E;
  const Rect R;
  const Rect Whole;
  const WeightSettings& S;
  const DiagonalLengths* D;
};
}

void ComputeBlendingWeights(const EdgesBuffer& edges, const Rect& whole,
  const WeightSettings& settings, WeightsBuffer& weights, Progress& progress)
{
  const Rect r = weights.Extent;
  if (r.Empty())
  {
    return;
  }
  const int maxDistance = settings.CellSize - 1;
  const size_t pixels = static_cast<size_t>(r.Width()) * r.Height();
  // The lengths of the staircases (DiagonalDetection) through the pixels of the extent, in
  // strips of columns.
  WeightsComputer::DiagonalLengths diagonal;
  const bool diagonalRuns = settings.Diagonals && settings.RunLengths;
  if (diagonalRuns)
  {
    weights.DiagonalLengths.Reserve(4 * pixels * sizeof(LineLength));
    LineLength* base = reinterpret_cast<LineLength*>(weights.DiagonalLengths.Get());
    diagonal.Extent = r;
    diagonal.RisingDown = base;
    diagonal.RisingUp = base + pixels;
    diagonal.FallingUp = base + 2 * pixels;
    diagonal.FallingDown = base + 3 * pixels;
    const WeightsComputer searcher(edges, whole, settings);
    constexpr int strip = 256;
    vtkSMPTools::For(0, (r.Width() + strip - 1) / strip, 1, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const int x0 = r.X0 + static_cast<int>(i) * strip;
        searcher.ComputeDiagonalLengths(diagonal, x0, std::min(r.X1, x0 + strip - 1));
      }
    });
  }
  const WeightsComputer computer(edges, whole, settings, diagonalRuns ? &diagonal : nullptr);
  // The up and down lengths of every pixel of the extent (the columns are scanned in strips),
  // the left and right ones row by row in each task.
  const bool runs = settings.RunLengths;
  weights.ColumnLengths.Reserve(runs ? 2 * pixels * sizeof(LineLength) : 0);
  LineLength* down = reinterpret_cast<LineLength*>(weights.ColumnLengths.Get());
  LineLength* up = down + pixels;
  if (runs)
  {
    ComputeColumnLineLengths(edges, r, maxDistance, down, up);
  }
  if (progress.CheckAbort())
  {
    return;
  }
  const int edgesWidth = edges.Extent.Width();
  vtkSMPTools::For(0, r.Height(), RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    std::vector<LineLength> rowLengths(runs ? 2 * static_cast<size_t>(edgesWidth) : 0);
    LineLength* left = rowLengths.data();
    LineLength* right = left + edgesWidth;
    const int offset = r.X0 - edges.Extent.X0;
    for (vtkIdType i = begin; i < end; ++i)
    {
      const int y = r.Y0 + static_cast<int>(i);
      const unsigned char* e = edges.At(r.X0, y);
      unsigned char* w = weights.At(r.X0, y);
      const size_t column = static_cast<size_t>(i) * r.Width();
      if (runs)
      {
        ComputeRowLineLengths(edges, y, maxDistance, left, right);
      }
      // Most pixels have no edgel: four at a time are skipped; their weights are not written.
      for (int x = r.X0; x <= r.X1;)
      {
        if (x + 4 <= r.X1 + 1)
        {
          std::uint64_t four;
          std::memcpy(&four, e + 2 * (x - r.X0), sizeof(four));
          if (four == 0)
          {
            x += 4;
            continue;
          }
        }
        const int i = x - r.X0;
        if (e[2 * i] | e[2 * i + 1])
        {
          // Lengths are only computed for pixels with the edgel they belong to.
          if (!runs)
          {
            computer.Compute(x, y, -1, -1, -1, -1, w + 4 * i);
            ++x;
            continue;
          }
          const bool hasTop = e[2 * i + 1] != 0;
          const bool hasLeft = e[2 * i] != 0;
          computer.Compute(x, y, hasTop ? left[offset + i] : 0, hasTop ? right[offset + i] : 0,
            hasLeft ? up[column + i] : 0, hasLeft ? down[column + i] : 0, w + 4 * i);
        }
        ++x;
      }
    }
    progress.RowsDone(end - begin);
  });
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
