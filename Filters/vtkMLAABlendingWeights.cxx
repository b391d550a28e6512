// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAABlendingWeights.h"

#include "vtkAntialiasingTableCache.h"

#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cmath>
#include <cstring>
#include <mutex>

namespace vtkMLAAStages
{
void WeightsBuffer::Allocate(const Rect& extent)
{
  this->Extent = extent;
  // Every entry is written by ComputeBlendingWeights.
  this->Data.Reserve(extent.Empty() ? 0 : 4 * static_cast<size_t>(extent.Width()) * extent.Height());
}

//------------------------------------------------------------------------------
ByteBuffer* WeightsBuffer::BandScratch::Acquire()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  if (this->Free.empty())
  {
    this->Buffers.emplace_back(new ByteBuffer);
    return this->Buffers.back().get();
  }
  ByteBuffer* buffer = this->Free.back();
  this->Free.pop_back();
  return buffer;
}

void WeightsBuffer::BandScratch::Release(ByteBuffer* buffer)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->Free.push_back(buffer);
}

size_t WeightsBuffer::BandScratch::GetCapacity() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  size_t bytes = 0;
  for (const auto& buffer : this->Buffers)
  {
    bytes += buffer->GetCapacity();
  }
  return bytes;
}

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

// The quantised table of one maximum distance (plain or diagonal), shared as vtkMLAAAreaTexture
// shares its float tables: while a filter uses it, and the two asked for last (a filter's pair)
// while they take at most 1 MB each.
std::shared_ptr<const std::vector<unsigned char>> SharedQuantised(
  int maxDistance, bool diagonal, std::shared_ptr<const std::vector<float>> (*table)(int))
{
  static vtkAntialiasingTableCache<std::pair<int, bool>, std::vector<unsigned char>> cache(2);
  return cache.Get({ maxDistance, diagonal }, [maxDistance, table]() {
    return std::make_shared<const std::vector<unsigned char>>(Quantised(*table(maxDistance)));
  });
}
}

