// Tests of the `mlaa` command-line tool, one case per ctest test:
//
//   TestMLAATool CASE MLAA_EXECUTABLE SCRATCH_DIRECTORY
//
// Each case writes its input images with OpenImageIO (row by row, with code of its own rather
// than the tool's), runs the tool as a child process, and checks the exit status, stdout,
// stderr and the files left behind. Antialiased images are compared exactly with vtkImageMLAA
// run here on the same pixels; the checks that antialiasing happened at all (edge pixels
// change, flat regions do not) are separate, as VTK's loose regression comparison cannot show
// it (see the project's ENVIRONMENT notes).
#include "vtkMLAATestUtilities.h"

#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkMLAAAreaTexture.h"

#include <OpenImageIO/half.h>
#include <OpenImageIO/imageio.h>

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstring>
#include <random>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>
#include <vector>

extern char** environ;

using namespace vtkMLAATest;
namespace fs = std::filesystem;

namespace
{
//------------------------------------------------------------------------------
// Where things are

struct Context
{
  std::string Tool; // the mlaa executable
  // The same tool with the test hooks compiled in (mlaa-test-hooks): runs whose environment
  // asks for a simulated crash (MLAA_TEST_CRASH_WHILE_WRITING) use it.
  std::string HookedTool;
  fs::path Work;    // input and output images
  fs::path Logs;    // the tool's stdout and stderr
  int RandomCases = 100; // cases of each random test
};

Context& Where()
{
  static Context context;
  return context;
}

fs::path WorkFile(const std::string& name)
{
  return Where().Work / name;
}

std::string ReadText(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void WriteText(const fs::path& path, const std::string& text)
{
  std::ofstream out(path, std::ios::binary);
  out << text;
}

// Names of the files in a directory, hidden ones included.
std::set<std::string> Listing(const fs::path& directory)
{
  std::set<std::string> names;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(directory, error))
  {
    names.insert(entry.path().filename().string());
  }
  return names;
}

//------------------------------------------------------------------------------
// Image files, written and read here independently of the tool's code: one scanline at a time,
// file row r <-> vtkImageData row height - 1 - r.

OIIO::TypeDesc BufferTypeOf(vtkImageData* image)
{
  switch (image->GetScalarType())
  {
    case VTK_UNSIGNED_CHAR:
      return OIIO::TypeDesc::UINT8;
    case VTK_UNSIGNED_SHORT:
      return OIIO::TypeDesc::UINT16;
    case VTK_FLOAT:
      return OIIO::TypeDesc::FLOAT;
    default:
      throw std::runtime_error("test images are uint8, uint16 or float");
  }
}

void WriteFile(vtkImageData* image, const fs::path& path, OIIO::TypeDesc fileType)
{
  int dims[3];
  image->GetDimensions(dims);
  const int channels = image->GetNumberOfScalarComponents();
  const OIIO::TypeDesc bufferType = BufferTypeOf(image);
  OIIO::ImageSpec spec(dims[0], dims[1], channels, fileType);
  spec.attribute("oiio:UnassociatedAlpha", 1); // alpha as stored, as the tool keeps it
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out || !out->open(path.string(), spec))
  {
    throw std::runtime_error("cannot write test image " + path.string() + ": " +
      (out ? out->geterror() : OIIO::geterror()));
  }
  // Each row from a copy with room after it: OpenImageIO 2.4's HEIF writer reads past the end
  // of rows (the tool works around it in its own way).
  const size_t rowBytes = static_cast<size_t>(dims[0]) * channels * bufferType.size();
  std::vector<char> rowCopy(rowBytes + 256, 0);
  for (int row = 0; row < dims[1]; ++row)
  {
    std::memcpy(rowCopy.data(), image->GetScalarPointer(0, dims[1] - 1 - row, 0), rowBytes);
    if (!out->write_scanline(row, 0, bufferType, rowCopy.data()))
    {
      throw std::runtime_error("cannot write test image " + path.string() + ": " + out->geterror());
    }
  }
  out->close();
}

// A file read back: its pixels (half as float) and what the file says it holds.
struct FileImage
{
  vtkSmartPointer<vtkImageData> Image;
  OIIO::TypeDesc Type;
  std::string Format;
};

FileImage ReadFile(const fs::path& path)
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path.string(), &config);
  if (!in)
  {
    throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  }
  const OIIO::ImageSpec& spec = in->spec();
  FileImage file;
  file.Type = spec.format;
  file.Format = in->format_name();
  int vtkType = VTK_FLOAT;
  if (spec.format == OIIO::TypeDesc::UINT8)
  {
    vtkType = VTK_UNSIGNED_CHAR;
  }
  else if (spec.format == OIIO::TypeDesc::UINT16)
  {
    vtkType = VTK_UNSIGNED_SHORT;
  }
  else if (spec.format != OIIO::TypeDesc::HALF && spec.format != OIIO::TypeDesc::FLOAT)
  {
    throw std::runtime_error(path.string() + " holds " + spec.format.c_str() + " pixels");
  }
  file.Image = MakeImage(spec.width, spec.height, spec.nchannels, vtkType);
  const OIIO::TypeDesc bufferType = BufferTypeOf(file.Image);
  for (int row = 0; row < spec.height; ++row)
  {
    if (!in->read_scanline(
          row, 0, bufferType, file.Image->GetScalarPointer(0, spec.height - 1 - row, 0)))
    {
      throw std::runtime_error("cannot read " + path.string() + ": " + in->geterror());
    }
  }
  return file;
}

// One value of a file as stored, at (column, row) counted from the top left of the file.
int FileTexel(const fs::path& path, int column, int row, int channel)
{
  auto in = OIIO::ImageInput::open(path.string());
  if (!in)
  {
    throw std::runtime_error("cannot read " + path.string() + ": " + OIIO::geterror());
  }
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<unsigned char> line(static_cast<size_t>(spec.width) * spec.nchannels);
  if (!in->read_scanline(row, 0, OIIO::TypeDesc::UINT8, line.data()))
  {
    throw std::runtime_error("cannot read " + path.string() + ": " + in->geterror());
  }
  return line[static_cast<size_t>(column) * spec.nchannels + channel];
}

//------------------------------------------------------------------------------
// Running the tool

// The argv and envp arrays of posix_spawn: a command, and the given variables ahead of this
// process's own environment. The arrays point into the object's strings, so it is not copied.
struct SpawnVectors
{
  SpawnVectors(std::vector<std::string> command, std::vector<std::string> variables)
    : Command(std::move(command))
    , Variables(std::move(variables))
  {
    for (std::string& arg : this->Command)
    {
      this->Argv.push_back(&arg[0]);
    }
    this->Argv.push_back(nullptr);
    for (std::string& variable : this->Variables)
    {
      this->Envp.push_back(&variable[0]);
    }
    for (char** e = environ; *e; ++e)
    {
      this->Envp.push_back(*e);
    }
    this->Envp.push_back(nullptr);
  }
  SpawnVectors(const SpawnVectors&) = delete;
  SpawnVectors& operator=(const SpawnVectors&) = delete;

  std::vector<std::string> Command, Variables;
  std::vector<char*> Argv, Envp;
};

struct Run
{
  int Status = -1;
  std::string Out;
  std::string Err;
  bool TimedOut = false;
  double Seconds = 0.0;
};

