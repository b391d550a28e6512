// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The tool's files and streams: an output killed mid-write leaves nothing (the unnamed file and
// the named fallback, with its sweep), the input opened once, what a damaged compressed file is
// reported as, and standard input and output ("-").
#include "mlaaToolTestSupport.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <cstdlib>

namespace mlaaToolTest
{
namespace
{
// Starts mlaa-test-hooks writing `output` from `input`, held in its writer (the "sleep" hook),
// and returns its process id once the writer has started (0 on failure).
pid_t StartWriting(const fs::path& input, const fs::path& output, bool namedTemporary)
{
  const fs::path markers = WorkFile("writing");
  fs::remove_all(markers);
  fs::create_directory(markers);
  const std::vector<std::string> command = { Where().HookedTool, input.string(), output.string() };
  std::vector<std::string> environment = { "MLAA_TEST_CRASH_WHILE_WRITING=sleep",
    "MLAA_TEST_WRITING_MARKER=" + (markers / "pid").string() };
  if (namedTemporary)
  {
    environment.push_back("MLAA_TEST_NAMED_TEMPORARY=1");
  }
  const SpawnVectors spawn(command, environment);
  std::cout << "$ MLAA_TEST_CRASH_WHILE_WRITING=sleep" << (namedTemporary ? " MLAA_TEST_NAMED_TEMPORARY=1" : "")
            << " mlaa " << input.filename() << " " << output.string() << "; then SIGKILL" << std::endl;
  pid_t pid = 0;
  if (posix_spawn(&pid, command[0].c_str(), nullptr, nullptr, spawn.Argv.data(), spawn.Envp.data()) != 0)
  {
    return 0;
  }
  const auto start = std::chrono::steady_clock::now();
  while (Listing(markers).empty() &&
    std::chrono::steady_clock::now() - start < std::chrono::seconds(60))
  {
    usleep(10000);
  }
  MLAA_CHECK(Listing(markers).size() == 1);
  return pid;
}

void KillNine(pid_t pid)
{
  kill(pid, SIGKILL);
  int status = 0;
  waitpid(pid, &status, 0);
  MLAA_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL);
}

// Sets the modification time of `path` (not following a link) `seconds` into the past.
void MakeOlder(const fs::path& path, int seconds)
{
  struct timespec times[2];
  clock_gettime(CLOCK_REALTIME, &times[0]);
  times[0].tv_sec -= seconds;
  times[1] = times[0];
  MLAA_CHECK(utimensat(AT_FDCWD, path.c_str(), times, AT_SYMLINK_NOFOLLOW) == 0);
}

// SIGKILL (or the OOM killer) while the output is written: nothing is left behind, an existing
// output is untouched. Where the fallback's named temporary had to be used, the next run of the
// tool in that directory removes it once stale, and only it.
void OutputKilled()
{
  const fs::path input = GoodInput();
  const fs::path out = WorkFile("out");
  fs::create_directories(out);
  const fs::path output = out / "result.png";
  const std::string previous = "the previous contents of the output\n";
  for (bool existing : { false, true })
  {
    if (existing)
    {
      WriteText(output, previous);
    }
    const std::set<std::string> before = Listing(out);
    const pid_t pid = StartWriting(input, output, false);
    if (!MLAA_CHECK(pid > 0))
    {
      return;
    }
    MLAA_CHECK(Listing(out) == before); // the file being written has no name
    KillNine(pid);
    MLAA_CHECK(Listing(out) == before);
    MLAA_CHECK(!existing || ReadText(output) == previous);
  }
  fs::remove(output);

  // The named fallback: SIGKILL cannot be caught, so its temporary stays...
  const pid_t pid = StartWriting(input, output, true);
  if (!MLAA_CHECK(pid > 0))
  {
    return;
  }
  MLAA_CHECK(TemporaryFiles(out) == 1);
  KillNine(pid);
  const std::set<std::string> left = Listing(out);
  if (!MLAA_CHECK(left.size() == 1 && TemporaryFiles(out) == 1))
  {
    return;
  }
  const fs::path stale = out / *left.begin();
  std::cout << "left by SIGKILL: " << stale.filename() << std::endl;
  MLAA_CHECK(stale.filename().string().find(".result.mlaa-" + std::to_string(pid) + "-") == 0);

  // ... until a later run in that directory finds it stale: an hour old, its process gone. These
  // stay: one too recent, one of a process that runs (this test), a link, a file not of ours.
  const std::string dead = std::to_string(pid);
  const fs::path recent = out / (".recent.mlaa-" + dead + "-abcdef.png");
  const fs::path alive = out / (".alive.mlaa-" + std::to_string(getpid()) + "-abcdef.png");
  const fs::path link = out / (".link.mlaa-" + dead + "-abcdef.png");
  const fs::path foreign = out / (".foreign.mlaa-" + dead + ".png");
  WriteText(recent, "x");
  WriteText(alive, "x");
  WriteText(foreign, "x");
  fs::create_symlink(input, link);
  for (const fs::path& old : { stale, alive, link, foreign })
  {
    MakeOlder(old, 7200);
  }
  MakeOlder(recent, 1800);
  // A run on the unnamed path that only creates a file does not look; the fallback does.
  const Run run = RunTool({ input.string(), (out / "other.png").string() },
    { "MLAA_TEST_NAMED_TEMPORARY=1" });
  MLAA_CHECK(run.Status == 0 && run.Err.empty());
  const std::set<std::string> expected = { "other.png", recent.filename().string(),
    alive.filename().string(), link.filename().string(), foreign.filename().string() };
  MLAA_CHECK(Listing(out) == expected);
  // Replacing an existing output takes a name for a moment on the unnamed path too, and sweeps.
  for (const fs::path& old : { recent })
  {
    MakeOlder(old, 7200);
  }
  const Run replace = RunTool({ input.string(), (out / "other.png").string() });
  MLAA_CHECK(replace.Status == 0 && replace.Err.empty());
  MLAA_CHECK(!fs::exists(recent));
  CheckFile(out / "other.png",
    Filter(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 })),
    OIIO::TypeDesc::UINT8);
  // The output of the fallback path gets the permissions a new file gets, as on the other.
  struct stat status;
  MLAA_CHECK(stat((out / "other.png").c_str(), &status) == 0);
  const mode_t mask = umask(0);
  umask(mask);
  MLAA_CHECK((status.st_mode & 0777) == (0666 & ~mask));
}

