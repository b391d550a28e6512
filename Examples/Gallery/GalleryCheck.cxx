// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// The gallery tests' checker (not an example).
//
//   mlaa-gallery-check antialiased BEFORE AFTER MIN_CHANGED
//     AFTER has BEFORE's size and channels; at least MIN_CHANGED pixels differ; and every pixel
//     whose 3x3 neighbourhood in BEFORE is flat (all nine equal) is unchanged, which holds for
//     MLAA: it only blends pixels with a neighbour across an edge.
//   mlaa-gallery-check size FILE WIDTH HEIGHT
//     FILE is an image of WIDTH x HEIGHT pixels.
#include "GalleryImageFiles.h"

#include "vtkImageData.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
vtkSmartPointer<vtkImageData> Read(const std::string& path)
{
  vtkSmartPointer<vtkImageReader2> reader = gallery::ReaderFor(path);
  if (!reader)
  {
    std::cerr << path << ": cannot be read\n";
    std::exit(1);
  }
  reader->Update();
  return reader->GetOutput();
}

bool SamePixel(vtkImageData* a, int xa, int ya, vtkImageData* b, int xb, int yb)
{
  for (int c = 0; c < a->GetNumberOfScalarComponents(); ++c)
  {
    if (a->GetScalarComponentAsDouble(xa, ya, 0, c) != b->GetScalarComponentAsDouble(xb, yb, 0, c))
      return false;
  }
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "size" && argc == 5)
  {
    int dims[3];
    Read(argv[2])->GetDimensions(dims);
    if (dims[0] != std::atoi(argv[3]) || dims[1] != std::atoi(argv[4]))
    {
      std::cerr << argv[2] << ": " << dims[0] << "x" << dims[1] << ", expected " << argv[3] << "x"
                << argv[4] << "\n";
      return 1;
    }
    std::cout << argv[2] << ": " << dims[0] << "x" << dims[1] << "\n";
    return 0;
  }
  if (mode != "antialiased" || argc != 5)
  {
    std::cerr << "usage: mlaa-gallery-check antialiased BEFORE AFTER MIN_CHANGED\n"
                 "       mlaa-gallery-check size FILE WIDTH HEIGHT\n";
    return 2;
  }
  vtkSmartPointer<vtkImageData> before = Read(argv[2]), after = Read(argv[3]);
  int db[3], da[3];
  before->GetDimensions(db);
  after->GetDimensions(da);
  if (db[0] != da[0] || db[1] != da[1] ||
    before->GetNumberOfScalarComponents() != after->GetNumberOfScalarComponents())
  {
    std::cerr << "the images differ in size or channels\n";
    return 1;
  }
  const int x0 = before->GetExtent()[0], y0 = before->GetExtent()[2];
  const int ax0 = after->GetExtent()[0], ay0 = after->GetExtent()[2];
  long changed = 0, flatChanged = 0;
  for (int y = 0; y < db[1]; ++y)
  {
    for (int x = 0; x < db[0]; ++x)
    {
      if (SamePixel(before, x0 + x, y0 + y, after, ax0 + x, ay0 + y))
        continue;
      ++changed;
      bool flat = x > 0 && y > 0 && x + 1 < db[0] && y + 1 < db[1];
      for (int dy = -1; flat && dy <= 1; ++dy)
        for (int dx = -1; flat && dx <= 1; ++dx)
          flat = SamePixel(before, x0 + x, y0 + y, before, x0 + x + dx, y0 + y + dy);
      flatChanged += flat ? 1 : 0;
    }
  }
  std::cout << changed << " pixels changed, " << flatChanged << " of them in flat regions\n";
  if (changed < std::atol(argv[4]) || flatChanged > 0)
  {
    std::cerr << "FAILED: expected at least " << argv[4]
              << " changed pixels and none in flat regions\n";
    return 1;
  }
  return 0;
}
