// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Topological reconstruction (vtkMLAAOptions::Reconstruction, Biri et al. section 4), in the
// reconstruction stage alone (exact pixels) and through vtkImageMLAA:
// - a one-pixel diagonal line with one pixel missing is closed by coverage (the pixel moves
//   towards the line's colour by the share vtkMLAATopology's coverage rule gives: 3/7 for a
//   gap with six pixels of the line in its 7 x 7 window) and nothing else changes; a line end,
//   an isolated dot, a corner and a thin line crossing another (of the same or another colour)
//   are left alone, and so is a pixel between two lines passing close by (more pixels of the
//   shape's colour in the window than one thin line has);
// - the mean is over the unlike neighbours, all components, alpha included, rounded to nearest;
//   a change in alpha alone makes a neighbour unlike; non-finite pixels are never unlike;
// - the rule's caveats (vtkMLAATopology) hold as documented;
// - through the filter, the output is MLAA's on the reconstructed image, and the restored pixel
//   is in the output even with no edge anywhere; off by default, and off changes nothing;
//   streamed equals unstreamed; the halo grows by vtkMLAATopology::ReconstructionReach;
// - against supersampled thin lines (widths under a pixel, eight angles), reconstruction brings
//   the antialiased picture closer to the reference, the gap pixels closer than the full
//   colour the paper's rule gives them would, and the lit pixels that the thin line rule
//   lightens (beside gaps, on lines up to half a pixel dense) closer than their full colour.
#include "vtkAntialiasingTestUtilities.h"

#include "vtkImageDataStreamer.h"
#include "vtkMLAAStages.h"

#include <limits>

using namespace vtkMLAATest;

namespace
{
constexpr int W = 48;
constexpr int H = 40;
constexpr double Background = 40.0;
constexpr double Ink = 220.0;

// The reconstruction stage alone on a whole 2D image of type T (values as doubles).
template <typename T>
vtkSmartPointer<vtkImageData> ReconstructOnly(vtkImageData* input, double threshold = 0.1,
  double lo = 0.0, double hi = 255.0)
{
  int ext[6];
  input->GetExtent(ext);
  const int c = input->GetNumberOfScalarComponents();
  vtkMLAAStages::SliceSetup setup;
  setup.Whole = setup.Input = setup.Output = { ext[0], ext[1], ext[2], ext[3] };
  vtkNew<vtkMLAAOptions> options;
  options->SetThreshold(threshold);
  options->ReconstructionOn();
  vtkMLAAStages::ConfigureSlice(options, c, lo, hi, setup);
  vtkIdType increments[3];
  input->GetIncrements(increments);
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(input);
  vtkMLAAStages::Progress progress;
  vtkMLAAStages::Reconstruct<T>(setup.GetReconstruction(), static_cast<const T*>(input->GetScalarPointer()),
    increments[1], static_cast<T*>(output->GetScalarPointer()), progress);
  return output;
}

// The pixels where two images differ.
std::vector<std::pair<int, int>> Changed(vtkImageData* a, vtkImageData* b)
{
  std::vector<std::pair<int, int>> changed;
  int dims[3];
  a->GetDimensions(dims);
  const int c = a->GetNumberOfScalarComponents();
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool differs = false;
      for (int k = 0; k < c; ++k)
      {
        const double va = GetValue(a, x, y, k);
        const double vb = GetValue(b, x, y, k);
        differs = differs || !(va == vb || (std::isnan(va) && std::isnan(vb)));
      }
      if (differs)
      {
        changed.emplace_back(x, y);
      }
    }
  }
  return changed;
}

