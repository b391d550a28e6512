// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-aligned: damage (shared/docs/MEASURING.md) of vtkImageMLAA, and of vtkImageDLAA, on exact
// pictures whose every side lies on a pixel boundary, with no rendering.
//
// Such a picture has no aliasing: its 8 x 8 supersampling is the picture itself, so every pixel is
// in MEASURING.md's set F and the damage is the share of all pixels that the filter changes by more
// than 4/255. The set is drawn from a seeded generator (the same images on every run and machine).
// Families, in turn:
//   rects    a background and eight overlapping rectangles, 2 to half the image a side;
//   bars     a bar chart: bars 3 to 40 pixels wide on a 1-pixel axis, with 1-pixel ticks and a
//            frame (a viewport border);
//   voxels   a grid of square cells 2 to 24 pixels a side with random colours (a zoomed image with
//            nearest-neighbour interpolation, seen straight on);
//   palette  the same with four colours only, so that neighbouring cells often match and the
//            sides end at L corners and T junctions;
//   legend   a colour legend: bands 1 to 8 pixels high of a smooth colour map, framed, beside
//            tick marks;
// colours at contrasts (largest channel difference) of 255, 160, 80 and 30 levels.
// Reported per configuration: the damage pooled over all images and per family, and the share of
// pixels changed at all. The damaged images of the configuration named by --dump, with
// --output-dir, are written as in.png, out.png, damage.png (red: changed by more than 4/255) and
// crops.png (the three magnified 8 times around the first damaged pixel).
//
// Configurations: the five presets, the high preset with 1 to 128 search steps, and the high
// preset with corner extrapolation at 16 and 128 steps, then vtkImageDLAA with its defaults
// ("DLAA") and without long edges ("DLAA-short"); with MLAA settings on the command line, those
// settings instead ("given"). --require-damage P fails (exit 1) where any configuration
// damages more than P percent.
#include "BenchmarkUtilities.h"

#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
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
#include <map>
#include <random>
#include <string>
#include <vector>

