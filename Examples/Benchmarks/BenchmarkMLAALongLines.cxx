// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-long-lines: AAR and damage (shared/docs/MEASURING.md) of vtkImageMLAA on a synthetic set
// of long, nearly horizontal and nearly vertical straight edges, with no rendering.
//
// The set is drawn from a seeded generator (the same images on every run and machine): each image
// is a background and a few convex quadrilaterals painted in order, all rotated by small angles
// (log-uniform between 0.05 and 5 degrees, either sign) from one axis, horizontal or vertical
// (alternating). Families, in turn:
//   halfplane  one half-plane whose edge crosses the image;
//   rects      three rectangles, 60 to 400 pixels a side, whose corners lie in the image;
//   strips     four strips 3 to 24 pixels wide and 150 to 480 long;
//   bars       five thin bars 1 to 3 pixels wide and 150 to 480 long;
// colours at contrasts (largest channel difference) of 255, 160, 80 and 30 levels.
// Per image:
//   none       one sample at each pixel centre (the aliased input);
//   reference  the exact 8 x 8 stratified samples of each pixel, averaged (double precision);
// and per configuration of the filter, AAR over E (none and reference differ by more than 4/255)
// and damage over F (pixels farther than 2 pixels from E, changed by more than 4/255), as
// mlaa-quality computes them. Reported per configuration: the AAR of the pooled squared errors,
// the mean AAR over the images, the damage pooled over all F pixels, the shares of the remaining
// error in E pixels the filter left unchanged, in those with no edge found at their boundaries,
// along stepless sides, sides with one step and the end runs of other sides (ClassifyRuns), the
// AAR along sides with two steps or more, per family and per contrast.
//
// Configurations: the four presets, and the high preset with 32, 64 and 128 search steps; with
// MLAA settings on the command line, those settings instead ("given").
// --per-image lists AAR, the untouched and missed shares and the damaged pixels of every image.
// --output-dir DIR writes, per image, none.png, reference.png and, for the configuration named by
// --dump (default P-ultra), out.png and damage.png (grey: the input dimmed; blue: E; red: damaged
// F pixels; yellow: F pixels changed by 1 to 4 levels) and error.png (the remaining error over E:
// red in end runs, yellow along sides with one step, green in whole runs, blue along stepless
// sides; see ClassifyRuns).
#include "BenchmarkUtilities.h"

#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using mlaaBenchmark::Contrasting;
using mlaaBenchmark::Random;
using mlaaBenchmark::RandomColour;
using mlaaBenchmark::WritePNG;
const double Tolerance = 4.0;
const double Pi = 3.14159265358979323846;

struct Point
{
  double X, Y;
};

// A convex quadrilateral (counter-clockwise) and its colour.
struct Shape
{
  std::array<Point, 4> P;
  std::array<int, 3> Colour;
  bool Inside(double x, double y) const
  {
    for (int i = 0; i < 4; ++i)
    {
      const Point& a = this->P[i];
      const Point& b = this->P[(i + 1) % 4];
      if ((b.X - a.X) * (y - a.Y) - (b.Y - a.Y) * (x - a.X) < 0.0)
      {
        return false;
      }
    }
    return true;
  }
};

struct Scene
{
  std::string Family;
  int Contrast;
  int Width, Height;
  std::array<int, 3> Background;
  std::vector<Shape> Shapes;
  const std::array<int, 3>& ColourAt(double x, double y) const
  {
    for (auto s = this->Shapes.rbegin(); s != this->Shapes.rend(); ++s)
    {
      if (s->Inside(x, y))
      {
        return s->Colour;
      }
    }
    return this->Background;
  }
};

// A rectangle of size length x width centred at (cx, cy), its length along the angle `angle`
// (radians) from the x axis.
Shape Rectangle(double cx, double cy, double length, double width, double angle,
  const std::array<int, 3>& colour)
{
  const double c = std::cos(angle), s = std::sin(angle);
  const double hl = 0.5 * length, hw = 0.5 * width;
  Shape shape;
  const double corners[4][2] = { { -hl, -hw }, { hl, -hw }, { hl, hw }, { -hl, hw } };
  for (int i = 0; i < 4; ++i)
  {
    shape.P[i] = { cx + c * corners[i][0] - s * corners[i][1],
      cy + s * corners[i][0] + c * corners[i][1] };
  }
  shape.Colour = colour;
  return shape;
}

