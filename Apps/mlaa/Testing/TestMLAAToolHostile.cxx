// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Cases of TestMLAATool: hostile and random files, and a library crash surfaced.
#include "mlaaToolTestSupport.h"

using namespace mlaaToolTest;

namespace
{
//------------------------------------------------------------------------------
// Hostile files: whatever the input or the output name, the tool ends by itself (no signal, no
// hang), says what is wrong in one short printable line naming the file, and leaves no output
// or temporary file behind.

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
    // The tool's own check names the pixels; OpenImageIO 3 refuses such headers itself first,
    // naming the size in MB.
    if (!MLAA_CHECK(run.Err.find("pixels") != std::string::npos ||
          run.Err.find(" MB") != std::string::npos))
    {
      std::cout << "  the error names neither the pixels nor the size: " << run.Err << std::endl;
    }
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

// An ICO file of one `width` x `height` bitmap icon (not a PNG one) of `bitsPerPixel` 8, 24 or
// 32: palette (8 bits), pixels and, below 32 bits, the 1-bit transparency mask, rows padded to
// 4 bytes as the format wants. The pixels are a vertical split, dark left and light right.
std::string IconFile(int width, int height, int bitsPerPixel)
{
  std::string bytes;
  auto put = [&bytes](unsigned value, int size)
  {
    for (int i = 0; i < size; ++i)
    {
      bytes.push_back(static_cast<char>((value >> (8 * i)) & 0xff));
    }
  };
  auto padded = [](int rowBytes) { return (rowBytes + 3) / 4 * 4; };
  const int paletteSize = bitsPerPixel == 8 ? 256 : 0;
  const int colourRow = padded((width * bitsPerPixel + 7) / 8);
  const int maskRow = bitsPerPixel < 32 ? padded((width + 7) / 8) : 0;
  const int size = 40 + 4 * paletteSize + height * (colourRow + maskRow);
  put(0, 2), put(1, 2), put(1, 2);                          // header: an icon file, one icon
  put(width, 1), put(height, 1), put(0, 1), put(0, 1);      // directory entry
  put(1, 2), put(bitsPerPixel, 2), put(size, 4), put(22, 4);
  put(40, 4), put(width, 4), put(2 * height, 4), put(1, 2); // bitmap header (both masks' height)
  put(bitsPerPixel, 2), put(0, 4), put(0, 4), put(0, 4), put(0, 4), put(0, 4), put(0, 4);
  for (int i = 0; i < paletteSize; ++i)
  {
    put(i, 1), put(i, 1), put(i, 1), put(0, 1);
  }
  for (int y = 0; y < height; ++y)
  {
    const size_t start = bytes.size();
    for (int x = 0; x < width; ++x)
    {
      const unsigned value = x < width / 2 ? 40 : 220;
      for (int b = 0; b < bitsPerPixel / 8; ++b)
      {
        put(b == 3 ? 255 : value, 1);
      }
    }
    bytes.resize(start + colourRow, '\0');
  }
  bytes.append(static_cast<size_t>(height * maskRow), '\0'); // all opaque
  return bytes;
}

void HostileUnsafeIcons()
{
  // OpenImageIO before 3.2 writes past its own buffer on bitmap icons with a transparency mask
  // whose width is not a multiple of 8 (mlaaImageFile.cxx, UnsafePixelsReason): the tool
  // refuses them before their pixels are read, whatever the file is called. Icons of any other
  // shape read as before.
  const bool unsafeReader = OIIO::openimageio_version() < 30200;
  struct Icon
  {
    int Width, Height, Bits;
    bool Unsafe;
  };
  int index = 0;
  for (const Icon& icon : { Icon{ 12, 6, 8, unsafeReader }, Icon{ 13, 5, 24, unsafeReader },
         Icon{ 1, 1, 8, unsafeReader }, Icon{ 16, 6, 8, false }, Icon{ 24, 4, 24, false },
         Icon{ 12, 6, 32, false }, Icon{ 13, 5, 32, false } })
  {
    for (const char* extension : { ".ico", ".png" })
    {
      const std::string stem = "icon" + std::to_string(index++);
      const fs::path input = WorkFile(stem + extension);
      WriteText(input, IconFile(icon.Width, icon.Height, icon.Bits));
      const fs::path output = WorkFile(stem + "-out.png");
      std::cout << "  " << icon.Width << " x " << icon.Height << ", " << icon.Bits
                << " bits, named " << input.filename().string() << std::endl;
      if (icon.Unsafe)
      {
        ExpectCleanFailure({}, input.string(), output, input.string());
        const Run run = RunTool({ input.string(), output.string() });
        MLAA_CHECK(run.Err.find("not a multiple of 8") != std::string::npos);
        MLAA_CHECK(run.Err.find("OpenImageIO") != std::string::npos);
      }
      else
      {
        ExpectSuccess({ input.string(), output.string() }, output);
        const FileImage read = ReadFile(output);
        int dims[3];
        read.Image->GetDimensions(dims);
        MLAA_CHECK(dims[0] == icon.Width && dims[1] == icon.Height);
        MLAA_CHECK(FileTexel(output, 0, 0, 0) == 40);
        MLAA_CHECK(FileTexel(output, icon.Width - 1, 0, 0) == 220);
      }
    }
  }
}

void HostileLibraryExceptions()
{
  // OpenImageIO 2.4.7's GIF reader throws std::length_error ("vector::_M_default_append") on
  // this 205-byte file, found by the tool's fuzz target: the tool says which file failed and
  // in what, with the library's text after, in one clean line, and writes nothing.
  std::string bytes = "GIF";
  for (int i = 0; i < 28; ++i)
  {
    bytes += "\xcc\xcc=\xcd";
  }
  bytes += '\xcc';
  bytes.append(20, '\0');
  bytes.append(69, '\x14');
  for (const char* name : { "exception.gif", "exception.png" })
  {
    const fs::path input = WorkFile(name);
    WriteText(input, bytes);
    const fs::path output = WorkFile("exception-out.png");
    ExpectCleanFailure({}, input.string(), output, input.string());
    const Run run = RunTool({ input.string(), output.string() });
    std::cout << "  " << run.Err;
    MLAA_CHECK(run.Err.find("_M_") == std::string::npos ||
      run.Err.find("OpenImageIO failed while reading it") != std::string::npos);
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
  // HEIF must work where the library has an encoder (mlaa-heif-output skips where it has not).
  const std::string noHeif = WriterUnavailable("heic");
  if (!noHeif.empty())
  {
    std::cout << "  HEIF output is not required here: " << noHeif << std::endl;
  }
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
          (extension == "heic" && channels >= 3 && noHeif.empty()) ||
          (extension == "dpx" && channels != 2);
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
  const std::string noHeif = WriterUnavailable("heic");
  for (const std::string& format : formats)
  {
    if (format == "heic" && !noHeif.empty())
    {
      // No valid HEIF file to start from (mlaa-heif-output skips here); the others still run.
      std::cout << "  no HEIF seed: " << noHeif << std::endl;
      continue;
    }
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

// HEIF output (a codec of its own in libheif, which some builds lack: then the case is skipped):
// 3 and 4 channels of 8 bits are written with their size and channels, and read back.
void HeifOutput()
{
  const std::string unavailable = WriterUnavailable("heic");
  if (!unavailable.empty())
  {
    Skip(unavailable);
  }
  for (int channels : { 3, 4 })
  {
    const fs::path input = WorkFile("in" + std::to_string(channels) + ".png");
    WriteFile(HostileSeedImage(channels, VTK_UNSIGNED_CHAR, 33, 17), input, OIIO::TypeDesc::UINT8);
    const fs::path output = WorkFile("out.heic");
    const Run run = RunTool({ input.string(), output.string() }, {}, 60.0);
    if (MLAA_CHECK(CheckOutcome(run, output, std::to_string(channels) + " channels to .heic")))
    {
      auto back = OIIO::ImageInput::open(output.string());
      MLAA_CHECK(back && back->spec().width == 33 && back->spec().height == 17 &&
        back->spec().nchannels == channels);
      fs::remove(output);
    }
  }
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
  // Both ways of writing: the file without a name, and the named temporary of the fallback.
  for (const char* how : { "abort", "segv", "exit", "abort-named", "segv-named", "exit-named" })
  {
    const std::string crash(how);
    const bool named = crash.find("-named") != std::string::npos;
    const std::set<std::string> before = Listing(Where().Work);
    std::vector<std::string> environment = { "MLAA_TEST_CRASH_WHILE_WRITING=" +
      crash.substr(0, crash.find('-')) };
    if (named)
    {
      environment.push_back("MLAA_TEST_NAMED_TEMPORARY=1");
    }
    const Run run = RunTool({ input.string(), output.string() }, environment);
    // 128 + the signal, or 3 for exit(3); under AddressSanitizer a SEGV ends with its status 1.
    MLAA_CHECK(run.Status != 0 && !run.TimedOut);
    MLAA_CHECK(run.Err.find("mlaa: " + output.string() + ": crashed while OpenImageIO was writing it") == 0);
    MLAA_CHECK(run.Err.find("simulated library message before a crash") != std::string::npos);
    MLAA_CHECK(Listing(Where().Work) == before);
    MLAA_CHECK(TemporaryFiles(Where().Work) == 0 && !fs::exists(output));
  }
}
} // namespace

static const bool Registered = RegisterCases({
  { "hostile-special-inputs", HostileSpecialInputs },
  { "hostile-huge-headers", HostileHugeHeaders },
  { "hostile-unsafe-icons", HostileUnsafeIcons },
  { "hostile-library-exceptions", HostileLibraryExceptions },
  { "hostile-output-formats", HostileOutputFormats },
  { "hostile-corpus", HostileCorpus },
  { "heif-output", HeifOutput },
  { "random-files-a", RandomFilesA },
  { "random-files-b", RandomFilesB },
  { "crash-surfaced", CrashSurfaced } });
