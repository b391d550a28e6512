// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "mlaaToolTestSupport.h"

namespace mlaaToolTest
{
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

void Skip(const std::string& why)
{
  throw SkippedCase(why);
}

int OpenTerminal()
{
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || grantpt(master) != 0 || unlockpt(master) != 0)
  {
    const std::string why = std::strerror(errno);
    if (master >= 0)
    {
      close(master);
    }
    Skip("no pseudo-terminal can be opened here (" + why + "; is /dev/pts mounted?)");
  }
  return master;
}

std::string WriterUnavailable(const std::string& extension)
{
  // Written as the cases write their inputs (WriteFile: rows from a padded copy, as OpenImageIO
  // 2.4's HEIF writer reads past the end of each row).
  const fs::path probe = WorkFile("writer-probe." + extension);
  std::string why;
  try
  {
    WriteFile(MakeImage(16, 16, 3, VTK_UNSIGNED_CHAR, 128.0), probe, OIIO::TypeDesc::UINT8);
  }
  catch (const std::exception& e)
  {
    why = e.what();
  }
  OIIO::geterror();
  std::error_code ignored;
  fs::remove(probe, ignored);
  if (!why.empty())
  {
    return "OpenImageIO cannot write ." + extension + " files here (" + why + ")";
  }
  return "";
}

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

Run RunTool(const std::vector<std::string>& args,
  const std::vector<std::string>& environment, double timeoutSeconds,
  bool quiet, const std::string& standardInput)
{
  const fs::path outPath = Where().Logs / "stdout";
  const fs::path errPath = Where().Logs / "stderr";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, standardInput.c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(
    &actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(
    &actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const bool hooked = std::any_of(environment.begin(), environment.end(),
    [](const std::string& variable) { return variable.rfind("MLAA_TEST_", 0) == 0; });
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

bool IsOneMlaaLine(const std::string& err)
{
  return err.size() > 6 && err.compare(0, 6, "mlaa: ") == 0 && err.back() == '\n' &&
    std::count(err.begin(), err.end(), '\n') == 1;
}

void ExpectSuccess(
  const std::vector<std::string>& args, const fs::path& output, bool expectWarning)
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

vtkSmartPointer<vtkImageData> TwoToneImage(int width, int height, int type,
  const std::vector<double>& lo, const std::vector<double>& hi,
  const std::function<bool(int, int)>& inside)
{
  auto image = MakeImage(width, height, static_cast<int>(lo.size()), type);
  FillImage(image, [&](int x, int y, int, int k) { return inside(x, y) ? hi[k] : lo[k]; });
  return image;
}

bool Staircase(int x, int y)
{
  return (3 * y > x + 10) != (3 * x > y + 60);
}

vtkSmartPointer<vtkImageData> StaircaseImage(
  int type, const std::vector<double>& lo, const std::vector<double>& hi)
{
  return TwoToneImage(32, 24, type, lo, hi, Staircase);
}

vtkSmartPointer<vtkImageData> Filter(vtkImageData* input,
  const std::function<void(vtkImageMLAA*)>& configure, vtkImageData* depth)
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
  vtkImageData* input, const std::function<void(vtkDLAAOptions*)>& configure)
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

void CheckAntialiased(vtkImageData* input, vtkImageData* output,
  const std::function<bool(int, int)>& ignore, double changedFraction)
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

void CheckFile(
  const fs::path& path, vtkImageData* expected, OIIO::TypeDesc type, double tolerance)
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

void RoundTrip(vtkImageData* pixels, OIIO::TypeDesc fileType, const std::string& inputName,
  const std::string& outputName, const std::vector<std::string>& options,
  const std::function<void(vtkImageMLAA*)>& configure)
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
int TemporaryFiles(const fs::path& directory)
{
  int count = 0;
  for (const std::string& name : Listing(directory))
  {
    count += name.find(".mlaa-") != std::string::npos ? 1 : 0;
  }
  return count;
}

//------------------------------------------------------------------------------
fs::path GoodInput(const std::string& name)
{
  const fs::path input = WorkFile(name);
  WriteFile(StaircaseImage(VTK_UNSIGNED_CHAR, { 20, 60, 200 }, { 240, 220, 40 }), input,
    name.size() > 4 && name.compare(name.size() - 4, 4, ".exr") == 0 ? OIIO::TypeDesc::FLOAT
                                                                     : OIIO::TypeDesc::UINT8);
  return input;
}

//------------------------------------------------------------------------------
std::map<std::string, Case>& Cases()
{
  static std::map<std::string, Case> cases;
  return cases;
}

//------------------------------------------------------------------------------
bool RegisterCases(std::initializer_list<std::pair<const char*, Case>> cases)
{
  for (const auto& entry : cases)
  {
    Cases()[entry.first] = entry.second;
  }
  return true;
}
} // namespace mlaaToolTest