// Runs the tool with `args` (and `environment` added to this process's), killing it after
// `timeoutSeconds`: Status is then -1 and TimedOut true.
Run RunTool(const std::vector<std::string>& args,
  const std::vector<std::string>& environment = {}, double timeoutSeconds = 120.0,
  bool quiet = false)
{
  const fs::path outPath = Where().Logs / "stdout";
  const fs::path errPath = Where().Logs / "stderr";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(
    &actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(
    &actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const bool hooked = std::any_of(environment.begin(), environment.end(),
    [](const std::string& variable) { return variable.rfind("MLAA_TEST_CRASH", 0) == 0; });
  std::vector<std::string> command = { hooked ? Where().HookedTool : Where().Tool };
  command.insert(command.end(), args.begin(), args.end());
  const SpawnVectors spawn(command, environment);

  if (!quiet)
  {
    std::cout << "$ mlaa";
    for (const std::string& arg : args)
    {
      std::cout << " '" << arg << "'";
    }
    std::cout << std::endl;
  }

  Run run;
  pid_t pid;
  if (posix_spawn(&pid, command[0].c_str(), &actions, nullptr, spawn.Argv.data(),
        spawn.Envp.data()) != 0)
  {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error("cannot run " + command[0]);
  }
  posix_spawn_file_actions_destroy(&actions);
  const auto start = std::chrono::steady_clock::now();
  int status = 0;
  for (;;)
  {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid)
    {
      break;
    }
    run.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (done < 0 || run.Seconds > timeoutSeconds)
    {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      run.TimedOut = true;
      break;
    }
    usleep(run.Seconds < 1.0 ? 2000 : 20000);
  }
  run.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.Status = run.TimedOut ? -1
    : WIFEXITED(status)     ? WEXITSTATUS(status)
                            : 128 + WTERMSIG(status);
  run.Out = ReadText(outPath);
  run.Err = ReadText(errPath);
  if (!quiet || run.TimedOut || run.Status > 2)
  {
    std::cout << "  exit status " << run.Status << (run.TimedOut ? " (timed out)" : "")
              << "; stderr: " << run.Err
              << (run.Err.empty() || run.Err.back() != '\n' ? "\n" : "");
  }
  return run;
}

// stderr is exactly one line, starting with "mlaa: ".
bool IsOneMlaaLine(const std::string& err)
{
  return err.size() > 6 && err.compare(0, 6, "mlaa: ") == 0 && err.back() == '\n' &&
    std::count(err.begin(), err.end(), '\n') == 1;
}

// Runs the tool on arguments that must succeed and produce `output` (and nothing else in its
// directory); stderr must be empty unless a warning is expected.
void ExpectSuccess(
  const std::vector<std::string>& args, const fs::path& output, bool expectWarning = false)
{
  const fs::path directory = output.parent_path();
  std::set<std::string> expected = Listing(directory);
  expected.insert(output.filename().string());
  const Run run = RunTool(args);
  MLAA_CHECK(run.Status == 0);
  MLAA_CHECK(run.Out.empty());
  if (expectWarning)
  {
    MLAA_CHECK(IsOneMlaaLine(run.Err) && run.Err.compare(0, 15, "mlaa: warning: ") == 0);
  }
  else
  {
    MLAA_CHECK(run.Err.empty());
  }
  MLAA_CHECK(fs::is_regular_file(output));
  MLAA_CHECK(Listing(directory) == expected); // no temporary file left
}

// Runs the tool on arguments that must fail with `status`: one "mlaa: " line on stderr, nothing
// on stdout, no new file anywhere near `output`; tried once without `output` (it must not
// appear) and once with an existing `output` (it must be unchanged).
void ExpectFailure(const std::vector<std::string>& args, const fs::path& output, int status)
{
  const fs::path directory = output.parent_path();
  for (bool existing : { false, true })
  {
    if (existing && !fs::is_directory(directory))
    {
      continue; // no file can exist there
    }
    const std::string previous = "the previous contents of the output\n";
    if (existing)
    {
      WriteText(output, previous);
    }
    const std::set<std::string> before = Listing(Where().Work);
    const std::set<std::string> beforeOutputDirectory = Listing(directory);
    const Run run = RunTool(args);
    MLAA_CHECK(run.Status == status);
    MLAA_CHECK(run.Out.empty());
    MLAA_CHECK(IsOneMlaaLine(run.Err));
    MLAA_CHECK(run.Err.compare(0, 14, "mlaa: warning:") != 0);
    // VTK's own error format must not show through.
    MLAA_CHECK(run.Err.find("ERROR: In") == std::string::npos);
    MLAA_CHECK(run.Err.find("(0x") == std::string::npos);
    MLAA_CHECK(Listing(Where().Work) == before);
    MLAA_CHECK(Listing(directory) == beforeOutputDirectory);
    if (existing)
    {
      MLAA_CHECK(ReadText(output) == previous);
      fs::remove(output);
    }
    else
    {
      MLAA_CHECK(!fs::exists(output));
    }
  }
}

//------------------------------------------------------------------------------
// Test images

// Two values per channel, `lo` below and `hi` above a shape given by `inside(x, y)` (y up).
vtkSmartPointer<vtkImageData> TwoToneImage(int width, int height, int type,
  const std::vector<double>& lo, const std::vector<double>& hi,
  const std::function<bool(int, int)>& inside)
{
  auto image = MakeImage(width, height, static_cast<int>(lo.size()), type);
  FillImage(image, [&](int x, int y, int, int k) { return inside(x, y) ? hi[k] : lo[k]; });
  return image;
}

// Two staircases: a shallow one (steps 3 pixels long, horizontal edges) and a steep one
// (vertical edges), so that L, Z and U shapes of both orientations occur.
bool Staircase(int x, int y)
{
  return (3 * y > x + 10) != (3 * x > y + 60);
}

// A staircase image of the given type, lo and hi values per channel.
vtkSmartPointer<vtkImageData> StaircaseImage(
  int type, const std::vector<double>& lo, const std::vector<double>& hi)
{
  return TwoToneImage(32, 24, type, lo, hi, Staircase);
}

vtkSmartPointer<vtkImageData> Filter(vtkImageData* input,
  const std::function<void(vtkImageMLAA*)>& configure = nullptr, vtkImageData* depth = nullptr)
{
  vtkNew<vtkImageMLAA> filter;
  if (configure)
  {
    configure(filter);
  }
  filter->SetInputData(input);
  if (depth)
  {
    filter->SetDepthInputData(depth);
  }
  filter->Update();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}

vtkSmartPointer<vtkImageData> FilterDLAA(
  vtkImageData* input, const std::function<void(vtkDLAAOptions*)>& configure = nullptr)
{
  vtkNew<vtkImageDLAA> filter;
  if (configure)
  {
    configure(filter->GetOptions());
  }
  filter->SetInputData(input);
  filter->Update();
  auto output = vtkSmartPointer<vtkImageData>::New();
  output->DeepCopy(filter->GetOutput());
  return output;
}

bool SamePixel(vtkImageData* image, int x0, int y0, int x1, int y1)
{
  for (int k = 0; k < image->GetNumberOfScalarComponents(); ++k)
  {
    if (GetValue(image, x0, y0, k) != GetValue(image, x1, y1, k))
    {
      return false;
    }
  }
  return true;
}

// Antialiasing happened where it should and nowhere else: pixels whose four neighbours all
// equal them (flat regions) are unchanged; pixels on an edge changed, most of them at least.
// Pixels for which `ignore` is true are not counted as edge pixels. At least
// `changedFraction` of the edge pixels must change.
void CheckAntialiased(vtkImageData* input, vtkImageData* output,
  const std::function<bool(int, int)>& ignore = nullptr, double changedFraction = 0.5)
{
  int dims[3];
  input->GetDimensions(dims);
  int flatChanged = 0;
  int edgePixels = 0;
  int edgeChanged = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool flat = true;
      const int neighbours[4][2] = { { x - 1, y }, { x + 1, y }, { x, y - 1 }, { x, y + 1 } };
      for (const auto& n : neighbours)
      {
        if (n[0] >= 0 && n[0] < dims[0] && n[1] >= 0 && n[1] < dims[1] &&
          !SamePixel(input, x, y, n[0], n[1]))
        {
          flat = false;
        }
      }
      bool changed = false;
      for (int k = 0; k < input->GetNumberOfScalarComponents(); ++k)
      {
        changed = changed || GetValue(input, x, y, k) != GetValue(output, x, y, k);
      }
      if (!flat && ignore && ignore(x, y))
      {
        continue;
      }
      flatChanged += (flat && changed) ? 1 : 0;
      edgePixels += flat ? 0 : 1;
      edgeChanged += (!flat && changed) ? 1 : 0;
    }
  }
  std::cout << "  " << edgeChanged << " of " << edgePixels << " edge pixels changed, "
            << flatChanged << " flat pixels changed" << std::endl;
  MLAA_CHECK(flatChanged == 0);
  MLAA_CHECK(edgePixels > 0 && edgeChanged > 0 && edgeChanged >= changedFraction * edgePixels);
}

// The output file has the input's size and channels and `type` pixels, and equals `expected`
// (within `tolerance`).
void CheckFile(
  const fs::path& path, vtkImageData* expected, OIIO::TypeDesc type, double tolerance = 0.0)
{
  const FileImage file = ReadFile(path);
  int da[3], db[3];
  file.Image->GetDimensions(da);
  expected->GetDimensions(db);
  MLAA_CHECK(da[0] == db[0] && da[1] == db[1]);
  MLAA_CHECK(file.Image->GetNumberOfScalarComponents() == expected->GetNumberOfScalarComponents());
  MLAA_CHECK(file.Type == type);
  const Difference d = Compare(file.Image, expected, tolerance);
  if (d.Count != 0)
  {
    std::cout << "  " << d.Count << " values differ from vtkImageMLAA's, by up to " << d.Max
              << std::endl;
  }
  MLAA_CHECK(d.Count == 0);
}

