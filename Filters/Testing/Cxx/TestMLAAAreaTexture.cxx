// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMLAAAreaTexture: the layout of Figure 4.2 (GPU Pro 2, section 4.3.3), mirror
// symmetry, the trapeze formula of the topological-reconstruction paper (section 3.4) for
// L shapes, hand-computed texels of the L, U and Z shapes, the 8-bit image, and the diagonal
// table.
#include "vtkImageData.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkNew.h"

#include <cmath>
#include <iostream>
#include <vector>

namespace
{
int Failures = 0;

void Expect(bool ok, const char* what, int line)
{
  if (!ok)
  {
    std::cerr << "line " << line << ": " << what << std::endl;
    ++Failures;
  }
}
#define EXPECT(cond) Expect((cond), #cond, __LINE__)

bool Near(double a, double b, double tolerance = 1e-6)
{
  return std::abs(a - b) <= tolerance;
}

// Owning-pixel (channel 0) and opposite-pixel (channel 1) areas of one texel.
void ExpectAreas(vtkMLAAAreaTexture* texture, int e1, int e2, int left, int right, double own,
  double opposite, int line)
{
  const double a0 = texture->GetArea(e1, e2, left, right, 0);
  const double a1 = texture->GetArea(e1, e2, left, right, 1);
  if (!Near(a0, own) || !Near(a1, opposite))
  {
    std::cerr << "line " << line << ": texel e1=" << e1 << " e2=" << e2 << " left=" << left
              << " right=" << right << " holds (" << a0 << ", " << a1 << "), expected (" << own
              << ", " << opposite << ")" << std::endl;
    ++Failures;
  }
}
#define EXPECT_AREAS(e1, e2, l, r, own, opp) ExpectAreas(texture, e1, e2, l, r, own, opp, __LINE__)
}

