// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Uses both modules through their installed headers: antialiases a small staircase with
// vtkImageMLAA and creates a vtkOpenGLMLAAPass sharing its options (no rendering: no display
// needed). Exit status 0 when the staircase was antialiased.
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkMLAAAreaTexture.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkOpenGLMLAAPass.h"

#include <iostream>

int main()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(16, 8, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int y = 0; y < 8; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      p[y * 16 + x] = (y < 2 + x / 4) ? 255 : 0;
    }
  }
  vtkNew<vtkMLAAOptions> options;
  vtkNew<vtkImageMLAA> filter;
  filter->SetOptions(options);
  filter->SetInputData(image);
  filter->Update();
  vtkNew<vtkOpenGLMLAAPass> pass;
  pass->SetOptions(options);
  vtkNew<vtkMLAAAreaTexture> area;

  int changed = 0;
  const auto* q = static_cast<const unsigned char*>(filter->GetOutput()->GetScalarPointer());
  for (int i = 0; i < 16 * 8; ++i)
  {
    changed += (p[i] != q[i]) ? 1 : 0;
  }
  std::cout << "consumer: " << changed << " pixels antialiased; area texture "
            << area->GetTextureSize() << " texels wide" << std::endl;
  return (changed > 0 && pass->GetOptions() == options.GetPointer()) ? 0 : 1;
}