// Writes `pixels` as `fileType` to `inputName`, runs the tool with `args` to `outputName`, and
// checks the output: same size, channels and pixel type, equal to vtkImageMLAA configured by
// `configure` on the same pixels, and antialiased.
void RoundTrip(vtkImageData* pixels, OIIO::TypeDesc fileType, const std::string& inputName,
  const std::string& outputName, const std::vector<std::string>& options = {},
  const std::function<void(vtkImageMLAA*)>& configure = nullptr)
{
  const fs::path input = WorkFile(inputName);
  const fs::path output = WorkFile(outputName);
  WriteFile(pixels, input, fileType);
  std::vector<std::string> args = options;
  args.push_back(input.string());
  args.push_back(output.string());
  ExpectSuccess(args, output);
  auto expected = Filter(pixels, configure);
  CheckFile(output, expected, fileType);
  CheckAntialiased(pixels, expected);
}

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
           "--frames RANGE", "--jobs N", "-q, --quiet",
           "mlaa [options] --output-dir DIR INPUT..." })
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
    for (int p = vtkMLAAOptions::LOW; p <= vtkMLAAOptions::ULTRA; ++p)
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
  for (int preset = vtkMLAAOptions::LOW; preset <= vtkMLAAOptions::ULTRA; ++preset)
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
  // A white square on a dark background whose lower half is a little lighter (0 and 40, a
  // shading edge of 0.157 that meets the square's sides): --local-contrast 0 keeps the shading
  // edge where it meets the silhouette, the default drops it there; both as the filter does.
  auto pixels = MakeImage(40, 40, 1);
  FillImage(pixels, [](int x, int y, int, int) {
    return (x >= 10 && x < 30 && y >= 12 && y < 28) ? 255.0 : (y < 20 ? 0.0 : 40.0);
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

//------------------------------------------------------------------------------
// Errors: exit status 1 for failures, 2 for bad command lines.

constexpr int Failure = 1;
constexpr int Usage = 2;

// A valid input image for the error cases.
fs::path GoodInput(const std::string& name = "in.png")
{
  const fs::path input = WorkFile(name);
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 }), input,
    name.size() > 4 && name.compare(name.size() - 4, 4, ".exr") == 0 ? OIIO::TypeDesc::FLOAT
                                                                     : OIIO::TypeDesc::UINT8);
  return input;
}

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

//------------------------------------------------------------------------------
// Hostile files: whatever the input or the output name, the tool ends by itself (no signal, no
// hang), says what is wrong in one short printable line naming the file, and leaves no output
// or temporary file behind.

// Names in `directory` that are temporary outputs of the tool (".NAME.mlaa-XXXXXX.ext").
int TemporaryFiles(const fs::path& directory)
{
  int count = 0;
  for (const std::string& name : Listing(directory))
  {
    count += name.find(".mlaa-") != std::string::npos ? 1 : 0;
  }
  return count;
}

// stderr is one "mlaa: " line of at most 500 bytes without control bytes; with `file`, the
// line is "mlaa: FILE: ...".
bool IsCleanErrorLine(const std::string& err, const std::string& file = "")
{
  bool ok = IsOneMlaaLine(err) && err.size() <= 501;
  for (size_t i = 0; ok && i + 1 < err.size(); ++i)
  {
    const unsigned char c = static_cast<unsigned char>(err[i]);
    ok = c >= 0x20 && c != 0x7f;
  }
  if (ok && !file.empty())
  {
    ok = err.compare(0, 6 + file.size() + 2, "mlaa: " + file + ": ") == 0;
  }
  if (!ok)
  {
    std::cout << "  not a clean error line (" << err.size() << " bytes) for '" << file << "'"
              << std::endl;
  }
  return ok;
}

// The tool, run on `input` to `output`, fails cleanly within `seconds`: exit status 1, one
// clean line naming `blamed`, nothing new in the output's directory.
void ExpectCleanFailure(const std::vector<std::string>& options, const std::string& input,
  const fs::path& output, const std::string& blamed, double seconds = 30.0)
{
  const std::set<std::string> before = Listing(output.parent_path());
  std::vector<std::string> args = options;
  args.push_back(input);
  args.push_back(output.string());
  const Run run = RunTool(args, {}, seconds);
  MLAA_CHECK(!run.TimedOut);
  MLAA_CHECK(run.Status == 1);
  MLAA_CHECK(run.Out.empty());
  MLAA_CHECK(IsCleanErrorLine(run.Err, blamed));
  MLAA_CHECK(Listing(output.parent_path()) == before);
}

// A PNG file whose header claims `width` x `height` pixels of `channels` 8-bit channels, with a
// little compressed data that does not fill it.
std::string PngHeaderOnly(unsigned width, unsigned height, int channels)
{
  auto crc32 = [](const std::string& bytes)
  {
    unsigned long crc = 0xffffffffUL;
    for (unsigned char c : bytes)
    {
      crc ^= c;
      for (int k = 0; k < 8; ++k)
      {
        crc = (crc >> 1) ^ (0xedb88320UL & (0UL - (crc & 1)));
      }
    }
    return crc ^ 0xffffffffUL;
  };
  auto be32 = [](unsigned long v)
  {
    std::string b(4, '\0');
    for (int k = 0; k < 4; ++k)
    {
      b[k] = static_cast<char>((v >> (24 - 8 * k)) & 0xff);
    }
    return b;
  };
  auto chunk = [&](const std::string& type, const std::string& data)
  { return be32(data.size()) + type + data + be32(crc32(type + data)); };
  const char colourType[] = { 0, 0, 4, 2, 6 };
  std::string ihdr = be32(width) + be32(height);
  ihdr += std::string{ 8, colourType[channels], 0, 0, 0 };
  // A stored (uncompressed) zlib stream of 16 zero bytes.
  std::string idat = std::string{ 0x78, 0x01, 0x01, 0x10, 0x00, static_cast<char>(0xef),
    static_cast<char>(0xff) };
  idat += std::string(16, '\0');
  idat += std::string{ 0, 0, 0, 1 }; // (wrong) Adler-32: a reader fails here at the latest
  return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", ihdr) + chunk("IDAT", idat) +
    chunk("IEND", "");
}

