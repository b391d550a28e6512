// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * libFuzzer target: the `mlaa` tool's path from an image file to the output file, in-process.
 * The fuzzer's bytes become a command line (options from the tool's option table, with values
 * of their kind) and the input file; the tool's own code parses the line
 * (mlaa::ParseCommandLine) and antialiases the file (Antialias in Apps/mlaa/mlaa.cxx: reading
 * with mlaa::ReadImageFile, the filter, writing with mlaa::WriteImageFile), exactly as
 * `mlaa [options] INPUT OUTPUT` does but for the crash report, which would take libFuzzer's
 * place as the sanitizers' death callback.
 *
 * The bytes, in order (mlaa_fuzz_input.h; make-corpus.py writes seeds in this layout):
 *   u8 the input file's extension (an index into InputExtensions)
 *   u8 the output file's extension (an index into OutputExtensions)
 *   u8 flags: bit 0 the output exists before (and must be left as it was on failure)
 *   u8 how many options (mod 5), then 3 bytes per option: which (an index into the options of
 *      the table that a single-file run takes), and two bytes for its value (see OptionArgs)
 *   the rest: the input file's bytes
 *
 * Invariants (a broken one aborts, which libFuzzer saves as a crash): every run ends in a
 * success or an mlaa::Error (or another std::exception, which the tool reports the same way)
 * with a message; after a failure the output is as it was before (absent, or its old bytes),
 * after a success it is an image that reads back with the input's width and height; no other
 * file is left in the directory (no temporary output).
 */

#include "mlaa_fuzz_input.h"

// Everything mlaa.cxx includes, first, so that the `main` renamed below is its own only.
#include "mlaaBatch.h"
#include "mlaaCrashReport.h"
#include "mlaaImageFile.h"
#include "mlaaOptionTable.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDLAAOptions.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageDLAA.h"
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkLogger.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// The tool itself, its main() renamed (libFuzzer has the process's): Antialias() and the rest
// of its file-local code become part of this file.
#define main mlaaToolMain
#include "mlaa.cxx"
#undef main

#include <OpenImageIO/imageio.h>
#include <sanitizer/common_interface_defs.h>

#include <csignal>
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>
#include <thread>

namespace
{
namespace fs = std::filesystem;
using mlaafuzz::ByteReader;

// Extensions OpenImageIO reads here. A file that its extension's reader refuses is tried by
// every other reader, so the bytes reach them all whatever the name.
const char* const InputExtensions[] = { "png", "tif", "jpg", "pnm", "pfm", "exr", "bmp", "tga",
  "hdr", "sgi", "gif", "webp", "psd", "dds", "ico", "heic" };
// Output formats the tool writes (and refuses: grey + alpha in BMP, for one).
const char* const OutputExtensions[] = { "png", "tif", "exr", "jpg", "ppm", "bmp", "tga", "sgi",
  "hdr" };

// The largest image a run may read, in pixels (as --max-pixels, which a run may lower): a
// hostile header must be refused before it is allocated, not run the fuzzer out of memory.
constexpr unsigned long long MaxPixels = 1 << 20;

fs::path WorkDirectory;

// In the child of OpenImageIOSurvives: any sanitizer report ends it with status 1, and nothing
// of libFuzzer's (its crash artifact) runs there.
void ExitFromChild()
{
  _exit(1);
}

// The child of OpenImageIOSurvives: opens the file with OpenImageIO alone (nothing of ours in
// between) and reads the first image, if it is no larger than MaxPixels; never returns.
[[noreturn]] void ReadInChild(const fs::path& path)
{
  __sanitizer_set_death_callback(ExitFromChild);
  // A signal ends the child as the kernel would end it: libFuzzer's handlers, inherited,
  // would report it as a crash of the fuzzer and save the input as a finding.
  for (const int signal : { SIGSEGV, SIGBUS, SIGILL, SIGFPE, SIGABRT })
  {
    std::signal(signal, SIG_DFL);
  }
  const int null = open("/dev/null", O_WRONLY);
  if (null >= 0)
  {
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
  }
  // An exception is how a reader may fail (the tool reports it): the reader survived.
  try
  {
    auto input = OIIO::ImageInput::open(path.string());
    if (input)
    {
      const OIIO::ImageSpec& spec = input->spec();
      const unsigned long long pixels = static_cast<unsigned long long>(std::max(spec.width, 0)) *
        static_cast<unsigned long long>(std::max(spec.height, 0)) *
        static_cast<unsigned long long>(std::max(spec.depth, 1));
      if (pixels > 0 && pixels <= MaxPixels && spec.nchannels > 0 && spec.nchannels <= 64)
      {
        std::vector<float> buffer(static_cast<size_t>(pixels) * spec.nchannels);
        input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, buffer.data());
      }
      input->close();
    }
  }
  catch (const std::exception&)
  {
  }
  _exit(0);
}