namespace
{
using namespace mlaaBenchmark;
const int Tolerance = 4;
using Colour = std::array<int, 3>;

struct Picture
{
  std::string Family;
  int Width = 0, Height = 0;
  std::vector<Colour> Pixels;
  Colour& At(int x, int y) { return this->Pixels[static_cast<size_t>(y) * this->Width + x]; }
  // Fills [x0, x1) x [y0, y1), clipped to the picture.
  void Fill(int x0, int y0, int x1, int y1, const Colour& colour)
  {
    for (int y = std::max(0, y0); y < std::min(this->Height, y1); ++y)
    {
      for (int x = std::max(0, x0); x < std::min(this->Width, x1); ++x)
      {
        this->At(x, y) = colour;
      }
    }
  }
};

Picture MakePicture(int k, int width, int height, Random& random)
{
  static const char* const families[] = { "rects", "bars", "voxels", "palette", "legend" };
  static const int contrasts[] = { 255, 160, 80, 30 };
  Picture p;
  p.Family = families[k % 5];
  p.Width = width;
  p.Height = height;
  const int contrast = contrasts[(k / 5) % 4];
  const Colour background = RandomColour(random);
  p.Pixels.assign(static_cast<size_t>(width) * height, background);
  auto colour = [&]() { return Contrasting(random, background, contrast); };
  if (p.Family == "rects")
  {
    for (int i = 0; i < 8; ++i)
    {
      const int w = random.Integer(2, std::max(2, width / 2));
      const int h = random.Integer(2, std::max(2, height / 2));
      const int x = random.Integer(-w / 4, width - 3 * w / 4);
      const int y = random.Integer(-h / 4, height - 3 * h / 4);
      p.Fill(x, y, x + w, y + h, colour());
    }
  }
  else if (p.Family == "bars")
  {
    const Colour ink = colour();
    const int left = random.Integer(4, std::max(4, width / 8));
    const int base = height - random.Integer(4, std::max(4, height / 8));
    int x = left + random.Integer(2, 8);
    const int barWidth = random.Integer(3, 40);
    const int gap = random.Integer(1, 12);
    while (x + barWidth < width - 4)
    {
      const int top = random.Integer(4, std::max(4, base - 2));
      p.Fill(x, top, x + barWidth, base, colour());
      x += barWidth + gap;
    }
    p.Fill(left, 2, left + 1, base + 1, ink);         // the vertical axis
    p.Fill(left, base, width - 2, base + 1, ink);     // the horizontal axis
    for (int y = base - 10; y > 4; y -= 10)
    {
      p.Fill(left - 4, y, left, y + 1, ink); // ticks
    }
    p.Fill(0, 0, width, 1, ink); // a viewport's frame
    p.Fill(0, height - 1, width, height, ink);
    p.Fill(0, 0, 1, height, ink);
    p.Fill(width - 1, 0, width, height, ink);
  }
  else if (p.Family == "voxels" || p.Family == "palette")
  {
    const int cell = random.Integer(2, 24);
    const int ox = random.Integer(0, cell - 1), oy = random.Integer(0, cell - 1);
    std::vector<Colour> palette;
    for (int i = 0; i < 4; ++i)
    {
      palette.push_back(colour());
    }
    for (int cy = -1; cy * cell < height; ++cy)
    {
      for (int cx = -1; cx * cell < width; ++cx)
      {
        const Colour c = p.Family == "palette" ? palette[random.Integer(0, 3)] : colour();
        p.Fill(ox + cx * cell, oy + cy * cell, ox + (cx + 1) * cell, oy + (cy + 1) * cell, c);
      }
    }
  }
  else // legend
  {
    const Colour low = colour(), high = colour();
    const int band = random.Integer(1, 8);
    const int x0 = random.Integer(4, std::max(4, width / 4));
    const int x1 = x0 + random.Integer(10, std::max(10, width / 4));
    const int y0 = 4, y1 = height - 4;
    for (int y = y0; y < y1; y += band)
    {
      const double t = static_cast<double>(y - y0) / std::max(1, y1 - y0);
      Colour c;
      for (int i = 0; i < 3; ++i)
      {
        c[i] = static_cast<int>(std::lround(low[i] + t * (high[i] - low[i])));
      }
      p.Fill(x0, y, x1, std::min(y + band, y1), c);
    }
    const Colour ink = colour();
    p.Fill(x0 - 1, y0 - 1, x1 + 1, y0, ink);
    p.Fill(x0 - 1, y1, x1 + 1, y1 + 1, ink);
    p.Fill(x0 - 1, y0 - 1, x0, y1 + 1, ink);
    p.Fill(x1, y0 - 1, x1 + 1, y1 + 1, ink);
    for (int y = y0; y < y1; y += 16)
    {
      p.Fill(x1 + 1, y, x1 + 6, y + 1, ink);
      p.Fill(x1 + 8, y - 2, x1 + 8 + random.Integer(6, 20), y + 3, ink); // a label's block
    }
  }
  return p;
}

vtkSmartPointer<vtkImageData> ToImage(const Picture& p)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(p.Width, p.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* data = static_cast<unsigned char*>(image->GetScalarPointer());
  for (size_t i = 0; i < p.Pixels.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      data[3 * i + c] = static_cast<unsigned char>(p.Pixels[i][c]);
    }
  }
  return image;
}

// A crop of `size` x `size` pixels centred on (cx, cy) of the input, the output and the damage
// image side by side, each magnified `zoom` times, for looking at what the filter did.
vtkSmartPointer<vtkImageData> Crops(
  const std::array<vtkImageData*, 3>& images, int cx, int cy, int size, int zoom)
{
  int dims[3];
  images[0]->GetDimensions(dims);
  const int x0 = std::max(0, std::min(dims[0] - size, cx - size / 2));
  const int y0 = std::max(0, std::min(dims[1] - size, cy - size / 2));
  const int panel = size * zoom;
  auto mosaic = vtkSmartPointer<vtkImageData>::New();
  mosaic->SetDimensions(3 * panel + 2 * zoom, panel, 1);
  mosaic->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* m = static_cast<unsigned char*>(mosaic->GetScalarPointer());
  std::fill(m, m + 3 * static_cast<size_t>(3 * panel + 2 * zoom) * panel, 255);
  for (int k = 0; k < 3; ++k)
  {
    const auto* src = static_cast<const unsigned char*>(images[k]->GetScalarPointer());
    for (int y = 0; y < panel; ++y)
    {
      for (int x = 0; x < panel; ++x)
      {
        const int sx = std::min(dims[0] - 1, x0 + x / zoom);
        const int sy = std::min(dims[1] - 1, y0 + y / zoom);
        const unsigned char* from = src + 3 * (static_cast<size_t>(sy) * dims[0] + sx);
        unsigned char* to = m + 3 * (static_cast<size_t>(y) * (3 * panel + 2 * zoom) +
                                  k * (panel + zoom) + x);
        std::copy(from, from + 3, to);
      }
    }
  }
  return mosaic;
}