void HostileSpecialInputs()
{
  const fs::path output = WorkFile("out.png");
  // A FIFO would block the reader forever, /dev/zero and /dev/urandom never end, a directory
  // and a socket are no images: all are refused before any library opens them.
  const fs::path fifo = WorkFile("fifo.png");
  MLAA_CHECK(mkfifo(fifo.c_str(), 0600) == 0);
  ExpectCleanFailure({}, fifo.string(), output, fifo.string(), 20.0);
  const fs::path directory = WorkFile("directory.png");
  fs::create_directory(directory);
  ExpectCleanFailure({}, directory.string(), output, directory.string());
  for (const char* device : { "/dev/zero", "/dev/urandom", "/dev/null" })
  {
    ExpectCleanFailure({}, device, output, device, 20.0);
    const fs::path link = WorkFile(std::string("device") + fs::path(device).filename().string() + ".png");
    fs::create_symlink(device, link);
    ExpectCleanFailure({}, link.string(), output, link.string(), 20.0);
  }
  const fs::path socketPath = WorkFile("socket.png");
  const int sock = socket(AF_UNIX, SOCK_STREAM, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  std::strncpy(address.sun_path, socketPath.c_str(), sizeof(address.sun_path) - 1);
  if (socketPath.string().size() < sizeof(address.sun_path) &&
    bind(sock, reinterpret_cast<sockaddr*>(&address), sizeof(address)) == 0)
  {
    ExpectCleanFailure({}, socketPath.string(), output, socketPath.string());
  }
  close(sock);
  // An empty file, and the same FIFO as the depth image.
  const fs::path empty = WorkFile("empty.png");
  WriteText(empty, "");
  ExpectCleanFailure({}, empty.string(), output, empty.string());
  const fs::path input = GoodInput();
  ExpectCleanFailure({ "--edges", "depth", "--depth-image", fifo.string() }, input.string(), output,
    fifo.string(), 20.0);

  // OUTPUT that exists and is not a regular file is left alone.
  ExpectCleanFailure({}, input.string(), fifo, fifo.string(), 20.0);
  MLAA_CHECK(fs::is_fifo(fifo));
  const Run run = RunTool({ input.string(), "/dev/null" }, {}, 20.0);
  MLAA_CHECK(run.Status == 1 && IsCleanErrorLine(run.Err, "/dev/null"));

  // Names and values with control bytes and line breaks are escaped, still on one line.
  const std::string strange = WorkFile("new\nline\x1b[31m.png").string();
  WriteText(strange, "not an image\x01\x02\x1b[2J\n");
  ExpectCleanFailure({}, strange, output, "");
  const Run value = RunTool({ "--threshold", "0.1\n0.2\x1b[0m", input.string(), output.string() });
  MLAA_CHECK(value.Status == 2 && IsCleanErrorLine(value.Err));
  MLAA_CHECK(value.Err.find("\\x0a") != std::string::npos);
}

void HostileHugeHeaders()
{
  // Headers claiming far more pixels than the file holds are refused from the header, at once:
  // without the check the tool allocated tens of gigabytes.
  const fs::path output = WorkFile("out.png");
  struct Claim
  {
    unsigned Width, Height;
    int Channels;
  };
  for (const Claim& claim :
    { Claim{ 60000, 60000, 4 }, Claim{ 60000, 60000, 3 }, Claim{ 20000, 20000, 4 },
      Claim{ 1000000, 1000000, 1 }, Claim{ 1000000, 3000, 2 } })
  {
    const fs::path input = WorkFile("huge.png");
    WriteText(input, PngHeaderOnly(claim.Width, claim.Height, claim.Channels));
    const Run run = RunTool({ input.string(), output.string() }, {}, 20.0);
    MLAA_CHECK(!run.TimedOut && run.Status == 1 && IsCleanErrorLine(run.Err, input.string()));
    MLAA_CHECK(run.Seconds < 10.0);
    MLAA_CHECK(run.Err.find("pixels") != std::string::npos);
    MLAA_CHECK(!fs::exists(output) && TemporaryFiles(Where().Work) == 0);
  }

  // --max-pixels: a limit of its own; the image's own size passes, one pixel less does not.
  const fs::path input = GoodInput(); // 32 x 24
  ExpectCleanFailure({ "--max-pixels", "767" }, input.string(), output, input.string());
  ExpectSuccess({ "--max-pixels", "768", input.string(), output.string() }, output);
  // The depth image is held to it as well.
  const fs::path depth = WorkFile("depth.png");
  WriteText(depth, PngHeaderOnly(60000, 60000, 1));
  ExpectCleanFailure({ "--edges", "depth", "--depth-image", depth.string() }, input.string(),
    WorkFile("out2.png"), depth.string());
  for (const char* bad : { "0", "-5", "ten", "", "1e9", "99999999999999999999999" })
  {
    ExpectFailure({ "--max-pixels", bad, input.string(), output.string() }, WorkFile("o.png"), Usage);
  }
}

// A small image with `channels` channels of VTK type `type` whose staircase the filter changes.
vtkSmartPointer<vtkImageData> HostileSeedImage(int channels, int type, int width = 32,
  int height = 24)
{
  const double top = type == VTK_FLOAT ? 1.0 : type == VTK_UNSIGNED_SHORT ? 65535.0 : 255.0;
  std::vector<double> lo, hi;
  for (int k = 0; k < channels; ++k)
  {
    lo.push_back(top * (0.1 + 0.2 * k) / 1.0);
    hi.push_back(top * (0.9 - 0.15 * k));
  }
  return TwoToneImage(width, height, type, lo, hi, Staircase);
}

// The output extensions OpenImageIO 2.4 has writers for, and some it has not.
const std::vector<std::string>& OutputExtensions()
{
  static const std::vector<std::string> extensions = { "png", "tif", "exr", "jpg", "bmp", "tga",
    "ppm", "pgm", "pnm", "dpx", "hdr", "sgi", "iff", "gif", "ico", "webp", "heic", "jp2", "fits",
    "rla", "zfile", "null", "term", "xyz" };
  return extensions;
}

// What a finished run must look like, whatever the input was: ended by itself; on success
// stdout empty, at most one warning line, OUTPUT there and readable; on failure one clean
// error line and no OUTPUT; never a temporary file. Returns whether the run succeeded.
bool CheckOutcome(const Run& run, const fs::path& output, const std::string& what)
{
  bool ok = !run.TimedOut && (run.Status == 0 || run.Status == 1 || run.Status == 2);
  if (ok && run.Status == 0)
  {
    ok = run.Out.empty() && (run.Err.empty() || (IsCleanErrorLine(run.Err) &&
                                                run.Err.compare(0, 15, "mlaa: warning: ") == 0));
    ok = ok && fs::is_regular_file(output) && OIIO::ImageInput::open(output.string()) != nullptr;
    OIIO::geterror();
  }
  else if (ok)
  {
    ok = run.Out.empty() && IsCleanErrorLine(run.Err) && !fs::exists(output);
  }
  ok = ok && TemporaryFiles(output.parent_path()) == 0;
  if (!MLAA_CHECK(ok))
  {
    std::cout << "  failed: " << what << ": exit status " << run.Status
              << (run.TimedOut ? " (timed out)" : "") << ", stderr: " << run.Err.substr(0, 300)
              << std::endl;
  }
  return run.Status == 0;
}

void HostileOutputFormats()
{
  // Every writer with 1 to 4 channels: the output keeps the input's size, and its channels
  // unless a warning names the change; what a writer cannot take is refused before it is called.
  const std::vector<std::pair<int, OIIO::TypeDesc>> types = { { VTK_UNSIGNED_CHAR,
                                                                OIIO::TypeDesc::UINT8 },
    { VTK_FLOAT, OIIO::TypeDesc::FLOAT } };
  int succeeded = 0, refused = 0;
  for (int channels = 1; channels <= 4; ++channels)
  {
    for (const auto& type : types)
    {
      // Odd sizes: rows whose length is no multiple of anything a writer might align to.
      const int width = type.first == VTK_FLOAT ? 5 : 33;
      const int height = type.first == VTK_FLOAT ? 3 : 17;
      const fs::path input = WorkFile("in" + std::to_string(channels) + ".tif");
      WriteFile(HostileSeedImage(channels, type.first, width, height), input, type.second);
      for (const std::string& extension : OutputExtensions())
      {
        if (type.first == VTK_FLOAT && extension != "png" && extension != "heic" &&
          extension != "jpg" && extension != "ico" && extension != "gif" && extension != "exr")
        {
          continue; // the formats that convert or pad float pixels themselves
        }
        const fs::path output = WorkFile("out." + extension);
        const Run run = RunTool({ input.string(), output.string() }, {}, 60.0);
        const std::string what = std::to_string(channels) + " channels " +
          type.second.c_str() + " to ." + extension;
        if (CheckOutcome(run, output, what))
        {
          ++succeeded;
          auto back = OIIO::ImageInput::open(output.string());
          MLAA_CHECK(back && back->spec().width == width && back->spec().height == height);
          const int written = back ? back->spec().nchannels : 0;
          const bool announced = run.Err.find("alpha dropped") != std::string::npos ||
            run.Err.find("alpha added") != std::string::npos;
          if (!MLAA_CHECK(written == channels || announced))
          {
            std::cout << "  " << what << ": " << written << " channels written silently"
                      << std::endl;
          }
          fs::remove(output);
        }
        else
        {
          ++refused;
          MLAA_CHECK(run.Status == 1 && IsCleanErrorLine(run.Err, output.string()));
        }
        // The cases the library gets wrong are refused, the others must work.
        const bool broken = extension == "jp2" || extension == "fits" || extension == "rla" ||
          extension == "null" || extension == "term" || extension == "xyz" ||
          (extension == "dpx" && channels == 2);
        const bool mustWork = extension == "png" || extension == "tif" || extension == "exr" ||
          extension == "jpg" || extension == "sgi" || extension == "tga" ||
          (extension == "heic" && channels >= 3) || (extension == "dpx" && channels != 2);
        if (broken)
        {
          MLAA_CHECK(run.Status == 1);
        }
        if (mustWork && !MLAA_CHECK(run.Status == 0))
        {
          std::cout << "  " << what << " should have been written" << std::endl;
        }
      }
    }
  }
  std::cout << "  " << succeeded << " written, " << refused << " refused" << std::endl;
}

// Variants of a valid file's bytes that readers meet in the wild.
std::vector<std::pair<std::string, std::string>> Mutations(
  const std::string& bytes, std::mt19937& random)
{
  std::vector<std::pair<std::string, std::string>> variants;
  for (double fraction : { 0.02, 0.3, 0.7, 0.97 })
  {
    variants.emplace_back("truncated", bytes.substr(0, static_cast<size_t>(bytes.size() * fraction)));
  }
  for (int flips : { 1, 4, 32 })
  {
    std::string flipped = bytes;
    for (int k = 0; k < flips; ++k)
    {
      // Headers are where readers trust numbers: half the flips land in the first 64 bytes.
      const size_t span = (k % 2 == 0) ? std::min<size_t>(64, bytes.size()) : bytes.size();
      flipped[random() % span] ^= static_cast<char>(1 << (random() % 8));
    }
    variants.emplace_back("bit-flipped", flipped);
  }
  std::string bytesOverwritten = bytes;
  for (size_t k = 8; k < std::min<size_t>(40, bytes.size()); k += 4)
  {
    bytesOverwritten[k] = static_cast<char>(0xff);
  }
  variants.emplace_back("header set to 0xff", bytesOverwritten);
  return variants;
}

void HostileCorpus()
{
  // Valid small files in every format OpenImageIO writes, then truncated, bit-flipped, with
  // their header overwritten, and renamed to other formats' extensions; plus files that are no
  // images at all.
  std::mt19937 random(20261122);
  const std::vector<std::string> formats = { "png", "tif", "exr", "jpg", "bmp", "tga", "ppm",
    "pgm", "dpx", "hdr", "sgi", "gif", "webp", "ico", "heic" };
  const fs::path output = WorkFile("out.png");
  int cases = 0, succeeded = 0;
  const auto start = std::chrono::steady_clock::now();
  auto run = [&](const std::string& name, const std::string& bytes, const std::string& what)
  {
    const fs::path input = WorkFile(name);
    WriteText(input, bytes);
    const Run r = RunTool({ input.string(), output.string() }, {}, 60.0, true);
    ++cases;
    if (CheckOutcome(r, output, what + " " + name))
    {
      ++succeeded;
      fs::remove(output);
    }
    else
    {
      MLAA_CHECK(r.Status == 1 && IsCleanErrorLine(r.Err, input.string()));
    }
    fs::remove(input);
  };
  for (const std::string& format : formats)
  {
    const int channels = (format == "pgm") ? 1 : (format == "ppm" || format == "hdr" || format == "jpg") ? 3 : 4;
    const fs::path seed = WorkFile("seed." + format);
    const int type = format == "exr" || format == "hdr" ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
    WriteFile(HostileSeedImage(channels, type), seed,
      type == VTK_FLOAT ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
    const std::string bytes = ReadText(seed);
    fs::remove(seed);
    for (const auto& variant : Mutations(bytes, random))
    {
      run("mutated." + format, variant.second, variant.first);
    }
    // The file under another format's name, and under no extension.
    run("renamed." + formats[random() % formats.size()], bytes, "renamed " + format);
    run("renamed", bytes, "renamed " + format);
  }
  for (const std::string& format : formats)
  {
    run("zeros." + format, std::string(4096, '\0'), "zero bytes");
    run("text." + format, "P6\n# \x1b[31m\x01\x07 comment\n4 4\n255\n", "text with control bytes");
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "  " << cases << " hostile files in " << seconds << " s: " << succeeded
            << " antialiased, " << cases - succeeded << " refused" << std::endl;
}

void RandomFiles(unsigned seed, int count)
{
  // Seeded random cases: a file (valid, mutated, or renamed) x an output format x options. The
  // same seed gives the same cases; a failure prints its case.
  std::mt19937 random(seed);
  const std::vector<std::string> inputFormats = { "png", "tif", "exr", "jpg", "bmp", "tga", "ppm",
    "dpx", "sgi", "gif", "webp" };
  const std::vector<std::vector<std::string>> optionSets = { {}, { "--threshold", "0.05" },
    { "--edges", "color" }, { "--debug", "edges" }, { "--debug", "weights" },
    { "--diagonals", "off" }, { "--value-range", "auto" }, { "--alpha", "premultiplied" },
    { "--max-search-steps", "1" }, { "--local-contrast", "0" }, { "--max-pixels", "100" },
    { "--threshold", "x\x1b\n" }, { "--dominant-blending", "off", "--edges", "luma" } };
  int succeeded = 0, failed = 0, usage = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < count; ++i)
  {
    const std::string format = inputFormats[random() % inputFormats.size()];
    int channels = 1 + static_cast<int>(random() % 4);
    if (format == "dpx" && channels == 2)
    {
      channels = 3; // OpenImageIO's DPX writer would abort this test itself
    }
    const int type = (random() % 3 == 0) ? VTK_FLOAT : VTK_UNSIGNED_CHAR;
    const int width = 1 + static_cast<int>(random() % 40);
    const int height = 1 + static_cast<int>(random() % 30);
    const fs::path seedFile = WorkFile("seed." + format);
    std::string bytes;
    try
    {
      WriteFile(HostileSeedImage(channels, type, width, height), seedFile,
        type == VTK_FLOAT ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8);
      bytes = ReadText(seedFile);
    }
    catch (const std::exception&)
    {
      OIIO::geterror();
      bytes = "no writer took it"; // a format that refuses these channels: a non-image
    }
    fs::remove(seedFile);
    std::string kind = "valid";
    switch (random() % 4)
    {
      case 0:
        break;
      case 1:
      {
        auto variants = Mutations(bytes, random);
        const auto& v = variants[random() % variants.size()];
        kind = v.first;
        bytes = v.second;
        break;
      }
      case 2:
        bytes = bytes.substr(0, random() % (bytes.size() + 1));
        kind = "truncated";
        break;
      default:
        for (int k = 0; k < 8 && !bytes.empty(); ++k)
        {
          bytes[random() % bytes.size()] = static_cast<char>(random());
        }
        kind = "random bytes";
    }
    const std::string inputName = "case" + std::to_string(i) + "." +
      (random() % 8 == 0 ? inputFormats[random() % inputFormats.size()] : format);
    const fs::path input = WorkFile(inputName);
    WriteText(input, bytes);
    const fs::path output =
      WorkFile("out." + OutputExtensions()[random() % OutputExtensions().size()]);
    std::vector<std::string> args = optionSets[random() % optionSets.size()];
    args.push_back(input.string());
    args.push_back(output.string());
    const Run run = RunTool(args, {}, 60.0, true);
    std::ostringstream what;
    what << "case " << i << " (seed " << seed << "): " << kind << " " << channels << "-channel "
         << (type == VTK_FLOAT ? "float" : "uint8") << " " << width << "x" << height << " "
         << inputName << " -> " << output.filename().string() << " with " << args.size() - 2
         << " option words";
    if (CheckOutcome(run, output, what.str()))
    {
      ++succeeded;
      if (kind == "valid")
      {
        auto back = OIIO::ImageInput::open(output.string());
        const bool debug = args[0] == "--debug";
        MLAA_CHECK(back && (debug || (back->spec().width == width && back->spec().height == height)));
      }
      fs::remove(output);
    }
    else
    {
      run.Status == 2 ? ++usage : ++failed;
    }
    fs::remove(input);
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "  " << count << " random cases (seed " << seed << ") in " << seconds << " s: "
            << succeeded << " written, " << failed << " refused, " << usage
            << " bad command lines" << std::endl;
}

void RandomFilesA()
{
  RandomFiles(1, Where().RandomCases);
}

void RandomFilesB()
{
  RandomFiles(2, Where().RandomCases);
}

void CrashSurfaced()
{
  // A library that aborts, crashes or calls exit() while the tool holds its stderr back: the
  // user still sees what happened and what it printed, and no temporary file stays behind.
  const fs::path input = GoodInput();
  const fs::path output = WorkFile("out.png");
  for (const char* how : { "abort", "segv", "exit" })
  {
    const std::set<std::string> before = Listing(Where().Work);
    const Run run =
      RunTool({ input.string(), output.string() }, { std::string("MLAA_TEST_CRASH_WHILE_WRITING=") + how });
    // 128 + the signal, or 3 for exit(3); under AddressSanitizer a SEGV ends with its status 1.
    MLAA_CHECK(run.Status != 0 && !run.TimedOut);
    MLAA_CHECK(run.Err.find("mlaa: " + output.string() + ": crashed while OpenImageIO was writing it") == 0);
    MLAA_CHECK(run.Err.find("simulated library message before a crash") != std::string::npos);
    MLAA_CHECK(Listing(Where().Work) == before);
    MLAA_CHECK(TemporaryFiles(Where().Work) == 0 && !fs::exists(output));
  }
}

//------------------------------------------------------------------------------
// Batches (--output-dir)

// The inputs of the batch tests in directory `in`: staircases of several formats, channel
// counts and pixel types.
std::vector<fs::path> BatchInputs(const fs::path& in)
{
  fs::create_directories(in);
  const std::vector<std::pair<std::string, OIIO::TypeDesc>> files = {
    { "rgb.png", OIIO::TypeDesc::UINT8 }, { "grey16.tif", OIIO::TypeDesc::UINT16 },
    { "float.exr", OIIO::TypeDesc::FLOAT }, { "rgba.tga", OIIO::TypeDesc::UINT8 },
    { "grey.pgm", OIIO::TypeDesc::UINT8 } };
  std::vector<fs::path> paths;
  for (const auto& file : files)
  {
    const fs::path path = in / file.first;
    const int type = file.second == OIIO::TypeDesc::UINT16 ? VTK_UNSIGNED_SHORT
      : file.second == OIIO::TypeDesc::FLOAT               ? VTK_FLOAT
                                                           : VTK_UNSIGNED_CHAR;
    const double top = type == VTK_UNSIGNED_SHORT ? 65535 : (type == VTK_FLOAT ? 1.0 : 255);
    std::vector<double> lo, hi;
    const int channels = file.first.find("grey") == 0 ? 1 : (file.first == "rgba.tga" ? 4 : 3);
    for (int k = 0; k < channels; ++k)
    {
      lo.push_back(k == 3 ? top : 0.1 * (k + 1) * top);
      hi.push_back(k == 3 ? 0.5 * top : (0.9 - 0.2 * k) * top);
    }
    WriteFile(StaircaseImage(type, lo, hi), path, file.second);
    paths.push_back(path);
  }
  return paths;
}

std::vector<std::string> Strings(const std::vector<fs::path>& paths)
{
  std::vector<std::string> strings;
  for (const fs::path& path : paths)
  {
    strings.push_back(path.string());
  }
  return strings;
}

std::vector<std::string> Lines(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream stream(text);
  std::string line;
  while (std::getline(stream, line))
  {
    lines.push_back(line);
  }
  return lines;
}

// A batch of five formats writes each output under its input's name, in its format, exactly
// as the tool writes that file alone; with --quiet, nothing is printed.
void BatchSameAsSingleFiles()
{
  const std::vector<fs::path> inputs = BatchInputs(WorkFile("in"));
  const fs::path out = WorkFile("out");
  fs::create_directory(out);
  std::vector<std::string> args = { "--preset", "high", "--quiet", "--jobs", "3",
    "--output-dir", out.string() };
  const std::vector<std::string> names = Strings(inputs);
  args.insert(args.end(), names.begin(), names.end());
  const Run run = RunTool(args);
  MLAA_CHECK(run.Status == 0 && run.Out.empty() && run.Err.empty());
  std::set<std::string> expected;
  for (const fs::path& input : inputs)
  {
    expected.insert(input.filename().string());
  }
  MLAA_CHECK(Listing(out) == expected);

  const fs::path single = WorkFile("single");
  fs::create_directory(single);
  for (const fs::path& input : inputs)
  {
    const fs::path alone = single / input.filename();
    ExpectSuccess({ "--preset", "high", input.string(), alone.string() }, alone);
    const fs::path batched = out / input.filename();
    if (!MLAA_CHECK(ReadText(batched) == ReadText(alone)))
    {
      std::cout << "  " << batched << " differs from " << alone << std::endl;
    }
    const FileImage in = ReadFile(input);
    const FileImage result = ReadFile(batched);
    MLAA_CHECK(result.Format == in.Format && result.Type == in.Type);
    MLAA_CHECK(result.Image->GetNumberOfScalarComponents() ==
      in.Image->GetNumberOfScalarComponents());
  }
  // Antialiasing happened (the outputs differ from the inputs).
  MLAA_CHECK(ReadText(out / "rgb.png") != ReadText(inputs[0]));
}

// Without a terminal, one line per file, in input order, whatever order they finish in.
void BatchProgressLines()
{
  const std::vector<fs::path> inputs = BatchInputs(WorkFile("in"));
  const fs::path out = WorkFile("out");
  fs::create_directory(out);
  std::vector<std::string> args = { "--jobs", "4", "--output-dir=" + out.string() };
  const std::vector<std::string> names = Strings(inputs);
  args.insert(args.end(), names.begin(), names.end());
  const Run run = RunTool(args);
  MLAA_CHECK(run.Status == 0 && run.Out.empty());
  std::vector<std::string> expected;
  for (size_t i = 0; i < inputs.size(); ++i)
  {
    expected.push_back("mlaa: [" + std::to_string(i + 1) + "/" + std::to_string(inputs.size()) +
      "] " + inputs[i].string() + " -> " + (out / inputs[i].filename()).string());
  }
  MLAA_CHECK(Lines(run.Err) == expected);
  // --quiet and the batch options are refused without --output-dir.
  for (const char* option : { "--quiet", "-q", "--jobs=2", "--frames=1-3" })
  {
    const Run refused = RunTool({ option, inputs[0].string(), (out / "x.png").string() });
    MLAA_CHECK(refused.Status == Usage && IsOneMlaaLine(refused.Err));
    MLAA_CHECK(refused.Err.find("--output-dir") != std::string::npos);
  }
}

// On a terminal, one line updated in place: "[====>   ] 2/3  1.5 files/s  ETA 0:01", redrawn
// with a carriage return, ending with a line break, and no per-file lines.
void BatchProgressBar()
{
  const std::vector<fs::path> inputs = BatchInputs(WorkFile("in"));
  const fs::path out = WorkFile("out");
  fs::create_directory(out);
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (!MLAA_CHECK(master >= 0 && grantpt(master) == 0 && unlockpt(master) == 0))
  {
    return;
  }
  const std::string terminal = ptsname(master);
  std::vector<std::string> command = { Where().Tool, "--jobs", "2", "--output-dir", out.string() };
  const std::vector<std::string> names = Strings(inputs);
  command.insert(command.end(), names.begin(), names.end());
  command.push_back((WorkFile("in") / "missing.png").string());
  std::vector<char*> argv;
  for (std::string& arg : command)
  {
    argv.push_back(&arg[0]);
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, terminal.c_str(), O_RDWR | O_NOCTTY, 0);
  std::cout << "$ mlaa --jobs 2 --output-dir ... (stderr on a terminal)" << std::endl;
  pid_t pid;
  const int spawned = posix_spawn(&pid, command[0].c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (!MLAA_CHECK(spawned == 0))
  {
    close(master);
    return;
  }
  // Read as it comes (the terminal's buffer is small), until the tool is gone.
  std::string text;
  int status = 0;
  for (;;)
  {
    char buffer[4096];
    const pid_t done = waitpid(pid, &status, WNOHANG);
    struct pollfd ready = { master, POLLIN, 0 };
    while (poll(&ready, 1, done == pid ? 0 : 20) > 0 && (ready.revents & POLLIN))
    {
      const ssize_t n = read(master, buffer, sizeof(buffer));
      if (n <= 0)
      {
        break;
      }
      text.append(buffer, static_cast<size_t>(n));
    }
    if (done == pid)
    {
      break;
    }
  }
  close(master);
  std::string shown;
  for (const char c : text)
  {
    char hex[8];
    std::snprintf(hex, sizeof(hex), "\\x%02x", static_cast<unsigned char>(c));
    shown += (c >= 0x20 && c < 0x7f) ? std::string(1, c) : std::string(hex);
  }
  std::cout << "  stderr: " << shown << std::endl;
  MLAA_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == Failure);
  const std::string total = "/" + std::to_string(inputs.size() + 1);
  MLAA_CHECK(text.compare(0, 2, "\r[") == 0);
  MLAA_CHECK(text.find("] 0" + total) != std::string::npos);
  MLAA_CHECK(text.find("] " + std::to_string(inputs.size() + 1) + total) != std::string::npos);
  MLAA_CHECK(text.find(" files/s  ETA ") != std::string::npos);
  MLAA_CHECK(text.find("\x1b[K") != std::string::npos);
  // The error pushes the bar up: cleared, printed on its own line, bar redrawn.
  MLAA_CHECK(text.find("\r\x1b[Kmlaa: " + (WorkFile("in") / "missing.png").string() + ": ") !=
    std::string::npos);
  MLAA_CHECK(text.find("mlaa: 1 of 6 files failed") != std::string::npos);
  MLAA_CHECK(text.find("mlaa: [") == std::string::npos);
  MLAA_CHECK(Listing(out).size() == inputs.size());
}

// Files that cannot be read or written are reported by name; the others are done; the exit
// status is 1; no temporary file is left; a library that crashes on one file fails only it.
void BatchFailuresReported()
{
  const fs::path in = WorkFile("in");
  std::vector<fs::path> inputs = BatchInputs(in);
  const fs::path missing = in / "missing.png";
  const fs::path corrupt = in / "corrupt.png";
  WriteText(corrupt, "This is a text file, not a PNG image.\n");
  const fs::path blocked = in / "blocked.png"; // its output is a directory
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 }), blocked, OIIO::TypeDesc::UINT8);
  const fs::path out = WorkFile("out");
  fs::create_directories(out / "blocked.png");
  WriteText(out / "blocked.png" / "inside.txt", "untouched\n");
  std::vector<fs::path> all = { inputs[0], missing, inputs[1], corrupt, blocked, inputs[2] };
  std::vector<std::string> args = { "--jobs", "2", "--output-dir", out.string() };
  const std::vector<std::string> names = Strings(all);
  args.insert(args.end(), names.begin(), names.end());

  const Run run = RunTool(args);
  MLAA_CHECK(run.Status == Failure && run.Out.empty());
  const std::vector<std::string> lines = Lines(run.Err);
  for (const fs::path& bad : { missing, corrupt })
  {
    MLAA_CHECK(std::count_if(lines.begin(), lines.end(), [&](const std::string& line)
                 { return line.compare(0, 6 + bad.string().size() + 2,
                            "mlaa: " + bad.string() + ": ") == 0; }) == 1);
  }
  MLAA_CHECK(std::count_if(lines.begin(), lines.end(), [&](const std::string& line)
               { return line.find("mlaa: " + (out / "blocked.png").string()) == 0; }) == 1);
  MLAA_CHECK(!lines.empty() && lines.back() == "mlaa: 3 of 6 files failed");
  const std::set<std::string> written = { "rgb.png", "grey16.tif", "float.exr", "blocked.png" };
  MLAA_CHECK(Listing(out) == written);
  MLAA_CHECK(Listing(out / "blocked.png") == std::set<std::string>{ "inside.txt" });
  for (const std::string& line : lines)
  {
    MLAA_CHECK(line.compare(0, 6, "mlaa: ") == 0 && line.size() < 600);
  }

  // DIR without write permission: every file fails, by name (root may write anywhere: not
  // tried as root).
  if (geteuid() != 0)
  {
    const fs::path readOnly = WorkFile("read-only");
    fs::create_directory(readOnly);
    fs::permissions(
      readOnly, fs::perms::owner_read | fs::perms::owner_exec, fs::perm_options::replace);
    const Run denied = RunTool({ "--output-dir", readOnly.string(), inputs[0].string(),
      inputs[1].string() });
    fs::permissions(readOnly, fs::perms::owner_all, fs::perm_options::replace);
    MLAA_CHECK(denied.Status == Failure && Listing(readOnly).empty());
    const std::vector<std::string> deniedLines = Lines(denied.Err);
    MLAA_CHECK(deniedLines.size() == 3 && deniedLines.back() == "mlaa: 2 of 2 files failed");
  }

  // A library that aborts, crashes or calls exit() on one file: that file is reported, the
  // others are written, and the tool does not hang.
  for (const char* how : { "abort", "segv", "exit" })
  {
    fs::remove_all(out);
    fs::create_directory(out);
    std::vector<std::string> crashArgs = { "--jobs", "2", "--output-dir", out.string() };
    const std::vector<std::string> good = Strings(inputs);
    crashArgs.insert(crashArgs.end(), good.begin(), good.end());
    const Run crash = RunTool(crashArgs,
      { std::string("MLAA_TEST_CRASH_WHILE_WRITING=") + how, "MLAA_TEST_CRASH_ONLY=grey16" },
      60.0);
    MLAA_CHECK(crash.Status == Failure && !crash.TimedOut);
    MLAA_CHECK(crash.Err.find("mlaa: " + (out / "grey16.tif").string() +
                 ": crashed while OpenImageIO was writing it") != std::string::npos);
    MLAA_CHECK(crash.Err.find("simulated library message before a crash") != std::string::npos);
    MLAA_CHECK(crash.Err.find("mlaa: 1 of 5 files failed") != std::string::npos);
    std::set<std::string> expected;
    for (const fs::path& input : inputs)
    {
      expected.insert(input.filename().string());
    }
    expected.erase("grey16.tif");
    MLAA_CHECK(Listing(out) == expected && TemporaryFiles(out) == 0);
  }
}

