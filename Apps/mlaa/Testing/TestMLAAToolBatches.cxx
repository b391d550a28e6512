// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Cases of TestMLAATool: batches (--output-dir).
#include "mlaaToolTestSupport.h"

using namespace mlaaToolTest;

namespace
{
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
  const int master = OpenTerminal();
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
    // The files being written have no name: each writer says when it has started.
    const fs::path markers = WorkFile("writing");
    fs::remove_all(markers);
    fs::create_directory(markers);
    const SpawnVectors spawn(command,
      { "MLAA_TEST_CRASH_WHILE_WRITING=sleep",
        "MLAA_TEST_WRITING_MARKER=" + (markers / "pid").string() });
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
    while (Listing(markers).size() < 3 &&
      std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
    {
      usleep(10000);
    }
    MLAA_CHECK(Listing(markers).size() == 3);
    MLAA_CHECK(Listing(out).empty()); // written without names
    kill(group ? -pid : pid, sig);
    int status = 0;
    waitpid(pid, &status, 0);
    MLAA_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == sig);
    for (const std::string& left : Listing(out))
    {
      std::cout << "left in the output directory: " << left << std::endl;
    }
    MLAA_CHECK(Listing(out).empty());
    usleep(200000); // nothing appears later either
    MLAA_CHECK(Listing(out).empty());
    // The next signal starts from an empty directory, whatever this one left.
    for (const std::string& left : Listing(out))
    {
      fs::remove(out / left);
    }
  }
}
} // namespace

static const bool Registered = RegisterCases({
  { "batch-same-as-single-files", BatchSameAsSingleFiles },
  { "batch-progress-lines", BatchProgressLines },
  { "batch-progress-bar", BatchProgressBar },
  { "batch-failures-reported", BatchFailuresReported },
  { "batch-refusals", BatchRefusals },
  { "batch-memory-shared", BatchMemoryShared },
  { "batch-sequence", BatchSequence },
  { "batch-interrupted", BatchInterrupted } });
