// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAALineLengths.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstring>

namespace vtkMLAAStages
{
//------------------------------------------------------------------------------
// Line lengths (section 4.3.1 as run lengths; see the header). With C = maxDistance and "p
// continues to q" meaning that q has the line's edgel and no crossing edgel lies between p and
// q (edgels read clamped to the extent):
//   length(p) = continues(p, next(p)) ? min(C, 1 + length(next(p))) : 0,
// evaluated from the far end of each row or column towards its near end. Past the border of the
// extent the clamped edgels repeat the border pixel's, so the border pixel continues to its
// outer neighbour exactly when every further one does too: its length is C or 0.

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
  LineLength* down, LineLength* up, bool threaded)
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
  auto strips = [&](vtkIdType begin, vtkIdType end) {
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
  };
  const vtkIdType count = (w + strip - 1) / strip;
  if (threaded)
  {
    vtkSMPTools::For(0, count, 1, strips);
  }
  else
  {
    strips(0, count);
  }
}
}