// The angle from the axis: log-uniform magnitude in [0.05, 5] degrees, either sign.
double SmallAngle(Random& random)
{
  const double degrees = std::exp(random.Uniform(std::log(0.05), std::log(5.0)));
  return (random.Uniform(0, 1) < 0.5 ? -1.0 : 1.0) * degrees * Pi / 180.0;
}

std::vector<Scene> MakeSet(int count, int width, int height, std::uint32_t seed)
{
  static const char* const families[] = { "halfplane", "rects", "strips", "bars" };
  static const int contrasts[] = { 255, 160, 80, 30 };
  Random random(seed);
  std::vector<Scene> scenes;
  for (int k = 0; k < count; ++k)
  {
    Scene scene;
    scene.Family = families[k % 4];
    scene.Width = width;
    scene.Height = height;
    const bool vertical = (k / 4) % 2 == 1;
    const double axis = vertical ? 0.5 * Pi : 0.0;
    const int contrast = contrasts[(k / 8) % 4];
    scene.Contrast = contrast;
    scene.Background = RandomColour(random);
    auto colour = [&]() { return Contrasting(random, scene.Background, contrast); };
    const double w = width, h = height;
    if (scene.Family == "halfplane")
    {
      // A huge square whose near side crosses the image's middle third.
      const double big = 100.0 * (w + h);
      const double angle = axis + SmallAngle(random);
      const double offset = random.Uniform(-h / 6, h / 6);
      const double nx = -std::sin(angle), ny = std::cos(angle); // normal of the edge
      const double cx = 0.5 * w + (offset - 0.5 * big) * nx;
      const double cy = 0.5 * h + (offset - 0.5 * big) * ny;
      scene.Shapes.push_back(Rectangle(cx, cy, big, big, angle, colour()));
    }
    else
    {
      const int n = scene.Family == "rects" ? 3 : scene.Family == "strips" ? 4 : 5;
      for (int i = 0; i < n; ++i)
      {
        double length, thickness;
        if (scene.Family == "rects")
        {
          length = random.Uniform(60, 400);
          thickness = random.Uniform(60, 300);
        }
        else if (scene.Family == "strips")
        {
          length = random.Uniform(150, 480);
          thickness = random.Uniform(3, 24);
        }
        else
        {
          length = random.Uniform(150, 480);
          thickness = random.Uniform(1, 3);
        }
        const double extentX = vertical ? thickness : length;
        const double extentY = vertical ? length : thickness;
        // Corners at least 8 pixels inside the image (the small angles move them little).
        const double cx = random.Uniform(
          std::min(0.5 * w, 8 + 0.5 * extentX), std::max(0.5 * w, w - 8 - 0.5 * extentX));
        const double cy = random.Uniform(
          std::min(0.5 * h, 8 + 0.5 * extentY), std::max(0.5 * h, h - 8 - 0.5 * extentY));
        scene.Shapes.push_back(
          Rectangle(cx, cy, length, thickness, axis + SmallAngle(random), colour()));
      }
    }
    scenes.push_back(scene);
  }
  return scenes;
}

struct Image
{
  int Width = 0, Height = 0;
  std::vector<double> Values; // 3 per pixel, row 0 at the bottom
};

void Render(const Scene& scene, int samples, Image& image)
{
  image.Width = scene.Width;
  image.Height = scene.Height;
  image.Values.assign(static_cast<size_t>(scene.Width) * scene.Height * 3, 0.0);
  for (int y = 0; y < scene.Height; ++y)
  {
    for (int x = 0; x < scene.Width; ++x)
    {
      double sum[3] = { 0, 0, 0 };
      for (int j = 0; j < samples; ++j)
      {
        for (int i = 0; i < samples; ++i)
        {
          const auto& c =
            scene.ColourAt(x + (i + 0.5) / samples, y + (j + 0.5) / samples);
          for (int k = 0; k < 3; ++k)
          {
            sum[k] += c[k];
          }
        }
      }
      for (int k = 0; k < 3; ++k)
      {
        image.Values[(static_cast<size_t>(y) * scene.Width + x) * 3 + k] =
          sum[k] / (samples * samples);
      }
    }
  }
}