// A grey picture with thin shapes: a diagonal line (5, 5) to (17, 17) with (11, 11) missing,
// an isolated dot, a filled square (its corners), a "+" crossing of two lines, and another "+"
// of two colours; and (StraightGapAndThinCorner) the gap in a straight line is closed and a thin
// L's corner kept.
bool Shapes(int x, int y, bool gap, double& v)
{
  v = Background;
  if (x == y && x >= 5 && x <= 17 && !(gap && x == 11))
  {
    v = Ink;
  }
  if (x == 30 && y == 6)
  {
    v = Ink; // dot
  }
  if (x >= 6 && x <= 14 && y >= 26 && y <= 34)
  {
    v = Ink; // a filled square: four corners
  }
  if ((y == 20 && x >= 24 && x <= 34) || (x == 29 && y >= 15 && y <= 25))
  {
    v = Ink; // crossing
  }
  if (y == 12 && x >= 34 && x <= 44)
  {
    v = Ink; // a second crossing: this line in ink, the other in a dark grey
  }
  else if (x == 39 && y >= 7 && y <= 17)
  {
    v = 120.0;
  }
  return true;
}

vtkSmartPointer<vtkImageData> ShapesImage(int type, int components, bool gap)
{
  auto image = MakeImage(W, H, components, type);
  FillImage(image, [&](int x, int y, int, int k) {
    double v;
    Shapes(x, y, gap, v);
    if ((components == 2 || components == 4) && k == components - 1)
    {
      return 255.0; // opaque
    }
    return v;
  });
  return image;
}

// Background + 3/7 (Ink - Background) rounded: a gap in a one-pixel line with six pixels of
// the line in its window (coverage 6 / (2 * 7)).
constexpr double ThreeSevenths = 117.0;

void ClosesTheGapOnly()
{
  MLAA_CHECK(vtkMLAATopology::CoverageRadius == 3);
  MLAA_CHECK(vtkMLAATopology::GetCoverage(6) == 6.0 / 14.0);
  MLAA_CHECK(vtkMLAATopology::GetCoverage(7) == 0.5);
  MLAA_CHECK(vtkMLAATopology::GetCoverage(8) == 0.0 && vtkMLAATopology::GetCoverage(0) == 0.0);
  // The thin line rule: lines up to half a pixel wide (up to 3 of 7 pixels lit).
  MLAA_CHECK(vtkMLAATopology::GetLineShare(1) == 1.0 / 7.0);
  MLAA_CHECK(vtkMLAATopology::GetLineShare(3) == 3.0 / 7.0);
  MLAA_CHECK(vtkMLAATopology::GetLineShare(4) == 1.0 && vtkMLAATopology::GetLineShare(0) == 1.0);
  MLAA_CHECK(vtkMLAATopology::ReconstructionReach == vtkMLAATopology::CoverageRadius + 1);
  for (int n = 0; n < vtkMLAATopology::CoverageTableSize; ++n)
  {
    MLAA_CHECK(vtkMLAATopology::GetCoverageTable()[n] ==
      static_cast<float>(vtkMLAATopology::GetCoverage(n)));
    MLAA_CHECK(vtkMLAATopology::GetLineShareTable()[n] ==
      static_cast<float>(vtkMLAATopology::GetLineShare(n)));
  }
  for (int components = 1; components <= 4; ++components)
  {
    auto gapped = ShapesImage(VTK_UNSIGNED_CHAR, components, true);
    auto out = ReconstructOnly<unsigned char>(gapped);
    const auto changed = Changed(gapped, out);
    if (!MLAA_CHECK(changed.size() == 1 && changed[0] == std::make_pair(11, 11)))
    {
      for (const auto& p : changed)
      {
        std::cerr << components << " components: (" << p.first << ", " << p.second
                  << ") changed" << std::endl;
      }
    }
    const int colours = (components == 2 || components == 4) ? components - 1 : components;
    for (int k = 0; k < components; ++k)
    {
      MLAA_CHECK(GetValue(out, 11, 11, k) == (k < colours ? ThreeSevenths : 255.0));
    }
    // The closed line is left as it is.
    auto closed = ShapesImage(VTK_UNSIGNED_CHAR, components, false);
    MLAA_CHECK(Compare(ReconstructOnly<unsigned char>(closed), closed).Count == 0);
  }
}

