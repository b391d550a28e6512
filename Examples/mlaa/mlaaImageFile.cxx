#include "mlaaImageFile.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"
#include "vtkType.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <sstream>
#include <type_traits>
#include <vector>

namespace mlaa
{
namespace
{
// OpenImageIO and the C library report errors that may span several lines; the tool reports
// exactly one.
std::string OneLine(const std::string& text)
{
  std::string line;
  bool pendingBreak = false;
  for (char c : text)
  {
    if (c == '\n' || c == '\r')
    {
      pendingBreak = !line.empty();
      continue;
    }
    if (pendingBreak)
    {
      line += "; ";
      pendingBreak = false;
    }
    line += c;
  }
  return line.empty() ? std::string("unknown error") : line;
}

// What the libraries under OpenImageIO print on stderr themselves (libpng does, before
// OpenImageIO turns its errors into messages of its own), captured instead of shown: the tool's
// errors are one line, and its warnings too.
class LibraryMessages
{
public:
  LibraryMessages()
  {
    std::fflush(stderr);
    this->Capture = std::tmpfile();
    this->SavedStderr = this->Capture ? dup(STDERR_FILENO) : -1;
    if (this->SavedStderr < 0 || dup2(fileno(this->Capture), STDERR_FILENO) < 0)
    {
      this->Restore(); // nothing captured: messages show, nothing else goes wrong
    }
  }

  ~LibraryMessages() { this->Restore(); }

  // Stops capturing; returns what was printed, as one line ("" if nothing).
  std::string Finish()
  {
    const bool captured = this->SavedStderr >= 0;
    std::string text;
    if (captured)
    {
      std::fflush(stderr);
      std::rewind(this->Capture);
      char buffer[4096];
      size_t n;
      while ((n = std::fread(buffer, 1, sizeof(buffer), this->Capture)) > 0)
      {
        text.append(buffer, n);
      }
    }
    this->Restore();
    return text.find_first_not_of(" \t\r\n") == std::string::npos ? std::string() : OneLine(text);
  }

private:
  LibraryMessages(const LibraryMessages&) = delete;
  void operator=(const LibraryMessages&) = delete;

  void Restore()
  {
    if (this->SavedStderr >= 0)
    {
      std::fflush(stderr);
      dup2(this->SavedStderr, STDERR_FILENO);
      close(this->SavedStderr);
      this->SavedStderr = -1;
    }
    if (this->Capture)
    {
      std::fclose(this->Capture);
      this->Capture = nullptr;
    }
  }

  std::FILE* Capture = nullptr;
  int SavedStderr = -1;
};

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

// The file that an image is written to before it replaces the destination: created empty, with
// the permissions the destination has (or would get), and removed again unless Commit()ed.
class TemporaryFile
{
public:
  explicit TemporaryFile(const std::string& destination)
  {
    namespace fs = std::filesystem;
    const fs::path target(destination);
    fs::path directory = target.parent_path();
    if (directory.empty())
    {
      directory = ".";
    }
    // Hidden, unique, and with the destination's extension so that OpenImageIO writes the same
    // format: "dir/.name.mlaa-XXXXXX.ext".
    const std::string extension = target.extension().string();
    std::string pattern =
      (directory / ("." + target.stem().string() + ".mlaa-XXXXXX" + extension)).string();
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = mkstemps(name.data(), static_cast<int>(extension.size()));
    if (fd < 0)
    {
      throw Error("cannot write '" + destination + "': cannot create a file in '" +
        directory.string() + "': " + std::strerror(errno));
    }
    this->Path = name.data();

    // mkstemps creates the file for its owner only; give it the permissions of the file it
    // replaces, or those a newly created file gets.
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
    const int chmodResult = fchmod(fd, mode);
    const int chmodErrno = errno;
    close(fd);
    if (chmodResult != 0)
    {
      throw Error("cannot write '" + destination + "': cannot set the permissions of '" +
        this->Path + "': " + std::strerror(chmodErrno));
    }
  }

  ~TemporaryFile()
  {
    if (!this->Path.empty())
    {
      std::remove(this->Path.c_str());
    }
  }

  const std::string& GetPath() const { return this->Path; }

  // Renames the file over `destination`; from then on it is no longer removed.
  void Commit(const std::string& destination)
  {
    if (std::rename(this->Path.c_str(), destination.c_str()) != 0)
    {
      throw Error("cannot write '" + destination + "': " + std::strerror(errno));
    }
    this->Path.clear();
  }

private:
  TemporaryFile(const TemporaryFile&) = delete;
  void operator=(const TemporaryFile&) = delete;

