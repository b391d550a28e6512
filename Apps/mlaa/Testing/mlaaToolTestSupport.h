// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Support of the tests of the `mlaa` tool (TestMLAATool and its groups of cases): where the
// files are, image files written and read independently of the tool, running the tool as a
// child process and checking what it did, the test images and the reference filters, and the
// registry of the cases.
#ifndef mlaaToolTestSupport_h
#define mlaaToolTestSupport_h

#include "vtkAntialiasingTestUtilities.h"

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
#include <cerrno>
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
#include <functional>

extern char** environ;

namespace mlaaToolTest
{
using namespace vtkMLAATest;
namespace fs = std::filesystem;

// The exit statuses of the tool's failures and of its bad command lines.
constexpr int Failure = 1;
constexpr int Usage = 2;

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

Context& Where();

fs::path WorkFile(const std::string& name);

std::string ReadText(const fs::path& path);

void WriteText(const fs::path& path, const std::string& text);

// Names of the files in a directory, hidden ones included.
std::set<std::string> Listing(const fs::path& directory);

//------------------------------------------------------------------------------
// Image files, written and read here independently of the tool's code: one scanline at a time,
// file row r <-> vtkImageData row height - 1 - r.

OIIO::TypeDesc BufferTypeOf(vtkImageData* image);

void WriteFile(vtkImageData* image, const fs::path& path, OIIO::TypeDesc fileType);

// A file read back: its pixels (half as float) and what the file says it holds.
struct FileImage
{
  vtkSmartPointer<vtkImageData> Image;
  OIIO::TypeDesc Type;
  std::string Format;
};

FileImage ReadFile(const fs::path& path);

// One value of a file as stored, at (column, row) counted from the top left of the file.
int FileTexel(const fs::path& path, int column, int row, int channel);

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

// Runs the tool with `args` (and `environment` added to this process's; a variable of the test
// hooks, MLAA_TEST_*, runs mlaa-test-hooks instead), its standard input read from
// `standardInput`, killing it after `timeoutSeconds`: Status is then -1 and TimedOut true.
Run RunTool(const std::vector<std::string>& args,
  const std::vector<std::string>& environment = {}, double timeoutSeconds = 120.0,
  bool quiet = false, const std::string& standardInput = "/dev/null");

// stderr is exactly one line, starting with "mlaa: ".
bool IsOneMlaaLine(const std::string& err);

// Runs the tool on arguments that must succeed and produce `output` (and nothing else in its
// directory); stderr must be empty unless a warning is expected.
void ExpectSuccess(
  const std::vector<std::string>& args, const fs::path& output, bool expectWarning = false);

// Runs the tool on arguments that must fail with `status`: one "mlaa: " line on stderr, nothing
// on stdout, no new file anywhere near `output`; tried once without `output` (it must not
// appear) and once with an existing `output` (it must be unchanged).
void ExpectFailure(const std::vector<std::string>& args, const fs::path& output, int status);

//------------------------------------------------------------------------------
// Test images

// Two values per channel, `lo` below and `hi` above a shape given by `inside(x, y)` (y up).
vtkSmartPointer<vtkImageData> TwoToneImage(int width, int height, int type,
  const std::vector<double>& lo, const std::vector<double>& hi,
  const std::function<bool(int, int)>& inside);

// Two staircases: a shallow one (steps 3 pixels long, horizontal edges) and a steep one
// (vertical edges), so that L, Z and U shapes of both orientations occur.
bool Staircase(int x, int y);

// A staircase image of the given type, lo and hi values per channel.
vtkSmartPointer<vtkImageData> StaircaseImage(
  int type, const std::vector<double>& lo, const std::vector<double>& hi);

vtkSmartPointer<vtkImageData> Filter(vtkImageData* input,
  const std::function<void(vtkImageMLAA*)>& configure = nullptr, vtkImageData* depth = nullptr);

vtkSmartPointer<vtkImageData> FilterDLAA(
  vtkImageData* input, const std::function<void(vtkDLAAOptions*)>& configure = nullptr);

bool SamePixel(vtkImageData* image, int x0, int y0, int x1, int y1);

// Antialiasing happened where it should and nowhere else: pixels whose four neighbours all
// equal them (flat regions) are unchanged; pixels on an edge changed, most of them at least.
// Pixels for which `ignore` is true are not counted as edge pixels. At least
// `changedFraction` of the edge pixels must change.
void CheckAntialiased(vtkImageData* input, vtkImageData* output,
  const std::function<bool(int, int)>& ignore = nullptr, double changedFraction = 0.5);

// The output file has the input's size and channels and `type` pixels, and equals `expected`
// (within `tolerance`).
void CheckFile(
  const fs::path& path, vtkImageData* expected, OIIO::TypeDesc type, double tolerance = 0.0);

// Writes `pixels` as `fileType` to `inputName`, runs the tool with `args` to `outputName`, and
// checks the output: same size, channels and pixel type, equal to vtkImageMLAA configured by
// `configure` on the same pixels, and antialiased.
void RoundTrip(vtkImageData* pixels, OIIO::TypeDesc fileType, const std::string& inputName,
  const std::string& outputName, const std::vector<std::string>& options = {},
  const std::function<void(vtkImageMLAA*)>& configure = nullptr);

// Names in `directory` that are named temporary outputs of the tool (".NAME.mlaa-PID-XXXXXX.ext",
// the fallback where files without a name cannot be made, or an output being put in place).
int TemporaryFiles(const fs::path& directory);

// A valid input image for the error cases.
fs::path GoodInput(const std::string& name = "in.png");

//------------------------------------------------------------------------------
// The cases

// A case: its checks fail through MLAA_CHECK (vtkAntialiasingTestUtilities.h).
using Case = void (*)();

// What a case throws when this machine cannot run it (no pseudo-terminal, a codec OpenImageIO
// lacks here): the driver prints "skipped: WHY" and exits with SkipStatus, which CTest counts as
// skipped (SKIP_RETURN_CODE), never as passed. Checks that failed before still fail the case.
struct SkippedCase : std::runtime_error
{
  using std::runtime_error::runtime_error;
};
constexpr int SkipStatus = 77;
[[noreturn]] void Skip(const std::string& why);

// A pseudo-terminal's master side (posix_openpt, granted and unlocked), for the cases that give
// the tool a terminal; skips the case where none can be opened. Close it when done.
int OpenTerminal();

// Why OpenImageIO cannot write a small RGB image as EXTENSION here (a format whose codec this
// build of the library lacks, such as HEIF without libheif's encoder plugins), or "" if it can.
std::string WriterUnavailable(const std::string& extension);

// The cases by name, as the groups register them (RegisterCases). CMakeLists.txt lists the
// names once, as the tests' names without "mlaa-"; the driver runs one by name, and the test
// mlaa-tool-cases-listed checks that the registry and that list hold the same names.
std::map<std::string, Case>& Cases();

// Adds a group's cases to Cases(); returns true (for a namespace-scope initialiser).
bool RegisterCases(std::initializer_list<std::pair<const char*, Case>> cases);
} // namespace mlaaToolTest

#endif