void StraightGapAndThinCorner()
{
  // vtkMLAATopology's additions to the paper's rule: a gap in a straight one-pixel line is
  // closed and nothing else changes (the paper's rule alone left the gap and filled the two
  // pixels beside it); the corner pixel of a one-pixel-wide L is left alone (the paper's rule
  // gave it the background's colour).
  auto straight = MakeImage(12, 7, 1, VTK_UNSIGNED_CHAR, Background);
  FillImage(straight, [](int x, int y, int, int) {
    return (y == 3 && x >= 1 && x <= 10 && x != 6) ? Ink : Background;
  });
  auto out = ReconstructOnly<unsigned char>(straight);
  const auto changed = Changed(straight, out);
  MLAA_CHECK(changed.size() == 1 && changed[0] == std::make_pair(6, 3));
  MLAA_CHECK(GetValue(out, 6, 3) == ThreeSevenths);

  auto ell = MakeImage(12, 12, 1, VTK_UNSIGNED_CHAR, Background);
  FillImage(ell, [](int x, int y, int, int) {
    return ((y == 3 && x >= 3 && x <= 9) || (x == 3 && y >= 3 && y <= 9)) ? Ink : Background;
  });
  auto ellOut = ReconstructOnly<unsigned char>(ell);
  const auto ellChanged = Changed(ell, ellOut);
  MLAA_CHECK(ellChanged.empty());

  // Two parallel diagonal lines (x + y = 18 and 22): every background pixel on x + y = 20
  // between them sees one line at NE and the other at SW, a diagonal gap to the paper's rule
  // and ours, but its window holds pixels of both lines, more of the shape's colour than one
  // thin line has (10 of 48 in the middle): these pixels are no gaps and keep their colour.
  auto pair = MakeImage(24, 24, 1, VTK_UNSIGNED_CHAR, Background);
  FillImage(pair, [](int x, int y, int, int) {
    return (x + y == 18 || x + y == 22) ? Ink : Background;
  });
  MLAA_CHECK(vtkMLAATopology::IsSelected((1 << 1) | (1 << 5))); // NE and SW
  auto pairOut = ReconstructOnly<unsigned char>(pair);
  MLAA_CHECK(Changed(pair, pairOut).empty());
}

void MeanAndAlpha()
{
  // A = (5, 5) between (6, 6) and (4, 4), two pixels of slightly different colours (Delta E
  // and alpha difference below the threshold, so one colour), the rest in the background. A
  // moves towards their mean, every component, by the coverage of two shape pixels in its
  // window (2/14), rounded to nearest.
  auto image = MakeImage(12, 12, 4, VTK_UNSIGNED_CHAR);
  FillImage(image, [](int x, int y, int, int k) {
    if (x == 6 && y == 6)
    {
      return std::vector<double>{ 200, 100, 51, 255 }[k];
    }
    if (x == 4 && y == 4)
    {
      return std::vector<double>{ 203, 101, 50, 250 }[k];
    }
    return std::vector<double>{ 20, 30, 41, 255 }[k];
  });
  auto out = ReconstructOnly<unsigned char>(image);
  const auto changed = Changed(image, out);
  MLAA_CHECK(changed.size() == 1 && changed[0] == std::make_pair(5, 5));
  // The mean (201.5, 100.5, 50.5, 252.5); 20 + 181.5 / 7, 30 + 70.5 / 7, 41 + 9.5 / 7 and
  // 255 - 2.5 / 7 rounded.
  const double expected[4] = { 46, 40, 42, 255 };
  for (int k = 0; k < 4; ++k)
  {
    MLAA_CHECK(GetValue(out, 5, 5, k) == expected[k]);
  }

  // Alpha alone: the same colour everywhere, the diagonal line transparent in an opaque image.
  auto alpha = MakeImage(20, 20, 2, VTK_UNSIGNED_CHAR);
  FillImage(alpha, [](int x, int y, int, int k) {
    return k == 0 ? 128.0 : ((x == y && x != 9) ? 0.0 : 255.0);
  });
  auto alphaOut = ReconstructOnly<unsigned char>(alpha);
  const auto alphaChanged = Changed(alpha, alphaOut);
  MLAA_CHECK(alphaChanged.size() == 1 && alphaChanged[0] == std::make_pair(9, 9));
  // Six pixels of the line in the window: 255 - 3/7 255 = 145.7.
  MLAA_CHECK(GetValue(alphaOut, 9, 9, 1) == 146.0 && GetValue(alphaOut, 9, 9, 0) == 128.0);

  // Floating point: a NaN in place of the missing pixel's neighbour is never unlike anything,
  // and a NaN pixel itself is never replaced.
  auto real = MakeImage(20, 20, 3, VTK_FLOAT);
  FillImage(real, [](int x, int y, int, int) { return (x == y && x != 9) ? 0.9 : 0.1; });
  auto realOut = ReconstructOnly<float>(real, 0.1, 0.0, 1.0);
  MLAA_CHECK(Changed(real, realOut).size() == 1 &&
    std::abs(GetValue(realOut, 9, 9, 0) - (0.1 + 0.8 * 3.0 / 7.0)) < 1e-6);
  real->GetPointData()->GetScalars()->SetComponent(10 * 20 + 10, 1, std::nan(""));
  realOut = ReconstructOnly<float>(real, 0.1, 0.0, 1.0);
  MLAA_CHECK(Changed(real, realOut).empty());
  real->GetPointData()->GetScalars()->SetComponent(10 * 20 + 10, 1, 0.9);
  real->GetPointData()->GetScalars()->SetComponent(9 * 20 + 9, 0, std::nan(""));
  realOut = ReconstructOnly<float>(real, 0.1, 0.0, 1.0);
  MLAA_CHECK(Changed(real, realOut).empty());
}