// The default size limit is shared by the files in flight: an image header that one file alone
// may claim is refused when --jobs files are read at once, so that as many hostile headers
// cannot take more memory than one could.
void BatchMemoryShared()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0;
  while (meminfo >> key && !(key == "MemAvailable:" && meminfo >> kilobytes))
  {
    meminfo.ignore(1 << 20, '\n');
  }
  if (kilobytes <= 0)
  {
    std::cout << "  no MemAvailable: nothing to test" << std::endl;
    return;
  }
  // The tool's limit for 8-bit RGB alone (mlaa::DefaultMaxPixels: 46 bytes a pixel), a claim
  // below it and below the tool's hard limit, and enough jobs to bring the share well under it.
  const double limit = kilobytes * 1024 / 2 / 46;
  const double hardLimit = std::numeric_limits<int>::max() / 4;
  const double claim = std::min(0.75 * limit, 0.5 * hardLimit);
  int jobs = 2;
  while (limit / jobs > 0.8 * claim)
  {
    ++jobs;
  }
  const fs::path in = WorkFile("in");
  fs::create_directories(in);
  const int width = 20000;
  const int height = static_cast<int>(claim / width);
  WriteText(in / "claim.ppm", "P6 " + std::to_string(width) + " " + std::to_string(height) +
      " 255\n"); // a header without pixels
  std::vector<std::string> args = { "--quiet", "--jobs", std::to_string(jobs), "--output-dir",
    WorkFile("out").string(), (in / "claim.ppm").string() };
  for (int k = 1; k < jobs; ++k)
  {
    const fs::path small = in / ("small" + std::to_string(k) + ".png");
    WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 }), small, OIIO::TypeDesc::UINT8);
    args.push_back(small.string());
  }
  fs::create_directory(WorkFile("out"));
  const Run run = RunTool(args);
  MLAA_CHECK(run.Status == Failure);
  const std::vector<std::string> lines = Lines(run.Err);
  MLAA_CHECK(lines.size() == 2 && lines[0].find("mlaa: " + (in / "claim.ppm").string()) == 0 &&
    lines[0].find("shared by " + std::to_string(jobs) + " files at a time") != std::string::npos);
  MLAA_CHECK(Listing(WorkFile("out")).size() == static_cast<size_t>(jobs - 1));
}