int TestMLAAAreaTexture(int, char*[])
{
  vtkNew<vtkMLAAAreaTexture> texture;
  vtkMLAAAreaTexture* t = texture;

  // Layout: 5 x 5 cells of D x D texels, D = maximum distance + 1.
  EXPECT(texture->GetMaxDistance() == 16);
  EXPECT(texture->GetCellSize() == 17);
  EXPECT(texture->GetTextureSize() == 85);
  for (int maxDistance : { 8, 16, 32, 64, 128 })
  {
    texture->SetMaxDistance(maxDistance);
    EXPECT(texture->GetTextureSize() == 5 * (maxDistance + 1));
  }
  texture->SetMaxDistance(8); // the chapter's 9 x 9 cells
  const int d = texture->GetCellSize();
  const int size = texture->GetTextureSize();
  const float* table = texture->GetTable();

  // Texel (D e1 + left, D e2 + right) of the table is what GetArea reports.
  EXPECT(table[2 * ((d * 3 + 2) * size + (d * 1 + 5)) + 0] == texture->GetArea(1, 3, 5, 2, 0));
  EXPECT(table[2 * ((d * 3 + 2) * size + (d * 1 + 5)) + 1] == texture->GetArea(1, 3, 5, 2, 1));

  // Code 2 cannot occur: its row and column of cells are empty. No crossing edges (code 0) give
  // no slope: nothing to blend. Code 4 at one end and no crossing edge at the other: no slope
  // either. Code 4 at one end and a one-sided crossing edge (1 or 3) at the other: the line
  // continues diagonally past the code-4 end, so that end acts as the other side's crossing edge
  // and the pattern is a Z. Code 4 at both ends (a thin feature's run between two diagonal
  // steps, whose side cannot be told): both pixels take the U's area, the owning pixel that of
  // the U into its side (3, 3), the other that of the U into its own (1, 1); the two are equal.
  const int otherSide[5] = { 0, 3, 0, 1, 0 };
  for (int e = 0; e < 5; ++e)
  {
    for (int l = 0; l < d; ++l)
    {
      for (int r = 0; r < d; ++r)
      {
        for (int c = 0; c < 2; ++c)
        {
          EXPECT(texture->GetArea(2, e, l, r, c) == 0.0f);
          EXPECT(texture->GetArea(e, 2, l, r, c) == 0.0f);
          EXPECT(texture->GetArea(0, 0, l, r, c) == 0.0f);
          EXPECT(texture->GetArea(4, 4, l, r, c) == texture->GetArea(c == 0 ? 3 : 1, c == 0 ? 3 : 1, l, r, c));
          EXPECT(texture->GetArea(4, 4, l, r, c) == texture->GetArea(4, 4, l, r, 1 - c));
          EXPECT(texture->GetArea(3, 3, l, r, 1) == 0.0f && texture->GetArea(1, 1, l, r, 0) == 0.0f);
          EXPECT(texture->GetArea(0, 4, l, r, c) == 0.0f);
          EXPECT(texture->GetArea(4, 0, l, r, c) == 0.0f);
          if (e == 1 || e == 3)
          {
            EXPECT(texture->GetArea(4, e, l, r, c) == texture->GetArea(otherSide[e], e, l, r, c));
            EXPECT(texture->GetArea(e, 4, l, r, c) == texture->GetArea(e, otherSide[e], l, r, c));
          }
        }
      }
    }
  }

  // Mirror symmetry: swapping the ends (e1, left) <-> (e2, right) mirrors the pattern, and the
  // pixel at `left` becomes the pixel at `right`: same areas. Checked for every texel of several
  // sizes.
  for (int maxDistance : { 4, 8, 16, 31, 64 })
  {
    texture->SetMaxDistance(maxDistance);
    const int cell = texture->GetCellSize();
    for (int e1 = 0; e1 < 5; ++e1)
    {
      for (int e2 = 0; e2 < 5; ++e2)
      {
        for (int l = 0; l < cell; ++l)
        {
          for (int r = 0; r < cell; ++r)
          {
            for (int c = 0; c < 2; ++c)
            {
              EXPECT(texture->GetArea(e1, e2, l, r, c) == texture->GetArea(e2, e1, r, l, c));
            }
          }
        }
      }
    }
  }

  // L shapes follow the trapeze formula A = 1/2 (1 - (2p + 1) / L) for every pixel p that lies
  // wholly before the middle of the line (2 p + 2 <= L), p counted from the crossing edge; the
  // pixel that holds the middle of an odd line gets the triangle 1/(8 L); pixels past the
  // middle get nothing. Code 3 (crossing edge on the owning side) fills channel 0, code 1
  // (opposite side) channel 1.
  texture->SetMaxDistance(32);
  for (int l = 0; l <= 32; ++l)
  {
    for (int r = 0; r <= 32; ++r)
    {
      const int length = l + r + 1;
      double expected = 0.0;
      if (2 * l + 2 <= length)
      {
        expected = 0.5 * (1.0 - (2.0 * l + 1.0) / length);
      }
      else if (2 * l + 1 == length)
      {
        expected = 1.0 / (8.0 * length);
      }
      // Crossing edge at the left end, p = l.
      ExpectAreas(t, 3, 0, l, r, expected, 0.0, __LINE__);
      ExpectAreas(t, 1, 0, l, r, 0.0, expected, __LINE__);
      // Crossing edge at the right end: the same with p = r.
      ExpectAreas(t, 0, 3, r, l, expected, 0.0, __LINE__);
      ExpectAreas(t, 0, 1, r, l, 0.0, expected, __LINE__);
      // And the double-precision function agrees with the float table.
      double areas[2];
      vtkMLAAAreaTexture::ComputeAreas(3, 0, l, r, areas);
      EXPECT(Near(areas[0], expected, 1e-12) && areas[1] == 0.0);
    }
  }

  // Hand-computed texels (D = 17).
  texture->SetMaxDistance(16);
  // L: crossing edge on the owning side at the left end, line of 4 pixels:
  // the line falls from -1/2 at x = 0 to 0 at x = 2.
  EXPECT_AREAS(3, 0, 0, 3, 3.0 / 8.0, 0.0);  // mean height over [0, 1]: 3/8
  EXPECT_AREAS(3, 0, 1, 2, 1.0 / 8.0, 0.0);  // over [1, 2]: 1/8
  EXPECT_AREAS(3, 0, 2, 1, 0.0, 0.0);        // past the middle
  EXPECT_AREAS(3, 0, 2, 2, 1.0 / 40.0, 0.0); // line of 5: triangle of width 1/2, height 1/10
  EXPECT_AREAS(1, 0, 0, 0, 0.0, 1.0 / 8.0);  // line of 1: triangle 1/2 x 1/2 / 2
  // U: crossing edges on the owning side at both ends.
  EXPECT_AREAS(3, 3, 0, 0, 1.0 / 4.0, 0.0);  // line of 1: two triangles of 1/8
  EXPECT_AREAS(3, 3, 2, 2, 1.0 / 20.0, 0.0); // middle of a line of 5: two triangles of 1/40
  EXPECT_AREAS(3, 3, 0, 4, 2.0 / 5.0, 0.0);  // first pixel of a line of 5: 1/2 (1 - 1/5)
  EXPECT_AREAS(3, 3, 4, 0, 2.0 / 5.0, 0.0);  // last pixel, by symmetry
  EXPECT_AREAS(1, 1, 1, 2, 0.0, 1.0 / 8.0);  // U opening the other way, line of 4, p = 1
  // Z: owning side at the left end, opposite side at the right end: one straight line from
  // -1/2 to +1/2, crossing the edge in the middle.
  EXPECT_AREAS(3, 1, 0, 4, 2.0 / 5.0, 0.0);         // first pixel of 5
  EXPECT_AREAS(3, 1, 4, 0, 0.0, 2.0 / 5.0);         // last pixel of 5: on the other side
  EXPECT_AREAS(3, 1, 2, 2, 1.0 / 40.0, 1.0 / 40.0); // middle pixel: a triangle each side
  EXPECT_AREAS(1, 3, 1, 1, 1.0 / 24.0, 1.0 / 24.0); // line of 3, middle: 1/(8*3) each
  EXPECT_AREAS(3, 1, 1, 2, 1.0 / 8.0, 0.0);         // line of 4, second pixel
  EXPECT_AREAS(3, 1, 2, 1, 0.0, 1.0 / 8.0);         // line of 4, third pixel
  // The top outline of a run of a one-pixel-wide line rising to the right: crossing edge on the
  // own side at the left end (3), on both sides at the right end (4, the line goes on up): a Z.
  EXPECT_AREAS(3, 4, 0, 3, 3.0 / 8.0, 0.0);
  EXPECT_AREAS(3, 4, 3, 0, 0.0, 3.0 / 8.0);
  // Its bottom outline: both sides at the left end, opposite side at the right end.
  EXPECT_AREAS(4, 1, 0, 3, 3.0 / 8.0, 0.0);
  EXPECT_AREAS(4, 1, 2, 1, 0.0, 1.0 / 8.0);

  // Areas never exceed one half (a pixel is never more than half covered by a neighbour).
  texture->SetMaxDistance(64);
  const int fullSize = texture->GetTextureSize();
  const float* fullTable = texture->GetTable();
  for (int i = 0; i < fullSize * fullSize * 2; ++i)
  {
    if (!(fullTable[i] >= 0.0f && fullTable[i] <= 0.5f))
    {
      EXPECT(!"area within [0, 1/2]");
      break;
    }
  }

  // The 8-bit image: 3 components, red/green = round(255 area), blue 0; texel row t is image
  // row size - 1 - t, so that it reads as Figure 4.2 once written to a file.
  texture->SetMaxDistance(8);
  vtkImageData* image = texture->GetImage();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT(dims[0] == 45 && dims[1] == 45 && dims[2] == 1);
  EXPECT(image->GetScalarType() == VTK_UNSIGNED_CHAR);
  EXPECT(image->GetNumberOfScalarComponents() == 3);
  bool imageMatches = true;
  for (int tRow = 0; tRow < 45; ++tRow)
  {
    for (int s = 0; s < 45; ++s)
    {
      const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(s, 44 - tRow, 0));
      const float* areas = texture->GetTable() + 2 * (tRow * 45 + s);
      imageMatches = imageMatches && px[0] == std::lround(255.0 * areas[0]) &&
        px[1] == std::lround(255.0 * areas[1]) && px[2] == 0;
    }
  }
  EXPECT(imageMatches);
  // A texel known by hand: L, owning side, line of 4, first pixel: 3/8 -> 96.
  const auto* lTexel =
    static_cast<unsigned char*>(image->GetScalarPointer(9 * 3 + 0, 44 - (9 * 0 + 3), 0));
  EXPECT(lTexel[0] == 96 && lTexel[1] == 0);

  // Tables are shared per size.
  EXPECT(vtkMLAAAreaTexture::GetSharedTable(8) == vtkMLAAAreaTexture::GetSharedTable(8));
  EXPECT(vtkMLAAAreaTexture::GetSharedTable(8) != vtkMLAAAreaTexture::GetSharedTable(16));
  // A table that no one holds goes, but for the last one asked for where it is small (1 MB at
  // most): a process that uses many search lengths in turn keeps only the tables in use.
  {
    using Table = std::weak_ptr<const std::vector<float>>;
    const Table large = vtkMLAAAreaTexture::GetSharedTable(256); // 12.6 MB
    EXPECT(large.expired());
    const auto held = vtkMLAAAreaTexture::GetSharedTable(40);
    const Table last = vtkMLAAAreaTexture::GetSharedTable(6);
    EXPECT(!last.expired());
    const Table next = vtkMLAAAreaTexture::GetSharedTable(7);
    EXPECT(last.expired() && !next.expired());
    EXPECT(held == vtkMLAAAreaTexture::GetSharedTable(40));
    const Table diagonal = vtkMLAAAreaTexture::GetSharedDiagonalTable(256);
    EXPECT(diagonal.expired());
  }

  // The line moved by a sample's offset (across towards the opposite pixel, along towards the
  // second end), worked by hand.
  auto expectMoved = [](int e1, int e2, int left, int right, double across, double along,
                       double own, double opposite, int line) {
    double a[2];
    vtkMLAAAreaTexture::ComputeAreas(e1, e2, left, right, a, across, along);
    if (!Near(a[0], own) || !Near(a[1], opposite))
    {
      std::cerr << "line " << line << ": e1=" << e1 << " e2=" << e2 << " left=" << left
                << " right=" << right << " moved by (" << across << ", " << along << ") gives ("
                << a[0] << ", " << a[1] << "), expected (" << own << ", " << opposite << ")"
                << std::endl;
      ++Failures;
    }
  };
  // A straight line (no slope at either end) raised or lowered by 1/4: a quarter of the pixel
  // on one side, wherever the pixel is; moving it along changes nothing.
  expectMoved(0, 0, 3, 5, 0.25, 0.0, 0.0, 0.25, __LINE__);
  expectMoved(0, 0, 3, 5, -0.25, 0.375, 0.25, 0.0, __LINE__);
  // L of one pixel (height 1/2 at x = 0 falling to 0 at x = 1/2; unmoved: 1/8 above).
  expectMoved(1, 0, 0, 0, 0.0, 0.0, 0.0, 0.125, __LINE__);
  // Raised by 1/4: 3/4 to 1/4 over the first half, 1/4 over the second: 1/4 + 1/8.
  expectMoved(1, 0, 0, 0, 0.25, 0.0, 0.0, 0.375, __LINE__);
  // Lowered by 1/4: crosses the edge at x = 1/4: 1/32 above, 1/32 + 1/8 below.
  expectMoved(1, 0, 0, 0, -0.25, 0.0, 0.15625, 0.03125, __LINE__);
  // Moved along by 1/4: the slope continues past the end (3/4 at x = 0), reaching 0 at
  // x = 3/4: (3/4)^2 / 2 above.
  expectMoved(1, 0, 0, 0, 0.0, 0.25, 0.0, 0.28125, __LINE__);
  // Moved by 1/2 both ways: height 3/2 - x, clamped to one pixel: 1/2 + 3/8 above.
  expectMoved(1, 0, 0, 0, 0.5, 0.5, 0.0, 0.875, __LINE__);
  // The middle pixel of an L of 5 (code 3, below the edge), moved along by 1/8: the line
  // -(1/2)(1 - x / 2.5), which reaches the edge at the middle x = 2.5, becomes
  // -(1/2)(1 - (x - 1/8) / 2.5) and reaches it at x = 2.625: a triangle over [2, 2.625].
  {
    const double h = [](double x) { return -0.5 * (1.0 - (x - 0.125) / 2.5); }(2.0);
    expectMoved(3, 0, 2, 2, 0.0, 0.125, 0.5 * -h * 0.625, 0.0, __LINE__);
  }
  // Unmoved, the same areas as the table; the tables of no offset are the usual one (shared),
  // of an offset another one, and offsets are clamped to half a pixel.
  double unmoved[2], plain[2];
  vtkMLAAAreaTexture::ComputeAreas(3, 1, 2, 5, unmoved, 0.0, 0.0);
  vtkMLAAAreaTexture::ComputeAreas(3, 1, 2, 5, plain);
  EXPECT(unmoved[0] == plain[0] && unmoved[1] == plain[1]);
  EXPECT(vtkMLAAAreaTexture::GetSharedTable(8, 0.0, 0.0) == vtkMLAAAreaTexture::GetSharedTable(8));
  EXPECT(vtkMLAAAreaTexture::GetSharedTable(8, 0.125, -0.375) !=
    vtkMLAAAreaTexture::GetSharedTable(8));
  EXPECT(vtkMLAAAreaTexture::GetSharedTable(8, 0.9, 0.0) ==
    vtkMLAAAreaTexture::GetSharedTable(8, 0.5, 0.0));
  {
    // A moved table holds ComputeAreas of its offsets, texel for texel.
    const auto held = vtkMLAAAreaTexture::GetSharedTable(8, 0.125, -0.375);
    const std::vector<float>& moved = *held;
    const int size = vtkMLAAAreaTexture::NumberOfCodes * 9;
    bool same = true;
    for (int e1 : { 0, 1, 3, 4 })
    {
      for (int e2 : { 0, 1, 3, 4 })
      {
        for (int left = 0; left < 9; ++left)
        {
          for (int right = 0; right < 9; ++right)
          {
            double a[2];
            vtkMLAAAreaTexture::ComputeAreas(e1, e2, left, right, a, 0.125, -0.375);
            const size_t texel = static_cast<size_t>(9 * e2 + right) * size + (9 * e1 + left);
            same = same && moved[2 * texel] == static_cast<float>(a[0]) &&
              moved[2 * texel + 1] == static_cast<float>(a[1]);
          }
        }
      }
    }
    EXPECT(same);
  }

  // Diagonal areas, worked by hand: (in, before, after) = ((1/2 + s)^2 / 2 at the unit's middle,
  // (1/2 - s)^2 / 2 at its two ends), s the revectorised line's shift.
  auto expectDiagonal = [](int e1, int e2, int d1, int d2, double in, double before,
                          double after, int line) {
    double a[3];
    vtkMLAAAreaTexture::ComputeDiagonalAreas(e1, e2, d1, d2, a);
    if (!Near(a[0], in) || !Near(a[1], before) || !Near(a[2], after))
    {
      std::cerr << "line " << line << ": diagonal e1=" << e1 << " e2=" << e2 << " d1=" << d1
                << " d2=" << d2 << " gives (" << a[0] << ", " << a[1] << ", " << a[2]
                << "), expected (" << in << ", " << before << ", " << after << ")" << std::endl;
      ++Failures;
    }
  };
  // No end tells a shift: the 45-degree line through the edgels' middles, 1/8 on each side, as
  // the orthogonal search gives a pure staircase.
  expectDiagonal(0, 0, 0, 0, 0.125, 0.125, 0.125, __LINE__);
  expectDiagonal(0, 0, 5, 9, 0.125, 0.125, 0.125, __LINE__);
  // Z of 4 units (out at the first end, in at the second), first unit: s = -3/8 at its middle,
  // -1/2 and -1/4 at its ends.
  expectDiagonal(1, 2, 0, 3, 0.0078125, 0.5, 0.28125, __LINE__);
  // Z of 3 units, middle unit: s = 0 at its middle, -1/6 and +1/6 at its ends.
  expectDiagonal(1, 2, 1, 1, 0.125, 2.0 / 9.0, 1.0 / 18.0, __LINE__);
  // U of one unit into the pixel: s = 0 in the middle, +1/2 at both ends.
  expectDiagonal(2, 2, 0, 0, 0.125, 0.0, 0.0, __LINE__);
  // One end only ("L" along the diagonal), second half of 2 units: s = +1/4 at the middle of the
  // second unit, 0 and +1/2 at its ends.
  expectDiagonal(0, 2, 1, 0, 0.28125, 0.125, 0.0, __LINE__);
  // Mirror symmetry: swapping the ends swaps the two other-side pixels.
  bool diagonalMirror = true;
  for (int e1 = 0; e1 < 3; ++e1)
  {
    for (int e2 = 0; e2 < 3; ++e2)
    {
      for (int d1 = 0; d1 <= 16; ++d1)
      {
        for (int d2 = 0; d2 <= 16; ++d2)
        {
          double a[3], b[3];
          vtkMLAAAreaTexture::ComputeDiagonalAreas(e1, e2, d1, d2, a);
          vtkMLAAAreaTexture::ComputeDiagonalAreas(e2, e1, d2, d1, b);
          diagonalMirror = diagonalMirror && Near(a[0], b[0], 1e-12) &&
            Near(a[1], b[2], 1e-12) && Near(a[2], b[1], 1e-12);
        }
      }
    }
  }
  EXPECT(diagonalMirror);
  // The shared diagonal table: 3 x 3 cells of D x D texels, three areas each.
  auto diagonal = vtkMLAAAreaTexture::GetSharedDiagonalTable(16);
  EXPECT(diagonal->size() == static_cast<size_t>(51 * 51 * 3));
  EXPECT(diagonal == vtkMLAAAreaTexture::GetSharedDiagonalTable(16));
  bool diagonalLayout = true;
  for (int t = 0; t < 51; ++t)
  {
    for (int s = 0; s < 51; ++s)
    {
      double a[3];
      vtkMLAAAreaTexture::ComputeDiagonalAreas(s / 17, t / 17, s % 17, t % 17, a);
      for (int c = 0; c < 3; ++c)
      {
        diagonalLayout = diagonalLayout && Near((*diagonal)[3 * (t * 51 + s) + c], a[c]);
      }
    }
  }
  EXPECT(diagonalLayout);

  if (Failures)
  {
    std::cerr << Failures << " failure(s)" << std::endl;
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