// How long a child may take, and how many children an input gets. The process forks with
// other threads running (libFuzzer's memory watcher, the worker pool of a library OpenImageIO
// loads), and clang 14's AddressSanitizer does not hold its allocator's locks across fork(): a
// child forked while another thread held one waits for it for ever (the test command's fuzzing
// stopped so on its first input, in CI, once). Such a child is killed and the input tried in a
// new one; an input on which every child runs out of time is one that OpenImageIO cannot read
// in reasonable time (a slow child takes well under a second).
constexpr int ChildSeconds = 15;
constexpr int ChildTries = 3;

enum class ChildOutcome
{
  Survived,
  Died,
  OutOfTime,
};

// One child reads the file (ReadInChild); waits for it at most ChildSeconds.
ChildOutcome ReadInOneChild(const fs::path& path)
{
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0)
  {
    return ChildOutcome::Survived; // cannot tell: run it
  }
  if (pid == 0)
  {
    ReadInChild(path);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(ChildSeconds);
  auto pause = std::chrono::microseconds(200);
  int status = 0;
  for (;;)
  {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid)
    {
      break;
    }
    if (done < 0 && errno != EINTR)
    {
      return ChildOutcome::Survived; // cannot tell: run it
    }
    if (std::chrono::steady_clock::now() > deadline)
    {
      kill(pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
      {
      }
      return ChildOutcome::OutOfTime;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(20000));
  }
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? ChildOutcome::Survived
                                                        : ChildOutcome::Died;
}

// Whether OpenImageIO's own readers survive the file: a child process reads it with
// OpenImageIO alone. OpenImageIO 2.4.7's readers crash on some malformed files (BMP and SGI ones
// were found: docs/development.md, Fuzzing); the tool reports such a crash as designed
// (mlaaCrashReport.h, tested by mlaa-crash-surfaced), but in-process it would end the fuzzer
// on a bug that is not ours. Those inputs are left out, and so are inputs that no child reads
// in time (see ChildSeconds); every other input runs in-process.
bool OpenImageIOSurvives(const fs::path& path, const char** why)
{
  for (int attempt = 0; attempt < ChildTries; ++attempt)
  {
    switch (ReadInOneChild(path))
    {
      case ChildOutcome::Survived:
        return true;
      case ChildOutcome::Died:
        *why = "OpenImageIO's reader crashed on the input";
        return false;
      case ChildOutcome::OutOfTime:
        break;
    }
  }
  *why = "no child read the input in time";
  return false;
}

// MLAA_FUZZ_VERBOSE set: each run's command line and outcome are printed (to see what the seeds
// or a corpus reach).
bool Verbose = false;

// The options of the table that a run on one file takes (no batch options, no help, and neither
// --area-texture nor --output-dir, which choose other modes).
const std::vector<const mlaa::Option*>& SingleFileOptions()
{
  static const std::vector<const mlaa::Option*> options = []
  {
    std::vector<const mlaa::Option*> list;
    for (const mlaa::Option& option : mlaa::GetOptions())
    {
      if (option.Kind == mlaa::ValueKind::Help || (option.Flags & mlaa::BatchOnly) ||
        std::string(option.Name) == "--area-texture" ||
        std::string(option.Name) == "--output-dir")
      {
        continue;
      }
      list.push_back(&option);
    }
    return list;
  }();
  return options;
}

