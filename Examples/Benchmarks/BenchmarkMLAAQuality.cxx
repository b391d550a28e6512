// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// mlaa-quality: the quality measure of the project's MEASURING.md on the shared scenes.
//
// For each scene, rendered offscreen at one size with one camera, it renders
//   none       single-sample (SetMultiSamples(0)), the input MLAA sees;
//   reference  N x N single-sample renders with the projection shifted by stratified sub-pixel
//              offsets (vtkCamera::SetWindowCenter(2 sx / W, 2 sy / H), sx, sy = (i + 0.5) / N - 0.5),
//              averaged in double precision;
//   FXAA       VTK's built-in FXAA (renderer->UseFXAAOn(), default vtkFXAAOptions);
//   MSAA4      4x multisampling (window->SetMultiSamples(4)); MSAA2 and MSAA8 likewise (a
//              driver may give another count: llvmpipe gives 4 for 2 and 8);
//   MLAA-CPU   vtkImageMLAA with default options on the single-sample render;
//   MLAA-pass  vtkOpenGLMLAAPass (delegate vtkRenderStepsPass, default options: overlays drawn
//              after the antialiasing);
//   DLAA-pass  vtkOpenGLDLAAPass (delegate vtkRenderStepsPass, default vtkDLAAOptions);
//   MLAA-temporal, DLAA-temporal  the two passes with temporal antialiasing (SetTemporal): the
//              still after 16 renders of the unchanged scene by a new pass;
//   MLAA-S2, MLAA-S4, MLAA-S8, DLAA-S4
//              the passes with SetMultiSamples(2, 4, 8): the method on each sample set of a
//              multisampled render, resolved (the count the driver gave is printed per scene);
//   MLAA-S4plain  MLAA-S4 without vtkOpenGLMLAAPass::SampleAreas (each sample set antialiased
//              as a single-sample image);
//   MLAA-S4pixel  MLAA-S4 without vtkOpenGLAntialiasingPass::SampleShading (each pixel shaded
//              once for all its samples, as plain multisampling does);
//   variants   (unless --no-variants) MLAA-pass with each feature of "Morphological
//              antialiasing and topological reconstruction" over the medium preset (+lab, +steps32,
//              +steps128, +recon), the three together (+all3) and each preset (P-low ...
//              P-max);
// all read back as RGB. Per method it reports, against the reference:
//   AAR      = 1 - MSE_E(method, reference) / MSE_E(none, reference), over the set E of pixels
//              where none and reference differ by more than 4/255 in some channel;
//   damage   = share of the pixels of F changed by more than 4/255 (in some channel) relative to
//              none, where F = pixels whose Chebyshev distance to E is greater than 2 (no E pixel
//              in the 5 x 5 square centred on them);
//   PSNR_E and PSNR_all (whole image), in dB, 8-bit peak;
//   changed  = share of all pixels the method changed by more than 4/255 (a no-op shows 0);
//   damage off the reference (CSV only) = share of F damaged and also more than 4/255 from the
//              reference: damage the reference disagrees with. The rest of the damage lies
//              within 4/255 of the reference on the other side of it from none, as where a
//              multisampled render puts a side between its sample positions (one sample of four
//              where the reference has an eighth: the rasterization's coverage steps, which 4x
//              MSAA has as well).
// It also reports, per scene, the CPU/GPU parity: the share of pixels where the pass (with
// AntialiasOverlaysOn, so that it sees the same image as the filter) is within 2/255 of
// MLAA-CPU in every channel.
// It prints a table and per-method summaries, writes a CSV and, per scene, a crop mosaic PNG:
// crops of the same region (the crop-size window with the largest squared none-vs-reference
// error), magnified with nearest-neighbour, left to right:
//   none | FXAA | MSAA4 | MLAA-CPU | MLAA-pass | DLAA-pass | MLAA-S4 | P-high | P-ultra |
//   reference
// each under a label strip.
#include "BenchmarkUtilities.h"
#include "vtkMLAAScenes.h"

