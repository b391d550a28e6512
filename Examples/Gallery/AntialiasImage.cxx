// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Gallery: antialias an image file with vtkImageMLAA.
//
//   mlaa-gallery-antialias-image INPUT OUTPUT [--preset low|medium|high|ultra|max]
//
// Reads INPUT with the VTK reader that recognises it (PNG, JPEG, BMP, PNM, ...), runs
// vtkImageMLAA on it and writes OUTPUT in the format its extension names (.png, .jpg, .bmp,
// .pnm). The command-line tool `mlaa` does the same with OpenImageIO, for more formats (TIFF,
// EXR, ...) and with more checks; this is the few lines to copy into a program of your own.
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"

#include "GalleryImageFiles.h"

#include "vtkImageData.h"
#include "vtkNew.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 3 && !(argc == 5 && std::string(argv[3]) == "--preset"))
  {
    std::cerr << "usage: " << argv[0] << " INPUT OUTPUT [--preset low|medium|high|ultra|max]\n";
    return 2;
  }
  const std::string input = argv[1], output = argv[2];

  // 1. Read: the factory picks the reader from the file's contents.
  vtkSmartPointer<vtkImageReader2> reader = gallery::ReaderFor(input);
  if (!reader)
  {
    std::cerr << input << ": not an image file VTK can read\n";
    return 1;
  }

  // 2. Antialias. The defaults are the `high` preset; a preset sets every quality option.
  vtkNew<vtkImageMLAA> mlaa;
  mlaa->SetInputConnection(reader->GetOutputPort());
  if (argc == 5 && !gallery::SetPreset(mlaa->GetOptions(), argv[4]))
  {
    return 2;
  }

  // 3. Write, in the format the output's extension names (GalleryImageFiles.h: through a
  // temporary file, renamed when complete).
  gallery::ErrorCounter errors;
  errors.Watch(reader);
  errors.Watch(mlaa);
  if (!gallery::WriteImage(mlaa->GetOutputPort(), output, errors))
  {
    return 1;
  }
  int dims[3];
  mlaa->GetOutput()->GetDimensions(dims);
  std::cout << "wrote " << output << " (" << dims[0] << "x" << dims[1] << ", "
            << mlaa->GetOutput()->GetNumberOfScalarComponents() << " channels)\n";
  return 0;
}
