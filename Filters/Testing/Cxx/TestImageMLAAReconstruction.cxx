// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Topological reconstruction (vtkMLAAOptions::Reconstruction, Biri et al. section 4), in the
// reconstruction stage alone (exact pixels) and through vtkImageMLAA:
// - a one-pixel diagonal line with one pixel missing is closed (the pixel gets the line's
//   colour) and nothing else changes; a line end, an isolated dot, a corner and a thin line
//   crossing another (of the same or another colour) are left alone;
// - the mean is over the unlike neighbours, all components, alpha included, rounded to nearest;
//   a change in alpha alone makes a neighbour unlike; non-finite pixels are never unlike;
// - the rule's caveats (vtkMLAATopology) hold as documented;
// - through the filter, the gapped line gives exactly the output of the closed line, and the
//   restored pixel is in the output even with no edge anywhere; off by default, and off changes
//   nothing; streamed equals unstreamed; the halo grows by one.
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

void ClosesTheGapOnly()
{
  for (int components = 1; components <= 4; ++components)
  {
    auto gapped = ShapesImage(VTK_UNSIGNED_CHAR, components, true);
    auto closed = ShapesImage(VTK_UNSIGNED_CHAR, components, false);
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
    MLAA_CHECK(Compare(out, closed).Count == 0);
    // The closed line is left as it is.
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
  MLAA_CHECK(GetValue(out, 6, 3) == Ink);

  auto ell = MakeImage(12, 12, 1, VTK_UNSIGNED_CHAR, Background);
  FillImage(ell, [](int x, int y, int, int) {
    return ((y == 3 && x >= 3 && x <= 9) || (x == 3 && y >= 3 && y <= 9)) ? Ink : Background;
  });
  auto ellOut = ReconstructOnly<unsigned char>(ell);
  const auto ellChanged = Changed(ell, ellOut);
  MLAA_CHECK(ellChanged.empty());
}

void MeanAndAlpha()
{
  // A = (5, 5) between (6, 6) and (4, 4), two pixels of slightly different colours (Delta E
  // and alpha difference below the threshold, so one colour), the rest in the background. A
  // becomes their mean, rounded to nearest, every component.
  auto image = MakeImage(12, 12, 4, VTK_UNSIGNED_CHAR);
  FillImage(image, [](int x, int y, int, int k) {
    if (x == 6 && y == 6)
    {
      return std::vector<double>{ 200, 100, 51, 255 }[k];
    }
    if (x == 4 && y == 4)
    {
      return std::vector<double>{ 203, 100, 50, 250 }[k];
    }
    return std::vector<double>{ 20, 30, 40, 255 }[k];
  });
  auto out = ReconstructOnly<unsigned char>(image);
  const auto changed = Changed(image, out);
  MLAA_CHECK(changed.size() == 1 && changed[0] == std::make_pair(5, 5));
  const double expected[4] = { 202, 100, 51, 253 }; // 201.5, 100, 50.5, 252.5 rounded
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
  MLAA_CHECK(GetValue(alphaOut, 9, 9, 1) == 0.0 && GetValue(alphaOut, 9, 9, 0) == 128.0);

  // Floating point: a NaN in place of the missing pixel's neighbour is never unlike anything,
  // and a NaN pixel itself is never replaced.
  auto real = MakeImage(20, 20, 3, VTK_FLOAT);
  FillImage(real, [](int x, int y, int, int) { return (x == y && x != 9) ? 0.9 : 0.1; });
  auto realOut = ReconstructOnly<float>(real, 0.1, 0.0, 1.0);
  MLAA_CHECK(Changed(real, realOut).size() == 1 && GetValue(realOut, 9, 9, 0) == 0.9f);
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
  MLAA_CHECK(halo.Reconstruction == 1);
  MLAA_CHECK(halo.Total() == vtkMLAAStages::ComputeHalo(defaults).Total() + 1);
  auto restored = RunMLAA(gapped, on);
  MLAA_CHECK(Compare(restored, RunMLAA(closed, on)).Count == 0);
  MLAA_CHECK(Compare(restored, RunMLAA(closed)).Count == 0);
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
  MLAA_CHECK(Compare(depthFilter->GetOutput(), closed).Count == 0);

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
}

int TestImageMLAAReconstruction(int, char*[])
{
  ClosesTheGapOnly();
  StraightGapAndThinCorner();
  MeanAndAlpha();
  ThroughTheFilter();
  return Result();
}