struct Configuration
{
  std::string Name;
  std::function<void(vtkMLAAOptions*)> Configure; // a vtkImageMLAA's settings
  std::function<void(vtkDLAAOptions*)> ConfigureDLAA = nullptr; // if set: a vtkImageDLAA's
};

// The filter of a configuration, its input set, updated.
vtkSmartPointer<vtkImageAlgorithm> RunFilter(
  const Configuration& configuration, vtkImageData* input)
{
  vtkSmartPointer<vtkImageAlgorithm> result;
  if (configuration.ConfigureDLAA)
  {
    auto filter = vtkSmartPointer<vtkImageDLAA>::New();
    configuration.ConfigureDLAA(filter->GetOptions());
    result = filter;
  }
  else
  {
    auto filter = vtkSmartPointer<vtkImageMLAA>::New();
    configuration.Configure(filter->GetOptions());
    result = filter;
  }
  result->SetInputData(input);
  result->Update();
  return result;
}

std::vector<Configuration> Configurations()
{
  std::vector<Configuration> list = {
    { "P-low", [](vtkMLAAOptions* o) { o->SetPresetToLow(); } },
    { "P-medium", [](vtkMLAAOptions* o) { o->SetPresetToMedium(); } },
    { "P-high", [](vtkMLAAOptions* o) { o->SetPresetToHigh(); } },
    { "P-ultra", [](vtkMLAAOptions* o) { o->SetPresetToUltra(); } },
    { "P-max", [](vtkMLAAOptions* o) { o->SetPresetToMax(); } },
  };
  for (int steps : { 1, 2, 4, 8, 32, 64, 128 })
  {
    list.push_back({ "high-steps" + std::to_string(steps),
      [steps](vtkMLAAOptions* o)
      {
        o->SetPresetToHigh();
        o->SetMaxSearchSteps(steps);
      } });
  }
  for (int steps : { 16, 128 })
  {
    list.push_back({ "high-corners" + std::to_string(steps),
      [steps](vtkMLAAOptions* o)
      {
        o->SetPresetToHigh();
        o->SetMaxSearchSteps(steps);
        o->CornerExtrapolationOn();
      } });
  }
  list.push_back({ "DLAA", nullptr, [](vtkDLAAOptions*) {} });
  list.push_back({ "DLAA-short", nullptr, [](vtkDLAAOptions* o) { o->LongEdgesOff(); } });
  return list;
}

struct Tally
{
  long long Pixels = 0, Damaged = 0, Changed = 0;
  double Damage() const { return this->Pixels ? 100.0 * this->Damaged / this->Pixels : 0.0; }
  double ChangedShare() const { return this->Pixels ? 100.0 * this->Changed / this->Pixels : 0.0; }
};

void Usage(const char* program)
{
  std::cout << "Usage: " << program << " [options]\n"
            << "  --size WxH          image size (default 320x240)\n"
            << "  --images N          number of images (default 60)\n"
            << "  --seed S            generator seed (default 2026)\n"
            << "  --per-image         list the damage of every image\n"
            << "  --output-dir DIR    write the worst images of the --dump configuration\n"
            << "  --dump NAME         configuration to write (default high-steps128)\n"
            << "  --require-damage P  exit 1 where a configuration damages more than P %\n"
            << MLAAOptionsUsage();
}
}

