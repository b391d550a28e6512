// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Cases of TestMLAATool: the formats round-tripped, each option, the debug images, the area texture and --help.
#include "mlaaToolTestSupport.h"

using namespace mlaaToolTest;

namespace
{
//------------------------------------------------------------------------------
// The cases

void HelpListsEveryOption()
{
  for (const char* flag : { "--help", "-h" })
  {
    // Help wins over anything else on the line, even arguments that are errors.
    const Run run = RunTool({ "--threshold", "abc", flag });
    MLAA_CHECK(run.Status == 0);
    MLAA_CHECK(run.Err.empty());
    // The text with every run of white space made one space, as the help wraps its lines.
    std::string words;
    {
      std::istringstream stream(run.Out);
      std::string word;
      while (stream >> word)
      {
        words += (words.empty() ? "" : " ") + word;
      }
    }
    for (const char* option : { "--threshold T", "--edges MODE", "--depth-image FILE",
           "--max-search-steps N", "--diagonals on|off", "--local-contrast F", "--dominant-blending on|off", "--alpha auto|straight|premultiplied", "--debug", "--value-range LO HI|auto", "--area-texture D",
           "--reconstruction on|off", "--preset NAME", "--method mlaa|dlaa", "--dlaa-epsilon E",
           "--dlaa-lambda L", "--dlaa-luma NAME", "--long-edges on|off",
           "-h, --help", "Usage: mlaa [options] INPUT OUTPUT", "--output-dir DIR",
           "--frames RANGE", "--jobs N", "-q, --quiet", "--format NAME",
           "mlaa [options] --output-dir DIR INPUT...",
           // The name DLAA is said once with what it is (a learned method has the same initials).
           "DLAA (--method dlaa; Andreev 2011, directionally localized antialiasing, not the "
           "learned method of the same initials" })
    {
      if (!MLAA_CHECK(words.find(option) != std::string::npos))
      {
        std::cout << "  help does not mention " << option << std::endl;
      }
    }
    // Every mode name, and the defaults, as vtkMLAAOptions has them.
    vtkNew<vtkMLAAOptions> defaults;
    for (int m = vtkMLAAOptions::LUMA; m <= vtkMLAAOptions::LAB; ++m)
    {
      MLAA_CHECK(words.find(std::string(vtkMLAAOptions::GetEdgeDetectionAsString(m)) + ":") !=
        std::string::npos);
    }
    for (int p = vtkMLAAOptions::LOW; p <= vtkMLAAOptions::MAX; ++p)
    {
      MLAA_CHECK(words.find(std::string(vtkMLAAOptions::GetPresetAsString(p)) + ":") !=
        std::string::npos);
    }
    for (int d = vtkMLAAOptions::NO_DEBUG_OUTPUT; d <= vtkMLAAOptions::BLENDING_WEIGHTS; ++d)
    {
      MLAA_CHECK(words.find(std::string(vtkMLAAOptions::GetDebugOutputAsString(d)) + ":") !=
        std::string::npos);
    }
    std::ostringstream threshold, steps;
    threshold << "Default: " << defaults->GetThreshold() << ".";
    steps << "Default: " << defaults->GetMaxSearchSteps() << " ";
    MLAA_CHECK(words.find(threshold.str()) != std::string::npos);
    MLAA_CHECK(words.find(steps.str()) != std::string::npos);
    MLAA_CHECK(words.find(std::string("Default: ") +
                 vtkMLAAOptions::GetEdgeDetectionAsString(defaults->GetEdgeDetection())) !=
      std::string::npos);
    // Every line fits a terminal.
    std::istringstream lines(run.Out);
    std::string line;
    size_t longest = 0;
    while (std::getline(lines, line))
    {
      longest = std::max(longest, line.size());
    }
    MLAA_CHECK(longest <= 80);
  }
}

void RoundTripPng8Rgb()
{
  RoundTrip(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 }),
    OIIO::TypeDesc::UINT8, "in.png", "out.png");
}

