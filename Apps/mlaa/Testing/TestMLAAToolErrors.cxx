// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Cases of TestMLAATool: errors: exit status 1 for failures, 2 for bad command lines.
#include "mlaaToolTestSupport.h"

using namespace mlaaToolTest;

namespace
{
//------------------------------------------------------------------------------
// Errors: exit status 1 for failures, 2 for bad command lines.

void ErrorMissingInput()
{
  const fs::path output = WorkFile("out.png");
  ExpectFailure({ WorkFile("missing.png").string(), output.string() }, output, Failure);
}

void ErrorCorruptInput()
{
  const fs::path input = WorkFile("x.png");
  WriteText(input, "This is a text file, not a PNG image.\n");
  const fs::path output = WorkFile("out.png");
  ExpectFailure({ input.string(), output.string() }, output, Failure);
  // A truncated PNG: a valid header, then nothing.
  const fs::path truncated = WorkFile("truncated.png");
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 }), truncated, OIIO::TypeDesc::UINT8);
  const std::string bytes = ReadText(truncated);
  WriteText(truncated, bytes.substr(0, bytes.size() / 2));
  ExpectFailure({ truncated.string(), output.string() }, output, Failure);
}

void ErrorUnsupportedOutputFormat()
{
  const fs::path input = GoodInput();
  for (const char* name : { "out.xyz", "out" })
  {
    const fs::path output = WorkFile(name);
    ExpectFailure({ input.string(), output.string() }, output, Failure);
  }
}

void ErrorOutputFormatRejectsImage()
{
  // BMP has no grey + alpha: the writer refuses the image once the temporary file exists.
  const fs::path input = WorkFile("in.png");
  WriteFile(
    StaircaseImage(VTK_UNSIGNED_CHAR, { 0, 255 }, { 255, 128 }), input, OIIO::TypeDesc::UINT8);
  const fs::path output = WorkFile("out.bmp");
  ExpectFailure({ input.string(), output.string() }, output, Failure);
}

void ErrorUnwritableOutputDirectory()
{
  const fs::path input = GoodInput();
  // A directory that does not exist, and a "directory" that is a file.
  ExpectFailure({ input.string(), (WorkFile("missing") / "out.png").string() },
    WorkFile("missing") / "out.png", Failure);
  WriteText(WorkFile("file.txt"), "a file\n");
  ExpectFailure({ input.string(), (WorkFile("file.txt") / "out.png").string() },
    WorkFile("file.txt") / "out.png", Failure);
  // A directory without write permission (root may write anywhere: not tried as root).
  if (geteuid() != 0)
  {
    const fs::path readOnly = WorkFile("read-only");
    fs::create_directory(readOnly);
    WriteText(readOnly / "out.png", "the previous contents of the output\n");
    fs::permissions(
      readOnly, fs::perms::owner_read | fs::perms::owner_exec, fs::perm_options::replace);
    const std::set<std::string> before = Listing(readOnly);
    const Run run = RunTool({ input.string(), (readOnly / "out.png").string() });
    MLAA_CHECK(run.Status == Failure && IsOneMlaaLine(run.Err));
    MLAA_CHECK(Listing(readOnly) == before);
    MLAA_CHECK(ReadText(readOnly / "out.png") == "the previous contents of the output\n");
    fs::permissions(readOnly, fs::perms::owner_all, fs::perm_options::replace);
  }
  // OUTPUT names an existing directory: the rename fails, the directory stays as it was.
  const fs::path directory = WorkFile("out.png");
  fs::create_directory(directory);
  WriteText(directory / "inside.txt", "untouched\n");
  const std::set<std::string> before = Listing(Where().Work);
  const Run run = RunTool({ input.string(), directory.string() });
  MLAA_CHECK(run.Status == Failure && IsOneMlaaLine(run.Err));
  MLAA_CHECK(Listing(Where().Work) == before);
  MLAA_CHECK(Listing(directory) == std::set<std::string>{ "inside.txt" });
}