// Command lines that would overwrite an input, or make no sense, are refused before any file
// is touched.
void BatchRefusals()
{
  const fs::path in = WorkFile("in");
  const std::vector<fs::path> inputs = BatchInputs(in);
  const fs::path other = WorkFile("other");
  fs::create_directories(other);
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 }), other / "rgb.png",
    OIIO::TypeDesc::UINT8);
  fs::create_directory_symlink(in, WorkFile("link"));
  const fs::path out = WorkFile("out");
  fs::create_directory(out);
  WriteText(WorkFile("file.txt"), "a file\n");
  const std::string a = inputs[0].string();
  const std::vector<std::vector<std::string>> refused = {
    { "--output-dir", in.string(), a },                      // output == input
    { "--output-dir", (WorkFile("link") / ".").string(), a }, // the same, through a link
    { "--output-dir", out.string(), a, (other / "rgb.png").string() }, // one output, two inputs
    { "--output-dir", WorkFile("missing").string(), a },
    { "--output-dir", WorkFile("file.txt").string(), a },
    { "--output-dir", out.string() },
    { "--output-dir", out.string(), "--jobs", "0", a },
    { "--output-dir", out.string(), "--frames", "1-3", a },
    { "--output-dir", out.string(), "--frames", "x", (in / "f.#.png").string() },
    { "--output-dir", out.string(), (in / "nothing.#.png").string() },
    { "--output-dir", out.string(), "--area-texture", "9" },
    { "--output-dir", out.string(), "--edges", "depth", "--depth-image", a, a },
    { "--output-dir", out.string(), "--quiet=yes", a },
  };
  for (const auto& args : refused)
  {
    const std::set<std::string> before = Listing(Where().Work);
    const std::set<std::string> inBefore = Listing(in);
    const std::string original = ReadText(inputs[0]);
    const Run run = RunTool(args);
    MLAA_CHECK(run.Status == Usage && run.Out.empty() && IsOneMlaaLine(run.Err));
    MLAA_CHECK(Listing(Where().Work) == before && Listing(in) == inBefore);
    MLAA_CHECK(Listing(out).empty());
    MLAA_CHECK(ReadText(inputs[0]) == original);
  }
}