void RoundTripPng8Rgba()
{
  // Alpha differs across the edge as well; it must come back unpremultiplied, as stored.
  RoundTrip(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200, 64 }, { 240, 220, 40, 255 }),
    OIIO::TypeDesc::UINT8, "in.png", "out.png");
}

void RoundTripPng16Rgb()
{
  // Values far from multiples of 257, so that an 8-bit detour would show.
  RoundTrip(StaircaseImage(VTK_UNSIGNED_SHORT, { 1000, 40000, 12345 }, { 60001, 3, 50000 }),
    OIIO::TypeDesc::UINT16, "in.png", "out.png");
}

void RoundTripTiff16GreyAlpha()
{
  RoundTrip(StaircaseImage(VTK_UNSIGNED_SHORT, { 5000, 65535 }, { 61000, 30000 }),
    OIIO::TypeDesc::UINT16, "in.tif", "out.tif");
}

void RoundTripExrFloat()
{
  RoundTrip(StaircaseImage(VTK_FLOAT, { 0.1f, 0.333f, 0.9f }, { 0.95f, 0.01f, 0.123456f }),
    OIIO::TypeDesc::FLOAT, "in.exr", "out.exr");
}

void RoundTripExrHalf()
{
  // The input holds halves; the output must be half again: vtkImageMLAA's float result
  // rounded to half.
  auto pixels = StaircaseImage(VTK_FLOAT, { 0.1, 0.333, 0.9, 1.0 }, { 0.95, 0.01, 0.5, 0.25 });
  FillImage(pixels,
    [&](int x, int y, int, int k)
    { return static_cast<float>(half(static_cast<float>(GetValue(pixels, x, y, k)))); });
  const fs::path input = WorkFile("in.exr");
  const fs::path output = WorkFile("out.exr");
  WriteFile(pixels, input, OIIO::TypeDesc::HALF);
  ExpectSuccess({ input.string(), output.string() }, output);
  // OpenEXR holds premultiplied (associated) alpha: the tool blends it as it is.
  auto expected =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetPremultipliedAlpha(true); });
  CheckAntialiased(pixels, expected);
  FillImage(expected,
    [&](int x, int y, int, int k)
    { return static_cast<float>(half(static_cast<float>(GetValue(expected, x, y, k)))); });
  CheckFile(output, expected, OIIO::TypeDesc::HALF);
}

void RoundTripTiffFloatValueRange()
{
  // Values in [0, 100] with a faint (0.5 %) checkerboard in the flat top left corner: with
  // --value-range 0 100 the staircase is antialiased and the checkerboard is not an edge; with
  // the default range [0, 1] it would be.
  auto pixels = TwoToneImage(32, 24, VTK_FLOAT, { 10.0 }, { 90.0 }, Staircase);
  auto checkerboard = [](int x, int y) { return x < 8 && y >= 18; };
  FillImage(pixels,
    [&](int x, int y, int, int)
    {
      const double v = GetValue(pixels, x, y);
      return checkerboard(x, y) ? v + 0.5 * ((x + y) % 2) : v;
    });
  const fs::path input = WorkFile("in.tif");
  const fs::path output = WorkFile("out.tif");
  WriteFile(pixels, input, OIIO::TypeDesc::FLOAT);
  ExpectSuccess({ "--value-range", "0", "100", input.string(), output.string() }, output);
  auto expected = Filter(pixels, [](vtkImageMLAA* f) { f->SetValueRange(0.0, 100.0); });
  CheckFile(output, expected, OIIO::TypeDesc::FLOAT);
  CheckAntialiased(pixels, expected, checkerboard);
  for (int y = 18; y < 24; ++y)
  {
    for (int x = 0; x < 8; ++x)
    {
      MLAA_CHECK(GetValue(expected, x, y) == GetValue(pixels, x, y));
    }
  }
  MLAA_CHECK(Compare(Filter(pixels), expected).Count > 0);
}