#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkOpenGLDLAAPass.h"
#include "vtkOpenGLMLAAPass.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkRenderStepsPass.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextProperty.h"
#include "vtkTextRenderer.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace
{
using mlaaBenchmark::Stopwatch;

// The methods in table order ("none" first: its AAR is 0 by definition); the variants are
// added unless --no-variants is given.
std::vector<std::string> Methods = { "none", "FXAA", "MSAA2", "MSAA4", "MSAA8", "MLAA-CPU",
  "MLAA-pass", "DLAA-pass", "MLAA-S2", "MLAA-S4", "MLAA-S8", "MLAA-S4plain", "MLAA-S4pixel", "DLAA-S4",
  "MLAA-temporal",
  "DLAA-temporal" };
// The methods of the crop mosaic, in order.
std::vector<std::string> MosaicMethods = { "none", "FXAA", "MSAA4", "MLAA-CPU", "MLAA-pass",
  "DLAA-pass", "MLAA-S4" };


// A difference of more than this (0..255 units) in some channel counts as "differs".
const double Tolerance = 4.0;

// An 8-bit RGB image as a flat array, row 0 at the bottom (as vtkImageData).
struct Image
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Values; // 3 per pixel, 0..255

  double At(int x, int y, int c) const { return this->Values[(y * this->Width + x) * 3 + c]; }
};

bool ToImage(vtkImageData* data, Image& image)
{
  int dims[3];
  data->GetDimensions(dims);
  vtkDataArray* scalars = data->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfComponents() != 3 || data->GetScalarType() != VTK_UNSIGNED_CHAR)
  {
    std::cerr << "expected an 8-bit RGB image" << std::endl;
    return false;
  }
  image.Width = dims[0];
  image.Height = dims[1];
  const auto* p = static_cast<const unsigned char*>(data->GetScalarPointer());
  image.Values.assign(p, p + static_cast<std::size_t>(dims[0]) * dims[1] * 3);
  return true;
}

vtkSmartPointer<vtkImageData> ToVTK(const Image& image)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(image.Width, image.Height, 1);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(data->GetScalarPointer());
  for (std::size_t i = 0; i < image.Values.size(); ++i)
  {
    p[i] = static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(image.Values[i]))));
  }
  return data;
}

bool Differs(const Image& a, const Image& b, std::size_t pixel)
{
  for (int c = 0; c < 3; ++c)
  {
    if (std::abs(a.Values[pixel * 3 + c] - b.Values[pixel * 3 + c]) > Tolerance)
    {
      return true;
    }
  }
  return false;
}

double SquaredError(const Image& a, const Image& b, std::size_t pixel)
{
  double sum = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double d = a.Values[pixel * 3 + c] - b.Values[pixel * 3 + c];
    sum += d * d;
  }
  return sum;
}

double PSNR(double mse)
{
  return mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();
}

// The pixel sets of MEASURING.md.
struct Sets
{
  std::vector<char> E; // none and reference differ by > 4/255 in some channel
  std::vector<char> F; // Chebyshev distance to E greater than 2
  std::size_t ECount = 0;
  std::size_t FCount = 0;
};

Sets ComputeSets(const Image& none, const Image& reference)
{
  const int w = none.Width, h = none.Height;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  Sets sets;
  sets.E.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    sets.E[i] = Differs(none, reference, i) ? 1 : 0;
    sets.ECount += sets.E[i];
  }
  // Dilate E by a 5 x 5 square (separable: rows, then columns): the pixels within Chebyshev
  // distance 2 of E. F is the rest.
  const int r = 2;
  std::vector<char> rows(n, 0), near(n, 0);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      char hit = 0;
      for (int dx = -r; dx <= r && !hit; ++dx)
      {
        const int xx = x + dx;
        hit = (xx >= 0 && xx < w) ? sets.E[static_cast<std::size_t>(y) * w + xx] : 0;
      }
      rows[static_cast<std::size_t>(y) * w + x] = hit;
    }
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      char hit = 0;
      for (int dy = -r; dy <= r && !hit; ++dy)
      {
        const int yy = y + dy;
        hit = (yy >= 0 && yy < h) ? rows[static_cast<std::size_t>(yy) * w + x] : 0;
      }
      near[static_cast<std::size_t>(y) * w + x] = hit;
    }
  }
  sets.F.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i)
  {
    sets.F[i] = near[i] ? 0 : 1;
    sets.FCount += sets.F[i];
  }
  return sets;
}