// Numbered sequences: printf and '#' patterns, ranges in the name or with --frames, or every
// existing frame.
void BatchSequence()
{
  const fs::path in = WorkFile("in");
  fs::create_directories(in);
  for (int frame : { 1, 2, 3, 4, 5, 12 })
  {
    char name[32];
    std::snprintf(name, sizeof(name), "frame.%04d.png", frame);
    WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 10.0 * frame }, { 250 }), in / name,
      OIIO::TypeDesc::UINT8);
  }
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0 }, { 255 }), in / "other.png",
    OIIO::TypeDesc::UINT8);
  const fs::path out = WorkFile("out");
  const std::vector<std::pair<std::vector<std::string>, std::set<std::string>>> cases = {
    { { (in / "frame.%04d.png").string(), "--frames", "2-4" },
      { "frame.0002.png", "frame.0003.png", "frame.0004.png" } },
    { { (in / "frame.#.png").string(), "--frames=1-5x2" },
      { "frame.0001.png", "frame.0003.png", "frame.0005.png" } },
    { { (in / "frame.4-5#.png").string(), (in / "other.png").string() },
      { "frame.0004.png", "frame.0005.png", "other.png" } },
    { { (in / "frame.#.png").string() },
      { "frame.0001.png", "frame.0002.png", "frame.0003.png", "frame.0004.png", "frame.0005.png",
        "frame.0012.png" } },
  };
  for (const auto& test : cases)
  {
    fs::remove_all(out);
    fs::create_directory(out);
    std::vector<std::string> args = { "--output-dir", out.string() };
    args.insert(args.end(), test.first.begin(), test.first.end());
    const Run run = RunTool(args);
    MLAA_CHECK(run.Status == 0);
    MLAA_CHECK(Listing(out) == test.second);
    MLAA_CHECK(Lines(run.Err).size() == test.second.size());
  }
  // Every existing frame, in frame order: 12 after 5.
  const Run run = RunTool({ "--jobs", "1", "--output-dir", out.string(), (in / "frame.#.png").string() });
  const std::vector<std::string> lines = Lines(run.Err);
  MLAA_CHECK(lines.size() == 6 && lines.back().find("frame.0012.png ->") != std::string::npos);
  // A frame of the range that does not exist is a file that fails; the others are done.
  fs::remove_all(out);
  fs::create_directory(out);
  const Run gap =
    RunTool({ "--output-dir", out.string(), (in / "frame.%04d.png").string(), "--frames", "5-6" });
  MLAA_CHECK(gap.Status == Failure);
  MLAA_CHECK(gap.Err.find("mlaa: " + (in / "frame.0006.png").string() + ": ") != std::string::npos);
  const std::set<std::string> written = { "frame.0005.png" };
  MLAA_CHECK(Listing(out) == written);
}