void JpegInputPngOutput()
{
  // JPEG is lossy: the reference is the filter on the pixels the JPEG file decodes to.
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 });
  const fs::path input = WorkFile("in.jpg");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  const FileImage decoded = ReadFile(input);
  ExpectSuccess({ input.string(), output.string() }, output);
  CheckFile(output, Filter(decoded.Image), OIIO::TypeDesc::UINT8);
}

void OutputReplacedPermissionsKept()
{
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 });
  const fs::path input = WorkFile("in.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  auto expected = Filter(pixels);

  // A new file gets the permissions the umask gives, not the temporary file's 0600.
  umask(022);
  const fs::path fresh = WorkFile("new.png");
  ExpectSuccess({ input.string(), fresh.string() }, fresh);
  CheckFile(fresh, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK((fs::status(fresh).permissions() & fs::perms::all) ==
    (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
      fs::perms::others_read));

  // An existing file is replaced and keeps its permissions.
  const fs::path existing = WorkFile("existing.png");
  WriteText(existing, "not an image");
  fs::permissions(existing, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read,
    fs::perm_options::replace);
  ExpectSuccess({ input.string(), existing.string() }, existing);
  CheckFile(existing, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK((fs::status(existing).permissions() & fs::perms::all) ==
    (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));

  // The input itself may be the output.
  ExpectSuccess({ input.string(), input.string() }, input);
  CheckFile(input, expected, OIIO::TypeDesc::UINT8);
}

void FloatToPngConvertedWithWarning()
{
  // PNG cannot hold floats: OpenImageIO's closest type (uint8) is written, values clamped to
  // the value range and scaled, and a warning says so.
  auto pixels = StaircaseImage(VTK_FLOAT, { -0.5, 0.25, 0.9 }, { 1.5, 0.6, 0.1 });
  const fs::path input = WorkFile("in.exr");
  WriteFile(pixels, input, OIIO::TypeDesc::FLOAT);
  auto filtered = Filter(pixels);
  for (const double lo : { 0.0, -1.0 })
  {
    const double hi = lo == 0.0 ? 1.0 : 2.0;
    const fs::path output = WorkFile(lo == 0.0 ? "unit.png" : "range.png");
    std::vector<std::string> args = { input.string(), output.string() };
    if (lo != 0.0)
    {
      args.insert(args.begin(), { "--value-range", "-1", "2" });
    }
    ExpectSuccess(args, output, true);
    auto expected = MakeImage(32, 24, 3, VTK_UNSIGNED_CHAR);
    FillImage(expected,
      [&](int x, int y, int, int k)
      {
        const double v = (GetValue(filtered, x, y, k) - lo) / (hi - lo);
        return std::floor(255.0 * std::min(1.0, std::max(0.0, v)) + 0.5);
      });
    // OpenImageIO converts in float or double arithmetic: rounding may differ by one.
    CheckFile(output, expected, OIIO::TypeDesc::UINT8, 1.0);
    // Out-of-range values are clamped: the first channel, -0.5 and 1.5, is 0 and 255 with the
    // unit range.
    if (lo == 0.0)
    {
      const FileImage file = ReadFile(output);
      MLAA_CHECK(GetValue(file.Image, 0, 0, 0) == 0.0);    // bottom left: below the staircase
      MLAA_CHECK(GetValue(file.Image, 0, 23, 0) == 255.0); // top left: above it
    }
  }
}

void OptionThreshold()
{
  // A 60/255 step: an edge at the default threshold, none at 0.3.
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 100 }, { 160 });
  {
    const fs::path input = WorkFile("in.png");
    const fs::path output = WorkFile("out.png");
    WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
    ExpectSuccess({ "--threshold=0.3", input.string(), output.string() }, output);
    auto expected = Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetThreshold(0.3); });
    CheckFile(output, expected, OIIO::TypeDesc::UINT8);
    MLAA_CHECK(Compare(expected, pixels).Count == 0);
  }
  // The default threshold does antialias the same image, and so does an explicit lower one.
  MLAA_CHECK(Compare(Filter(pixels), pixels).Count > 0);
  RoundTrip(pixels, OIIO::TypeDesc::UINT8, "in.png", "out.png", { "--threshold", "0.2" },
    [](vtkImageMLAA* f) { f->GetOptions()->SetThreshold(0.2); });
}