// Each value of `option` is refused as a usage error, and no output is written.
void ExpectBadValues(const char* option, std::initializer_list<const char*> values)
{
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  for (const char* value : values)
  {
    ExpectFailure({ option, value, input.string(), output.string() }, output, Usage);
  }
}

void ErrorBadAlpha()
{
  ExpectBadValues("--alpha", { "associated", "", "Straight", "auto,straight" });
}

void ErrorBadThreshold()
{
  ExpectBadValues("--threshold", { "abc", "1.5", "-0.1", "nan", "inf", "", "0.5x", "0,5" });
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  ExpectFailure({ "--threshold=2", input.string(), output.string() }, output, Usage);
}

void ErrorUnknownEdgesName()
{
  ExpectBadValues("--edges", { "lum", "LUMA", "colour", "", "edges" });
}

void ErrorUnknownDebugName()
{
  ExpectBadValues("--debug", { "edge", "blending-weights", "luma", "" });
}

void ErrorBadMaxSearchSteps()
{
  ExpectBadValues("--max-search-steps", { "0", "129", "-1", "2.5", "eight", "99999999999999999999" });
}

void ErrorMethodOptions()
{
  ExpectBadValues("--method", { "fxaa", "MLAA", "", "dlaa,mlaa" });
  ExpectBadValues("--dlaa-epsilon", { "-0.1", "2", "x", "" });
  ExpectBadValues("--dlaa-lambda", { "-1", "101", "nan" });
  ExpectBadValues("--dlaa-luma", { "luma", "Green", "" });
  ExpectBadValues("--long-edges", { "yes", "1", "" });
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  // One method's options with the other method: refused, nothing written.
  for (const auto& args : std::vector<std::vector<std::string>>{
         { "--method", "dlaa", "--threshold", "0.2" }, { "--preset", "high", "--method", "dlaa" },
         { "--method", "dlaa", "--debug", "edges" }, { "--long-edges", "off" },
         { "--dlaa-lambda", "4", "--method", "mlaa" } })
  {
    std::vector<std::string> full = args;
    full.push_back(input.string());
    full.push_back(output.string());
    ExpectFailure(full, output, Usage);
  }
}

void ErrorBadPreset()
{
  ExpectBadValues("--preset", { "best", "High", "", "custom", "2" });
}

void ErrorBadReconstruction()
{
  ExpectBadValues("--reconstruction", { "yes", "1", "On", "" });
}

void ErrorBadLocalContrast()
{
  ExpectBadValues("--local-contrast", { "-1", "101", "two", "nan", "" });
}

void ErrorBadDominantBlending()
{
  ExpectBadValues("--dominant-blending", { "yes", "0", "Off", "" });
}

void ErrorBadDiagonals()
{
  ExpectBadValues("--diagonals", { "yes", "1", "ON", "" });
}

void ErrorBadValueRange()
{
  const fs::path input = GoodInput("in.exr");
  const fs::path output = WorkFile("out.exr");
  for (const auto& range : std::vector<std::pair<const char*, const char*>>{
         { "1", "0" }, { "0.5", "0.5" }, { "a", "1" }, { "0", "inf" }, { "nan", "1" } })
  {
    ExpectFailure({ "--value-range", range.first, range.second, input.string(), output.string() },
      output, Usage);
  }
  ExpectFailure({ "--value-range=0", "1", input.string(), output.string() }, output, Usage);
}

void ErrorMissingArgument()
{
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  ExpectFailure({}, output, Usage);
  ExpectFailure({ input.string() }, output, Usage);
  ExpectFailure({ input.string(), output.string(), "--threshold" }, output, Usage);
  ExpectFailure({ input.string(), output.string(), "--value-range", "0" }, output, Usage);
  ExpectFailure({ "--edges", "--debug", "edges", input.string(), output.string() }, output, Usage);
  ExpectFailure({ "--area-texture" }, output, Usage);
  ExpectFailure({ "--area-texture", "9" }, output, Usage);
  ExpectFailure({ "--edges", "depth", input.string(), output.string() }, output, Usage);
}