void ThroughTheFilter()
{
  auto gapped = ShapesImage(VTK_UNSIGNED_CHAR, 3, true);
  auto closed = ShapesImage(VTK_UNSIGNED_CHAR, 3, false);

  // Off by default, and off changes nothing.
  vtkNew<vtkMLAAOptions> defaults;
  MLAA_CHECK(!defaults->GetReconstruction());
  MLAA_CHECK(vtkMLAAStages::ComputeHalo(defaults).Reconstruction == 0);
  auto plain = RunMLAA(gapped);
  MLAA_CHECK(Compare(RunMLAA(gapped, defaults), plain).Count == 0);
  MLAA_CHECK(GetValue(plain, 11, 11) == Background);

  vtkNew<vtkMLAAOptions> on;
  on->ReconstructionOn();
  const vtkMLAAStages::Halo halo = vtkMLAAStages::ComputeHalo(on);
  MLAA_CHECK(halo.Total() ==
    vtkMLAAStages::ComputeHalo(defaults).Total() + vtkMLAATopology::ReconstructionReach);
  MLAA_CHECK(halo.Reconstruction == vtkMLAATopology::ReconstructionReach);
  // The filter's output is MLAA's on the reconstructed image.
  auto reconstructed = ReconstructOnly<unsigned char>(gapped);
  auto restored = RunMLAA(gapped, on);
  MLAA_CHECK(Compare(restored, RunMLAA(reconstructed)).Count == 0);
  MLAA_CHECK(Compare(restored, plain).Count > 0);
  MLAA_CHECK(GetValue(restored, 11, 11) != Background);

  // The reconstructed image is the output where no edge is found: depth edges on a flat depth
  // image find none, and the output is the reconstruction stage's result.
  auto flatDepth = MakeImage(W, H, 1, VTK_FLOAT, 0.5);
  vtkNew<vtkMLAAOptions> depthOptions;
  depthOptions->ReconstructionOn();
  depthOptions->SetEdgeDetectionToDepth();
  vtkNew<vtkImageMLAA> depthFilter;
  depthFilter->SetOptions(depthOptions);
  depthFilter->SetInputData(gapped);
  depthFilter->SetDepthInputData(flatDepth);
  depthFilter->Update();
  MLAA_CHECK(Compare(depthFilter->GetOutput(), reconstructed).Count == 0);

  // Streamed equals unstreamed, and the number of threads does not matter.
  on->SetEdgeDetectionToLab();
  auto whole = RunMLAA(gapped, on);
  for (int divisions : { 2, 5, 13 })
  {
    for (int mode = 0; mode < 3; ++mode)
    {
      vtkNew<vtkImageMLAA> streamed;
      streamed->SetOptions(on);
      streamed->SetInputData(gapped);
      vtkNew<vtkImageDataStreamer> streamer;
      streamer->SetInputConnection(streamed->GetOutputPort());
      streamer->SetNumberOfStreamDivisions(divisions);
      SetSplitMode(streamer->GetExtentTranslator(), mode);
      streamer->Update();
      const Difference d = Compare(whole, streamer->GetOutput());
      if (!MLAA_CHECK(d.Count == 0))
      {
        std::cerr << divisions << " pieces, split mode " << mode << ": " << d.Pixels
                  << " pixels differ" << std::endl;
      }
    }
  }
  vtkSMPTools::Initialize(1);
  auto oneThread = RunMLAA(gapped, on);
  vtkSMPTools::Initialize(2);
  MLAA_CHECK(Compare(whole, oneThread).Count == 0);
}
// A line `width` pixels wide at `degrees` through the middle of a W x H image, ink on the
// background: point-sampled (ink where a pixel's centre lies within width / 2 of the line, as a
// renderer samples it) and the reference, each pixel's coverage by 16 x 16 samples.
void ThinLine(double width, double degrees, vtkImageData* sampled, vtkImageData* reference)
{
  const double pi = std::acos(-1.0);
  const double nx = -std::sin(degrees * pi / 180.0);
  const double ny = std::cos(degrees * pi / 180.0);
  const double cx = 0.5 * W + 0.31; // off the pixel grid
  const double cy = 0.5 * H + 0.17;
  auto inside = [&](double x, double y) {
    return std::abs((x - cx) * nx + (y - cy) * ny) <= 0.5 * width;
  };
  FillImage(sampled, [&](int x, int y, int, int) {
    return inside(x + 0.5, y + 0.5) ? Ink : Background;
  });
  constexpr int S = 16;
  FillImage(reference, [&](int x, int y, int, int) {
    int covered = 0;
    for (int j = 0; j < S; ++j)
    {
      for (int i = 0; i < S; ++i)
      {
        covered += inside(x + (i + 0.5) / S, y + (j + 0.5) / S) ? 1 : 0;
      }
    }
    return Background + (Ink - Background) * covered / (S * S);
  });
}