void OptionEdgesColor()
{
  // Pure red against a green of (almost) the same luma: no luma edge at all, a colour edge.
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 255, 0, 0 }, { 0, 76, 0 });
  MLAA_CHECK(
    Compare(Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetEdgeDetectionToLuma(); }),
      pixels)
      .Count == 0);
  const std::string color = vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::COLOR);
  RoundTrip(pixels, OIIO::TypeDesc::UINT8, "in.png", "out.png", { "--edges", color },
    [](vtkImageMLAA* f) { f->GetOptions()->SetEdgeDetectionToColor(); });
}

void OptionEdgesLab()
{
  // Red against a blue of the same luma (87 * 0.2126 = 255 * 0.0722, within 0.0003): no luma
  // edge at all, a CIELAB one (Delta E above 50).
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 87, 0, 0 }, { 0, 0, 255 });
  MLAA_CHECK(
    Compare(Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetEdgeDetectionToLuma(); }),
      pixels)
      .Count == 0);
  const std::string lab = vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::LAB);
  RoundTrip(pixels, OIIO::TypeDesc::UINT8, "in.png", "out.png", { "--edges", lab },
    [](vtkImageMLAA* f) { f->GetOptions()->SetEdgeDetectionToLab(); });
  MLAA_CHECK(
    Compare(Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetEdgeDetectionToLab(); }),
      pixels)
      .Count > 0);
}

void OptionReconstruction()
{
  // A one-pixel diagonal line with one pixel missing: --reconstruction on closes it, as the
  // filter does; off (the default) leaves the gap.
  auto pixels = TwoToneImage(
    24, 24, VTK_UNSIGNED_CHAR, { 10, 20, 30 }, { 250, 200, 60 },
    [](int x, int y) { return x == y && x != 12; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--reconstruction", "on", input.string(), output.string() }, output);
  auto expected = Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->ReconstructionOn(); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(expected->GetScalarComponentAsDouble(12, 12, 0, 0) > 100.0); // the gap is closed
  MLAA_CHECK(pixels->GetScalarComponentAsDouble(12, 12, 0, 0) < 100.0);
  ExpectSuccess({ "--reconstruction=off", input.string(), output.string() }, output);
  CheckFile(output, Filter(pixels), OIIO::TypeDesc::UINT8);
}

void OptionPreset()
{
  // Steps 12 pixels long: the low preset's 4 steps (8 pixels each way) smooth them otherwise
  // than the default 8 steps.
  auto pixels = TwoToneImage(
    64, 16, VTK_UNSIGNED_CHAR, { 0 }, { 255 }, [](int x, int y) { return 12 * y > x + 20; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  for (int preset = vtkMLAAOptions::LOW; preset <= vtkMLAAOptions::MAX; ++preset)
  {
    ExpectSuccess(
      { "--preset", vtkMLAAOptions::GetPresetAsString(preset), input.string(), output.string() },
      output);
    CheckFile(output,
      Filter(pixels, [preset](vtkImageMLAA* f) { f->GetOptions()->SetPreset(preset); }),
      OIIO::TypeDesc::UINT8);
  }
  auto low = Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetPresetToLow(); });
  MLAA_CHECK(Compare(low, Filter(pixels)).Count > 0);
  // Options after the preset override it.
  ExpectSuccess(
    { "--preset=low", "--max-search-steps", "8", input.string(), output.string() }, output);
  CheckFile(output,
    Filter(pixels,
      [](vtkImageMLAA* f)
      {
        f->GetOptions()->SetPresetToLow();
        f->GetOptions()->SetMaxSearchSteps(8);
      }),
    OIIO::TypeDesc::UINT8);
  // Options that describe the data may come first.
  ExpectSuccess(
    { "--alpha", "straight", "--preset", "high", input.string(), output.string() }, output);
  // A quality option before the preset would be silently replaced: refused, nothing written.
  const fs::path untouched = WorkFile("untouched.png");
  ExpectFailure(
    { "--threshold", "0.2", "--preset", "high", input.string(), untouched.string() }, untouched,
    2);
}

void MethodDLAA()
{
  // --method dlaa gives vtkImageDLAA's image, 8-bit RGB and 16-bit grey + alpha, with default
  // and with given DLAA options; it differs from MLAA's.
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--method", "dlaa", input.string(), output.string() }, output);
  auto expected = FilterDLAA(pixels);
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(expected, pixels).Count > 0);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0);
  ExpectSuccess({ "--method=dlaa", "--dlaa-epsilon", "0.05", "--dlaa-lambda=5", "--dlaa-luma",
                  "green", "--long-edges", "off", input.string(), output.string() },
    output);
  auto configured = FilterDLAA(pixels, [](vtkDLAAOptions* o) {
    o->SetEpsilon(0.05);
    o->SetLambda(5.0);
    o->SetLumaFunctionToGreen();
    o->LongEdgesOff();
  });
  CheckFile(output, configured, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(configured, expected).Count > 0);
  // --method mlaa is the default.
  ExpectSuccess({ "--method", "mlaa", input.string(), output.string() }, output);
  CheckFile(output, Filter(pixels), OIIO::TypeDesc::UINT8);

  auto grey = StaircaseImage(VTK_UNSIGNED_SHORT, { 5000, 65535 }, { 61000, 30000 });
  const fs::path greyInput = WorkFile("grey.tif");
  const fs::path greyOutput = WorkFile("grey-out.tif");
  WriteFile(grey, greyInput, OIIO::TypeDesc::UINT16);
  ExpectSuccess({ "--method", "dlaa", greyInput.string(), greyOutput.string() }, greyOutput);
  CheckFile(greyOutput, FilterDLAA(grey), OIIO::TypeDesc::UINT16);
}

