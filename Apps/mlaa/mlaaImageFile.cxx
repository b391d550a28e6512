// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "mlaaImageFile.h"
#include "mlaaCrashReport.h"

#include "vtkAntialiasingKit.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkType.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <random>
#include <set>
#include <sstream>
#include <type_traits>
#include <vector>

namespace mlaa
{
namespace
{
// A line with its digits left out: libraries repeat one message per scanline or strip with
// only the number changing.
std::string WithoutNumbers(const std::string& line)
{
  std::string shape;
  for (char c : line)
  {
    if (c < '0' || c > '9')
    {
      shape += c;
    }
    else if (shape.empty() || shape.back() != '#')
    {
      shape += '#';
    }
  }
  return shape;
}

// The length of the valid UTF-8 sequence at text[i] that is not a control character, or 0.
size_t PrintableUTF8Length(const std::string& text, size_t i)
{
  const unsigned char c = static_cast<unsigned char>(text[i]);
  size_t length = c >= 0xf0 && c <= 0xf4 ? 4 : c >= 0xe0 ? 3 : c >= 0xc2 && c < 0xe0 ? 2 : 0;
  if (length == 0 || i + length > text.size())
  {
    return 0;
  }
  for (size_t k = 1; k < length; ++k)
  {
    if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80)
    {
      return 0;
    }
  }
  // U+0080..U+009F are the C1 control characters.
  if (c == 0xc2 && static_cast<unsigned char>(text[i + 1]) < 0xa0)
  {
    return 0;
  }
  return length;
}

// Where several channels have their own types (an EXR file with half colour and float depth,
// say), all are read as the most precise one: floating point over integers, then the widest.
OIIO::TypeDesc FilePixelType(const OIIO::ImageSpec& spec)
{
  if (spec.channelformats.empty())
  {
    return spec.format;
  }
  OIIO::TypeDesc best = spec.channelformats.front();
  for (const OIIO::TypeDesc& type : spec.channelformats)
  {
    const bool typeIsFloat = type.is_floating_point();
    const bool bestIsFloat = best.is_floating_point();
    if ((typeIsFloat && !bestIsFloat) || (typeIsFloat == bestIsFloat && type.size() > best.size()))
    {
      best = type;
    }
  }
  return best;
}

// The OpenImageIO type of a buffer of VTK scalars of type `vtkType`.
OIIO::TypeDesc BufferType(int vtkType)
{
  switch (vtkType)
  {
    case VTK_UNSIGNED_CHAR:
      return OIIO::TypeDesc::UINT8;
    case VTK_SIGNED_CHAR:
      return OIIO::TypeDesc::INT8;
    case VTK_CHAR:
      return std::is_signed<char>::value ? OIIO::TypeDesc::INT8 : OIIO::TypeDesc::UINT8;
    case VTK_UNSIGNED_SHORT:
      return OIIO::TypeDesc::UINT16;
    case VTK_SHORT:
      return OIIO::TypeDesc::INT16;
    case VTK_UNSIGNED_INT:
      return OIIO::TypeDesc::UINT32;
    case VTK_INT:
      return OIIO::TypeDesc::INT32;
    case VTK_UNSIGNED_LONG:
      return sizeof(long) == 8 ? OIIO::TypeDesc::UINT64 : OIIO::TypeDesc::UINT32;
    case VTK_LONG:
      return sizeof(long) == 8 ? OIIO::TypeDesc::INT64 : OIIO::TypeDesc::INT32;
    case VTK_UNSIGNED_LONG_LONG:
      return OIIO::TypeDesc::UINT64;
    case VTK_LONG_LONG:
      return OIIO::TypeDesc::INT64;
    case VTK_FLOAT:
      return OIIO::TypeDesc::FLOAT;
    case VTK_DOUBLE:
      return OIIO::TypeDesc::DOUBLE;
    default:
      return OIIO::TypeDesc::UNKNOWN;
  }
}

// Largest value of an integer pixel type, as OpenImageIO's conversions scale to it.
double IntegerTypeMaximum(OIIO::TypeDesc type)
{
  switch (type.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return std::numeric_limits<unsigned char>::max();
    case OIIO::TypeDesc::INT8:
      return std::numeric_limits<signed char>::max();
    case OIIO::TypeDesc::UINT16:
      return std::numeric_limits<unsigned short>::max();
    case OIIO::TypeDesc::INT16:
      return std::numeric_limits<short>::max();
    case OIIO::TypeDesc::UINT32:
      return std::numeric_limits<unsigned int>::max();
    case OIIO::TypeDesc::INT32:
      return std::numeric_limits<int>::max();
    default:
      return 1.0;
  }
}

} // namespace

//------------------------------------------------------------------------------
size_t ReadAt(int fd, std::uint64_t offset, char* data, size_t size)
{
  size_t done = 0;
  while (done < size)
  {
    const ssize_t got = pread(fd, data + done, size - done, static_cast<off_t>(offset + done));
    if (got < 0 && errno == EINTR)
    {
      continue;
    }
    if (got <= 0)
    {
      break;
    }
    done += static_cast<size_t>(got);
  }
  return done;
}

std::string Printable(const std::string& text, size_t maxLength, bool joinLines)
{
  if (!joinLines)
  {
    std::string escaped;
    for (char c : text)
    {
      escaped += c == '\n' ? std::string("\\x0a") : c == '\r' ? std::string("\\x0d") : std::string(1, c);
    }
    return Printable(escaped, maxLength, true);
  }
  // Lines, each once, in order of first appearance, with how often they (or lines that differ
  // only in their numbers) came.
  std::vector<std::pair<std::string, int>> lines;
  std::vector<std::string> shapes;
  size_t begin = 0;
  while (begin <= text.size())
  {
    size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos)
    {
      end = text.size();
    }
    std::string line = text.substr(begin, end - begin);
    const size_t first = line.find_first_not_of(" \t");
    const size_t last = line.find_last_not_of(" \t");
    line = first == std::string::npos ? "" : line.substr(first, last - first + 1);
    if (!line.empty())
    {
      const std::string shape = WithoutNumbers(line);
      const auto seen = std::find(shapes.begin(), shapes.end(), shape);
      if (seen == shapes.end())
      {
        shapes.push_back(shape);
        lines.emplace_back(line, 1);
      }
      else
      {
        ++lines[static_cast<size_t>(seen - shapes.begin())].second;
      }
    }
    begin = end + 1;
  }

  std::string joined;
  for (const auto& line : lines)
  {
    joined += (joined.empty() ? "" : "; ") + line.first;
    if (line.second > 1)
    {
      joined += " (" + std::to_string(line.second) + " times)";
    }
  }

  std::string printable;
  for (size_t i = 0; i < joined.size() && printable.size() < maxLength + 8;)
  {
    const unsigned char c = static_cast<unsigned char>(joined[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      printable += static_cast<char>(c);
      ++i;
      continue;
    }
    const size_t length = c >= 0x80 ? PrintableUTF8Length(joined, i) : 0;
    if (length)
    {
      printable.append(joined, i, length);
      i += length;
      continue;
    }
    const char* hex = "0123456789abcdef";
    printable += "\\x";
    printable += hex[c >> 4];
    printable += hex[c & 15];
    ++i;
  }
  if (printable.size() > maxLength)
  {
    // Cut at a character boundary, not inside a UTF-8 sequence.
    size_t cut = maxLength - 3;
    while (cut > 0 && (static_cast<unsigned char>(printable[cut]) & 0xc0) == 0x80)
    {
      --cut;
    }
    printable = printable.substr(0, cut) + "...";
  }
  return printable;
}