vtkSmartPointer<vtkImageData> ToVTK(const Image& image)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.Width, image.Height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(data->GetScalarPointer());
  for (size_t i = 0; i < image.Values.size(); ++i)
  {
    p[i] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(image.Values[i]))));
  }
  return data;
}

Image FromVTK(vtkImageData* data)
{
  Image image;
  int dims[3];
  data->GetDimensions(dims);
  image.Width = dims[0];
  image.Height = dims[1];
  const auto* p = static_cast<const unsigned char*>(data->GetScalarPointer());
  image.Values.assign(p, p + static_cast<size_t>(dims[0]) * dims[1] * 3);
  return image;
}

double MaxDifference(const Image& a, const Image& b, size_t pixel)
{
  double d = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    d = std::max(d, std::abs(a.Values[3 * pixel + c] - b.Values[3 * pixel + c]));
  }
  return d;
}

double SquaredError(const Image& a, const Image& b, size_t pixel)
{
  double s = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double d = a.Values[3 * pixel + c] - b.Values[3 * pixel + c];
    s += d * d;
  }
  return s;
}

// E and F of MEASURING.md.
void ComputeSets(const Image& none, const Image& reference, std::vector<char>& e,
  std::vector<char>& f)
{
  const int w = none.Width, h = none.Height;
  e.assign(static_cast<size_t>(w) * h, 0);
  for (size_t i = 0; i < e.size(); ++i)
  {
    e[i] = MaxDifference(none, reference, i) > Tolerance;
  }
  f.assign(e.size(), 1);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      for (int dy = -2; dy <= 2; ++dy)
      {
        for (int dx = -2; dx <= 2; ++dx)
        {
          const int xx = x + dx, yy = y + dy;
          if (xx >= 0 && xx < w && yy >= 0 && yy < h && e[static_cast<size_t>(yy) * w + xx])
          {
            f[static_cast<size_t>(y) * w + x] = 0;
          }
        }
      }
    }
  }
}

// Where each E pixel lies on the staircase of its side (the side nearest its centre, hidden parts
// of sides included: the shapes overlap little). A side nearly horizontal steps where it crosses
// a row of pixel centres (a column if nearly vertical); the runs of its staircase lie between
// those steps, and the runs at the side's ends are cut by its corners or by the image border.
// Classes: a whole run between two steps; an end run, between a step and a corner or the border,
// of a side with two steps or more (the next run past its step is a whole run, which gives the
// slope); a side with one step, whose two runs are both end runs (no run gives the slope); a
// stepless side, which crosses no row (column) of centres in the image and is sampled as a
// straight run of edgels: its sub-pixel offset from the pixel boundary is not in the input.
enum RunClass : char
{
  NotE = 0,
  WholeRun,
  EndRun,
  OneStepSide,
  SteplessSide
};
std::vector<char> ClassifyRuns(const Scene& scene, const std::vector<char>& e)
{
  struct Side
  {
    Point A, B;
    bool Horizontal;
    double Lo, Hi; // the part inside the image, along the major axis
  };
  std::vector<Side> sides;
  const double w = scene.Width, h = scene.Height;
  for (const Shape& shape : scene.Shapes)
  {
    for (int i = 0; i < 4; ++i)
    {
      const Point a = shape.P[i], b = shape.P[(i + 1) % 4];
      const bool horizontal = std::abs(b.X - a.X) >= std::abs(b.Y - a.Y);
      const double u0 = horizontal ? a.X : a.Y, u1 = horizontal ? b.X : b.Y;
      const double lo = std::max(std::min(u0, u1), 0.0);
      const double hi = std::min(std::max(u0, u1), horizontal ? w : h);
      if (lo < hi)
      {
        sides.push_back({ a, b, horizontal, lo, hi });
      }
    }
  }
  std::vector<char> classes(e.size(), NotE);
  for (size_t i = 0; i < e.size(); ++i)
  {
    if (!e[i])
    {
      continue;
    }
    const double px = static_cast<double>(i % scene.Width) + 0.5;
    const double py = static_cast<double>(i / scene.Width) + 0.5;
    double best = std::numeric_limits<double>::max();
    const Side* nearest = nullptr;
    for (const Side& side : sides)
    {
      const double dx = side.B.X - side.A.X, dy = side.B.Y - side.A.Y;
      const double t = std::min(
        1.0, std::max(0.0, ((px - side.A.X) * dx + (py - side.A.Y) * dy) / (dx * dx + dy * dy)));
      const double d = std::hypot(side.A.X + t * dx - px, side.A.Y + t * dy - py);
      if (d < best)
      {
        best = d;
        nearest = &side;
      }
    }
    if (!nearest)
    {
      continue;
    }
    // The staircase's row (column) of centres below the side, at the pixel and at both ends of
    // the side's part in the image: a step lies between two places where it differs.
    const Side& side = *nearest;
    const double u0 = side.Horizontal ? side.A.X : side.A.Y;
    const double u1 = side.Horizontal ? side.B.X : side.B.Y;
    const double v0 = side.Horizontal ? side.A.Y : side.A.X;
    const double v1 = side.Horizontal ? side.B.Y : side.B.X;
    auto level = [&](double u) { return std::floor(v0 + (v1 - v0) * (u - u0) / (u1 - u0) - 0.5); };
    const double u = std::min(side.Hi, std::max(side.Lo, side.Horizontal ? px : py));
    const double lo = level(side.Lo), hi = level(side.Hi), here = level(u);
    if (lo == hi)
    {
      classes[i] = SteplessSide;
    }
    else
    {
      classes[i] = std::abs(hi - lo) == 1 ? OneStepSide
        : here == lo || here == hi       ? EndRun
                                         : WholeRun;
    }
  }
  return classes;
}