void OptionEdgesDepth()
{
  // The colour image has two staircases, the depth image (1-channel float TIFF) only the
  // shallow one: only that one is antialiased.
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 });
  auto depth = TwoToneImage(
    32, 24, VTK_FLOAT, { 0.25 }, { 0.75 }, [](int x, int y) { return 3 * y > x + 10; });
  const fs::path input = WorkFile("in.png");
  const fs::path depthFile = WorkFile("depth.tif");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  WriteFile(depth, depthFile, OIIO::TypeDesc::FLOAT);
  const std::string depthName = vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH);
  ExpectSuccess({ "--edges", depthName, "--depth-image", depthFile.string(), "--threshold", "0.01",
                  input.string(), output.string() },
    output);
  auto expected = Filter(
    pixels,
    [](vtkImageMLAA* f)
    {
      f->GetOptions()->SetEdgeDetectionToDepth();
      f->GetOptions()->SetThreshold(0.01);
    },
    depth);
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(expected, pixels).Count > 0);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0); // not what luma edges give
}

void OptionMaxSearchSteps()
{
  // Steps 12 pixels long: a search of 1 step (2 pixels each way) finds the ends of few lines,
  // and smooths only the pixels near them; the default search smooths most.
  auto pixels = TwoToneImage(
    64, 16, VTK_UNSIGNED_CHAR, { 0 }, { 255 }, [](int x, int y) { return 12 * y > x + 20; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--max-search-steps", "1", input.string(), output.string() }, output);
  auto expected = Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetMaxSearchSteps(1); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  CheckAntialiased(pixels, expected, nullptr, 0.1);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0);
}

void OptionDiagonals()
{
  // A staircase of one-pixel steps that turns flatter every fifth step: the diagonal search
  // smooths it differently from the orthogonal one, and --diagonals off gives the latter.
  auto pixels = TwoToneImage(
    48, 48, VTK_UNSIGNED_CHAR, { 0 }, { 255 }, [](int x, int y) { return 5 * y < 4 * x; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--diagonals", "off", input.string(), output.string() }, output);
  auto expected =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->DiagonalDetectionOff(); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0);
  ExpectSuccess({ "--diagonals=on", input.string(), output.string() }, output);
  CheckFile(output, Filter(pixels), OIIO::TypeDesc::UINT8);
}

void OptionLocalContrast()
{
  // A white parallelogram (its slanted sides staircases of 4-pixel runs) on a dark background
  // whose lower part is a little lighter (0 and 40 from row 22, a shading edge of 0.157 that
  // meets the slanted sides in the middle of their runs): --local-contrast 0 keeps the shading edge where it meets the silhouette, the
  // default drops it there; both as the filter does.
  auto pixels = MakeImage(40, 40, 1);
  FillImage(pixels, [](int x, int y, int, int) {
    const int shift = (y - 12) / 4;
    return (x >= 6 + shift && x < 26 + shift && y >= 12 && y < 28) ? 255.0
                                                                  : (y < 22 ? 0.0 : 40.0);
  });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--local-contrast", "0", input.string(), output.string() }, output);
  auto expected =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetLocalContrastFactor(0.0); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0);
  ExpectSuccess({ "--local-contrast=2.5", input.string(), output.string() }, output);
  CheckFile(output,
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetLocalContrastFactor(2.5); }),
    OIIO::TypeDesc::UINT8);
}