// The sum over all pixels of |a - b|.
double AbsoluteError(vtkImageData* a, vtkImageData* b)
{
  int dims[3];
  a->GetDimensions(dims);
  double sum = 0.0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      sum += std::abs(GetValue(a, x, y) - GetValue(b, x, y));
    }
  }
  return sum;
}

void AgainstSupersampledLines()
{
  // Lines under a pixel wide break into pieces when point-sampled; reconstruction fills the
  // gaps with the share of ink the line's density implies. Over every gap it fills, that share
  // is closer to the supersampled line than the gap left open and than the full ink of the
  // paper's rule; on lines up to half a pixel wide the lit pixels beside the gaps keep the
  // line's share of the ink, which is closer to the reference than their full ink; and the
  // antialiased picture as a whole comes closer to the reference.
  int filledLines = 0, lightenedLines = 0;
  for (double width : { 0.35, 0.55, 0.75 })
  {
    for (double degrees : { 4.0, 11.0, 24.0, 38.0, 52.0, 66.0, 79.0, 86.0 })
    {
      auto sampled = MakeImage(W, H, 1, VTK_UNSIGNED_CHAR);
      auto reference = MakeImage(W, H, 1, VTK_UNSIGNED_CHAR);
      ThinLine(width, degrees, sampled, reference);
      auto reconstructed = ReconstructOnly<unsigned char>(sampled);
      double open = 0.0, coverage = 0.0, full = 0.0, lit = 0.0, share = 0.0;
      int gaps = 0, litPixels = 0;
      for (const auto& p : Changed(sampled, reconstructed))
      {
        const double r = GetValue(reference, p.first, p.second);
        const double before = GetValue(sampled, p.first, p.second);
        const double after = GetValue(reconstructed, p.first, p.second);
        if (before == Ink)
        {
          // A lit pixel of the line beside a gap (the thin line rule): it keeps 1, 2 or 3
          // sevenths of the ink (the line's density), the rest going to the background.
          bool sevenths = false;
          for (int k = 1; k <= 3; ++k)
          {
            sevenths = sevenths || std::abs(after - (Background + k * (Ink - Background) / 7.0)) <= 0.5;
          }
          MLAA_CHECK(sevenths);
          lit += std::abs(before - r);
          share += std::abs(after - r);
          ++litPixels;
          continue;
        }
        open += std::abs(before - r);
        coverage += std::abs(after - r);
        full += std::abs(Ink - r);
        ++gaps;
      }
      if (litPixels > 0)
      {
        std::cout << "width " << width << ", " << degrees << " degrees: " << litPixels
                  << " lit pixels lightened; error over them full ink " << lit
                  << ", line share " << share << std::endl;
        ++lightenedLines;
        MLAA_CHECK(share < lit);
      }
      vtkNew<vtkMLAAOptions> on;
      on->ReconstructionOn();
      const double withIt = AbsoluteError(RunMLAA(sampled, on), reference);
      const double without = AbsoluteError(RunMLAA(sampled), reference);
      std::cout << "width " << width << ", " << degrees << " degrees: " << gaps
                << " gaps filled; error over them open " << open << ", coverage " << coverage
                << ", full ink " << full << "; whole picture with reconstruction " << withIt
                << ", without " << without << std::endl;
      if (gaps == 0)
      {
        MLAA_CHECK(withIt == without);
        continue;
      }
      ++filledLines;
      MLAA_CHECK(coverage < open);
      MLAA_CHECK(coverage < full);
      MLAA_CHECK(withIt < without);
    }
  }
  // Most of these lines have gaps that the rule fills; the thinnest, lit pixels it lightens.
  MLAA_CHECK(filledLines >= 12);
  MLAA_CHECK(lightenedLines >= 2);
}
}