//------------------------------------------------------------------------------
namespace
{
int ImagesInFlight = 1; // SetImagesInFlight
}

void SetImagesInFlight(int count)
{
  ImagesInFlight = std::max(1, count);
}

//------------------------------------------------------------------------------
std::uint64_t DefaultMaxPixels(int channels, OIIO::TypeDesc type)
{
  // Bytes per pixel: the input and the output images, a double copy of floating-point values
  // rescaled for an integer format, and the filter's edges, weights and contrasts (about 16).
  const std::uint64_t valueBytes = type.is_floating_point() ? std::max<size_t>(type.size(), 4)
                                                            : std::max<size_t>(type.size(), 1);
  const std::uint64_t perPixel =
    2 * valueBytes * static_cast<std::uint64_t>(channels) + 8 * channels + 16;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kilobytes = 0;
  while (meminfo >> key)
  {
    if (key == "MemAvailable:" && meminfo >> kilobytes)
    {
      break;
    }
    meminfo.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
  }
  if (kilobytes == 0)
  {
    return std::uint64_t(1) << 28;
  }
  return kilobytes * 1024 / 2 / static_cast<std::uint64_t>(ImagesInFlight) / perPixel;
}

//------------------------------------------------------------------------------
int GetVTKScalarType(OIIO::TypeDesc type)
{
  if (type.aggregate != OIIO::TypeDesc::SCALAR || type.arraylen != 0)
  {
    return 0;
  }
  switch (type.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return VTK_UNSIGNED_CHAR;
    case OIIO::TypeDesc::INT8:
      return VTK_SIGNED_CHAR;
    case OIIO::TypeDesc::UINT16:
      return VTK_UNSIGNED_SHORT;
    case OIIO::TypeDesc::INT16:
      return VTK_SHORT;
    case OIIO::TypeDesc::UINT32:
      return VTK_UNSIGNED_INT;
    case OIIO::TypeDesc::INT32:
      return VTK_INT;
    case OIIO::TypeDesc::UINT64:
      return VTK_UNSIGNED_LONG_LONG;
    case OIIO::TypeDesc::INT64:
      return VTK_LONG_LONG;
    case OIIO::TypeDesc::HALF:
    case OIIO::TypeDesc::FLOAT:
      return VTK_FLOAT;
    case OIIO::TypeDesc::DOUBLE:
      return VTK_DOUBLE;
    default:
      return 0;
  }
}

namespace
{
// A path as it may appear in a message: control bytes escaped, length bounded.
std::string Name(const std::string& path)
{
  return Printable(path, 160, false);
}

// What a file's status says it is, if it is not an image file that can be read: only regular
// files are read (a FIFO blocks the reader, /dev/zero and its kind never end, a directory or
// socket is no image), and an empty file holds nothing.
void CheckStatus(const struct stat& status, const std::string& name)
{
  const char* kind = S_ISDIR(status.st_mode) ? "a directory"
    : S_ISFIFO(status.st_mode)               ? "a FIFO (named pipe)"
    : S_ISCHR(status.st_mode)                ? "a character device"
    : S_ISBLK(status.st_mode)                ? "a block device"
    : S_ISSOCK(status.st_mode)               ? "a socket"
                                             : nullptr;
  if (kind)
  {
    throw Error(name + ": is " + kind + ", not a regular file");
  }
  if (!S_ISREG(status.st_mode))
  {
    throw Error(name + ": is not a regular file");
  }
  if (status.st_size == 0)
  {
    throw Error(name + ": the file is empty");
  }
}

// "/proc/self/fd/N": the open file `fd` under a name that libraries which open files by name
// (OpenImageIO's readers and writers) can open, reaching that very file whatever happens to
// its own name meanwhile; "" where /proc is not mounted.
std::string DescriptorPath(int fd)
{
  const std::string path = "/proc/self/fd/" + std::to_string(fd);
  struct stat byName, byDescriptor;
  if (stat(path.c_str(), &byName) != 0 || fstat(fd, &byDescriptor) != 0 ||
    byName.st_dev != byDescriptor.st_dev || byName.st_ino != byDescriptor.st_ino)
  {
    return "";
  }
  return path;
}

// `text` with every `from` replaced by `to` (the descriptor path by the user's name in
// OpenImageIO's messages).
std::string ReplaceAll(std::string text, const std::string& from, const std::string& to)
{
  if (from.empty())
  {
    return text;
  }
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
  {
    text.replace(at, from.size(), to);
  }
  return text;
}

// Writes all of `size` bytes to `fd`; false (errno set) on failure.
bool WriteAll(int fd, const char* data, size_t size)
{
  while (size > 0)
  {
    const ssize_t done = write(fd, data, size);
    if (done < 0 && errno == EINTR)
    {
      continue;
    }
    if (done <= 0)
    {
      return false;
    }
    data += done;
    size -= static_cast<size_t>(done);
  }
  return true;
}

#ifdef MLAA_TEST_HOOKS
// For tests only: MLAA_TEST_REPLACE_INPUT_BEFORE_OPEN=PATH (or ..._AFTER_OPEN) renames PATH
// over the input between the tool's check of its name and its open() (or after the open()),
// as another process could, so that the tests can show that what is read is what was checked.
void ReplaceInputForTests(const char* variable, const std::string& input)
{
  const char* replacement = std::getenv(variable);
  if (replacement && *replacement && std::rename(replacement, input.c_str()) != 0)
  {
    std::fprintf(stderr, "%s: cannot rename %s: %s\n", variable, replacement, std::strerror(errno));
    std::exit(4);
  }
}
#endif

// The input, opened once: a regular file by name (checked by name first, so that a device is
// never even opened, then checked again on the open descriptor, which is what is read), or
// standard input ("-"), copied into a file without a name so that readers can seek in it.
class InputFile
{
public:
  explicit InputFile(const std::string& path)
    : Shown(DisplayName(path, false))
  {
    if (path == "-")
    {
      this->ReadStandardInput();
      return;
    }
    struct stat status;
    if (stat(path.c_str(), &status) != 0)
    {
      throw Error(this->Shown + ": " + std::strerror(errno));
    }
    CheckStatus(status, this->Shown);
#ifdef MLAA_TEST_HOOKS
    ReplaceInputForTests("MLAA_TEST_REPLACE_INPUT_BEFORE_OPEN", path);
#endif
    // O_NONBLOCK: a FIFO put in the file's place after the check must not block the open.
    this->Fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | O_NONBLOCK);
    if (this->Fd < 0)
    {
      throw Error(this->Shown + ": " + std::strerror(errno));
    }
    if (fstat(this->Fd, &status) != 0)
    {
      throw Error(this->Shown + ": " + std::strerror(errno));
    }
    CheckStatus(status, this->Shown);
    fcntl(this->Fd, F_SETFL, fcntl(this->Fd, F_GETFL) & ~O_NONBLOCK);
#ifdef MLAA_TEST_HOOKS
    ReplaceInputForTests("MLAA_TEST_REPLACE_INPUT_AFTER_OPEN", path);
#endif
    this->ReadPath = DescriptorPath(this->Fd);
    if (this->ReadPath.empty())
    {
      this->ReadPath = path; // no /proc: by name, as checked just before
    }
    else
    {
      // Readers are tried in the order OpenImageIO would for the name: its extension's first.
      this->FormatHint = std::filesystem::path(path).extension().string();
      if (this->FormatHint.size() > 1)
      {
        this->FormatHint.erase(0, 1);
      }
    }
  }