void OptionDominantBlending()
{
  // A white bar on black: its end pixels lie on a vertical line (above and below) and a
  // horizontal one (the side); --dominant-blending off averages both, as the filter does.
  auto pixels = TwoToneImage(
    16, 8, VTK_UNSIGNED_CHAR, { 0 }, { 255 }, [](int x, int y) { return y == 3 && x >= 5 && x <= 9; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  ExpectSuccess({ "--dominant-blending", "off", input.string(), output.string() }, output);
  auto expected =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->DominantDirectionBlendingOff(); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(Compare(expected, Filter(pixels)).Count > 0);
  ExpectSuccess({ "--dominant-blending=on", input.string(), output.string() }, output);
  CheckFile(output, Filter(pixels), OIIO::TypeDesc::UINT8);
}

void OptionValueRange()
{
  // 12-bit values (500 and 3500) in a 16-bit PNG: with the type's range (the default) the edge
  // is 0.05, below the threshold, and nothing changes; --value-range 0 4095 and --value-range
  // auto (the image's own 500..3500) antialias it as the filter does with that range.
  auto pixels = StaircaseImage(VTK_UNSIGNED_SHORT, { 500 }, { 3500 });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT16);
  ExpectSuccess({ input.string(), output.string() }, output);
  CheckFile(output, pixels, OIIO::TypeDesc::UINT16);
  ExpectSuccess({ "--value-range", "0", "4095", input.string(), output.string() }, output);
  auto twelveBits = Filter(pixels, [](vtkImageMLAA* f) { f->SetValueRange(0.0, 4095.0); });
  CheckAntialiased(pixels, twelveBits);
  CheckFile(output, twelveBits, OIIO::TypeDesc::UINT16);
  for (const std::vector<std::string>& option :
    { std::vector<std::string>{ "--value-range", "auto" }, { "--value-range=auto" } })
  {
    std::vector<std::string> args = option;
    args.push_back(input.string());
    args.push_back(output.string());
    ExpectSuccess(args, output);
    CheckFile(
      output, Filter(pixels, [](vtkImageMLAA* f) { f->SetValueRange(500.0, 3500.0); }),
      OIIO::TypeDesc::UINT16);
  }
}

void OptionAlpha()
{
  // A grey staircase over a transparent black background in a PNG (straight alpha): by default
  // the colour of partly covered pixels stays grey and only alpha is blended; --alpha
  // premultiplied blends the values as they are (darker edges in any viewer).
  auto pixels = StaircaseImage(VTK_UNSIGNED_CHAR, { 0, 0, 0, 0 }, { 150, 150, 150, 255 });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("out.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  auto straight = Filter(pixels);
  auto premultiplied =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->PremultipliedAlphaOn(); });
  MLAA_CHECK(Compare(straight, premultiplied).Count > 0);
  for (const char* mode : { "", "auto", "straight" })
  {
    std::vector<std::string> args = { input.string(), output.string() };
    if (*mode)
    {
      args.insert(args.begin(), { "--alpha", mode });
    }
    ExpectSuccess(args, output);
    CheckFile(output, straight, OIIO::TypeDesc::UINT8);
  }
  ExpectSuccess({ "--alpha", "premultiplied", input.string(), output.string() }, output);
  CheckFile(output, premultiplied, OIIO::TypeDesc::UINT8);
}

