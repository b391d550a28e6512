// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Gallery: antialias every image of a directory.
//
//   mlaa-gallery-batch INPUT_DIR OUTPUT_DIR [--preset low|medium|high|ultra|max]
//
// Each image file of INPUT_DIR (what VTK's readers recognise: PNG, JPEG, BMP, PNM) goes
// through one vtkImageMLAA, set up once and reused, into OUTPUT_DIR under the same name and
// format. Each output is written to a temporary name in OUTPUT_DIR and renamed when complete,
// so a failure never leaves a half-written image. A file that fails is reported and the rest go
// on; the exit status is 1 if any failed. (`mlaa --output-dir` does this for more formats, with
// progress and all cores.)
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"

#include "GalleryImageFiles.h"

#include "vtkImageData.h"
#include "vtkNew.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char* argv[])
{
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--preset"))
  {
    std::cerr << "usage: " << argv[0]
              << " INPUT_DIR OUTPUT_DIR [--preset low|medium|high|ultra|max]\n";
    return 2;
  }
  const fs::path inputDir = argv[1], outputDir = argv[2];
  std::error_code ec;
  if (!fs::is_directory(inputDir, ec))
  {
    std::cerr << inputDir.string() << ": not a directory\n";
    return 2;
  }
  fs::create_directories(outputDir, ec);
  if (ec || fs::equivalent(inputDir, outputDir, ec))
  {
    std::cerr << outputDir.string() << ": cannot be the output directory"
              << (ec ? ": " + ec.message() : std::string(" (it is the input directory)"))
              << "\n";
    return 2;
  }

  // One filter for all files: its options (and the area texture they select) are set up once.
  vtkNew<vtkImageMLAA> mlaa;
  if (argc == 5 && !gallery::SetPreset(mlaa->GetOptions(), argv[4]))
  {
    return 2;
  }
  gallery::ErrorCounter errors;
  errors.Watch(mlaa);

  std::vector<fs::path> inputs;
  for (const fs::directory_entry& entry : fs::directory_iterator(inputDir, ec))
  {
    if (entry.is_regular_file() && gallery::WriterFor(entry.path().string()))
      inputs.push_back(entry.path());
  }
  std::sort(inputs.begin(), inputs.end());

  int failed = 0;
  for (const fs::path& input : inputs)
  {
    const fs::path output = outputDir / input.filename();
    vtkSmartPointer<vtkImageReader2> reader = gallery::ReaderFor(input.string());
    bool ok = reader != nullptr;
    if (ok)
    {
      errors.Watch(reader);
      mlaa->SetInputConnection(reader->GetOutputPort());
      ok = gallery::WriteImage(mlaa->GetOutputPort(), output.string(), errors);
      mlaa->SetInputConnection(nullptr); // release the reader
    }
    else
    {
      std::cerr << input.string() << ": not an image file VTK can read\n";
    }
    if (!ok)
    {
      std::cerr << input.string() << ": failed\n";
      ++failed;
      continue;
    }
    std::cout << input.string() << " -> " << output.string() << "\n";
  }
  std::cout << inputs.size() - failed << " of " << inputs.size() << " images antialiased\n";
  return failed > 0 ? 1 : 0;
}