int main(int argc, char* argv[])
{
  int width = 320, height = 240, count = 60, seed = 2026;
  bool perImage = false;
  std::string outputDir, dump = "high-steps128";
  double requiredDamage = -1.0;
  vtkNew<vtkMLAAOptions> given;
  bool haveGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--size" && hasValue && ParseSize(argv[i + 1], width, height))
    {
      ++i;
    }
    else if (arg == "--images" && hasValue && ParsePositive(argv[i + 1], count))
    {
      ++i;
    }
    else if (arg == "--seed" && hasValue && ParsePositive(argv[i + 1], seed))
    {
      ++i;
    }
    else if (arg == "--per-image")
    {
      perImage = true;
    }
    else if (arg == "--output-dir" && hasValue)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--dump" && hasValue)
    {
      dump = argv[++i];
    }
    else if (arg == "--require-damage" && hasValue &&
      ParseNumber(argv[i + 1], 0.0, 100.0, requiredDamage))
    {
      ++i;
    }
    else if (ParseMLAAOption(argc, argv, i, given))
    {
      haveGiven = true;
    }
    else
    {
      Usage(argv[0]);
      return arg == "--help" ? 0 : 2;
    }
  }

  std::vector<Configuration> configurations;
  if (haveGiven)
  {
    configurations.push_back({ "given", [&given](vtkMLAAOptions* o) { o->DeepCopy(given); } });
    dump = "given";
  }
  else
  {
    configurations = Configurations();
  }
  Random random(static_cast<std::uint32_t>(seed));
  std::vector<Picture> pictures;
  for (int k = 0; k < count; ++k)
  {
    pictures.push_back(MakePicture(k, width, height, random));
  }
  if (!outputDir.empty())
  {
    std::filesystem::create_directories(outputDir);
  }

  std::cout << "mlaa-aligned: " << count << " exact images of " << width << " x " << height
            << " whose sides all lie on pixel boundaries (seed " << seed << ")\n"
            << "damage: % of pixels changed by more than " << Tolerance
            << "/255 (every pixel is in F); changed: % changed at all\n\n";
  std::cout << std::left << std::setw(18) << "configuration" << std::right << std::setw(10)
            << "damage %" << std::setw(11) << "changed %";
  std::vector<std::string> families = { "rects", "bars", "voxels", "palette", "legend" };
  for (const auto& family : families)
  {
    std::cout << std::setw(10) << family;
  }
  std::cout << "\n";
  bool failed = false;
  for (const auto& configuration : configurations)
  {
    Tally all;
    std::map<std::string, Tally> byFamily;
    std::vector<std::pair<long long, int>> worst;
    for (int k = 0; k < count; ++k)
    {
      const Picture& p = pictures[k];
      auto input = ToImage(p);
      auto filter = RunFilter(configuration, input);
      vtkImageData* output = filter->GetOutput();
      const auto* in = static_cast<const unsigned char*>(input->GetScalarPointer());
      const auto* out = static_cast<const unsigned char*>(output->GetScalarPointer());
      Tally image;
      int firstDamaged = -1;
      image.Pixels = static_cast<long long>(p.Pixels.size());
      vtkNew<vtkImageData> damage;
      damage->DeepCopy(input);
      auto* marks = static_cast<unsigned char*>(damage->GetScalarPointer());
      for (size_t i = 0; i < p.Pixels.size(); ++i)
      {
        int largest = 0;
        for (int c = 0; c < 3; ++c)
        {
          largest = std::max(largest, std::abs(int(out[3 * i + c]) - int(in[3 * i + c])));
        }
        image.Changed += largest > 0;
        if (largest > Tolerance && firstDamaged < 0)
        {
          firstDamaged = static_cast<int>(i);
        }
        image.Damaged += largest > Tolerance;
        for (int c = 0; c < 3; ++c)
        {
          marks[3 * i + c] = largest > Tolerance ? (c == 0 ? 255 : 0) : in[3 * i + c] / 3;
        }
      }
      for (Tally* t : { &all, &byFamily[p.Family] })
      {
        t->Pixels += image.Pixels;
        t->Damaged += image.Damaged;
        t->Changed += image.Changed;
      }
      if (perImage && image.Damaged > 0)
      {
        std::cout << "  " << configuration.Name << " image " << k << " (" << p.Family
                  << "): " << image.Damaged << " damaged, " << image.Changed << " changed\n";
      }
      if (!outputDir.empty() && configuration.Name == dump && image.Damaged > 0)
      {
        const std::string prefix = outputDir + "/" + std::to_string(k) + "-" + p.Family + "-";
        WritePNG(input, prefix + "in.png");
        WritePNG(output, prefix + "out.png");
        WritePNG(damage, prefix + "damage.png");
        WritePNG(Crops({ input, output, damage }, firstDamaged % p.Width, firstDamaged / p.Width,
                   24, 8),
          prefix + "crops.png");
      }
    }
    std::cout << std::left << std::setw(18) << configuration.Name << std::right << std::fixed
              << std::setprecision(4) << std::setw(10) << all.Damage() << std::setw(11)
              << all.ChangedShare();
    for (const auto& family : families)
    {
      std::cout << std::setw(10) << byFamily[family].Damage();
    }
    std::cout << "\n";
    if (requiredDamage >= 0.0 && all.Damage() > requiredDamage)
    {
      failed = true;
    }
  }
  if (failed)
  {
    std::cout << "FAILED: damage above " << requiredDamage << " % in some configuration\n";
    return 1;
  }
  return 0;
}