std::string Number(double value)
{
  std::ostringstream text;
  text.precision(17);
  text << value;
  return text.str();
}

// The command-line words of `option` with a value made from `a` and `b`: in its range mostly,
// now and then outside it (which the parser must refuse).
std::vector<std::string> OptionArgs(
  const mlaa::Option& option, int a, int b, const std::string& inputPath)
{
  std::vector<std::string> args{ option.Name };
  double range[2] = { 0.0, 1.0 };
  if (option.Range)
  {
    option.Range(range);
  }
  switch (option.Kind)
  {
    case mlaa::ValueKind::Number:
      args.push_back(Number(b == 255 ? range[1] + 1 : range[0] + (range[1] - range[0]) * a / 255.0));
      break;
    case mlaa::ValueKind::Integer:
    {
      const long lo = static_cast<long>(range[0]);
      const long span = static_cast<long>(range[1]) - lo + 1;
      args.push_back(std::to_string(b == 255 ? lo - 1 : lo + (a * 256 + b) % span));
      break;
    }
    case mlaa::ValueKind::Count:
      args.push_back(std::to_string(a * 256 + b + 1));
      break;
    case mlaa::ValueKind::Name:
    {
      const std::vector<std::string> names = option.Names();
      args.push_back(b == 255 || names.empty() ? std::string("none-such") : names[a % names.size()]);
      break;
    }
    case mlaa::ValueKind::Text: // --depth-image: the input itself, as one channel of depth
      args.push_back(inputPath);
      break;
    case mlaa::ValueKind::ValueRange:
      if (a % 4 == 0)
      {
        args.push_back("auto");
      }
      else
      {
        const double lo = (a % 16) * 0.25 - 1.0;
        args.push_back(Number(lo));
        args.push_back(Number(lo + (b % 16) * 0.25));
      }
      break;
    default:
      break;
  }
  return args;
}