struct Sums
{
  double NoneSE = 0.0;   // squared error of none over E
  double MethodSE = 0.0; // squared error of the method over E
  double UntouchedSE = 0.0; // part of MethodSE in E pixels the method left as they were
  double MissedSE = 0.0; // part of MethodSE in E pixels with no edge found at their boundaries
  double SteplessNoneSE = 0.0, SteplessSE = 0.0; // NoneSE and MethodSE along stepless sides
  double EndRunSE = 0.0; // part of MethodSE in the end runs of sides with two steps or more
  double OneStepNoneSE = 0.0, OneStepSE = 0.0; // NoneSE and MethodSE along sides with one step
  size_t F = 0;
  size_t Damaged = 0;
  double SumAAR = 0.0;
  int Images = 0;
  void Add(const Sums& o)
  {
    this->NoneSE += o.NoneSE;
    this->MethodSE += o.MethodSE;
    this->UntouchedSE += o.UntouchedSE;
    this->MissedSE += o.MissedSE;
    this->SteplessNoneSE += o.SteplessNoneSE;
    this->SteplessSE += o.SteplessSE;
    this->EndRunSE += o.EndRunSE;
    this->OneStepNoneSE += o.OneStepNoneSE;
    this->OneStepSE += o.OneStepSE;
    this->F += o.F;
    this->Damaged += o.Damaged;
    this->SumAAR += o.SumAAR;
    this->Images += o.Images;
  }
  double AAR() const { return this->NoneSE > 0 ? 1.0 - this->MethodSE / this->NoneSE : 0.0; }
  double MeanAAR() const { return this->Images ? this->SumAAR / this->Images : 0.0; }
  double Damage() const { return this->F ? static_cast<double>(this->Damaged) / this->F : 0.0; }
  double UntouchedShare() const
  {
    return this->MethodSE > 0 ? this->UntouchedSE / this->MethodSE : 0.0;
  }
  double MissedShare() const { return this->MethodSE > 0 ? this->MissedSE / this->MethodSE : 0.0; }
  double SteplessShare() const
  {
    return this->MethodSE > 0 ? this->SteplessSE / this->MethodSE : 0.0;
  }
  double EndRunShare() const { return this->MethodSE > 0 ? this->EndRunSE / this->MethodSE : 0.0; }
  double OneStepShare() const
  {
    return this->MethodSE > 0 ? this->OneStepSE / this->MethodSE : 0.0;
  }
  // AAR over the E pixels along sides with two steps or more (whose slope the image holds).
  double SlopeAAR() const
  {
    const double none = this->NoneSE - this->SteplessNoneSE - this->OneStepNoneSE;
    return none > 0 ? 1.0 - (this->MethodSE - this->SteplessSE - this->OneStepSE) / none : 0.0;
  }
};

