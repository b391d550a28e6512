// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Regression test of vtkImageMLAA on a committed VTK render (Testing/Data/mixed-320x240.png):
// the output must equal the committed baseline exactly (the CPU filter is deterministic), must
// differ from the input along its edges, and must leave flat regions (no edge within 2 pixels)
// untouched. VTK's own image comparison is too loose to show any of this, hence the strict one.
//
// Arguments: -I <input png> -V <baseline png> -T <directory for the result on failure>.
#include "vtkAntialiasingTestUtilities.h"

using namespace vtkMLAATest;

int TestImageMLAARegression(int argc, char* argv[])
{
  const std::string inputPath = Argument(argc, argv, "-I");
  const std::string baselinePath = Argument(argc, argv, "-V");
  const std::string outputDir = Argument(argc, argv, "-T");
  auto input = ReadPNG(inputPath);
  if (!MLAA_CHECK(input != nullptr))
  {
    std::cerr << "cannot read the input image " << inputPath << std::endl;
    return Result();
  }
  auto output = RunMLAA(input);
  const std::string resultPath = outputDir + "/TestImageMLAARegression.png";

  auto baseline = ReadPNG(baselinePath);
  if (!baseline)
  {
    WritePNG(output, resultPath);
    std::cerr << "no baseline at " << baselinePath << "; the result is in " << resultPath
              << std::endl;
    MLAA_CHECK(!"baseline present");
    return Result();
  }
  const Difference d = Compare(output, baseline, 0.0);
  if (!MLAA_CHECK(d.Count == 0))
  {
    WritePNG(output, resultPath);
    std::cerr << d.Pixels << " pixels differ from the baseline (largest difference " << d.Max
              << "); the result is in " << resultPath << std::endl;
  }

  // It antialiased something, and only near edges.
  int dims[3];
  input->GetDimensions(dims);
  int changed = 0, flatChanged = 0, flat = 0;
  for (int y = 0; y < dims[1]; ++y)
  {
    for (int x = 0; x < dims[0]; ++x)
    {
      bool differs = false;
      for (int k = 0; k < 3; ++k)
      {
        differs = differs || GetValue(input, x, y, k) != GetValue(output, x, y, k);
      }
      changed += differs ? 1 : 0;
      if (IsFlatAround(input, x, y))
      {
        ++flat;
        flatChanged += differs ? 1 : 0;
      }
    }
  }
  std::cout << changed << " pixels antialiased, " << flat << " flat pixels, " << flatChanged
            << " of them changed" << std::endl;
  MLAA_CHECK(changed > 500);
  MLAA_CHECK(flat > dims[0] * dims[1] / 2);
  MLAA_CHECK(flatChanged == 0);
  return Result();
}