// Floating-point values so large that the sum of two overflows (found by the filter's fuzz
// target: a finite image gave -inf): the same gap as above, in a line of the most negative
// values over a mid-grey background, is filled with the same share of the line's value, and
// every output value stays finite and within the input's values.
void HugeValues()
{
  const double big = 0.9 * std::numeric_limits<double>::max();
  auto image = MakeImage(W, H, 3, VTK_DOUBLE);
  FillImage(image, [&](int x, int y, int, int) {
    double v;
    Shapes(x, y, true, v);
    return v == Background ? 0.5 : (v == Ink ? -big : 0.0);
  });
  auto out = ReconstructOnly<double>(image, 0.1, 0.0, 1.0);
  bool finite = true;
  for (int y = 0; y < H; ++y)
  {
    for (int x = 0; x < W; ++x)
    {
      for (int k = 0; k < 3; ++k)
      {
        const double v = GetValue(out, x, y, k);
        finite = finite && std::isfinite(v) && v >= -big && v <= 0.5;
      }
    }
  }
  MLAA_CHECK(finite);
  // 6/14 of the way from the background to the line.
  const double filled = GetValue(out, 11, 11, 0);
  const double expected = 0.5 + 3.0 / 7.0 * (-big - 0.5);
  if (!MLAA_CHECK(std::abs(filled - expected) <= 1e-12 * big))
  {
    std::cerr << "huge values: the gap became " << filled << ", not " << expected << std::endl;
  }
}

int TestImageMLAAReconstruction(int, char*[])
{
  HugeValues();
  ClosesTheGapOnly();
  StraightGapAndThinCorner();
  MeanAndAlpha();
  ThroughTheFilter();
  AgainstSupersampledLines();
  return Result();
}
