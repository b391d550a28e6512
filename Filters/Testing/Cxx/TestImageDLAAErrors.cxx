// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Bad input to vtkImageDLAA: a clear error message and an empty output, never a crash or a
// partial result; then the same filter works again on good input. And NaN and infinity: a
// pixel that reads one (within the short-edge cross, and with long edges within the long-edge
// windows, see vtkDLAAOptions) is left as it is; every other pixel gets exactly the result of
// the image without them.
#include "vtkDLAAOptions.h"
#include "vtkImageDLAA.h"
#include "vtkMLAATestUtilities.h"

#include "vtkBitArray.h"
#include "vtkExecutive.h"
#include "vtkUnsignedCharArray.h"

#include <limits>

using namespace vtkMLAATest;

namespace
{
void ExpectError(vtkImageData* input, const std::string& expected,
  const double* valueRange = nullptr)
{
  vtkNew<vtkImageDLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  if (valueRange)
  {
    filter->SetValueRange(valueRange[0], valueRange[1]);
  }
  filter->SetInputData(input);
  filter->Update();
  if (!MLAA_CHECK(messages->HasError(expected)))
  {
    std::cerr << "expected an error containing \"" << expected << "\"; got:";
    for (const auto& e : messages->Errors)
    {
      std::cerr << "\n  " << e;
    }
    std::cerr << std::endl;
  }
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 0);
  MLAA_CHECK(filter->GetOutput()->GetPointData()->GetScalars() == nullptr);
}

void BadInput()
{
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(8, 8, 1);
  ExpectError(noScalars, "no point scalars");

  vtkNew<vtkImageData> empty;
  empty->SetExtent(0, -1, 0, -1, 0, -1);
  vtkNew<vtkUnsignedCharArray> emptyScalars;
  emptyScalars->SetNumberOfComponents(3);
  empty->GetPointData()->SetScalars(emptyScalars);
  ExpectError(empty, "empty");

  ExpectError(MakeImage(8, 8, 5), "vtkImageDLAA takes 1 to 4");
  ExpectError(MakeImage(8, 8, 9, VTK_FLOAT), "9 components");

  vtkNew<vtkImageData> bits;
  bits->SetDimensions(8, 8, 1);
  vtkNew<vtkBitArray> bitScalars;
  bitScalars->SetNumberOfTuples(64);
  bits->GetPointData()->SetScalars(bitScalars);
  ExpectError(bits, "does not support");

  vtkNew<vtkImageData> short_;
  short_->SetDimensions(8, 8, 1);
  vtkNew<vtkUnsignedCharArray> fewTuples;
  fewTuples->SetNumberOfComponents(3);
  fewTuples->SetNumberOfTuples(10);
  short_->GetPointData()->SetScalars(fewTuples);
  ExpectError(short_, "fewer than the 64 points");

  const double emptyRange[2] = { 1.0, 1.0 };
  ExpectError(MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", emptyRange);
  const double infinite[2] = { 0.0, std::numeric_limits<double>::infinity() };
  ExpectError(MakeImage(8, 8, 1, VTK_FLOAT), "ValueRange", infinite);

  // After an error, the same filter object works on good input.
  vtkNew<vtkImageDLAA> filter;
  vtkNew<MessageObserver> messages;
  messages->Watch(filter);
  messages->Watch(filter->GetExecutive());
  filter->SetInputData(MakeImage(8, 8, 7));
  filter->Update();
  MLAA_CHECK(!messages->Errors.empty());
  messages->Clear();
  auto good = MakeImage(8, 8, 3);
  FillImage(good, [](int x, int y, int, int) { return y < 2 + x / 3 ? 255.0 : 0.0; });
  filter->SetInputData(good);
  filter->Update();
  MLAA_CHECK(messages->Errors.empty());
  MLAA_CHECK(filter->GetOutput()->GetNumberOfPoints() == 64);
  MLAA_CHECK(Compare(good, filter->GetOutput()).Count > 0);
}

// Whether the result of pixel (x, y) reads pixel (bx, by) (the dependency region in
// vtkDLAAOptions): the cross of radius 2 around any pixel within `reach` along x or y.
bool Reads(int x, int y, int bx, int by, int reach)
{
  const int dx = std::abs(bx - x);
  const int dy = std::abs(by - y);
  return (dy <= 2 && dx <= reach) || (dx <= 2 && dy <= reach) ||
    (dy == 0 && dx <= reach + 2) || (dx == 0 && dy <= reach + 2);
}

void NonFinite()
{
  const double bad[] = { std::numeric_limits<double>::quiet_NaN(),
    std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity() };
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    for (bool longEdges : { true, false })
    {
      vtkNew<vtkDLAAOptions> options;
      options->SetLongEdges(longEdges);
      const int reach = longEdges ? 8 : 0;
      // A long edge with 20-pixel steps and a short steep one, in RGBA.
      auto clean = MakeImage(90, 40, 4, type);
      FillImage(clean, [](int x, int y, int, int k) {
        const bool inside = y < 10 + x / 20 || (x > 60 && y < 2 * x - 100);
        return k == 3 ? 1.0 : (inside ? 0.9 - 0.2 * k : 0.1 + 0.1 * k);
      });
      const auto cleanOut = RunDLAA(clean, options);
      for (int b = 0; b < 3; ++b)
      {
        // One non-finite pixel on the ramp of the long edge (row 11 near x = 40), in one
        // channel.
        const int bx = 37, by = 11;
        auto image = vtkSmartPointer<vtkImageData>::New();
        image->DeepCopy(clean);
        image->SetScalarComponentFromDouble(bx, by, 0, 1, bad[b]);
        vtkNew<vtkImageDLAA> filter;
        filter->SetOptions(options);
        filter->SetInputData(image);
        filter->Update();
        vtkImageData* out = filter->GetOutput();
        int frozen = 0, wrong = 0;
        for (int y = 0; y < 40; ++y)
        {
          for (int x = 0; x < 90; ++x)
          {
            const bool reads = Reads(x, y, bx, by, reach);
            for (int k = 0; k < 4; ++k)
            {
              const double v = GetValue(out, x, y, k);
              const double expected = reads ? GetValue(image, x, y, k) : GetValue(cleanOut, x, y, k);
              const bool same = v == expected || (std::isnan(v) && std::isnan(expected));
              wrong += same ? 0 : 1;
            }
            frozen += reads ? 1 : 0;
          }
        }
        if (!MLAA_CHECK(wrong == 0))
        {
          std::cerr << "type " << type << ", long edges " << longEdges << ", value " << bad[b]
                    << ": " << wrong << " values differ from the expected ones" << std::endl;
        }
        MLAA_CHECK(frozen > 0);
        // The clean result changes pixels that the non-finite one freezes.
        const int cx = longEdges ? 36 : 38;
        MLAA_CHECK(Reads(cx, 11, bx, by, reach));
        MLAA_CHECK(GetValue(cleanOut, cx, 11, 0) != GetValue(clean, cx, 11, 0));
      }
    }
  }
}
}

int TestImageDLAAErrors(int, char*[])
{
  BadInput();
  NonFinite();
  return Result();
}