struct Metrics
{
  double MSEE = 0.0;
  double MSEAll = 0.0;
  double AAR = 0.0;
  double Damage = 0.0;  // share of F, 0..1
  double Changed = 0.0; // share of all pixels, 0..1
  std::size_t Damaged = 0;
  std::size_t DamagedOffReference = 0; // of those, also more than 4/255 from the reference
};

Metrics Measure(const Image& method, const Image& none, const Image& reference, const Sets& sets,
  double noneMSEE)
{
  Metrics m;
  const std::size_t n = method.Values.size() / 3;
  double sumE = 0.0, sumAll = 0.0;
  std::size_t changed = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double se = SquaredError(method, reference, i);
    sumAll += se;
    if (sets.E[i])
    {
      sumE += se;
    }
    const bool differs = Differs(method, none, i);
    changed += differs ? 1 : 0;
    if (sets.F[i] && differs)
    {
      ++m.Damaged;
      m.DamagedOffReference += Differs(method, reference, i) ? 1 : 0;
    }
  }
  // Mean over pixels and channels.
  m.MSEE = sets.ECount ? sumE / (3.0 * sets.ECount) : 0.0;
  m.MSEAll = sumAll / (3.0 * n);
  m.AAR = noneMSEE > 0.0 ? 1.0 - m.MSEE / noneMSEE : std::numeric_limits<double>::quiet_NaN();
  m.Damage = sets.FCount ? static_cast<double>(m.Damaged) / sets.FCount : 0.0;
  m.Changed = static_cast<double>(changed) / n;
  return m;
}

// The origin of the crop-size window with the largest sum of squared none-vs-reference error
// (a summed-area table; the first maximum in row-major order wins).
void FindCrop(const Image& none, const Image& reference, int cw, int ch, int& cx, int& cy)
{
  const int w = none.Width, h = none.Height;
  std::vector<double> table(static_cast<std::size_t>(w + 1) * (h + 1), 0.0);
  auto T = [&](int x, int y) -> double& { return table[static_cast<std::size_t>(y) * (w + 1) + x]; };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      T(x + 1, y + 1) = SquaredError(none, reference, static_cast<std::size_t>(y) * w + x) +
        T(x, y + 1) + T(x + 1, y) - T(x, y);
    }
  }
  double best = -1.0;
  cx = cy = 0;
  for (int y = 0; y + ch <= h; ++y)
  {
    for (int x = 0; x + cw <= w; ++x)
    {
      const double sum = T(x + cw, y + ch) - T(x, y + ch) - T(x + cw, y) + T(x, y);
      if (sum > best)
      {
        best = sum;
        cx = x;
        cy = y;
      }
    }
  }
}