void DebugEdgesRgba8TopRowFirst()
{
  // The top half of the picture white, the bottom half black. In the file the top row comes
  // first: the edge is at the top boundary of the first black row, file row 3 of 6, and edges
  // are green (top boundary).
  auto pixels = TwoToneImage(
    8, 6, VTK_UNSIGNED_CHAR, { 0, 0, 0 }, { 255, 255, 255 }, [](int, int y) { return y >= 3; });
  const fs::path input = WorkFile("in.png");
  const fs::path output = WorkFile("edges.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT8);
  const std::string edges = vtkMLAAOptions::GetDebugOutputAsString(vtkMLAAOptions::EDGES);
  ExpectSuccess({ "--debug", edges, input.string(), output.string() }, output);
  CheckFile(output,
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetDebugOutputToEdges(); }),
    OIIO::TypeDesc::UINT8);
  MLAA_CHECK(ReadFile(output).Image->GetNumberOfScalarComponents() == 4);
  for (int row = 0; row < 6; ++row)
  {
    MLAA_CHECK(FileTexel(output, 4, row, 1) == (row == 3 ? 255 : 0)); // green: top edge
    MLAA_CHECK(FileTexel(output, 4, row, 0) == 0);                    // red: left edge
    MLAA_CHECK(FileTexel(output, 4, row, 3) == 255);                  // alpha
  }
}

void DebugWeightsRgba8()
{
  // A 16-bit input: the debug image is 8-bit RGBA all the same. Its alpha is a weight, not
  // coverage, and must be stored as it is.
  auto pixels = StaircaseImage(VTK_UNSIGNED_SHORT, { 1000 }, { 60000 });
  const fs::path input = WorkFile("in.tif");
  const fs::path output = WorkFile("weights.png");
  WriteFile(pixels, input, OIIO::TypeDesc::UINT16);
  const std::string weights =
    vtkMLAAOptions::GetDebugOutputAsString(vtkMLAAOptions::BLENDING_WEIGHTS);
  ExpectSuccess({ "--debug", weights, input.string(), output.string() }, output);
  auto expected =
    Filter(pixels, [](vtkImageMLAA* f) { f->GetOptions()->SetDebugOutputToBlendingWeights(); });
  CheckFile(output, expected, OIIO::TypeDesc::UINT8);
  MLAA_CHECK(ReadFile(output).Image->GetNumberOfScalarComponents() == 4);
  double largest[4] = { 0, 0, 0, 0 };
  for (int y = 0; y < 24; ++y)
  {
    for (int x = 0; x < 32; ++x)
    {
      for (int k = 0; k < 4; ++k)
      {
        largest[k] = std::max(largest[k], GetValue(expected, x, y, k));
      }
    }
  }
  // Weights in every channel (horizontal and vertical lines, both sides), none above 0.5.
  for (double w : largest)
  {
    MLAA_CHECK(w > 0.0 && w <= 128.0);
  }
}