// The input is opened once: a file put in its place between the check of its name and the
// open is checked on the open descriptor and refused, and one put there after the open is not
// what is read.
void InputOpenedOnce()
{
  const fs::path input = WorkFile("once.png");
  const fs::path output = WorkFile("once-out.png");
  const fs::path swap = WorkFile("swap.png");
  struct Swap
  {
    const char* What;
    const char* Expected;
  };
  for (const Swap& s : { Swap{ "fifo", "is a FIFO (named pipe), not a regular file" },
         Swap{ "device", "is a character device, not a regular file" },
         Swap{ "empty", "the file is empty" } })
  {
    GoodInput("once.png");
    if (std::string(s.What) == "fifo")
    {
      MLAA_CHECK(mkfifo(swap.c_str(), 0600) == 0);
    }
    else if (std::string(s.What) == "device")
    {
      fs::create_symlink("/dev/zero", swap);
    }
    else
    {
      WriteText(swap, "");
    }
    const Run run = RunTool({ input.string(), output.string() },
      { "MLAA_TEST_REPLACE_INPUT_BEFORE_OPEN=" + swap.string() }, 30.0);
    MLAA_CHECK(run.Status == Failure && !run.TimedOut && IsOneMlaaLine(run.Err));
    MLAA_CHECK(run.Err == "mlaa: " + input.string() + ": " + s.Expected + "\n");
    MLAA_CHECK(!fs::exists(output) && !fs::exists(swap));
    fs::remove(input);
  }

  // Replaced by another image after the open: the opened file is read.
  GoodInput("once.png");
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 0, 0, 0 }, { 255, 255, 255 }), swap,
    OIIO::TypeDesc::UINT8);
  const Run run = RunTool({ input.string(), output.string() },
    { "MLAA_TEST_REPLACE_INPUT_AFTER_OPEN=" + swap.string() });
  MLAA_CHECK(run.Status == 0 && run.Err.empty() && !fs::exists(swap));
  CheckFile(output, Filter(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 })),
    OIIO::TypeDesc::UINT8);
}