// Writes the crop mosaic: panels left to right in `images` order, each magnified `zoom` times
// (nearest neighbour), separated by `gap` grey pixels, under a label strip.
bool WriteMosaic(const std::string& path, const std::vector<const Image*>& images,
  const std::vector<std::string>& labels, int cx, int cy, int cw, int ch, int zoom)
{
  const int gap = 4, strip = 22;
  const int pw = cw * zoom, ph = ch * zoom;
  const int count = static_cast<int>(images.size());
  const int mw = count * pw + (count + 1) * gap;
  const int mh = ph + strip + 2 * gap;
  vtkNew<vtkImageData> mosaic;
  mosaic->SetDimensions(mw, mh, 1);
  mosaic->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(mosaic->GetScalarPointer());
  std::fill(out, out + static_cast<std::size_t>(mw) * mh * 3, static_cast<unsigned char>(96));

  vtkTextRenderer* text = vtkTextRenderer::GetInstance();
  vtkNew<vtkTextProperty> property;
  property->SetFontFamilyToArial();
  property->SetFontSize(14);
  property->SetColor(1.0, 1.0, 1.0);
  property->SetJustificationToLeft();
  property->SetVerticalJustificationToBottom();

  for (int k = 0; k < count; ++k)
  {
    const int ox = gap + k * (pw + gap), oy = gap; // panel origin, bottom-left
    for (int y = 0; y < ph; ++y)
    {
      for (int x = 0; x < pw; ++x)
      {
        const int sx = cx + x / zoom, sy = cy + y / zoom;
        for (int c = 0; c < 3; ++c)
        {
          const double v = images[k]->At(sx, sy, c);
          out[((static_cast<std::size_t>(oy + y)) * mw + ox + x) * 3 + c] =
            static_cast<unsigned char>(std::min(255.0, std::max(0.0, std::round(v))));
        }
      }
    }
    // The label, alpha-blended into the strip above the panel.
    vtkNew<vtkImageData> label;
    int dims[2] = { 0, 0 };
    if (text && text->RenderString(property, labels[k], label, dims, 72) &&
      label->GetNumberOfScalarComponents() == 4 && label->GetScalarType() == VTK_UNSIGNED_CHAR)
    {
      int ext[6];
      label->GetExtent(ext);
      const int lx = ox + 4, ly = oy + ph + (strip - dims[1]) / 2;
      for (int y = ext[2]; y <= std::min(ext[3], ext[2] + dims[1] - 1); ++y)
      {
        for (int x = ext[0]; x <= std::min(ext[1], ext[0] + dims[0] - 1); ++x)
        {
          const int tx = lx + x - ext[0], ty = ly + y - ext[2];
          if (tx < 0 || tx >= mw || ty < 0 || ty >= mh)
          {
            continue;
          }
          const auto* t = static_cast<unsigned char*>(label->GetScalarPointer(x, y, 0));
          const double a = t[3] / 255.0;
          unsigned char* o = out + (static_cast<std::size_t>(ty) * mw + tx) * 3;
          for (int c = 0; c < 3; ++c)
          {
            o[c] = static_cast<unsigned char>(std::round(o[c] * (1.0 - a) + t[c] * a));
          }
        }
      }
    }
  }
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(mosaic);
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

bool WritePNG(const Image& image, const std::string& path)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(ToVTK(image));
  writer->SetFileName(path.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

bool Capture(vtkRenderWindow* window, Image& image)
{
  return ToImage(vtkMLAAScenes::Capture(window), image);
}

struct SceneResult
{
  std::string Scene;
  std::size_t ECount = 0, FCount = 0;
  double Parity = 0.0; // share of pixels where the pass is within 2/255 of MLAA-CPU
  std::map<std::string, Metrics> ByMethod;
};

void Usage(const char* program)
{
  std::cout
    << "Usage: " << program << " [options]\n"
    << "Measures antialiasing quality against a supersampled reference (MEASURING.md).\n"
    << "  --size WxH        render size (default 800x600)\n"
    << "  --scenes a,b,c    scenes to measure (default all:";
  for (const auto& name : vtkMLAAScenes::Names())
  {
    std::cout << " " << name;
  }
  std::cout << ");\n"
            << "                    \"all\" and \"held-out\" stand for those lists; held-out scenes,\n"
            << "                    kept out of every default so that nothing is tuned on them:";
  for (const auto& name : vtkMLAAScenes::HeldOutNames())
  {
    std::cout << " " << name;
  }
  std::cout
    << "\n"
    << "  --samples N       reference is N x N shifted renders (default 8)\n"
    << "  --output-dir DIR  where the CSV and the crop mosaics go (default .)\n"
    << "  --crop WxH        crop size before magnification (default 100x75)\n"
    << "  --zoom Z          crop magnification (default 4)\n"
    << "  --write-full      also write the full-size render of every method per scene\n"
    << "  --no-variants     measure only the methods above, not the MLAA-pass variants:\n"
    << "                    +lab, +steps32, +steps128, +recon (each over the medium preset), +all3\n"
    << "                    (the three), P-low, P-medium, P-high, P-ultra, P-max (the presets)\n"
    << "For MLAA-CPU and MLAA-pass alike, " << mlaaBenchmark::MLAAOptionsUsage()
    << "Mosaic panel order, left to right: none | FXAA | MSAA4 | MLAA-CPU | MLAA-pass | "
       "DLAA-pass | MLAA-S4 | P-high | P-ultra | reference\n";
}
}

int main(int argc, char* argv[])
{
  int width = 800, height = 600, samples = 8, cropW = 100, cropH = 75, zoom = 4;
  std::vector<std::string> scenes = vtkMLAAScenes::Names();
  std::string outputDir = ".";
  bool writeFull = false;
  bool variants = true;
  vtkNew<vtkMLAAOptions> options; // for MLAA-CPU and MLAA-pass
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    const bool hasValue = i + 1 < argc;
    if (arg == "--help" || arg == "-h")
    {
      Usage(argv[0]);
      return EXIT_SUCCESS;
    }
    else if (arg == "--size" && hasValue && mlaaBenchmark::ParseSize(argv[i + 1], width, height))
    {
      ++i;
    }
    else if (arg == "--scenes" && hasValue)
    {
      // "all" and "held-out" stand for those lists.
      scenes = mlaaBenchmark::SceneList(argv[++i]);
    }
    else if (arg == "--samples" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], samples))
    {
      ++i;
    }
    else if (arg == "--output-dir" && hasValue)
    {
      outputDir = argv[++i];
    }
    else if (arg == "--crop" && hasValue && mlaaBenchmark::ParseSize(argv[i + 1], cropW, cropH))
    {
      ++i;
    }
    else if (arg == "--zoom" && hasValue && mlaaBenchmark::ParsePositive(argv[i + 1], zoom))
    {
      ++i;
    }
    else if (arg == "--write-full")
    {
      writeFull = true;
    }
    else if (arg == "--no-variants")
    {
      variants = false;
    }
    else if (mlaaBenchmark::ParseMLAAOption(argc, argv, i, options))
    {
      continue; // applied to `options`
    }
    else
    {
      std::cerr << "bad or incomplete argument: " << arg << std::endl;
      Usage(argv[0]);
      return EXIT_FAILURE;
    }
  }
  for (const auto& scene : scenes)
  {
    if (vtkMLAAScenes::Describe(scene).empty())
    {
      std::cerr << "unknown scene: " << scene << std::endl;
      return EXIT_FAILURE;
    }
  }
  if (variants)
  {
    for (const auto& variant : mlaaBenchmark::Variants())
    {
      Methods.push_back(variant.Name);
    }
    MosaicMethods.push_back("P-high");
    MosaicMethods.push_back("P-ultra");
  }
  cropW = std::min(cropW, width);
  cropH = std::min(cropH, height);
  std::error_code directoryError;
  std::filesystem::create_directories(outputDir, directoryError);
  if (directoryError)
  {
    std::cerr << "mlaa-quality: cannot create " << outputDir << ": " << directoryError.message()
              << std::endl;
    return EXIT_FAILURE;
  }

  std::cout << "mlaa-quality: " << width << "x" << height << ", reference " << samples << "x"
            << samples << " shifted renders, E: |none - reference| > 4/255 in some channel, "
            << "F: Chebyshev distance to E > 2 px" << std::endl;
  std::cout << "MLAA-CPU filters the RGB render; MLAA-pass runs on the same opaque window (KeepAlpha "
               "off: edges in the colour alone) and draws overlays after the antialiasing"
            << std::endl;
  std::cout << mlaaBenchmark::DescribeMLAAOptions(options) << std::endl;

  std::vector<SceneResult> results;
  std::string rendererName;
  int problems = 0;
  for (const auto& scene : scenes)
  {
    Stopwatch clock;
    auto window = vtkMLAAScenes::NewOffscreenWindow(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build(scene, renderer);

    std::map<std::string, Image> images;
    std::string multisampleNote; // the sample counts the passes used
    if (!Capture(window, images["none"]))
    {
      return EXIT_FAILURE;
    }
    if (rendererName.empty())
    {
      rendererName = mlaaBenchmark::OpenGLRenderer(window);
      mlaaBenchmark::PrintRasteriserNote(rendererName);
    }

    // Reference: N x N renders with the projection shifted by stratified sub-pixel offsets.
    vtkCamera* camera = renderer->GetActiveCamera();
    double center[2];
    camera->GetWindowCenter(center);
    Image& reference = images["reference"];
    reference = images["none"];
    std::fill(reference.Values.begin(), reference.Values.end(), 0.0);
    for (int j = 0; j < samples; ++j)
    {
      for (int i = 0; i < samples; ++i)
      {
        const double sx = (i + 0.5) / samples - 0.5;
        const double sy = (j + 0.5) / samples - 0.5;
        camera->SetWindowCenter(center[0] + 2.0 * sx / width, center[1] + 2.0 * sy / height);
        Image shifted;
        if (!Capture(window, shifted))
        {
          return EXIT_FAILURE;
        }
        for (std::size_t k = 0; k < shifted.Values.size(); ++k)
        {
          reference.Values[k] += shifted.Values[k];
        }
      }
    }
    for (double& v : reference.Values)
    {
      v /= static_cast<double>(samples) * samples;
    }
    camera->SetWindowCenter(center[0], center[1]);

    // VTK's built-in FXAA.
    renderer->UseFXAAOn();
    Capture(window, images["FXAA"]);
    renderer->UseFXAAOff();

    // 2x, 4x and 8x MSAA (as the window gives them).
    for (int count : { 2, 4, 8 })
    {
      window->SetMultiSamples(count);
      Capture(window, images["MSAA" + std::to_string(count)]);
    }
    window->SetMultiSamples(0);

    // vtkImageMLAA on the single-sample render.
    {
      vtkNew<vtkImageData> input;
      input->DeepCopy(ToVTK(images["none"]));
      vtkNew<vtkImageMLAA> filter;
      filter->SetInputData(input);
      filter->SetOptions(options);
      filter->Update();
      ToImage(filter->GetOutput(), images["MLAA-CPU"]);
    }

    // vtkOpenGLMLAAPass.
    {
      vtkNew<vtkRenderStepsPass> steps;
      vtkNew<vtkOpenGLMLAAPass> pass;
      pass->SetDelegatePass(steps);
      pass->SetOptions(options);
      renderer->SetPass(pass);
      Capture(window, images["MLAA-pass"]);
      // Multisampled: the method per sample set, resolved.
      for (int count : { 2, 4, 8 })
      {
        pass->SetMultiSamples(count);
        Capture(window, images["MLAA-S" + std::to_string(count)]);
        multisampleNote += " MLAA-S" + std::to_string(count) + ": " +
          std::to_string(pass->GetRenderedMultiSamples()) + " samples;";
      }
      pass->SetMultiSamples(4);
      pass->SampleAreasOff();
      Capture(window, images["MLAA-S4plain"]);
      pass->SampleAreasOn();
      pass->SampleShadingOff();
      Capture(window, images["MLAA-S4pixel"]);
      pass->SampleShadingOn();
      pass->SetMultiSamples(0);
      // Parity with MLAA-CPU: the overlays antialiased too, as the filter sees them.
      pass->AntialiasOverlaysOn();
      Capture(window, images["MLAA-pass-overlays"]);
      pass->AntialiasOverlaysOff();
      // The variants, with the pass as MLAA-pass (overlays after the antialiasing; the filter
      // gives the same image: TestMLAAPassMatchesFilter).
      if (variants)
      {
        for (const auto& variant : mlaaBenchmark::Variants())
        {
          vtkNew<vtkMLAAOptions> variantOptions;
          variant.Configure(variantOptions);
          pass->SetOptions(variantOptions);
          Capture(window, images[variant.Name]);
        }
      }
      renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(window);
    }

    // vtkOpenGLDLAAPass.
    {
      vtkNew<vtkRenderStepsPass> steps;
      vtkNew<vtkOpenGLDLAAPass> pass;
      pass->SetDelegatePass(steps);
      renderer->SetPass(pass);
      Capture(window, images["DLAA-pass"]);
      pass->SetMultiSamples(4);
      Capture(window, images["DLAA-S4"]);
      multisampleNote +=
        " DLAA-S4: " + std::to_string(pass->GetRenderedMultiSamples()) + " samples;";
      renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(window);
    }

    // Temporal antialiasing: the still after 16 renders (a new pass: the first render starts the
    // history).
    for (const char* name : { "MLAA-temporal", "DLAA-temporal" })
    {
      vtkNew<vtkRenderStepsPass> steps;
      vtkSmartPointer<vtkOpenGLAntialiasingPass> pass;
      if (std::string(name) == "MLAA-temporal")
      {
        auto mlaa = vtkSmartPointer<vtkOpenGLMLAAPass>::New();
        mlaa->SetOptions(options);
        pass = mlaa;
      }
      else
      {
        pass = vtkSmartPointer<vtkOpenGLDLAAPass>::New();
      }
      pass->SetDelegatePass(steps);
      pass->TemporalOn();
      renderer->SetPass(pass);
      for (int k = 1; k < 16; ++k)
      {
        window->Render();
      }
      Capture(window, images[name]);
      renderer->SetPass(nullptr);
      pass->ReleaseGraphicsResources(window);
    }

    // The state must be back to single-sample, no AA: the plain render must not have changed.
    Image again;
    Capture(window, again);
    std::size_t drift = 0;
    for (std::size_t k = 0; k < again.Values.size() / 3; ++k)
    {
      drift += again.Values[k * 3] != images["none"].Values[k * 3] ||
          again.Values[k * 3 + 1] != images["none"].Values[k * 3 + 1] ||
          again.Values[k * 3 + 2] != images["none"].Values[k * 3 + 2]
        ? 1
        : 0;
    }
    if (drift)
    {
      std::cerr << "WARNING: scene " << scene << ": the plain render after all methods differs from "
                << "the first one in " << drift << " pixels (state not reset?)" << std::endl;
      ++problems;
    }

    SceneResult result;
    result.Scene = scene;
    {
      const Image& cpu = images["MLAA-CPU"];
      const Image& gpu = images["MLAA-pass-overlays"];
      std::size_t within = 0;
      const std::size_t pixels = cpu.Values.size() / 3;
      for (std::size_t k = 0; k < pixels; ++k)
      {
        bool close = true;
        for (int c = 0; c < 3; ++c)
        {
          close = close && std::abs(cpu.Values[k * 3 + c] - gpu.Values[k * 3 + c]) <= 2.0;
        }
        within += close ? 1 : 0;
      }
      result.Parity = pixels ? static_cast<double>(within) / pixels : 0.0;
    }
    const Sets sets = ComputeSets(images["none"], reference);
    result.ECount = sets.ECount;
    result.FCount = sets.FCount;
    const Metrics none = Measure(images["none"], images["none"], reference, sets, 0.0);
    for (const auto& method : Methods)
    {
      result.ByMethod[method] = Measure(images[method], images["none"], reference, sets, none.MSEE);
    }
    result.ByMethod["none"].AAR = 0.0;
    results.push_back(result);

    int cx = 0, cy = 0;
    FindCrop(images["none"], reference, cropW, cropH, cx, cy);
    std::vector<const Image*> panels;
    std::vector<std::string> labels;
    for (const auto& method : MosaicMethods)
    {
      panels.push_back(&images[method]);
      labels.push_back(method);
    }
    panels.push_back(&reference);
    labels.push_back("reference " + std::to_string(samples) + "x" + std::to_string(samples));
    const std::string mosaic = outputDir + "/quality-" + scene + "-crops.png";
    if (!WriteMosaic(mosaic, panels, labels, cx, cy, cropW, cropH, zoom))
    {
      std::cerr << "could not write " << mosaic << std::endl;
      ++problems;
    }
    if (writeFull)
    {
      for (const auto& entry : images)
      {
        const std::string path = outputDir + "/quality-" + scene + "-" + entry.first + ".png";
        if (!WritePNG(entry.second, path))
        {
          std::cerr << "could not write " << path << std::endl;
          ++problems;
        }
      }
    }
    // The crop origin as the PNG shows it (row 0 at the top).
    std::cout << "scene " << scene << " (" << vtkMLAAScenes::Describe(scene) << "): |E| = "
              << sets.ECount << " px, |F| = " << sets.FCount << " px, crop " << cropW << "x"
              << cropH << " at x = " << cx << ", y = " << (height - cy - cropH)
              << " from the top-left, " << std::fixed << std::setprecision(1)
              << clock.Milliseconds() / 1000.0 << " s; CPU/GPU parity "
              << std::setprecision(3) << 100.0 * result.Parity << " % of pixels within 2/255"
              << std::defaultfloat << std::endl;
    const bool msaaSame = images["MSAA2"].Values == images["MSAA4"].Values &&
      images["MSAA8"].Values == images["MSAA4"].Values;
    std::cout << "  multisampling:" << multisampleNote
              << (msaaSame ? " the window's MSAA2 and MSAA8 images equal MSAA4's" : "")
              << std::endl;
  }

  // The table.
  std::cout << "\n"
            << std::left << std::setw(12) << "scene" << std::setw(14) << "method" << std::right
            << std::setw(8) << "AAR" << std::setw(10) << "damage%" << std::setw(9) << "PSNR_E"
            << std::setw(10) << "PSNR_all" << std::setw(10) << "changed%" << "\n";
  std::ofstream csv(outputDir + "/quality.csv");
  if (!csv)
  {
    std::cerr << "could not write " << outputDir << "/quality.csv" << std::endl;
    ++problems;
  }
  csv << "scene,method,E_pixels,F_pixels,AAR,damage_percent,damaged_pixels,psnr_E_dB,psnr_all_dB,"
         "changed_percent,damage_off_reference_percent\n";
  for (const auto& result : results)
  {
    for (const auto& method : Methods)
    {
      const Metrics& m = result.ByMethod.at(method);
      std::cout << std::left << std::setw(12) << result.Scene << std::setw(14) << method
                << std::right << std::fixed << std::setprecision(3) << std::setw(8) << m.AAR
                << std::setw(10) << 100.0 * m.Damage << std::setprecision(2) << std::setw(9)
                << PSNR(m.MSEE) << std::setw(10) << PSNR(m.MSEAll) << std::setprecision(3)
                << std::setw(10) << 100.0 * m.Changed << "\n";
      csv << result.Scene << "," << method << "," << result.ECount << "," << result.FCount << ","
          << std::setprecision(6) << m.AAR << "," << 100.0 * m.Damage << "," << m.Damaged << ","
          << PSNR(m.MSEE) << "," << PSNR(m.MSEAll) << "," << 100.0 * m.Changed << ","
          << (result.FCount ? 100.0 * m.DamagedOffReference / result.FCount : 0.0) << "\n";
    }
  }
  std::cout << std::defaultfloat;

  // CPU/GPU parity.
  double worstParity = 1.0;
  std::string worstParityScene;
  std::cout << "\nCPU/GPU parity (pass with overlays antialiased vs MLAA-CPU, pixels within 2/255):";
  for (const auto& result : results)
  {
    std::cout << " " << result.Scene << " " << std::fixed << std::setprecision(3)
              << 100.0 * result.Parity << " %" << std::defaultfloat;
    if (result.Parity < worstParity || worstParityScene.empty())
    {
      worstParity = result.Parity;
      worstParityScene = result.Scene;
    }
  }
  std::cout << "\nworst parity: " << std::fixed << std::setprecision(3) << 100.0 * worstParity
            << " % (" << worstParityScene << ")" << std::defaultfloat << std::endl;

  // Per-method summaries.
  std::cout << "\n"
            << std::left << std::setw(14) << "method" << std::right << std::setw(10) << "meanAAR"
            << std::setw(10) << "worstAAR" << "  " << std::left << std::setw(12) << "(scene)"
            << std::right << std::setw(13) << "meanDamage%" << std::setw(12) << "maxDamage%"
            << std::setw(12) << "meanPSNR_E" << "\n";
  for (const auto& method : Methods)
  {
    double sumAAR = 0.0, worstAAR = std::numeric_limits<double>::infinity(), sumDamage = 0.0,
           maxDamage = 0.0, sumPSNR = 0.0;
    std::string worstScene;
    int count = 0;
    for (const auto& result : results)
    {
      const Metrics& m = result.ByMethod.at(method);
      if (std::isnan(m.AAR))
      {
        continue;
      }
      sumAAR += m.AAR;
      if (m.AAR < worstAAR)
      {
        worstAAR = m.AAR;
        worstScene = result.Scene;
      }
      sumDamage += m.Damage;
      maxDamage = std::max(maxDamage, m.Damage);
      sumPSNR += PSNR(m.MSEE);
      ++count;
    }
    if (!count)
    {
      continue;
    }
    std::cout << std::left << std::setw(14) << method << std::right << std::fixed
              << std::setprecision(3) << std::setw(10) << sumAAR / count << std::setw(10)
              << worstAAR << "  " << std::left << std::setw(12) << ("(" + worstScene + ")")
              << std::right << std::setw(13) << 100.0 * sumDamage / count << std::setw(12)
              << 100.0 * maxDamage << std::setprecision(2) << std::setw(12) << sumPSNR / count
              << std::defaultfloat << "\n";
  }
  std::cout << "\nCSV: " << outputDir << "/quality.csv; crop mosaics: " << outputDir
            << "/quality-<scene>-crops.png (none | FXAA | MSAA4 | MLAA-CPU | MLAA-pass | DLAA-pass | MLAA-S4 | "
               "P-high | P-ultra | reference)"
            << std::endl;
  return problems ? EXIT_FAILURE : EXIT_SUCCESS;
}