  std::string Path;
};
} // namespace

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

//------------------------------------------------------------------------------
ImageFile ReadImageFile(const std::string& path)
{
  const std::string what = "cannot read '" + path + "': ";
  struct stat status;
  if (stat(path.c_str(), &status) != 0)
  {
    throw Error(what + std::strerror(errno));
  }
  if (S_ISDIR(status.st_mode))
  {
    throw Error(what + "it is a directory");
  }

  LibraryMessages messages;
  // Keep unassociated alpha as stored (PNG, TIFF): premultiplying it on reading and dividing
  // it out again on writing would change pixels that antialiasing leaves alone.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> input = OIIO::ImageInput::open(path, &config);
  if (!input)
  {
    throw Error(what + OneLine(OIIO::geterror()));
  }

  ImageFile file;
  file.Spec = input->spec();
  file.FormatName = input->format_name();
  const OIIO::ImageSpec& spec = file.Spec;
  if (spec.deep)
  {
    throw Error(what + "deep images are not supported");
  }
  if (spec.depth > 1)
  {
    throw Error(
      what + "volume images (" + std::to_string(spec.depth) + " slices) are not supported");
  }
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1)
  {
    throw Error(what + "the image is empty");
  }
  file.PixelType = FilePixelType(spec);
  const int vtkType = GetVTKScalarType(file.PixelType);
  if (!vtkType)
  {
    throw Error(what + "pixels of type " + file.PixelType.c_str() + " are not supported");
  }

  file.Image = vtkSmartPointer<vtkImageData>::New();
  file.Image->SetDimensions(spec.width, spec.height, 1);
  file.Image->AllocateScalars(vtkType, spec.nchannels);
  file.Image->GetPointData()->GetScalars()->SetName("Pixels");

  // The file's top row goes to the image's last row, and so on down: start at the last row
  // and step backwards.
  const OIIO::TypeDesc bufferType = BufferType(vtkType);
  const OIIO::stride_t rowBytes =
    static_cast<OIIO::stride_t>(spec.width) * spec.nchannels * bufferType.size();
  char* lastRow = static_cast<char*>(file.Image->GetScalarPointer()) + (spec.height - 1) * rowBytes;
  if (!input->read_image(0, 0, 0, spec.nchannels, bufferType, lastRow, OIIO::AutoStride, -rowBytes))
  {
    throw Error(what + OneLine(input->geterror()));
  }
  input->close();
  const std::string printed = messages.Finish();
  if (!printed.empty())
  {
    file.Warning = "reading '" + path + "': " + printed;
  }
  return file;
}

//------------------------------------------------------------------------------
std::string WriteImageFile(vtkImageData* image, const std::string& path,
  const OIIO::ImageSpec& description, OIIO::TypeDesc pixelType, const double valueRange[2])
{
  const std::string what = "cannot write '" + path + "': ";
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

  LibraryMessages messages; // declared first: also covers the writer's destruction
  // The writer comes from the destination's extension, before any file is created.
  std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
  if (!output)
  {
    OIIO::geterror(); // consumed: the message below says it in one line
    throw Error(what +
      "OpenImageIO has no writer for files named like this (unsupported "
      "format '" +
      std::filesystem::path(path).extension().string() + "')");
  }

  OIIO::ImageSpec spec = description;
  spec.width = dims[0];
  spec.height = dims[1];
  spec.depth = 1;
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

  TemporaryFile temporary(path);
  if (!output->open(temporary.GetPath(), spec))
  {
    throw Error(what + OneLine(output->geterror()));
  }
  const OIIO::TypeDesc written = output->spec().format;
  const std::string formatName = output->format_name();

  // Floating-point pixels in an integer format: OpenImageIO maps [0, 1] to the whole integer
  // range; map the value range there instead.
  const void* pixels = scalars->GetVoidPointer(0);
  std::vector<double> rescaled;
  OIIO::TypeDesc sourceType = bufferType;
  const bool floatToInteger = bufferType.is_floating_point() && !written.is_floating_point();
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

  const OIIO::stride_t rowBytes =
    static_cast<OIIO::stride_t>(dims[0]) * channels * sourceType.size();
  const char* lastRow = static_cast<const char*>(pixels) + (dims[1] - 1) * rowBytes;
  if (!output->write_image(sourceType, lastRow, OIIO::AutoStride, -rowBytes))
  {
    throw Error(what + OneLine(output->geterror()));
  }
  if (!output->close())
  {
    throw Error(what + OneLine(output->geterror()));
  }
  output.reset();
  temporary.Commit(path);

  const std::string printed = messages.Finish();
  std::string note = printed.empty() ? "" : "writing '" + path + "': " + printed;
  if (written.basetype == pixelType.basetype)
  {
    return note;
  }
  note += note.empty() ? "" : "; ";
  note += "'" + path + "': " + formatName + " files cannot hold " + pixelType.c_str() +
    " pixels; wrote " + written.c_str();
  if (floatToInteger)
  {
    std::ostringstream range;
    range << " (values in [" << valueRange[0] << ", " << valueRange[1] << "] scaled to 0.."
          << IntegerTypeMaximum(written) << ", others clamped)";
    note += range.str();
  }
  else if (!pixelType.is_floating_point() && written.is_floating_point())
  {
    note += " (values scaled to [0, 1])";
  }
  return note;
}
} // namespace mlaa