// A damaged compressed TIFF: the message says what failed, in the tool's words, then the
// library's text (libtiff's, through OpenImageIO: "Decoding error at scanline N" here).
void DamagedCompressedTIFF()
{
  const fs::path path = WorkFile("damaged.tif");
  {
    vtkSmartPointer<vtkImageData> image =
      StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 });
    int dims[3];
    image->GetDimensions(dims);
    OIIO::ImageSpec spec(dims[0], dims[1], 3, OIIO::TypeDesc::UINT8);
    spec.tile_width = spec.tile_height = 16;
    spec.attribute("compression", "zip");
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path.string());
    MLAA_CHECK(out && out->open(path.string(), spec));
    const OIIO::stride_t row = static_cast<OIIO::stride_t>(dims[0]) * 3;
    const unsigned char* last =
      static_cast<unsigned char*>(image->GetScalarPointer()) + (dims[1] - 1) * row;
    MLAA_CHECK(out->write_image(OIIO::TypeDesc::UINT8, last, 3, -row));
    MLAA_CHECK(out->close());
  }
  // The compressed data of every tile damaged past its zlib header: TileOffsets (324) and
  // TileByteCounts (325) of the first directory of the little-endian file OpenImageIO writes.
  std::string bytes = ReadText(path);
  auto number = [&bytes](size_t at, int size) -> size_t
  {
    size_t value = 0;
    for (int k = size - 1; k >= 0 && at + k < bytes.size(); --k)
    {
      value = value * 256 + static_cast<unsigned char>(bytes[at + k]);
    }
    return value;
  };
  if (!MLAA_CHECK(bytes.compare(0, 4, std::string("II*\0", 4)) == 0))
  {
    return;
  }
  const size_t directory = number(4, 4);
  std::vector<size_t> offsets, counts;
  for (size_t entry = 0; entry < number(directory, 2); ++entry)
  {
    const size_t at = directory + 2 + 12 * entry;
    const size_t tag = number(at, 2), type = number(at + 2, 2), count = number(at + 4, 4);
    const int size = type == 3 ? 2 : 4; // SHORT or LONG
    const size_t values = count * size <= 4 ? at + 8 : number(at + 8, 4);
    for (size_t k = 0; (tag == 324 || tag == 325) && k < count; ++k)
    {
      (tag == 324 ? offsets : counts).push_back(number(values + k * size, size));
    }
  }
  MLAA_CHECK(!offsets.empty() && offsets.size() == counts.size());
  for (size_t tile = 0; tile < offsets.size() && tile < counts.size(); ++tile)
  {
    for (size_t k = 2; k < counts[tile] && k < 40 && offsets[tile] + k < bytes.size(); ++k)
    {
      bytes[offsets[tile] + k] = static_cast<char>(bytes[offsets[tile] + k] ^ 0x5a);
    }
  }
  WriteText(path, bytes);
  const fs::path output = WorkFile("damaged-out.png");
  ExpectFailure({ path.string(), output.string() }, output, Failure);
  const Run run = RunTool({ path.string(), output.string() });
  const std::string prefix =
    "mlaa: " + path.string() + ": cannot read the pixels of this tiff file (zip compressed): ";
  MLAA_CHECK(run.Err.compare(0, prefix.size(), prefix) == 0);
  // The library's own text follows, without a dangling ':'.
  MLAA_CHECK(run.Err.size() > prefix.size() + 5);
  MLAA_CHECK(run.Err.size() > 2 && run.Err[run.Err.size() - 2] != ':');

  // Not an image at all: what failed, then the library's text.
  const fs::path garbage = WorkFile("garbage.png");
  WriteText(garbage, "this is not an image, whatever its name says\n");
  const Run notImage = RunTool({ garbage.string(), output.string() });
  MLAA_CHECK(notImage.Status == Failure && IsOneMlaaLine(notImage.Err));
  MLAA_CHECK(notImage.Err.find("mlaa: " + garbage.string() + ": cannot open it as an image: ") == 0);
  // OpenImageIO's message names the file as the user did, not as the tool opened it.
  MLAA_CHECK(notImage.Err.find("/proc/self/fd") == std::string::npos);
}