// SIGINT (Ctrl-C: to the tool alone or its whole process group) or SIGTERM while a batch writes
// its files: the tool ends by that signal and leaves no temporary (nor any other) file.
void BatchInterrupted()
{
  const std::vector<fs::path> inputs = BatchInputs(WorkFile("in"));
  const fs::path out = WorkFile("out");
  fs::create_directory(out);
  for (int how = 0; how < 3; ++how)
  {
    const int sig = how == 2 ? SIGTERM : SIGINT;
    const bool group = how == 1;
    std::vector<std::string> command = { Where().HookedTool, "--quiet", "--jobs", "3", "--output-dir",
      out.string() };
    const std::vector<std::string> names = Strings(inputs);
    command.insert(command.end(), names.begin(), names.end());
    const SpawnVectors spawn(command, { "MLAA_TEST_CRASH_WHILE_WRITING=sleep" });
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    if (group)
    {
      posix_spawnattr_setpgroup(&attributes, 0);
      posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
    }
    pid_t pid;
    std::cout << "$ MLAA_TEST_CRASH_WHILE_WRITING=sleep mlaa --jobs 3 --output-dir ... ; then "
              << (sig == SIGINT ? "SIGINT" : "SIGTERM") << (group ? " to its group" : "")
              << std::endl;
    const int spawned =
      posix_spawn(&pid, command[0].c_str(), nullptr, &attributes, spawn.Argv.data(),
        spawn.Envp.data());
    posix_spawnattr_destroy(&attributes);
    if (!MLAA_CHECK(spawned == 0))
    {
      return;
    }
    // Wait until three files are being written.
    const auto start = std::chrono::steady_clock::now();
    while (TemporaryFiles(out) < 3 &&
      std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    {
      usleep(10000);
    }
    MLAA_CHECK(TemporaryFiles(out) == 3);
    kill(group ? -pid : pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    MLAA_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == sig);
    MLAA_CHECK(Listing(out).empty());
    usleep(200000); // nothing appears later either
    MLAA_CHECK(Listing(out).empty());
  }
}
} // namespace

//------------------------------------------------------------------------------
int main(int argc, char* argv[])
{
  if (argc != 6)
  {
    std::cerr << "Usage: " << argv[0]
              << " CASE MLAA_EXECUTABLE SCRATCH_DIRECTORY RANDOM_CASES MLAA_TEST_HOOKS_EXECUTABLE"
              << std::endl;
    return EXIT_FAILURE;
  }
  const std::map<std::string, void (*)()> cases = {
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
    { "error-method-options", ErrorMethodOptions },
    { "option-max-search-steps", OptionMaxSearchSteps },
    { "option-diagonals", OptionDiagonals },
    { "option-local-contrast", OptionLocalContrast },
    { "option-dominant-blending", OptionDominantBlending },
    { "option-value-range", OptionValueRange },
    { "option-alpha", OptionAlpha },
    { "error-bad-alpha", ErrorBadAlpha },
    { "debug-edges-rgba8-top-row-first", DebugEdgesRgba8TopRowFirst },
    { "debug-weights-rgba8", DebugWeightsRgba8 },
    { "area-texture-9", AreaTexture9 },
    { "area-texture-17", AreaTexture17 },
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
    { "error-bad-area-texture", ErrorBadAreaTexture },
    { "hostile-special-inputs", HostileSpecialInputs },
    { "hostile-huge-headers", HostileHugeHeaders },
    { "hostile-output-formats", HostileOutputFormats },
    { "hostile-corpus", HostileCorpus },
    { "random-files-a", RandomFilesA },
    { "random-files-b", RandomFilesB },
    { "crash-surfaced", CrashSurfaced },
    { "batch-same-as-single-files", BatchSameAsSingleFiles },
    { "batch-progress-lines", BatchProgressLines },
    { "batch-progress-bar", BatchProgressBar },
    { "batch-failures-reported", BatchFailuresReported },
    { "batch-refusals", BatchRefusals },
    { "batch-memory-shared", BatchMemoryShared },
    { "batch-sequence", BatchSequence },
    { "batch-interrupted", BatchInterrupted },
  };
  const auto found = cases.find(argv[1]);
  if (found == cases.end())
  {
    std::cerr << "Unknown case " << argv[1] << std::endl;
    return EXIT_FAILURE;
  }

  Where().Tool = argv[2];
  Where().RandomCases = std::atoi(argv[4]);
  Where().HookedTool = argv[5];
  const fs::path scratch = argv[3];
  Where().Work = scratch / "work";
  Where().Logs = scratch / "logs";
  fs::remove_all(scratch);
  fs::create_directories(Where().Work);
  fs::create_directories(Where().Logs);
  try
  {
    found->second();
  }
  catch (const std::exception& e)
  {
    std::cerr << "exception: " << e.what() << std::endl;
    ++Failures();
  }
  OIIO::geterror();
  return Result();
}