  ~InputFile()
  {
    if (this->Fd >= 0)
    {
      close(this->Fd);
    }
  }

  /** The name to give OpenImageIO. */
  const std::string& GetReadPath() const { return this->ReadPath; }
  /** The extension of the input's name ("" for standard input). */
  const std::string& GetFormatHint() const { return this->FormatHint; }
  /** Up to `size` bytes of the file from `offset` (mlaa::ReadAt). */
  size_t ReadAt(std::uint64_t offset, unsigned char* data, size_t size) const
  {
    return mlaa::ReadAt(this->Fd, offset, reinterpret_cast<char*>(data), size);
  }

  /** OpenImageIO's message with the descriptor path replaced by the input's name. */
  std::string Explain(const std::string& message) const
  {
    return ReplaceAll(message, this->ReadPath, this->Shown);
  }

private:
  InputFile(const InputFile&) = delete;
  void operator=(const InputFile&) = delete;

  void ReadStandardInput()
  {
    if (isatty(STDIN_FILENO))
    {
      throw Error(this->Shown + ": is a terminal; pipe an image into it (mlaa - OUT.png < IN.png)");
    }
    this->Fd = CreateAnonymousFile();
    if (this->Fd < 0)
    {
      throw Error(this->Shown + ": cannot create a file to hold it: " + std::strerror(errno));
    }
    std::vector<char> buffer(1 << 16);
    off_t total = 0;
    for (;;)
    {
      const ssize_t got = read(STDIN_FILENO, buffer.data(), buffer.size());
      if (got < 0 && errno == EINTR)
      {
        continue;
      }
      if (got < 0)
      {
        throw Error(this->Shown + ": " + std::strerror(errno));
      }
      if (got == 0)
      {
        break;
      }
      if (!WriteAll(this->Fd, buffer.data(), static_cast<size_t>(got)))
      {
        throw Error(this->Shown + ": cannot hold it in a temporary file: " + std::strerror(errno));
      }
      total += got;
    }
    if (total == 0)
    {
      throw Error(this->Shown + ": is empty");
    }
    this->ReadPath = DescriptorPath(this->Fd);
    if (this->ReadPath.empty())
    {
      throw Error(this->Shown + ": cannot be read without /proc/self/fd (is /proc mounted?)");
    }
  }

  std::string Shown;
  std::string ReadPath;
  std::string FormatHint;
  int Fd = -1;
};

// Opens `path` for reading the way OpenImageIO's ImageInput::open does, but with the reader
// for `hint` (an extension or format name, may be "") tried first: `path` may be a descriptor
// path without an extension. On failure, the first reader's error is the one kept.
std::unique_ptr<OIIO::ImageInput> OpenReader(
  const std::string& path, const std::string& hint, const OIIO::ImageSpec* config, std::string& error)
{
  if (!hint.empty())
  {
    std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::create(hint, false, config);
    OIIO::geterror();
    if (input)
    {
      OIIO::ImageSpec spec;
      if (config ? input->open(path, spec, *config) : input->open(path, spec))
      {
        return input;
      }
      error = input->geterror();
    }
  }
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path, config);
  const std::string generic = input ? std::string() : OIIO::geterror();
  if (!input && error.empty())
  {
    error = generic;
  }
  return input;
}

// Stale temporaries of ours: ".NAME.mlaa-PID-XXXXXX.EXT", regular, ours, untouched for this
// long, and their process gone.
constexpr time_t StaleTemporarySeconds = 3600;

// The process id in a name of our temporaries' pattern, or 0 if it is not one.
long TemporaryOwner(const std::string& name)
{
  const size_t mark = name.rfind(".mlaa-");
  if (name.empty() || name[0] != '.' || mark == std::string::npos || mark == 0)
  {
    return 0;
  }
  size_t at = mark + 6;
  long pid = 0;
  const size_t digits = at;
  while (at < name.size() && name[at] >= '0' && name[at] <= '9' && at - digits < 10)
  {
    pid = pid * 10 + (name[at++] - '0');
  }
  if (at == digits || at >= name.size() || name[at] != '-' || name.size() < at + 7)
  {
    return 0;
  }
  for (size_t k = at + 1; k < at + 7; ++k)
  {
    if (!std::isalnum(static_cast<unsigned char>(name[k])))
    {
      return 0;
    }
  }
  return at + 7 == name.size() || name[at + 7] == '.' ? pid : 0;
}

// Directories already swept by this process (or by the batch's parent before it forked).
std::set<std::string>& SweptDirectories()
{
  static std::set<std::string> swept;
  return swept;
}

// Where O_TMPFILE cannot be used, the image goes to a named temporary; in mlaa-test-hooks,
// MLAA_TEST_NAMED_TEMPORARY=1 takes that path everywhere, for the tests of the fallback.
bool UnnamedFilesAllowed()
{
#ifdef MLAA_TEST_HOOKS
  const char* named = std::getenv("MLAA_TEST_NAMED_TEMPORARY");
  return !(named && *named == '1');
#else
  return true;
#endif
}

// A new name for a temporary beside `destination`, of the pattern TemporaryOwner reads, as a
// mkstemps template ("XXXXXX" to fill), and the length of its suffix.
std::string TemporaryTemplate(const std::string& destination, int& suffixLength)
{
  namespace fs = std::filesystem;
  const fs::path target(destination);
  fs::path directory = target.parent_path();
  if (directory.empty())
  {
    directory = ".";
  }
  const std::string extension = target.extension().string();
  suffixLength = static_cast<int>(extension.size());
  return (directory / ("." + target.stem().string() + ".mlaa-" + std::to_string(getpid()) +
                        "-XXXXXX" + extension))
    .string();
}