// "-": standard input (any format, found from its bytes) and standard output (--format).
void StandardStreams()
{
  const vtkSmartPointer<vtkImageData> expected =
    Filter(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 }));
  const fs::path png = GoodInput("stream.png");
  const fs::path exr = GoodInput("stream.exr");
  const fs::path piped = WorkFile("piped.png");
  const std::set<std::string> before = Listing(Where().Work);

  // mlaa --format png - - < in.png > out.png
  const Run both = RunTool({ "--format", "png", "-", "-" }, {}, 120.0, false, png.string());
  MLAA_CHECK(both.Status == 0 && both.Err.empty());
  MLAA_CHECK(both.Out.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
  MLAA_CHECK(Listing(Where().Work) == before); // nothing written beside the files
  WriteText(piped, both.Out);
  CheckFile(piped, expected, OIIO::TypeDesc::UINT8);

  // The same bytes as writing to a file; an OpenEXR input, found without an extension.
  const fs::path named = WorkFile("named.png");
  const Run toFile = RunTool({ png.string(), named.string() });
  MLAA_CHECK(toFile.Status == 0 && ReadText(named) == both.Out);
  const Run fromExr = RunTool({ "-", WorkFile("from-exr.exr").string() }, {}, 120.0, false, exr.string());
  MLAA_CHECK(fromExr.Status == 0 && fromExr.Err.empty());
  FileImage back = ReadFile(WorkFile("from-exr.exr"));
  MLAA_CHECK(back.Format == "openexr" && back.Type == OIIO::TypeDesc::FLOAT);

  // --format by extension, to a file (whatever its name) and to standard output.
  const Run tif = RunTool({ "--format", "tif", png.string(), "-" });
  MLAA_CHECK(tif.Status == 0 && tif.Out.compare(0, 4, "II*\0", 4) == 0);
  const Run area = RunTool({ "--area-texture", "9", "--format", "png", "-" });
  MLAA_CHECK(area.Status == 0 && area.Out.compare(0, 4, "\x89PNG") == 0);

  // Failures: one line, nothing at all on standard output, no file left.
  const fs::path greyAlpha = WorkFile("grey-alpha.png");
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 255 }, { 240, 128 }), greyAlpha,
    OIIO::TypeDesc::UINT8);
  const fs::path garbage = WorkFile("garbage.bin");
  WriteText(garbage, "not an image\n");
  struct Refusal
  {
    std::vector<std::string> Args;
    std::string Input;
    int Status;
    std::string Message;
  };
  const std::vector<Refusal> refusals = {
    { { "-", "-" }, png.string(), Usage, "mlaa: OUTPUT - (standard output) needs --format NAME" },
    { { "--area-texture", "9", "-" }, "/dev/null", Usage, "mlaa: OUTPUT - (standard output) needs --format" },
    { { "--format", "nosuchformat", png.string(), "-" }, "/dev/null", Usage, "mlaa: --format 'nosuchformat': " },
    { { "--format", "png", "--output-dir", Where().Work.string(), png.string() }, "/dev/null", Usage,
      "mlaa: --format cannot be used with --output-dir" },
    { { "--output-dir", Where().Work.string(), "-" }, png.string(), Usage,
      "mlaa: - (standard input) cannot be an INPUT of a batch" },
    { { "--edges", "depth", "--depth-image", "-", "-", "x.png" }, png.string(), Usage,
      "mlaa: INPUT and --depth-image cannot both be -" },
    { { "--format", "png", "-", "-" }, "/dev/null", Failure, "mlaa: standard input: is empty" },
    { { "--format", "png", "-", "-" }, garbage.string(), Failure,
      "mlaa: standard input: cannot open it as an image: " },
    { { "--format", "jp2", png.string(), "-" }, "/dev/null", Failure,
      "mlaa: standard output: the tool does not write jpeg2000 files" },
    // Grey + alpha, which BMP cannot hold: refused after antialiasing, before writing.
    { { "--format", "bmp", greyAlpha.string(), "-" }, "/dev/null", Failure,
      "mlaa: standard output: cannot write 2-channel (grey + alpha) images as bmp" },
  };
  for (const Refusal& r : refusals)
  {
    const std::set<std::string> listing = Listing(Where().Work);
    const Run run = RunTool(r.Args, {}, 120.0, false, r.Input);
    MLAA_CHECK(run.Status == r.Status && IsOneMlaaLine(run.Err) && run.Out.empty());
    MLAA_CHECK(run.Err.compare(0, r.Message.size(), r.Message) == 0);
    MLAA_CHECK(Listing(Where().Work) == listing);
  }
}

// A terminal as standard input: the user forgot the redirection; refused, not waited on.
void StandardInputTerminal()
{
  const int master = OpenTerminal();
  const Run run = RunTool({ "-", WorkFile("from-terminal.png").string() }, {}, 30.0, false,
    ptsname(master));
  MLAA_CHECK(run.Status == Failure && !run.TimedOut && IsOneMlaaLine(run.Err));
  MLAA_CHECK(run.Err.find("mlaa: standard input: is a terminal") == 0);
  MLAA_CHECK(!fs::exists(WorkFile("from-terminal.png")));
  close(master);
}
} // namespace

static const bool Registered = RegisterCases({
  { "output-killed-leaves-nothing", OutputKilled },
  { "input-opened-once", InputOpenedOnce },
  { "damaged-compressed-tiff", DamagedCompressedTIFF },
  { "standard-streams", StandardStreams },
  { "standard-input-terminal", StandardInputTerminal } });
} // namespace mlaaToolTest