void MakeWeightSettings(vtkMLAAOptions* options, WeightSettings& settings)
{
  const int maxDistance = options->GetMaxDistance();
  settings.SearchSteps = options->GetMaxSearchSteps();
  settings.Diagonals = options->GetDiagonalDetection();
  settings.Corners = options->GetCornerExtrapolation();
  settings.RunLengths = options->GetCountsExactLineLengths();
  settings.CellSize = options->GetSearchReach();
  settings.AreaSize = vtkMLAAAreaTexture::NumberOfCodes * settings.CellSize;
  settings.DiagonalAreaSize = vtkMLAAAreaTexture::NumberOfDiagonalCodes * settings.CellSize;
  settings.Area = SharedQuantised(maxDistance, false, &vtkMLAAAreaTexture::GetSharedTable);
  settings.FloatArea =
    settings.Corners ? vtkMLAAAreaTexture::GetSharedTable(maxDistance) : nullptr;
  settings.DiagonalArea = settings.Diagonals
    ? SharedQuantised(maxDistance, true, &vtkMLAAAreaTexture::GetSharedDiagonalTable)
    : nullptr;
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
  // up and down along its column; leftEnd -1: none given, they are searched. With
  // DiagonalDetection, an edgel that is part of a 45-degree staircase takes its weights from the
  // diagonal line instead (ComputeDiagonalWeights).
  void Compute(int x, int y, int leftEnd, int rightEnd, int up, int down, unsigned char* w) const
  {
    w[0] = w[1] = w[2] = w[3] = 0;
    bool top = this->E.Top(x, y);
    bool left = this->E.Left(x, y);
    if (leftEnd < 0)
    {
      // No lengths counted beforehand: search.
      leftEnd = top ? this->SearchLine(Line<false>{ x, y }, 0, 0, -1) : 0;
      rightEnd = top ? this->SearchLine(Line<false>{ x, y }, 0, 0, +1) : 0;
      up = left ? this->SearchLine(Line<true>{ x, y }, 0, 0, -1) : 0;
      down = left ? this->SearchLine(Line<true>{ x, y }, 0, 0, +1) : 0;
    }
    if (this->S.Diagonals)
    {
      this->ComputeDiagonalWeights(x, y, top, left, w);
    }
    if (top)
    {
      this->LineWeights(Line<false>{ x, y }, leftEnd, rightEnd, w);
    }
    if (left)
    {
      this->LineWeights(Line<true>{ x, y }, up, down, w + 2);
    }
  }

private:
  // Line coordinates: the lines of top edgels (horizontal) and of left edgels (vertical) are
  // followed by the same code. In them u runs along the line towards its second end (right, or
  // down: a vertical line's first end is the upper one, as in the area table) and v across it,
  // towards the pixels on the line's other side (up, or left). The line's own edgel of a pixel
  // then lies between the pixel and its neighbour at v + 1, and the crossing edgel between the
  // pixel and its neighbour at u - 1, for either orientation; crossing-edge codes count the
  // edgel at v = 0 three times. Line<Vertical> is the pixel whose edgel the line goes through.
  template <bool Vertical>
  struct Line
  {
    int X, Y;
    int XAt(int u, int v) const { return Vertical ? this->X - v : this->X + u; }
    int YAt(int u, int v) const { return Vertical ? this->Y - u : this->Y + v; }
  };
  // The edgels at (u, v): along the line (Along) or crossing it (Crossing), clamped to the
  // available pixels as the GPU's reads are; AlongInside and CrossingInside, none outside the
  // image (the reads of the diagonal search).
  template <bool V>
  int AlongAt(const Line<V>& l, int u, int v) const
  {
    return V ? this->LeftAt(l.XAt(u, v), l.YAt(u, v)) : this->TopAt(l.XAt(u, v), l.YAt(u, v));
  }
  template <bool V>
  int CrossingAt(const Line<V>& l, int u, int v) const
  {
    return V ? this->TopAt(l.XAt(u, v), l.YAt(u, v)) : this->LeftAt(l.XAt(u, v), l.YAt(u, v));
  }
  template <bool V>
  int AlongInside(const Line<V>& l, int u, int v) const
  {
    return V ? this->DiagonalLeftAt(l.XAt(u, v), l.YAt(u, v))
             : this->DiagonalTopAt(l.XAt(u, v), l.YAt(u, v));
  }
  template <bool V>
  int CrossingInside(const Line<V>& l, int u, int v) const
  {
    return V ? this->DiagonalTopAt(l.XAt(u, v), l.YAt(u, v))
             : this->DiagonalLeftAt(l.XAt(u, v), l.YAt(u, v));
  }
  // How many pixels the image holds past the line's pixel in direction s (-1 or +1) of u.
  template <bool V>
  int ToBorder(const Line<V>& l, int s) const
  {
    if (V)
    {
      return s < 0 ? this->Whole.Y1 - l.Y : l.Y - this->Whole.Y0;
    }
    return s < 0 ? l.X - this->Whole.X0 : this->Whole.X1 - l.X;
  }

  // The weights (two of w) of the line through the edgel of l's pixel, whose ends lie d1 pixels
  // before it and d2 after it along u.
  template <bool V>
  void LineWeights(const Line<V>& l, int d1, int d2, unsigned char* w) const
  {
    int e1 = this->CrossingCode(l, -d1);
    int e2 = this->CrossingCode(l, d2 + 1);
    if (this->JunctionGoesOn(l, e1, -d1, -d1 - 1))
    {
      e1 = 0;
    }
    if (this->JunctionGoesOn(l, e2, d2 + 1, d2 + 1))
    {
      e2 = 0;
    }
    if (this->SideWithoutSteps(l, e1, e2, d1, d2))
    {
      w[0] = w[1] = 0;
      return;
    }
    bool half1 = false, half2 = false;
    if (this->S.Corners && d1 + d2 > 0)
    {
      // Past a step the staircase goes on one row (column) over, at v - 1 (code 3: the crossing
      // edge is on this side) or v + 1 (code 1), from the pixel just beyond the end; at a corner
      // the crossing edge goes on one more pixel that way instead.
      End first{ e1, d1 };
      End second{ e2, d2 };
      this->LineEnd(l, -1, first);
      this->LineEnd(l, +1, second);
      const int border1 = this->ToBorder(l, -1);
      const int border2 = this->ToBorder(l, +1);
      if (d1 >= border1)
      {
        first = End{ 0, border1, true };
      }
      if (d2 >= border2)
      {
        second = End{ 0, border2, true };
      }
      if (this->ExtrapolateCorners(first, second))
      {
        e1 = first.Code;
        d1 = first.Distance;
        e2 = second.Code;
        d2 = second.Distance;
        half1 = first.Half;
        half2 = second.Half;
      }
    }
    if (e1 == 4 && e2 == 4 && !this->ThinAcross(l))
    {
      e1 = e2 = 0; // junctions of wider shapes at both ends: no slope
    }
    this->LookUpArea(e1, e2, d1, d2, half1, half2, w);
  }

  // Issue 50: whether l's line, with ends of codes e1 and e2 d1 pixels before it and d2 after it,
  // is the side of a shape that shows no step of a staircase, and is left alone. The area table
  // reads every crossing edge on one side of an end as a one-pixel step (section 4.3.2). At a
  // corner of a shape (CornerEnd, and not CrossingEndsInStep) it is not: the crossing edge is a
  // side of its own. Where the other end is no step either (a corner too, a junction of wider
  // shapes, the image border, no crossing edge, or beyond the search's reach), nothing seen
  // tells that the side leaves the pixel
  // boundary, and the chapter's U, Z or L ramp from the corner would blur a side that is right
  // (axis-aligned rectangles, voxels seen straight on, bars, legends, viewport borders). A side
  // whose true course is a fraction of a pixel off the boundary looks the same, and no reading
  // of these pixels tells which way it is off: no ramp is also the estimate of an offset equally
  // likely either way. A line of one pixel keeps the chapter's reading (the Z of a step of the
  // staircase across it, the U of a one-pixel bar's end), and so does a small shape: a side
  // shorter than MinimumSideLength (within the reach: an end beyond it makes the side longer
  // than the search sees) whose corners' sides are that short too, a rendered point of 2 or 3
  // pixels, which the U shapes round as its supersampled image is; small cells of a grid (voxels
  // of 2 or 3 pixels) have sides that run on past their corners. A corner at one end and a step
  // at the other keeps the chapter's reading (or CornerExtrapolation's).
  // Must match sideWithoutSteps in vtkMLAABlendingWeightsFS.glsl.
  static constexpr int MinimumSideLength = 4;
  template <bool V>
  bool SideWithoutSteps(const Line<V>& l, int e1, int e2, int d1, int d2) const
  {
    const int length = d1 + d2 + 1;
    if (length == 1)
    {
      return false;
    }
    const bool corner1 = this->CornerEnd(l, -1, e1, d1);
    const bool corner2 = this->CornerEnd(l, +1, e2, d2);
    if (!((corner1 || corner2) && (corner1 || e1 == 0 || this->WideJunction(l, -1, e1, d1)) &&
          (corner2 || e2 == 0 || this->WideJunction(l, +1, e2, d2))))
    {
      return false;
    }
    int run1 = 0, run2 = 0;
    if ((corner1 && this->CrossingEndsInStep(l, -1, e1, d1, run1)) ||
      (corner2 && this->CrossingEndsInStep(l, +1, e2, d2, run2)))
    {
      return false;
    }
    // A small shape, short in both directions, keeps the chapter's reading.
    const int maxDistance = this->S.CellSize - 1;
    return length >= MinimumSideLength || d1 >= maxDistance || d2 >= maxDistance ||
      std::max(run1, run2) >= MinimumSideLength;
  }

  // Whether the end of l's line in direction s (-1 or +1), `distance` pixels away with crossing
  // code `code`, is the corner of a shape: a crossing edge on one side only (1 or 3) that goes on
  // for a second pixel away from the line (CrossingGoesOn), and no line going on one row
  // (column) over past it (which would make it a step). Edgels outside the image are none.
  template <bool V>
  bool CornerEnd(const Line<V>& l, int s, int code, int distance) const
  {
    if (code != 1 && code != 3)
    {
      return false;
    }
    const int beyond = s * (distance + 1); // the pixel just past the end
    const int crossing = s < 0 ? beyond + 1 : beyond;
    return !this->AlongInside(l, beyond, code == 3 ? -1 : 1) &&
      this->CrossingGoesOn(l, crossing, 0, code);
  }

  // Whether the crossing edge of such a corner, followed away from the line within the search's
  // reach, ends at a step of its own: where a side meets a steep staircase (the corner of a
  // polygon in perspective, a checkerboard's squares), the crossing edge goes on one column (row)
  // over, for two pixels or more, and the line is the flat run of a slanted outline whose corner
  // the chapter's reading rounds as it should. That next run begins where the crossing edge ends:
  // an edge one column over that runs alongside it (the far side of a line one pixel wide, where
  // the near side's edgels stop at a junction, or where local contrast adaptation drops a few)
  // is no step (issue 50: the bars of a chart, hanging from such a line, were ramped over their
  // whole height). `run` counts the crossing edge's pixels.
  template <bool V>
  bool CrossingEndsInStep(const Line<V>& l, int s, int code, int distance, int& run) const
  {
    const int crossing = s < 0 ? -distance : distance + 1;
    // The crossing edge covers v = 0 and -1 (code 3) or v = 1 and 2 (code 1); follow it on.
    const int away = code == 3 ? -1 : 1;
    const int reach = this->S.CellSize - 1;
    run = 2;
    for (int v = code == 3 ? -2 : 3; std::abs(v) <= reach; v += away, ++run)
    {
      if (!this->CrossingInside(l, crossing, v))
      {
        for (int side : { -1, 1 })
        {
          if (this->CrossingInside(l, crossing + side, v) &&
            this->CrossingInside(l, crossing + side, v + away) &&
            !this->CrossingInside(l, crossing + side, v - away))
          {
            return true;
          }
        }
        return false;
      }
    }
    return false;
  }

  // Whether that end has crossing edges on both sides (code 4) that both go on for a second pixel
  // away from the line: a junction of shapes at least two pixels wide, not the diagonal step of a
  // one-pixel-thin line or gap (vtkMLAAAreaTexture's reading of code 4).
  template <bool V>
  bool WideJunction(const Line<V>& l, int s, int code, int distance) const
  {
    const int crossing = s < 0 ? -distance : distance + 1;
    return code == 4 && this->CrossingGoesOn(l, crossing, 0, 1) &&
      this->CrossingGoesOn(l, crossing, 0, 3);
  }

  // One end of an orthogonal line for CornerExtrapolation: crossing-edge code and distance from
  // the pixel, whether the line's course past it is unseen (a corner of a shape, or the image
  // border), and, at a step of a staircase, the length of the staircase's next run (0: none).
  struct End
  {
    int Code;
    int Distance;
    bool Unseen = false;
    int Next = 0;
    bool NextUnseen = false; // the next run ends at a corner or the border: no second step
    bool Half = false; // set by ExtrapolateCorners: the end's height is unknown
  };

  // CornerExtrapolation (vtkMLAAOptions). The area table (section 4.3.3) reads a crossing edge on
  // one side of an end as a one-pixel step of a staircase, which the revectorised line crosses
  // half-way up, and ramps the line from it over half its length (an L shape, Biri et al.,
  // section 3.4). That holds where the line goes on one row (column) over past the edge: a step.
  // Where instead the crossing edge is a side of the shape (it goes on along the crossing
  // direction for two pixels or more) and the line does not go on past it, the edge turns at a
  // corner; at the image border the line's course is not seen at all. At such an end the line's
  // height is not half a pixel: the corner's position along the staircase decides it, and the
  // longer the search, the farther the L ramp from it reaches along the side (the damage of
  // issue 20). The side of a shape is straight up to its corner, so the height there follows
  // from the staircase seen at the line's other end: if that end is a step, the run past it is a
  // whole run of the staircase, of length L (its length gives the slope, as the line lengths of
  // Biri et al., section 3.3, do), and this line, cut short by the corner, is ramped as the
  // whole run it is part of: a Z shape from the step to a virtual step L - 1 - d pixels from the
  // pixel, in the same table. A next run beyond the search's reach puts the virtual step beyond it
  // too (code 0 at the maximum distance, as a capped search). Where the next run itself ends at a
  // corner or the image border (End::NextUnseen), the step is the side's only one and neither run
  // is seen whole: the run R is at least the longer of the two, m. With no run length more likely
  // than another at its scale (prior density 1 / R), a step at that place has probability 1 / R,
  // so R's posterior density is proportional to 1 / R^2 on [m, inf), under which the mean slope
  // E[1 / R] is 1 / (2m): the line is ramped as a run of L = 2m (issue 20), whose ramp falls from
  // the step to nothing at distance m. Where nothing is seen to
  // extrapolate from (corners at both ends, an end beyond the reach or of code 4, or a next run
  // that cannot belong to one straight staircase with this line: shorter than 2, or more than
  // one pixel shorter than this line, and ending at a step) the chapter's reading stays, which is
  // right on average there, with one exception (issue 20): where the other end is seen, within the
  // reach, but gives no slope (such a next run, or no crossing edge there), the corner's height is
  // unknown:
  // the chapter's step (half a pixel) and a flat end (nothing) are equally likely readings, and
  // the end takes their mean, half the chapter's ramp (End::Half; the area table's ramps are
  // linear in the end's height, so that is half of the corner end's share of the two areas, see
  // LookUpArea). Left as the chapter reads them: corners at both ends, and an other end beyond
  // the reach or with crossing edges on both sides (code 4, whose reading depends on this end's).
  // Returns whether it changed the ends. Must match extrapolateCorners in
  // vtkMLAABlendingWeightsFS.glsl.
  bool ExtrapolateCorners(End& first, End& second) const
  {
    if (first.Unseen == second.Unseen)
    {
      return false;
    }
    End& corner = first.Unseen ? first : second;
    const End& step = first.Unseen ? second : first;
    const int length = first.Distance + second.Distance + 1;
    const int maxDistance = this->S.CellSize - 1;
    int run = std::max(length, step.Next);
    if (step.NextUnseen)
    {
      run *= 2; // the step is the side's only one: the expected run is twice the longer one seen
    }
    else if (step.Next < 2 || step.Next + 1 < length)
    {
      if (step.Code == 4 || step.Distance >= maxDistance || (corner.Code != 1 && corner.Code != 3))
      {
        return false;
      }
      corner.Half = true;
      return true;
    }
    const int distance = run - 1 - step.Distance;
    if (step.Next > maxDistance || distance > maxDistance)
    {
      corner.Code = 0;
      corner.Distance = maxDistance;
    }
    else
    {
      corner.Code = 4 - step.Code;
      corner.Distance = distance;
    }
    return true;
  }

  // The end of l's line in direction s (-1: the first, d1 before the pixel; +1: the second),
  // with a crossing edge on one side (code 1 or 3). A step if the line goes on one row (column)
  // over from the pixel just past the end (then the length of that next run, and whether it ends
  // unseen), a corner if the crossing edge goes on instead. Edgels outside the image are none.
  template <bool V>
  void LineEnd(const Line<V>& l, int s, End& end) const
  {
    if (end.Code != 1 && end.Code != 3)
    {
      return;
    }
    const int beyond = s * (end.Distance + 1); // the pixel just past the end
    const int crossing = s < 0 ? beyond + 1 : beyond; // the crossing edge's pixel
    const int next = end.Code == 3 ? -1 : 1;
    if (this->AlongInside(l, beyond, next))
    {
      end.Next = this->SearchLine(l, beyond, next, s) + 1;
      end.NextUnseen = this->RunEndsUnseen(l, beyond, next, s, end.Next);
    }
    else
    {
      end.Unseen = this->CrossingGoesOn(l, crossing, 0, end.Code);
    }
  }

  // Whether the next run of a staircase (at v, from u in direction s, `length` pixels) ends at a
  // corner or the image border, so that the staircase shows no second step and that run is cut
  // short too: past its last pixel the crossing edge is on one side only and goes on for a second
  // pixel that way, and the run does not go on one row (column) over. Within the reach; edgels
  // outside the image are none.
  template <bool V>
  bool RunEndsUnseen(const Line<V>& l, int u, int v, int s, int length) const
  {
    const int last = u + s * (length - 1);
    if (s * last >= this->ToBorder(l, s))
    {
      return true;
    }
    if (length - 1 >= 2 * this->S.SearchSteps)
    {
      return false;
    }
    const int crossing = s < 0 ? last : last + 1;
    const int code =
      3 * this->CrossingInside(l, crossing, v) + this->CrossingInside(l, crossing, v + 1);
    if ((code != 1 && code != 3) || this->AlongInside(l, last + s, code == 3 ? v - 1 : v + 1))
    {
      return false;
    }
    return this->CrossingGoesOn(l, crossing, v, code);
  }

  // The edgels at (x, y) clamped to the available pixels, as a GPU reads a texture with
  // clamp-to-edge.
  const unsigned char* Clamped(int x, int y) const
  {
    return this->E.At(std::min(std::max(x, this->R.X0), this->R.X1),
      std::min(std::max(y, this->R.Y0), this->R.Y1));
  }
  int TopAt(int x, int y) const { return this->Clamped(x, y)[1] ? 1 : 0; }
  int LeftAt(int x, int y) const { return this->Clamped(x, y)[0] ? 1 : 0; }

  // Section 4.3.1, searched (below vtkMLAAOptions::ExactLineLengthsSteps; the run lengths give the
  // same numbers): distance from the pixel at (u, v) of l's line coordinates to the end of its
  // line (of l's kind) in direction s of u. Each step looks at the next two pixels along the
  // line, as the GPU does with one bilinear fetch (searchLine in vtkMLAABlendingWeightsFS.glsl):
  // - the two edgels along the line;
  // - the crossing edgels (perpendicular ones, on either side of the line) at the boundary
  //   before the first pixel and at the boundary between the two.
  // The line ends before the first pixel without an edgel, or at the first boundary with a
  // crossing edgel. Stopping at crossing edges (which the chapter's search does not, section
  // 4.3.1 and 4.6) keeps the top and bottom outlines of one-pixel-wide lines apart.
  template <bool V>
  int SearchLine(const Line<V>& l, int u, int v, int s) const
  {
    for (int i = 0; i < this->S.SearchSteps; ++i)
    {
      const int first = u + s * (2 * i + 1);
      const int second = first + s;
      // The crossing edgels of the two boundaries, on this row (column) and the one across.
      const int nearOwner = std::max(first, first - s);
      const int midOwner = std::max(first, second);
      if (this->CrossingAt(l, nearOwner, v) || this->CrossingAt(l, nearOwner, v + 1) ||
        !this->AlongAt(l, first, v))
      {
        return 2 * i;
      }
      if (this->CrossingAt(l, midOwner, v) || this->CrossingAt(l, midOwner, v + 1) ||
        !this->AlongAt(l, second, v))
      {
        return 2 * i + 1;
      }
    }
    return 2 * this->S.SearchSteps;
  }

  // Section 4.3.2: the crossing-edge code at an end of a line, 3 * (edgel on the owning pixel's
  // side) + (edgel on the opposite side), as the bilinear fetch a quarter pixel off the edge
  // reads it. Ends outside the image have no crossing edge.
  template <bool V>
  int CrossingCode(const Line<V>& l, int u) const
  {
    if (u < -this->ToBorder(l, -1) || u > this->ToBorder(l, +1))
    {
      return 0;
    }
    return 3 * this->CrossingAt(l, u, 0) + this->CrossingAt(l, u, 1);
  }

  // Whether the end of l's line whose crossing edgels belong to the pixel at u = crossing, of
  // crossing-edge code `code`, is a T junction that the line goes on past (issue 20). The area
  // table reads a crossing edge on one side of an end as a one-pixel step of a staircase (section
  // 4.3.2), past which the line goes on one row (column) over. Where instead the line's own edge
  // goes on straight past the end (at u = beyond) and the crossing edge goes on for a second
  // pixel away from the line, the crossing edge is the side of a region that meets the line (a
  // band of a colour map, say), and the line has no step there: the end is read as one without
  // crossing edges. A crossing edge one pixel long keeps the step's reading: it may be the step of
  // a feature narrower than a pixel (the rim of a shaded surface, whose colour changes along a
  // silhouette). Edgels outside the image are none. Must match junctionGoesOn in
  // vtkMLAABlendingWeightsFS.glsl.
  template <bool V>
  bool JunctionGoesOn(const Line<V>& l, int code, int crossing, int beyond) const
  {
    return (code == 1 || code == 3) && this->AlongInside(l, beyond, 0) &&
      this->CrossingGoesOn(l, crossing, 0, code);
  }

  // Whether the crossing edge of code `code` (1 or 3: on one side) of the line at row (column) v,
  // whose edgels belong to the pixel at u = crossing, goes on for a second pixel away from the
  // line: the side of a shape or a region, not a one-pixel step. The test of a corner (LineEnd,
  // RunEndsUnseen) and of a T junction (JunctionGoesOn). None outside the image.
  template <bool V>
  bool CrossingGoesOn(const Line<V>& l, int crossing, int v, int code) const
  {
    return this->CrossingInside(l, crossing, code == 3 ? v - 1 : v + 2) != 0;
  }

  // Edgels for the diagonal search and ThinAcross: none outside the image.
  int DiagonalTopAt(int x, int y) const
  {
    return this->Whole.Contains(x, y) ? this->TopAt(x, y) : 0;
  }
  int DiagonalLeftAt(int x, int y) const
  {
    return this->Whole.Contains(x, y) ? this->LeftAt(x, y) : 0;
  }
  // Whether one of the two pixels across the edgel of l's pixel (that pixel and the one at v + 1:
  // above it, or left of it) is one pixel thin across it: it has an edgel on its far side too. A
  // line with crossing edges on both sides at both ends (code 4 at both) is read as a thin
  // feature's run only there (vtkMLAAAreaTexture); between the junctions of wider shapes (a
  // checkerboard's corners, say) it keeps no slope.
  template <bool V>
  bool ThinAcross(const Line<V>& l) const
  {
    return this->AlongInside(l, 0, -1) || this->AlongInside(l, 0, 1);
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

  // The two areas of texel (e1, e2, d1, d2), quantised. With half1 or half2 (CornerExtrapolation,
  // End::Half), that end's height is halved: the table's areas are sums of one part from each
  // end (vtkMLAAAreaTexture::ComputeAreas), so the areas are those of (e1, 0) and (0, e2) with
  // the halved end's weighted by 1/2, added in float and then quantised, as
  // vtkMLAABlendingWeightsFS.glsl adds them before the pass stores the weights. Neither end may
  // then have code 4 (whose part depends on the other end's).
  void LookUpArea(
    int e1, int e2, int d1, int d2, bool half1, bool half2, unsigned char* w) const
  {
    const int d = this->S.CellSize;
    if (half1 || half2)
    {
      const float* table = this->S.FloatArea->data();
      const float* a = table + 2 * (static_cast<size_t>(d2) * this->S.AreaSize + (d * e1 + d1));
      const float* b = table + 2 * (static_cast<size_t>(d * e2 + d2) * this->S.AreaSize + d1);
      const float k1 = half1 ? 0.5f : 1.0f;
      const float k2 = half2 ? 0.5f : 1.0f;
      for (int c = 0; c < 2; ++c)
      {
        w[c] = static_cast<unsigned char>(std::nearbyint((k1 * a[c] + k2 * b[c]) * 255.0f));
      }
      return;
    }
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
  const bool runs = settings.RunLengths;
  const bool diagonalRuns = settings.Diagonals && runs;
  const int edgesWidth = edges.Extent.Width();
  // With run lengths, each task takes a band of rows at least as high as the maximum distance,
  // so that counting a band's column lengths, which reads up to that far beyond it, costs at most
  // twice what counting them over the whole extent would; higher bands, where there are enough
  // of them for the threads, cost less again (BandRowsPerTask).
  const int bandHeight =
    runs ? std::max(BandRowsPerTask(r.Height()), maxDistance) : RowsPerTask;
  const vtkIdType bands = (r.Height() + bandHeight - 1) / bandHeight;
  vtkSMPTools::For(0, bands, 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType band = begin; band < end; ++band)
    {
      if (progress.Aborted())
      {
        return;
      }
      const int y0 = r.Y0 + static_cast<int>(band) * bandHeight;
      const Rect b{ r.X0, r.X1, y0, std::min(r.Y1, y0 + bandHeight - 1) };
      const size_t pixels = static_cast<size_t>(b.Width()) * b.Height();
      // The band's line lengths, in a scratch buffer of this task: down and up lengths of its
      // pixels, then the staircases' (ComputeDiagonalLengths), then the left and right lengths
      // of one row of the edges.
      ByteBuffer* scratch = runs ? weights.Scratch.Acquire() : nullptr;
      LineLength* down = nullptr;
      LineLength* up = nullptr;
      LineLength* left = nullptr;
      LineLength* right = nullptr;
      WeightsComputer::DiagonalLengths diagonal;
      if (runs)
      {
        const size_t columnValues = 2 * pixels;
        const size_t diagonalValues = diagonalRuns ? 4 * pixels : 0;
        const size_t rowValues = 2 * static_cast<size_t>(edgesWidth);
        scratch->Reserve((columnValues + diagonalValues + rowValues) * sizeof(LineLength));
        LineLength* base = reinterpret_cast<LineLength*>(scratch->Get());
        down = base;
        up = base + pixels;
        left = base + columnValues + diagonalValues;
        right = left + edgesWidth;
        ComputeColumnLineLengths(edges, b, maxDistance, down, up, false);
        if (diagonalRuns)
        {
          diagonal.Extent = b;
          diagonal.RisingDown = base + columnValues;
          diagonal.RisingUp = diagonal.RisingDown + pixels;
          diagonal.FallingUp = diagonal.RisingUp + pixels;
          diagonal.FallingDown = diagonal.FallingUp + pixels;
          // Where a staircase leaves the band, its length is searched (SearchDiagonal), which
          // gives the count that the recursion over the whole extent would.
          WeightsComputer(edges, whole, settings).ComputeDiagonalLengths(diagonal, b.X0, b.X1);
        }
      }
      const WeightsComputer computer(edges, whole, settings, diagonalRuns ? &diagonal : nullptr);
      const int offset = r.X0 - edges.Extent.X0;
      for (int y = b.Y0; y <= b.Y1; ++y)
      {
        const unsigned char* e = edges.At(r.X0, y);
        unsigned char* w = weights.At(r.X0, y);
        const size_t column = static_cast<size_t>(y - b.Y0) * b.Width();
        if (runs)
        {
          ComputeRowLineLengths(edges, y, maxDistance, left, right);
        }
        // Most pixels have no edgel: sixteen or four at a time are skipped; their weights are
        // not written.
        for (int x = r.X0; x <= r.X1;)
        {
          if (x + 16 <= r.X1 + 1 && !AnyByte32(e + 2 * (x - r.X0)))
          {
            x += 16;
            continue;
          }
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
      if (scratch)
      {
        weights.Scratch.Release(scratch);
      }
      progress.RowsDone(b.Height());
    }
  });
}
}