struct Configuration
{
  std::string Name;
  std::function<void(vtkMLAAOptions*)> Configure;
};
}

int main(int argc, char* argv[])
{
  int width = 512, height = 512, count = 32, samples = 8;
  std::uint32_t seed = 20;
  std::string outputDir, dump = "P-ultra";
  bool perImage = false;
  vtkNew<vtkMLAAOptions> given;
  bool haveGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--size" && i + 1 < argc && mlaaBenchmark::ParseSize(argv[i + 1], width, height))
    {
      ++i;
    }
    else if (arg == "--images" && i + 1 < argc && mlaaBenchmark::ParsePositive(argv[i + 1], count))
    {
      ++i;
    }
    else if (arg == "--samples" && i + 1 < argc &&
      mlaaBenchmark::ParsePositive(argv[i + 1], samples))
    {
      ++i;
    }
    else if (arg == "--seed" && i + 1 < argc)
    {
      seed = static_cast<std::uint32_t>(std::stoul(argv[++i]));
    }
    else if (arg == "--output-dir" && i + 1 < argc)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--per-image")
    {
      perImage = true;
    }
    else if (arg == "--dump" && i + 1 < argc)
    {
      dump = argv[++i];
    }
    else if (mlaaBenchmark::ParseMLAAOption(argc, argv, i, given))
    {
      haveGiven = true;
    }
    else
    {
      std::cerr << "usage: mlaa-long-lines [--size WxH] [--images N] [--samples N] [--seed S]\n"
                   "  [--output-dir DIR] [--dump CONFIGURATION] [--per-image] [MLAA settings]\n"
                << mlaaBenchmark::MLAAOptionsUsage();
      return 2;
    }
  }

  std::vector<Configuration> configurations;
  if (haveGiven)
  {
    configurations.push_back(
      { "given", [&given](vtkMLAAOptions* o) { o->CopyQualitySettings(given); } });
    dump = "given";
  }
  else
  {
    configurations = {
      { "P-low", [](vtkMLAAOptions* o) { o->SetPresetToLow(); } },
      { "P-medium", [](vtkMLAAOptions* o) { o->SetPresetToMedium(); } },
      { "P-high", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); } },
      { "P-ultra", [](vtkMLAAOptions* o) { o->SetPresetToUltra(); } },
      { "high+32", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); o->SetMaxSearchSteps(32); } },
      { "high+64", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); o->SetMaxSearchSteps(64); } },
      { "high+128", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); o->SetMaxSearchSteps(128); } },
    };
  }

  const std::vector<Scene> scenes = MakeSet(count, width, height, seed);
  std::vector<std::vector<Sums>> sums(configurations.size()); // per configuration, per image
  for (size_t k = 0; k < scenes.size(); ++k)
  {
    const Scene& scene = scenes[k];
    Image none, reference;
    Render(scene, 1, none);
    Render(scene, samples, reference);
    std::vector<char> e, f;
    ComputeSets(none, reference, e, f);
    const std::vector<char> runs = ClassifyRuns(scene, e);
    auto input = ToVTK(none);
    char name[32];
    std::snprintf(name, sizeof(name), "%02zu-%s", k, scene.Family.c_str());
    const std::string prefix = outputDir.empty() ? std::string() : outputDir + "/" + name;
    if (!prefix.empty())
    {
      std::filesystem::create_directories(outputDir);
      WritePNG(input, prefix + "-none.png");
      WritePNG(ToVTK(reference), prefix + "-reference.png");
    }
    for (size_t c = 0; c < configurations.size(); ++c)
    {
      vtkNew<vtkImageMLAA> filter;
      configurations[c].Configure(filter->GetOptions());
      filter->SetInputData(input);
      filter->Update();
      const Image out = FromVTK(filter->GetOutput());
      // The edges the filter found (DebugOutput Edges: red, the pixel's left edgel; green, its
      // top edgel, towards higher rows), to tell the error of edges it did not find.
      vtkNew<vtkImageMLAA> edgesFilter;
      edgesFilter->GetOptions()->CopyQualitySettings(filter->GetOptions());
      edgesFilter->GetOptions()->SetDebugOutputToEdges();
      edgesFilter->SetInputData(input);
      edgesFilter->Update();
      vtkImageData* edges = edgesFilter->GetOutput(); // RGBA
      const auto* edgeBytes = static_cast<const unsigned char*>(edges->GetScalarPointer());
      auto edgel = [edgeBytes, width, height](int x, int y, int which) {
        if (x < 0 || y < 0 || x >= width || y >= height)
        {
          return false;
        }
        return edgeBytes[4 * (static_cast<size_t>(y) * width + x) + which] > 0;
      };
      Sums s;
      s.Images = 1;
      double noneSE = 0.0, methodSE = 0.0;
      for (size_t i = 0; i < e.size(); ++i)
      {
        if (e[i])
        {
          const double noneSquared = SquaredError(none, reference, i);
          noneSE += noneSquared;
          const double se = SquaredError(out, reference, i);
          methodSE += se;
          if (runs[i] == SteplessSide)
          {
            s.SteplessNoneSE += noneSquared;
            s.SteplessSE += se;
          }
          else if (runs[i] == EndRun)
          {
            s.EndRunSE += se;
          }
          else if (runs[i] == OneStepSide)
          {
            s.OneStepNoneSE += noneSquared;
            s.OneStepSE += se;
          }
          if (MaxDifference(out, none, i) == 0.0)
          {
            s.UntouchedSE += se;
          }
          const int x = static_cast<int>(i % width), y = static_cast<int>(i / width);
          if (!edgel(x, y, 0) && !edgel(x, y, 1) && !edgel(x + 1, y, 0) && !edgel(x, y - 1, 1))
          {
            s.MissedSE += se;
          }
        }
        if (f[i])
        {
          ++s.F;
          s.Damaged += MaxDifference(out, none, i) > Tolerance;
        }
      }
      s.NoneSE = noneSE;
      s.MethodSE = methodSE;
      s.SumAAR = noneSE > 0 ? 1.0 - methodSE / noneSE : 0.0;
      sums[c].push_back(s);
      if (!prefix.empty() && configurations[c].Name == dump)
      {
        WritePNG(filter->GetOutput(), prefix + "-out.png");
        Image map = none;
        for (size_t i = 0; i < e.size(); ++i)
        {
          const double grey =
            0.25 * (none.Values[3 * i] + none.Values[3 * i + 1] + none.Values[3 * i + 2]) / 3.0;
          const double d = MaxDifference(out, none, i);
          std::array<double, 3> v = { grey, grey, grey };
          if (e[i])
          {
            v = { grey, grey, 160.0 };
          }
          else if (f[i] && d > Tolerance)
          {
            v = { 255.0, 0.0, 0.0 };
          }
          else if (f[i] && d > 0)
          {
            v = { 255.0, 255.0, 0.0 };
          }
          for (int ch = 0; ch < 3; ++ch)
          {
            map.Values[3 * i + ch] = v[ch];
          }
        }
        WritePNG(ToVTK(map), prefix + "-damage.png");
        // The error map: over E, the remaining error (root of the squared error, doubled) in
        // red for end runs, yellow for sides with one step, green for whole runs, blue for
        // stepless sides; black elsewhere.
        for (size_t i = 0; i < e.size(); ++i)
        {
          std::array<double, 3> v = { 0.0, 0.0, 0.0 };
          if (e[i])
          {
            const double error = std::min(255.0, 2.0 * std::sqrt(SquaredError(out, reference, i)));
            // Yellow for sides with one step.
            if (runs[i] == OneStepSide)
            {
              v = { error, error, 0.0 };
            }
            else
            {
              v[runs[i] == EndRun ? 0 : runs[i] == WholeRun ? 1 : 2] = error;
            }
          }
          for (int ch = 0; ch < 3; ++ch)
          {
            map.Values[3 * i + ch] = v[ch];
          }
        }
        WritePNG(ToVTK(map), prefix + "-error.png");
      }
    }
  }

  std::cout << "mlaa-long-lines: " << scenes.size() << " images of " << width << " x " << height
            << ", seed " << seed << ", reference " << samples << " x " << samples << "\n";
  // One table per breakdown: the images' families, then their contrasts. "untouched" is the share
  // of the remaining squared error over E that lies in pixels the filter left as they were
  // (edges it did not find or did not ramp), the rest lies in pixels it changed; "missed" the
  // share in pixels with no edge found at any of their four boundaries (a threshold question);
  // "stepless", "1step" and "endrun" the shares of the classes of ClassifyRuns (the rest lies in
  // whole runs), "AAR-2+" the AAR along sides with two steps or more.
  const std::vector<std::string> families = { "halfplane", "rects", "strips", "bars" };
  const std::vector<std::string> contrasts = { "255", "160", "80", "30" };
  auto printTable = [&](const std::vector<std::string>& parts, bool byContrast) {
    std::cout << std::left << std::setw(10) << "config" << std::right << std::setw(9) << "AAR"
              << std::setw(9) << "meanAAR" << std::setw(10) << "damage%" << std::setw(9)
              << "damaged" << std::setw(10) << "untouched" << std::setw(8) << "missed" << std::setw(9)
              << "stepless" << std::setw(8) << "1step" << std::setw(8) << "endrun" << std::setw(8)
              << "AAR-2+";
    for (const std::string& part : parts)
    {
      std::cout << std::setw(19) << ((byContrast ? "c" : "") + part + " AAR/dmg%");
    }
    std::cout << "\n";
    for (size_t c = 0; c < configurations.size(); ++c)
    {
      Sums all;
      for (const Sums& s : sums[c])
      {
        all.Add(s);
      }
      std::cout << std::left << std::setw(10) << configurations[c].Name << std::right
                << std::fixed << std::setprecision(3) << std::setw(9) << all.AAR() << std::setw(9)
                << all.MeanAAR() << std::setw(10) << 100.0 * all.Damage() << std::setw(9)
                << all.Damaged << std::setw(10) << all.UntouchedShare() << std::setw(8)
                << all.MissedShare() << std::setw(9) << all.SteplessShare() << std::setw(8)
                << all.OneStepShare() << std::setw(8) << all.EndRunShare() << std::setw(8)
                << all.SlopeAAR();
      for (const std::string& part : parts)
      {
        Sums sub;
        for (size_t k = 0; k < scenes.size(); ++k)
        {
          if (byContrast ? std::to_string(scenes[k].Contrast) == part : scenes[k].Family == part)
          {
            sub.Add(sums[c][k]);
          }
        }
        std::ostringstream cell;
        cell << std::fixed << std::setprecision(3) << sub.AAR() << "/" << 100.0 * sub.Damage();
        std::cout << std::setw(19) << cell.str();
      }
      std::cout << "\n";
    }
  };
  if (perImage)
  {
    // Per configuration and image: AAR, the untouched share and the damaged pixels.
    for (size_t c = 0; c < configurations.size(); ++c)
    {
      for (size_t k = 0; k < scenes.size(); ++k)
      {
        const Sums& s = sums[c][k];
        std::cout << configurations[c].Name << " " << std::setw(2) << k << " " << std::left
                  << std::setw(10) << scenes[k].Family << std::right << std::setw(4)
                  << scenes[k].Contrast << std::fixed << std::setprecision(3) << std::setw(8)
                  << s.AAR() << std::setw(8) << s.UntouchedShare() << std::setw(8) << s.MissedShare()
                  << std::setw(8) << s.SteplessShare() << std::setw(8) << s.OneStepShare()
                  << std::setw(8) << s.EndRunShare()
                  << std::setw(8) << s.SlopeAAR()
                  << std::setw(7) << s.Damaged
                  << "\n";
      }
    }
  }
  printTable(families, false);
  std::cout << "by contrast (levels):\n";
  printTable(contrasts, true);
  return 0;
}