// Where an image is written before it becomes the output: the output's directory or standard
// output gets the image only once it is complete and read back (Commit), and nothing stays
// behind whatever ends the process.
//
// - A file: a file without a name in the destination's directory (O_TMPFILE), which OpenImageIO
//   writes through /proc/self/fd/N and which is linked into place on success (linkat, then a
//   rename where the destination exists); a process killed by anything, SIGKILL included,
//   leaves nothing. Where the file system or the kernel has no O_TMPFILE (or /proc is not
//   mounted), a hidden named temporary ".NAME.mlaa-PID-XXXXXX.EXT" is written and renamed
//   instead: removed on errors and on signals that can be caught, and, should SIGKILL leave one,
//   removed by a later run of the tool in that directory (SweepStaleTemporaries).
// - Standard output ("-"): a file without a name in $TMPDIR, copied to standard output once it
//   is complete, so that nothing partial reaches the pipe.
class OutputFile
{
public:
  explicit OutputFile(const std::string& destination)
    : Destination(destination)
  {
    if (destination == "-")
    {
      this->Fd = CreateAnonymousFile();
      this->WritePath = this->Fd >= 0 ? DescriptorPath(this->Fd) : std::string();
      if (this->WritePath.empty())
      {
        throw Error(DisplayName(destination, true) + ": cannot create a file to hold the image " +
          "before it is sent (" +
          (this->Fd < 0 ? std::string(std::strerror(errno)) : "is /proc mounted?") + ")");
      }
      return;
    }

    namespace fs = std::filesystem;
    fs::path directory = fs::path(destination).parent_path();
    if (directory.empty())
    {
      directory = ".";
    }
    this->Directory = directory.string();
    // The permissions of the file it replaces, or those a newly created file gets.
    struct stat existing;
    mode_t mode;
    if (stat(destination.c_str(), &existing) == 0 && S_ISREG(existing.st_mode))
    {
      mode = existing.st_mode & 07777;
    }
    else
    {
      const mode_t mask = umask(0);
      umask(mask);
      mode = 0666 & ~mask;
    }

    if (UnnamedFilesAllowed())
    {
      this->Fd = open(this->Directory.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
      if (this->Fd >= 0 && fchmod(this->Fd, mode) == 0)
      {
        this->WritePath = DescriptorPath(this->Fd);
      }
      if (!this->WritePath.empty())
      {
        return;
      }
      if (this->Fd >= 0)
      {
        close(this->Fd);
        this->Fd = -1;
      }
    }

    // A named temporary; first the stale ones a SIGKILL may have left here.
    SweepStaleTemporaries(this->Directory);
    int suffixLength = 0;
    const std::string pattern = TemporaryTemplate(destination, suffixLength);
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = mkstemps(name.data(), suffixLength);
    if (fd < 0)
    {
      throw Error(Name(destination) + ": cannot create a file in '" + Name(this->Directory) +
        "': " + std::strerror(errno));
    }
    this->Named = name.data();
    SetTemporaryOutput(this->Named.c_str()); // removed even if a library crashes
    const int chmodResult = fchmod(fd, mode);
    const int chmodErrno = errno;
    close(fd);
    if (chmodResult != 0)
    {
      throw Error(Name(destination) + ": cannot set the permissions of '" + Name(this->Named) +
        "': " + std::strerror(chmodErrno));
    }
    this->WritePath = this->Named;
  }

  ~OutputFile()
  {
    if (this->Fd >= 0)
    {
      close(this->Fd);
    }
    if (!this->Named.empty())
    {
      std::remove(this->Named.c_str());
      SetTemporaryOutput(nullptr);
    }
  }

  /** The name OpenImageIO writes (and reads back). */
  const std::string& GetWritePath() const { return this->WritePath; }

  /** The write path replaced by the destination's name in a message. */
  std::string Explain(const std::string& message) const
  {
    return ReplaceAll(message, this->WritePath, DisplayName(this->Destination, true));
  }

  /** Makes the written file the output. */
  void Commit()
  {
    if (this->Destination == "-")
    {
      this->CopyToStandardOutput();
    }
    else if (this->Named.empty())
    {
      this->LinkIntoPlace();
    }
    else
    {
      this->RenameOver(this->Named);
    }
  }

private:
  OutputFile(const OutputFile&) = delete;
  void operator=(const OutputFile&) = delete;

  void RenameOver(const std::string& from)
  {
    if (std::rename(from.c_str(), this->Destination.c_str()) != 0)
    {
      throw Error(Name(this->Destination) + ": cannot replace it: " + std::strerror(errno));
    }
    this->Named.clear();
    SetTemporaryOutput(nullptr);
  }

  void LinkIntoPlace()
  {
    // A new output appears whole under its name at once.
    if (linkat(AT_FDCWD, this->WritePath.c_str(), AT_FDCWD, this->Destination.c_str(),
          AT_SYMLINK_FOLLOW) == 0)
    {
      return;
    }
    if (errno != EEXIST)
    {
      throw Error(Name(this->Destination) + ": cannot create it: " + std::strerror(errno));
    }
    // An existing one is replaced by a rename, from a name it has only for that moment.
    SweepStaleTemporaries(this->Directory);
    int suffixLength = 0;
    const std::string pattern = TemporaryTemplate(this->Destination, suffixLength);
    const size_t x = pattern.size() - static_cast<size_t>(suffixLength) - 6;
    std::random_device random;
    const char* letters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
    for (int attempt = 0; attempt < 100; ++attempt)
    {
      std::string name = pattern;
      for (size_t k = 0; k < 6; ++k)
      {
        name[x + k] = letters[random() % 62];
      }
      this->Named = name;
      SetTemporaryOutput(this->Named.c_str());
      if (linkat(AT_FDCWD, this->WritePath.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0)
      {
        this->RenameOver(name);
        return;
      }
      const int linkErrno = errno;
      this->Named.clear();
      SetTemporaryOutput(nullptr);
      if (linkErrno != EEXIST)
      {
        throw Error(Name(this->Destination) + ": cannot replace it: " + std::strerror(linkErrno));
      }
    }
    throw Error(Name(this->Destination) + ": cannot replace it: no free temporary name");
  }

  void CopyToStandardOutput()
  {
    std::vector<char> buffer(1 << 16);
    if (lseek(this->Fd, 0, SEEK_SET) != 0)
    {
      throw Error("standard output: cannot read back the image: " + std::string(std::strerror(errno)));
    }
    for (;;)
    {
      const ssize_t got = read(this->Fd, buffer.data(), buffer.size());
      if (got < 0 && errno == EINTR)
      {
        continue;
      }
      if (got < 0)
      {
        throw Error("standard output: cannot read back the image: " + std::string(std::strerror(errno)));
      }
      if (got == 0)
      {
        return;
      }
      if (!WriteAll(STDOUT_FILENO, buffer.data(), static_cast<size_t>(got)))
      {
        throw Error("standard output: " + std::string(std::strerror(errno)));
      }
    }
  }

  std::string Destination;
  std::string Directory;
  std::string WritePath;
  std::string Named; // the named temporary to remove, or ""
  int Fd = -1;       // the file without a name, or -1
};

// OpenImageIO's error `text` as the end of a message: one line, the dangling ':' of messages
// such as "ZLib error:" dropped, or `fallback` if it says nothing.
std::string LibraryText(const std::string& text, const std::string& fallback)
{
  std::string line = Printable(text);
  while (!line.empty() && (line.back() == ':' || line.back() == ' '))
  {
    line.pop_back();
  }
  return line.empty() ? fallback : line;
}

// What a writer of OpenImageIO 2.4 does with an image of 1 to 4 channels, found by writing
// and reading back every case (the tool's tests keep checking it).
enum class Channels
{
  Keep,       // written as they are
  DropAlpha,  // the format has no alpha: the colour channels are written
  AddAlpha,   // the writer always writes 4 channels (GIF, ICO)
  Refuse      // the writer refuses them or is known to get them wrong
};

struct WriterRule
{
  const char* Format;
  Channels ByCount[4];  // for 1, 2, 3, 4 channels
  const char* Why;      // for Refuse
};

const WriterRule WriterRules[] = {
  { "bmp", { Channels::Keep, Channels::Refuse, Channels::Keep, Channels::Keep },
    "BMP files have no grey + alpha" },
  { "dpx", { Channels::Keep, Channels::Refuse, Channels::Keep, Channels::Keep },
    "OpenImageIO's DPX writer aborts on grey + alpha" },
  { "gif", { Channels::Refuse, Channels::Refuse, Channels::AddAlpha, Channels::Keep },
    "OpenImageIO's GIF writer takes only RGB and RGBA" },
  { "hdr", { Channels::Refuse, Channels::Refuse, Channels::Keep, Channels::DropAlpha },
    "HDR (RGBE) files hold RGB only" },
  { "heif", { Channels::Refuse, Channels::Refuse, Channels::Keep, Channels::Keep },
    "OpenImageIO's HEIF writer takes only RGB and RGBA" },
  { "ico", { Channels::AddAlpha, Channels::AddAlpha, Channels::AddAlpha, Channels::Keep }, "" },
  { "iff", { Channels::Refuse, Channels::Refuse, Channels::Keep, Channels::Keep },
    "IFF files hold RGB and RGBA only" },
  { "jpeg", { Channels::Keep, Channels::DropAlpha, Channels::Keep, Channels::DropAlpha }, "" },
  { "pnm", { Channels::Keep, Channels::DropAlpha, Channels::Keep, Channels::DropAlpha }, "" },
  { "webp", { Channels::Refuse, Channels::Refuse, Channels::Keep, Channels::Keep },
    "OpenImageIO's WebP writer takes only RGB and RGBA" },
  { "zfile", { Channels::Keep, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "Zfile files hold one channel" },
  { "jpeg2000", { Channels::Refuse, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "OpenImageIO 2.4's JPEG 2000 writer writes files that cannot be read back" },
  { "fits", { Channels::Refuse, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "OpenImageIO 2.4's FITS writer writes truncated or transposed images" },
  { "rla", { Channels::Refuse, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "OpenImageIO 2.4's RLA writer writes wrong headers (a width of -1)" },
  { "null", { Channels::Refuse, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "the null format writes no file" },
  { "term", { Channels::Refuse, Channels::Refuse, Channels::Refuse, Channels::Refuse },
    "the term format draws on a terminal and writes no file" },
};

Channels RuleFor(const std::string& format, int channels, std::string& why)
{
  for (const WriterRule& rule : WriterRules)
  {
    if (format == rule.Format && channels >= 1 && channels <= 4)
    {
      why = rule.Why;
      return rule.ByCount[channels - 1];
    }
  }
  return Channels::Keep; // other writers: the read-back check below is the safeguard
}

const char* ChannelWord(int channels)
{
  switch (channels)
  {
    case 1:
      return "grey";
    case 2:
      return "grey + alpha";
    case 3:
      return "RGB";
    case 4:
      return "RGBA";
    default:
      return "other";
  }
}

#ifdef MLAA_TEST_HOOKS
// For tests only (compiled into mlaa-test-hooks, never into the installed mlaa):
// MLAA_TEST_CRASH_WHILE_WRITING=abort|segv|exit makes the tool fail as a library
// would, after a library message, while it writes `path`, so that the tests can see a crash
// reported; =sleep makes it wait there (up to a minute) for a signal. With
// MLAA_TEST_CRASH_ONLY=TEXT, only outputs whose name contains TEXT (one file of a batch).
void SimulateLibraryCrashForTests(const std::string& path)
{
  const char* crash = std::getenv("MLAA_TEST_CRASH_WHILE_WRITING");
  const char* only = std::getenv("MLAA_TEST_CRASH_ONLY");
  if (!crash || !*crash || (only && *only && path.find(only) == std::string::npos))
  {
    return;
  }
  if (std::strcmp(crash, "sleep") == 0)
  {
    // MLAA_TEST_WRITING_MARKER=PREFIX: PREFIX.PID is created once the writer has started, for
    // tests that must know when (the file being written may have no name).
    const char* marker = std::getenv("MLAA_TEST_WRITING_MARKER");
    if (marker && *marker)
    {
      const std::string name = std::string(marker) + "." + std::to_string(getpid());
      const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
      if (fd >= 0)
      {
        close(fd);
      }
    }
    for (int second = 0; second < 60; ++second)
    {
      sleep(1);
    }
    return;
  }
  std::fprintf(stderr, "simulated library message before a crash\n");
  if (std::strcmp(crash, "abort") == 0)
  {
    std::abort();
  }
  if (std::strcmp(crash, "segv") == 0)
  {
    std::raise(SIGSEGV);
  }
  if (std::strcmp(crash, "exit") == 0)
  {
    std::exit(3);
  }
}
#endif
} // namespace

//------------------------------------------------------------------------------
std::string DisplayName(const std::string& path, bool output)
{
  return path == "-" ? (output ? "standard output" : "standard input") : Name(path);
}

//------------------------------------------------------------------------------
void CheckOutputFormat(const std::string& format)
{
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(format);
  OIIO::geterror();
  if (!output || format.find_first_of("/.") != std::string::npos)
  {
    throw UsageError("--format '" + Printable(format, 40, false) +
      "': OpenImageIO has no writer of that name (give a format or an extension: png, tif, exr, "
      "jpg, ...)");
  }
}

//------------------------------------------------------------------------------
void SweepStaleTemporaries(const std::string& directory)
{
  if (!SweptDirectories().insert(directory).second)
  {
    return;
  }
  DIR* listing = opendir(directory.c_str());
  if (!listing)
  {
    return;
  }
  const int fd = dirfd(listing);
  const time_t now = time(nullptr);
  while (const dirent* entry = readdir(listing))
  {
    const long pid = TemporaryOwner(entry->d_name);
    struct stat status;
    if (pid <= 0 || pid == getpid() ||
      fstatat(fd, entry->d_name, &status, AT_SYMLINK_NOFOLLOW) != 0 ||
      !S_ISREG(status.st_mode) || status.st_uid != geteuid() ||
      now - status.st_mtime < StaleTemporarySeconds)
    {
      continue;
    }
    // Its writer must be gone: a process that still runs (or that this user may not signal)
    // keeps its file.
    if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH)
    {
      continue;
    }
    unlinkat(fd, entry->d_name, 0);
  }
  closedir(listing);
}

//------------------------------------------------------------------------------
// Why OpenImageIO's reader must not read the pixels of this file, or "" where it may.
//
// OpenImageIO before 3.2 writes up to 28 bytes past the end of its own pixel buffer when it
// reads an ICO file whose first icon is a bitmap (not a PNG) of fewer than 32 bits per pixel
// and whose width is not a multiple of 8: it applies the icon's 1-bit transparency mask eight
// pixels at a time without stopping at the end of the row (upstream fix: OpenImageIO pull
// request 5088, in 3.2). A heap overflow is not an error the tool could report afterwards (it
// was found by the tool's fuzz target, Testing/Fuzz), so such files are refused before their
// pixels are read. The layout read here is the ICO directory entry (6-byte header, then 16
// bytes per icon: width at 0, image offset at 12) and the bitmap header at that offset (bits
// per pixel at 14), or a PNG signature there.
std::string UnsafePixelsReason(
  const InputFile& source, const std::string& formatName, const OIIO::ImageSpec& spec)
{
  const int version = OIIO::openimageio_version();
  if (formatName != "ico" || version >= 30200 || spec.width % 8 == 0)
  {
    return std::string();
  }
  unsigned char entry[16];
  if (source.ReadAt(6, entry, sizeof(entry)) != sizeof(entry))
  {
    return std::string();
  }
  const std::uint32_t offset = entry[12] | (entry[13] << 8) | (entry[14] << 16) |
    (static_cast<std::uint32_t>(entry[15]) << 24);
  unsigned char bitmap[16];
  if (source.ReadAt(offset, bitmap, sizeof(bitmap)) != sizeof(bitmap) ||
    (bitmap[1] == 'P' && bitmap[2] == 'N' && bitmap[3] == 'G'))
  {
    return std::string(); // a PNG icon, read by OpenImageIO's PNG code
  }
  const int bitsPerPixel = bitmap[14] | (bitmap[15] << 8);
  if (bitsPerPixel >= 32)
  {
    return std::string(); // no transparency mask
  }
  return "cannot read this ico file safely: its icon is " + std::to_string(spec.width) +
    " pixels wide (not a multiple of 8) with " + std::to_string(bitsPerPixel) +
    " bits per pixel and a transparency mask, which the ICO reader of OpenImageIO " +
    std::to_string(version / 10000) + "." + std::to_string(version / 100 % 100) + "." +
    std::to_string(version % 100) + " mishandles (it writes past the end of its buffer; " +
    "fixed in OpenImageIO 3.2); convert the icon to PNG with another program";
}

namespace
{
// Runs `work` (a read or a write through OpenImageIO) and turns an exception that is not the
// tool's own (a library's std::length_error, say, whose text is only "vector::_M_default_append")
// into an mlaa::Error that says what failed in the tool's words, the library's text after it.
// `what`: "NAME: "; `doing`: "reading it", "writing it"; `format`: the format, once known.
template <typename Work>
auto LibraryExceptionsAsErrors(
  const std::string& what, const char* doing, const std::string& format, Work&& work)
  -> decltype(work())
{
  try
  {
    return work();
  }
  catch (const Error&)
  {
    throw;
  }
  catch (const std::bad_alloc&)
  {
    throw Error(what + "not enough memory while " + doing);
  }
  catch (const std::exception& e)
  {
    throw Error(what + "OpenImageIO" + (format.empty() ? std::string() : "'s " + format + " code") +
      " failed while " + doing + " (the file is probably damaged): " +
      LibraryText(e.what(), "an exception without a message"));
  }
}
} // namespace

// ReadImageFile without LibraryExceptionsAsErrors; `format` gets the format's name once known.
static ImageFile ReadImageFileUnguarded(
  const std::string& path, std::uint64_t maxPixels, std::string& format);

ImageFile ReadImageFile(const std::string& path, std::uint64_t maxPixels)
{
  std::string format;
  return LibraryExceptionsAsErrors(DisplayName(path, false) + ": ", "reading it", format,
    [&] { return ReadImageFileUnguarded(path, maxPixels, format); });
}

static ImageFile ReadImageFileUnguarded(
  const std::string& path, std::uint64_t maxPixels, std::string& format)
{
  const std::string what = DisplayName(path, false) + ": ";
  const InputFile source(path);

  CapturedStderr messages(DisplayName(path, false), "OpenImageIO was reading it");
  // Keep unassociated alpha as stored (PNG, TIFF): premultiplying it on reading and dividing
  // it out again on writing would change pixels that antialiasing leaves alone.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::string openError;
  std::unique_ptr<OIIO::ImageInput> input =
    OpenReader(source.GetReadPath(), source.GetFormatHint(), &config, openError);
  if (!input)
  {
    const std::string printed = messages.Finish();
    throw Error(what + "cannot open it as an image: " +
      LibraryText(source.Explain(openError + "\n" + printed),
        "no reader of OpenImageIO knows it, or the file is damaged"));
  }

  ImageFile file;
  file.Spec = input->spec();
  file.FormatName = input->format_name();
  format = file.FormatName;
  const OIIO::ImageSpec& spec = file.Spec;
  if (spec.deep)
  {
    throw Error(what + "deep images are not supported");
  }
  const std::string unsafe = UnsafePixelsReason(source, file.FormatName, spec);
  if (!unsafe.empty())
  {
    throw Error(what + unsafe);
  }
  if (spec.depth > 1)
  {
    throw Error(
      what + "volume images (" + std::to_string(spec.depth) + " slices) are not supported");
  }
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
  {
    throw Error(what + "the image is empty (" + std::to_string(spec.width) + " x " +
      std::to_string(spec.height) + " pixels, " + std::to_string(spec.nchannels) + " channels)");
  }
  file.PixelType = FilePixelType(spec);
  const int vtkType = GetVTKScalarType(file.PixelType);
  if (!vtkType)
  {
    throw Error(what + "pixels of type " + file.PixelType.c_str() + " are not supported");
  }
  // vtkImageMLAA takes up to 4 channels; more would only cost memory before it says so.
  if (spec.nchannels > 64)
  {
    throw Error(what + "the file claims " + std::to_string(spec.nchannels) +
      " channels; at most 4 can be antialiased");
  }

  // The size comes from the header, which may lie: checked before anything is allocated.
  const std::uint64_t pixels =
    static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height);
  const bool defaultLimit = maxPixels == 0;
  const std::uint64_t limit =
    defaultLimit ? DefaultMaxPixels(spec.nchannels, file.PixelType) : maxPixels;
  const std::uint64_t hardLimit = std::numeric_limits<int>::max() / 4; // VTK's point ids
  if (pixels > limit || pixels > hardLimit)
  {
    throw Error(what + "the image is " + std::to_string(spec.width) + " x " +
      std::to_string(spec.height) + " = " + std::to_string(pixels) + " pixels, more than " +
      (pixels > hardLimit ? "the tool can hold (" + std::to_string(hardLimit) + ")"
                          : defaultLimit
            ? "the " + std::to_string(limit) + " that fit in half of the available memory" +
              (ImagesInFlight > 1
                  ? " shared by " + std::to_string(ImagesInFlight) + " files at a time"
                  : std::string()) +
              " (--max-pixels N raises the limit)"
            : "--max-pixels " + std::to_string(limit)));
  }

  file.Image = vtkSmartPointer<vtkImageData>::New();
  file.Image->SetDimensions(spec.width, spec.height, 1);
  file.Image->AllocateScalars(vtkType, spec.nchannels);
  file.Image->GetPointData()->GetScalars()->SetName("Pixels");
  // A batch reads each file in a process of its own, where every buffer is fresh memory.
  vtkAntialiasingKit::PreferHugePages(file.Image->GetPointData()->GetScalars());

  // The file's top row goes to the image's last row, and so on down: start at the last row
  // and step backwards.
  const OIIO::TypeDesc bufferType = BufferType(vtkType);
  const OIIO::stride_t rowBytes =
    static_cast<OIIO::stride_t>(spec.width) * spec.nchannels * bufferType.size();
  char* lastRow = static_cast<char*>(file.Image->GetScalarPointer()) + (spec.height - 1) * rowBytes;
  if (!input->read_image(0, 0, 0, spec.nchannels, bufferType, lastRow, OIIO::AutoStride, -rowBytes))
  {
    const std::string error = input->geterror();
    const std::string printed = messages.Finish();
    const std::string compression = spec.get_string_attribute("compression");
    throw Error(what + "cannot read the pixels of this " + file.FormatName + " file" +
      (compression.empty() || compression == "none" ? std::string()
                                                    : " (" + Printable(compression, 40) + " compressed)") +
      ": " +
      LibraryText(source.Explain(error + "\n" + printed),
        "OpenImageIO's reader gave no reason; the file is probably truncated or damaged"));
  }
  input->close();
  const std::string printed = Printable(messages.Finish());
  if (!printed.empty())
  {
    file.Warning = what + "while reading: " + printed;
  }
  return file;
}

//------------------------------------------------------------------------------
// WriteImageFile without LibraryExceptionsAsErrors; `formatName` gets the format's name.
static std::string WriteImageFileUnguarded(vtkImageData* image, const std::string& path,
  const OIIO::ImageSpec& description, OIIO::TypeDesc pixelType, const double valueRange[2],
  const std::string& format, std::string& formatName);

std::string WriteImageFile(vtkImageData* image, const std::string& path,
  const OIIO::ImageSpec& description, OIIO::TypeDesc pixelType, const double valueRange[2],
  const std::string& format)
{
  std::string formatName;
  return LibraryExceptionsAsErrors(DisplayName(path, true) + ": ", "writing it", formatName,
    [&] {
      return WriteImageFileUnguarded(
        image, path, description, pixelType, valueRange, format, formatName);
    });
}

static std::string WriteImageFileUnguarded(vtkImageData* image, const std::string& path,
  const OIIO::ImageSpec& description, OIIO::TypeDesc pixelType, const double valueRange[2],
  const std::string& format, std::string& formatNameOut)
{
  const std::string what = DisplayName(path, true) + ": ";
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    throw Error(what + "there is no 2D image to write");
  }
  const int channels = scalars->GetNumberOfComponents();
  if (channels != description.nchannels)
  {
    throw Error(what + "the image has " + std::to_string(channels) + " channels, its description " +
      std::to_string(description.nchannels));
  }
  const OIIO::TypeDesc bufferType = BufferType(scalars->GetDataType());
  if (bufferType == OIIO::TypeDesc::UNKNOWN)
  {
    throw Error(what + "pixels of type " + scalars->GetDataTypeAsString() + " cannot be written");
  }
  // Only a file is replaced: not a directory, a device or a FIFO.
  struct stat existing;
  if (path != "-" && stat(path.c_str(), &existing) == 0 && !S_ISREG(existing.st_mode))
  {
    throw Error(what + "exists and is not a regular file; OUTPUT must name a file");
  }
  if (path == "-" && format.empty())
  {
    throw UsageError("OUTPUT - (standard output) needs --format NAME, e.g. --format png");
  }

  // The writer comes from --format or the destination's extension, before any file is created.
  if (!format.empty())
  {
    CheckOutputFormat(format);
  }
  CapturedStderr messages(DisplayName(path, true), "OpenImageIO was writing it"); // also covers the writer's destruction
  std::unique_ptr<OIIO::ImageOutput> output =
    OIIO::ImageOutput::create(format.empty() ? path : format);
  if (!output)
  {
    OIIO::geterror(); // consumed: the message below says it in one line
    throw Error(what +
      "OpenImageIO has no writer for files named like this (unsupported format '" +
      Printable(std::filesystem::path(path).extension().string(), 40) + "'; --format NAME chooses one)");
  }
  const std::string formatName = output->format_name();
  formatNameOut = formatName;

  // What the writer is given: all channels, or the colour ones of a format without alpha.
  std::string why;
  const Channels rule = RuleFor(formatName, channels, why);
  std::string ignored;
  const bool refusesAll = RuleFor(formatName, 1, ignored) == Channels::Refuse &&
    RuleFor(formatName, 3, ignored) == Channels::Refuse &&
    RuleFor(formatName, 4, ignored) == Channels::Refuse;
  if (refusesAll)
  {
    throw Error(what + "the tool does not write " + formatName + " files: " + why);
  }
  if (rule == Channels::Refuse)
  {
    throw Error(what + "cannot write " + std::to_string(channels) + "-channel (" +
      ChannelWord(channels) + ") images as " + formatName + ": " + why);
  }
  const int written = rule == Channels::DropAlpha ? channels - 1 : channels;
  const int expectedChannels = rule == Channels::AddAlpha ? 4 : written;

  OIIO::ImageSpec spec = description;
  spec.width = dims[0];
  spec.height = dims[1];
  spec.depth = 1;
  spec.nchannels = written;
  spec.channelnames.resize(static_cast<size_t>(written));
  if (spec.alpha_channel >= written)
  {
    spec.alpha_channel = -1;
  }
  spec.set_format(pixelType);
  spec.channelformats.clear();
  spec.tile_width = spec.tile_height = 0;
  spec.tile_depth = 1;
  // The source's storage details would be wrong for another format or pixel type; each
  // writer's defaults (lossless where the format has a choice) apply instead.
  for (const char* name : { "compression", "Compression", "CompressionQuality",
         "oiio:BitsPerSample", "tiff:Compression" })
  {
    spec.erase_attribute(name);
  }

  OutputFile temporary(path);
  // On failure the writer is destroyed before the temporary file is removed: writers that
  // write on closing (HEIF) would otherwise create it again.
  struct WriterFirst
  {
    std::unique_ptr<OIIO::ImageOutput>& Output;
    ~WriterFirst() { this->Output.reset(); }
  } writerFirst{ output };
  if (!output->open(temporary.GetWritePath(), spec))
  {
    const std::string error = output->geterror();
    throw Error(what + "cannot start writing it as " + formatName + ": " +
      LibraryText(temporary.Explain(error + "\n" + messages.Finish()),
        "OpenImageIO's writer gave no reason"));
  }
  const OIIO::TypeDesc writtenType = output->spec().format;
#ifdef MLAA_TEST_HOOKS
  SimulateLibraryCrashForTests(path);
#endif

  // Floating-point pixels in an integer format: OpenImageIO maps [0, 1] to the whole integer
  // range; map the value range there instead.
  const void* pixels = scalars->GetVoidPointer(0);
  std::vector<double> rescaled;
  OIIO::TypeDesc sourceType = bufferType;
  const bool floatToInteger = bufferType.is_floating_point() && !writtenType.is_floating_point();
  if (floatToInteger && (valueRange[0] != 0.0 || valueRange[1] != 1.0))
  {
    const vtkIdType count = scalars->GetNumberOfValues();
    rescaled.resize(static_cast<size_t>(count));
    const double scale = 1.0 / (valueRange[1] - valueRange[0]);
    const float* floats = static_cast<const float*>(pixels);
    const double* doubles = static_cast<const double*>(pixels);
    const bool isFloat = bufferType == OIIO::TypeDesc::FLOAT;
    for (vtkIdType i = 0; i < count; ++i)
    {
      rescaled[i] = ((isFloat ? floats[i] : doubles[i]) - valueRange[0]) * scale;
    }
    pixels = rescaled.data();
    sourceType = OIIO::TypeDesc::DOUBLE;
  }

  // Pixels are `channels` values apart; the writer takes the first `written` of each.
  const OIIO::stride_t pixelBytes = static_cast<OIIO::stride_t>(channels) * sourceType.size();
  const OIIO::stride_t rowBytes = static_cast<OIIO::stride_t>(dims[0]) * pixelBytes;
  const char* lastRow = static_cast<const char*>(pixels) + (dims[1] - 1) * rowBytes;
  bool ok;
  if (formatName == "heif")
  {
    // OpenImageIO 2.4's HEIF writer copies each row with the length of libheif's (aligned)
    // row, reading past the end of rows whose length is not a multiple of it. It is given 8-bit
    // rows (all it writes) with room after each.
    const OIIO::stride_t rowOut = static_cast<OIIO::stride_t>(dims[0]) * written;
    const OIIO::stride_t paddedRow = rowOut + 256;
    std::vector<unsigned char> padded(static_cast<size_t>(paddedRow) * dims[1], 0);
    ok = OIIO::convert_image(written, dims[0], dims[1], 1, lastRow, sourceType, pixelBytes,
      -rowBytes, OIIO::AutoStride, padded.data(), OIIO::TypeDesc::UINT8, written, paddedRow,
      OIIO::AutoStride);
    for (int row = 0; ok && row < dims[1]; ++row)
    {
      ok = output->write_scanline(row, 0, OIIO::TypeDesc::UINT8, padded.data() + row * paddedRow);
    }
  }
  else
  {
    ok = output->write_image(sourceType, lastRow, pixelBytes, -rowBytes);
  }
  if (!ok)
  {
    const std::string error = output->geterror();
    throw Error(what + "cannot write the pixels as " + formatName + ": " +
      LibraryText(temporary.Explain(error + "\n" + messages.Finish()),
        "OpenImageIO's writer gave no reason"));
  }
  if (!output->close())
  {
    const std::string error = output->geterror();
    throw Error(what + "cannot finish writing it as " + formatName + ": " +
      LibraryText(temporary.Explain(error + "\n" + messages.Finish()),
        "OpenImageIO's writer gave no reason"));
  }
  output.reset();

  // Read back before it replaces anything: a writer that reported success may still have
  // written something else.
  {
    std::string error;
    std::unique_ptr<OIIO::ImageInput> check =
      OpenReader(temporary.GetWritePath(), formatName, nullptr, error);
    if (!check)
    {
      throw Error(what + "OpenImageIO's " + formatName +
        " writer wrote a file that cannot be read back (" +
        LibraryText(temporary.Explain(error + "\n" + messages.Finish()),
          "OpenImageIO gave no reason") +
        ")");
    }
    const OIIO::ImageSpec& back = check->spec();
    if (back.width != dims[0] || back.height != dims[1] || back.nchannels != expectedChannels)
    {
      throw Error(what + "OpenImageIO's " + formatName + " writer wrote a " +
        std::to_string(back.width) + " x " + std::to_string(back.height) + " image with " +
        std::to_string(back.nchannels) + " channels instead of " + std::to_string(dims[0]) +
        " x " + std::to_string(dims[1]) + " with " + std::to_string(expectedChannels) +
        "; nothing was written");
    }
    check->close();
  }
  temporary.Commit();

  const std::string printed = Printable(messages.Finish());
  std::string note = printed.empty() ? "" : what + "while writing: " + printed;
  if (expectedChannels != channels)
  {
    note += note.empty() ? "" : "; ";
    note += what + formatName + " files cannot hold " + ChannelWord(channels) + " images: wrote " +
      ChannelWord(expectedChannels) + " (" +
      (expectedChannels < channels ? "alpha dropped" : "alpha added") + ")";
  }
  if (writtenType.basetype == pixelType.basetype)
  {
    return note;
  }
  note += note.empty() ? "" : "; ";
  note += what + formatName + " files cannot hold " + pixelType.c_str() + " pixels; wrote " +
    writtenType.c_str();
  if (floatToInteger)
  {
    std::ostringstream range;
    range << " (values in [" << valueRange[0] << ", " << valueRange[1] << "] scaled to 0.."
          << IntegerTypeMaximum(writtenType) << ", others clamped)";
    note += range.str();
  }
  else if (!pixelType.is_floating_point() && writtenType.is_floating_point())
  {
    note += " (values scaled to [0, 1])";
  }
  return note;
}
} // namespace mlaa