std::string ReadAll(const fs::path& path)
{
  std::ifstream file(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

void RemoveWorkFiles()
{
  std::error_code ignored;
  for (const fs::directory_entry& entry : fs::directory_iterator(WorkDirectory, ignored))
  {
    fs::remove_all(entry.path(), ignored);
  }
}

void RemoveWorkDirectory()
{
  std::error_code ignored;
  fs::remove_all(WorkDirectory, ignored);
}

// The names in the work directory.
std::vector<std::string> ListWorkFiles()
{
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(WorkDirectory))
  {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  // For make-corpus.py, which names options and extensions rather than their places here: one
  // line each of the options, the input extensions and the output extensions.
  if (std::getenv("MLAA_FUZZ_LIST"))
  {
    for (const mlaa::Option* option : SingleFileOptions())
    {
      std::cout << option->Name << " ";
    }
    std::cout << "\n";
    for (const char* extension : InputExtensions)
    {
      std::cout << extension << " ";
    }
    std::cout << "\n";
    for (const char* extension : OutputExtensions)
    {
      std::cout << extension << " ";
    }
    std::cout << std::endl;
    std::exit(0);
  }
  mlaafuzz::KeepStderr();
  Verbose = std::getenv("MLAA_FUZZ_VERBOSE") != nullptr;
  vtkSMPTools::SetBackend("Sequential");
  OIIO::attribute("threads", 1);
  // No OpenEXR thread pool at all (-1; 1 is a pool of one thread): a child forked by
  // OpenImageIOSurvives would wait for pool threads it does not have.
  OIIO::attribute("exr_threads", -1);
  // The catalogue of formats, made once here: otherwise the first child of OpenImageIOSurvives
  // would make it (and every child until the first input that runs in-process).
  OIIO::get_string_attribute("extension_list");
  // Messages no observer takes go to a string, not the terminal (the tool's VTKMessages does
  // the same for each run).
  vtkNew<vtkStringOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);

  const char* tmp = std::getenv("TMPDIR");
  std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/mlaa_tool_fuzzer-XXXXXX";
  if (!mkdtemp(pattern.data()))
  {
    mlaafuzz::Fail("cannot create a work directory");
  }
  WorkDirectory = pattern;
  std::atexit(&RemoveWorkDirectory);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader in(data, size);
  const std::string inputExtension =
    InputExtensions[in.U8() % (sizeof(InputExtensions) / sizeof(InputExtensions[0]))];
  const std::string outputExtension =
    OutputExtensions[in.U8() % (sizeof(OutputExtensions) / sizeof(OutputExtensions[0]))];
  const int flags = in.U8();
  const fs::path inputPath = WorkDirectory / ("input." + inputExtension);
  const fs::path outputPath = WorkDirectory / ("output." + outputExtension);

  std::vector<std::string> args;
  const int optionCount = in.U8() % 5;
  const std::vector<const mlaa::Option*>& options = SingleFileOptions();
  for (int o = 0; o < optionCount; ++o)
  {
    const mlaa::Option& option = *options[in.U8() % options.size()];
    const int a = in.U8();
    const int b = in.U8();
    for (const std::string& word : OptionArgs(option, a, b, inputPath.string()))
    {
      args.push_back(word);
    }
  }
  args.push_back(inputPath.string());
  args.push_back(outputPath.string());

  RemoveWorkFiles();
  {
    std::ofstream file(inputPath, std::ios::binary);
    file.write(reinterpret_cast<const char*>(in.Rest()), static_cast<std::streamsize>(in.Remaining()));
  }
  const char* why = "";
  if (!OpenImageIOSurvives(inputPath, &why))
  {
    if (Verbose)
    {
      dprintf(mlaafuzz::ReportFd(), "skipped: %s\n", why);
    }
    return 0;
  }
  const std::string sentinel = "not an image: the output before the run\n";
  const bool outputExisted = flags & 1;
  if (outputExisted)
  {
    std::ofstream(outputPath, std::ios::binary) << sentinel;
  }
  const std::vector<std::string> filesBefore = ListWorkFiles();

  bool failed = false;
  std::string message;
  try
  {
    CommandLine cl;
    mlaa::ParseCommandLine(args, cl);
    cl.MaxPixels = cl.MaxPixels ? std::min(cl.MaxPixels, MaxPixels) : MaxPixels;
    Antialias(cl, cl.Files[0], cl.Files[1]);
  }
  catch (const std::exception& e)
  {
    failed = true;
    message = e.what();
  }
  // The tool clears what OpenImageIO holds after each file (main, and a batch's children).
  OIIO::geterror();
  if (Verbose)
  {
    std::string line = "mlaa";
    for (const std::string& word : args)
    {
      line += " " + word;
    }
    dprintf(mlaafuzz::ReportFd(), "%s: %s\n", line.c_str(), failed ? message.c_str() : "written");
  }

  if (failed)
  {
    MLAA_FUZZ_CHECK(!message.empty(), "a failure without a message");
    MLAA_FUZZ_CHECK(ListWorkFiles() == filesBefore, "a failure left a file behind");
    if (outputExisted)
    {
      MLAA_FUZZ_CHECK(ReadAll(outputPath) == sentinel, "a failure changed the existing output");
    }
    return 0;
  }
  std::vector<std::string> expected = filesBefore;
  if (!outputExisted)
  {
    expected.push_back(outputPath.filename().string());
    std::sort(expected.begin(), expected.end());
  }
  MLAA_FUZZ_CHECK(ListWorkFiles() == expected, "a success left other files than its output");
  try
  {
    const mlaa::ImageFile input = mlaa::ReadImageFile(inputPath.string(), MaxPixels);
    const mlaa::ImageFile output = mlaa::ReadImageFile(outputPath.string(), MaxPixels);
    MLAA_FUZZ_CHECK(output.Spec.width == input.Spec.width && output.Spec.height == input.Spec.height,
      "the output's size differs from the input's");
  }
  catch (const std::exception&)
  {
    mlaafuzz::Fail("the output of a success does not read back");
  }
  OIIO::geterror();
  return 0;
}