// The area texture for cells of D texels: 5D x 5D, 8-bit RGB, laid out as Figure 4.2 counted
// from the top of the file; the same as vtkMLAAAreaTexture's image.
void CheckAreaTexture(int d)
{
  const fs::path output = WorkFile("area.png");
  ExpectSuccess({ "--area-texture", std::to_string(d), output.string() }, output);
  const FileImage file = ReadFile(output);
  int dims[3];
  file.Image->GetDimensions(dims);
  MLAA_CHECK(dims[0] == 5 * d && dims[1] == 5 * d);
  MLAA_CHECK(file.Image->GetNumberOfScalarComponents() == 3);
  MLAA_CHECK(file.Type == OIIO::TypeDesc::UINT8);
  MLAA_CHECK(file.Format == "png");

  // L shapes (section 4.3.3): for the p-th pixel from the crossing edge on a line of L pixels,
  // the area is 1/2 (1 - (2p + 1) / L). With e1 = 3 (crossing edge on the owning pixel's side,
  // at the left end) it is red; with e1 = 1 (opposite side) green.
  auto lArea = [](int p, int length) { return 0.5 * (1.0 - (2.0 * p + 1.0) / length); };
  struct Texel
  {
    int E1, E2, Left, Right;
  };
  for (const Texel& t : { Texel{ 3, 0, 0, 3 }, Texel{ 3, 0, 2, 5 }, Texel{ 1, 0, 0, 3 } })
  {
    const int column = d * t.E1 + t.Left;
    const int row = d * t.E2 + t.Right; // from the top of the file
    const int value = static_cast<int>(std::lround(255.0 * lArea(t.Left, t.Left + t.Right + 1)));
    const int channel = t.E1 == 3 ? 0 : 1;
    std::cout << "  texel (" << column << ", " << row << ") channel " << channel << ": "
              << FileTexel(output, column, row, channel) << ", expected " << value << std::endl;
    MLAA_CHECK(FileTexel(output, column, row, channel) == value);
    MLAA_CHECK(FileTexel(output, column, row, 1 - channel) == 0);
    MLAA_CHECK(FileTexel(output, column, row, 2) == 0);
  }
  if (d == 9)
  {
    MLAA_CHECK(FileTexel(output, 27, 3, 0) == 96); // the brief's example: round(255 * 3 / 8)
  }

  vtkNew<vtkMLAAAreaTexture> texture;
  texture->SetMaxDistance(d - 1);
  MLAA_CHECK(Compare(file.Image, texture->GetImage()).Count == 0);
}

void AreaTexture9()
{
  CheckAreaTexture(9);
}

void AreaTexture17()
{
  CheckAreaTexture(17);
}
} // namespace

static const bool Registered = RegisterCases({
  { "help-lists-every-option", HelpListsEveryOption },
  { "roundtrip-png8-rgb", RoundTripPng8Rgb },
  { "roundtrip-png8-rgba", RoundTripPng8Rgba },
  { "roundtrip-png16-rgb", RoundTripPng16Rgb },
  { "roundtrip-tiff16-grey-alpha", RoundTripTiff16GreyAlpha },
  { "roundtrip-exr-float", RoundTripExrFloat },
  { "roundtrip-exr-half", RoundTripExrHalf },
  { "roundtrip-tiff-float-value-range", RoundTripTiffFloatValueRange },
  { "jpeg-input-png-output", JpegInputPngOutput },
  { "output-replaced-permissions-kept", OutputReplacedPermissionsKept },
  { "float-to-png-converted-with-warning", FloatToPngConvertedWithWarning },
  { "option-threshold", OptionThreshold },
  { "option-edges-color", OptionEdgesColor },
  { "option-edges-depth", OptionEdgesDepth },
  { "option-edges-lab", OptionEdgesLab },
  { "option-reconstruction", OptionReconstruction },
  { "option-preset", OptionPreset },
  { "method-dlaa", MethodDLAA },
  { "option-max-search-steps", OptionMaxSearchSteps },
  { "option-diagonals", OptionDiagonals },
  { "option-local-contrast", OptionLocalContrast },
  { "option-dominant-blending", OptionDominantBlending },
  { "option-value-range", OptionValueRange },
  { "option-alpha", OptionAlpha },
  { "debug-edges-rgba8-top-row-first", DebugEdgesRgba8TopRowFirst },
  { "debug-weights-rgba8", DebugWeightsRgba8 },
  { "area-texture-9", AreaTexture9 },
  { "area-texture-17", AreaTexture17 } });