void ErrorExtraArgument()
{
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  ExpectFailure({ input.string(), output.string(), WorkFile("extra.png").string() }, output, Usage);
  ExpectFailure({ "--frobnicate", input.string(), output.string() }, output, Usage);
  ExpectFailure({ "--threshold", "0.2", "0.3", input.string(), output.string() }, output, Usage);
  ExpectFailure({ "--area-texture", "9", input.string(), output.string() }, output, Usage);
  ExpectFailure({ "--area-texture", "9", "--threshold", "0.2", output.string() }, output, Usage);
}

void ErrorMoreThan4Channels()
{
  // vtkImageMLAA refuses 5 channels; its error must become the one "mlaa: " line.
  const fs::path input = WorkFile("in.tif");
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0, 1, 2, 3, 4 }, { 200, 201, 202, 203, 204 }),
    input, OIIO::TypeDesc::UINT8);
  for (const char* name : { "out.tif", "out.png" })
  {
    const fs::path output = WorkFile(name);
    ExpectFailure({ input.string(), output.string() }, output, Failure);
  }
}

void ErrorDepthImage()
{
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  const std::string depthName = vtkMLAAOptions::GetEdgeDetectionAsString(vtkMLAAOptions::DEPTH);
  // Wrong size, wrong number of channels, missing.
  const fs::path small = WorkFile("small.tif");
  WriteFile(MakeImage(16, 24, 1, VTK_FLOAT, 0.5), small, OIIO::TypeDesc::FLOAT);
  const fs::path rgb = WorkFile("rgb.tif");
  WriteFile(MakeImage(32, 24, 3, VTK_FLOAT, 0.5), rgb, OIIO::TypeDesc::FLOAT);
  for (const fs::path& depth : { small, rgb, WorkFile("missing.tif") })
  {
    ExpectFailure(
      { "--edges", depthName, "--depth-image", depth.string(), input.string(), output.string() },
      output, Failure);
  }
  // A depth image without depth edges.
  const fs::path good = WorkFile("depth.tif");
  WriteFile(MakeImage(32, 24, 1, VTK_FLOAT, 0.5), good, OIIO::TypeDesc::FLOAT);
  ExpectFailure({ "--depth-image", good.string(), input.string(), output.string() }, output, Usage);
}

void ErrorBadAreaTexture()
{
  const fs::path output = WorkFile("area.png");
  for (const char* value : { "1", "0", "-9", "1025", "9.0", "nine", "" })
  {
    ExpectFailure({ "--area-texture", value, output.string() }, output, Usage);
  }
  ExpectFailure(
    { "--area-texture", "9", WorkFile("area.xyz").string() }, WorkFile("area.xyz"), Failure);
}
} // namespace

static const bool Registered = RegisterCases({
  { "error-method-options", ErrorMethodOptions },
  { "error-bad-alpha", ErrorBadAlpha },
  { "error-missing-input", ErrorMissingInput },
  { "error-corrupt-input", ErrorCorruptInput },
  { "error-unsupported-output-format", ErrorUnsupportedOutputFormat },
  { "error-output-format-rejects-image", ErrorOutputFormatRejectsImage },
  { "error-unwritable-output-directory", ErrorUnwritableOutputDirectory },
  { "error-bad-threshold", ErrorBadThreshold },
  { "error-unknown-edges-name", ErrorUnknownEdgesName },
  { "error-unknown-debug-name", ErrorUnknownDebugName },
  { "error-bad-max-search-steps", ErrorBadMaxSearchSteps },
  { "error-bad-preset", ErrorBadPreset },
  { "error-bad-reconstruction", ErrorBadReconstruction },
  { "error-bad-diagonals", ErrorBadDiagonals },
  { "error-bad-local-contrast", ErrorBadLocalContrast },
  { "error-bad-dominant-blending", ErrorBadDominantBlending },
  { "error-bad-value-range", ErrorBadValueRange },
  { "error-missing-argument", ErrorMissingArgument },
  { "error-extra-argument", ErrorExtraArgument },
  { "error-more-than-4-channels", ErrorMoreThan4Channels },
  { "error-depth-image", ErrorDepthImage },
  { "error-bad-area-texture", ErrorBadAreaTexture } });
