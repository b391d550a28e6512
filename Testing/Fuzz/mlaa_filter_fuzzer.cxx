// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * libFuzzer target: vtkImageMLAA and vtkImageDLAA on an image and options made from the
 * fuzzer's bytes, with the invariants their documentation promises checked on every run.
 *
 * The bytes, in order (mlaa_fuzz_input.h: fields past the end read as zeros; make-corpus.py
 * writes seeds in this layout):
 *   u8  flags: bit 0 DLAA (else MLAA); bit 1 also update a sub-extent with a second filter and
 *       compare; bit 2 a value range of its own; bit 3 pixels from a palette (else raw bytes);
 *       bits 4-5 damage: 0 none, 1 scalars one tuple short, 2 no scalars, 3 bit-array scalars;
 *       bit 6 a depth image (MLAA)
 *   u8  scalar type (an index into ScalarTypes)       u8  components - 1 (mod 6: 1 to 6)
 *   u16 width - 1 (mod 512)   u16 height - 1 (mod 512)   u8 depth - 1 (mod 3)
 *   i8  x0, y0, z0: where the extent starts           (width x height x depth at most 2^14)
 *   MLAA: u8 preset (0-3: LOW to ULTRA, 5: MAX, which then replaces the quality fields; else,
 *      4 in the seeds, none),
 *         u8 threshold (/255), u8 local contrast factor (/2.55), u8 edge detection (mod 4),
 *         u8 max search steps - 1 (mod 128), u8 switches (bit 0 diagonals, 1 corner
 *         extrapolation, 2 dominant-direction blending, 3 premultiplied alpha,
 *         4 reconstruction), u8 debug output (mod 3)
 *   DLAA: u8 epsilon (/255), u8 lambda (/2.55), u8 luma function (mod 2), u8 long edges (bit 0)
 *   f64 value range lo, f64 hi (any bits)
 *   u8 x 6: the sub-extent (start and length in x, y, z, each modulo what is left)
 *   u8  depth image type: even float, odd unsigned char
 *   pixels: with a palette, u8 count - 1 (mod 4), the palette's tuples as raw bytes of the type,
 *           then a 2-bit palette index per point (4 a byte); else the tuples' raw bytes
 *   the depth image's raw bytes
 *
 * Invariants (a broken one aborts, which libFuzzer saves as a crash):
 * - bad input (damage, more than 4 components, a value range that is not finite with lo < hi,
 *   depth edges without a depth image) is an error event and an empty output; anything else
 *   no error, and an output of the input's extent, type and components (8-bit RGBA for debug
 *   outputs) with one tuple per point;
 * - integer images: every output value within the range of the input's values of that
 *   component (blending mixes neighbours, reconstruction averages them); for 64-bit types,
 *   which the filters blend in double, within a few units in the last place of the range;
 * - floating-point images without NaN or infinity give none;
 * - an image of one colour comes out unchanged, bit for bit (but for depth edges);
 * - a sub-extent updated on its own gives the same bits as the whole image there (the filters
 *   are streaming-safe).
 */

#include "mlaa_fuzz_input.h"

#include "vtkBitArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDLAAOptions.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkImageDLAA.h"
#include "vtkImageData.h"
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"
#include "vtkVariant.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using mlaafuzz::ByteReader;

const int ScalarTypes[] = { VTK_CHAR, VTK_SIGNED_CHAR, VTK_UNSIGNED_CHAR, VTK_SHORT,
  VTK_UNSIGNED_SHORT, VTK_INT, VTK_UNSIGNED_INT, VTK_LONG, VTK_UNSIGNED_LONG, VTK_LONG_LONG,
  VTK_UNSIGNED_LONG_LONG, VTK_FLOAT, VTK_DOUBLE, VTK_ID_TYPE };
constexpr int ScalarTypeCount = sizeof(ScalarTypes) / sizeof(ScalarTypes[0]);
constexpr long long MaxPoints = 1 << 14;

// Counts the error events of the objects it observes (and keeps them off the terminal).
struct ErrorCounter
{
  vtkNew<vtkCallbackCommand> Callback;
  int Errors = 0;

  ErrorCounter()
  {
    this->Callback->SetClientData(this);
    this->Callback->SetCallback(
      [](vtkObject*, unsigned long event, void* self, void*)
      {
        if (event == vtkCommand::ErrorEvent)
        {
          ++static_cast<ErrorCounter*>(self)->Errors;
        }
      });
  }

  void Observe(vtkAlgorithm* algorithm)
  {
    for (vtkObject* object :
      { static_cast<vtkObject*>(algorithm), static_cast<vtkObject*>(algorithm->GetExecutive()) })
    {
      object->AddObserver(vtkCommand::ErrorEvent, this->Callback);
      object->AddObserver(vtkCommand::WarningEvent, this->Callback);
    }
  }
};

// The bytes of point (i, j, k) of `image` (its own extent), or nullptr outside it.
const unsigned char* TupleAt(vtkImageData* image, int i, int j, int k)
{
  int ext[6];
  image->GetExtent(ext);
  if (i < ext[0] || i > ext[1] || j < ext[2] || j > ext[3] || k < ext[4] || k > ext[5])
  {
    return nullptr;
  }
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const vtkIdType id = (static_cast<vtkIdType>(k - ext[4]) * (ext[3] - ext[2] + 1) + (j - ext[2])) *
      (ext[1] - ext[0] + 1) +
    (i - ext[0]);
  const int tupleBytes = scalars->GetNumberOfComponents() * scalars->GetDataTypeSize();
  return static_cast<const unsigned char*>(scalars->GetVoidPointer(0)) + id * tupleBytes;
}

// Fills `scalars` (already sized) from the bytes: a palette of up to 4 tuples and 2-bit indices,
// or raw bytes.
void FillPixels(ByteReader& in, vtkDataArray* scalars, bool palette)
{
  const vtkIdType tuples = scalars->GetNumberOfTuples();
  const int tupleBytes = scalars->GetNumberOfComponents() * scalars->GetDataTypeSize();
  auto* out = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
  if (!palette)
  {
    in.Read(out, static_cast<std::size_t>(tuples) * tupleBytes);
    return;
  }
  const int colours = in.U8() % 4 + 1;
  std::vector<unsigned char> table(static_cast<std::size_t>(colours) * tupleBytes);
  in.Read(table.data(), table.size());
  std::uint8_t indices = 0;
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    if (t % 4 == 0)
    {
      indices = in.U8();
    }
    const int index = ((indices >> (2 * (t % 4))) & 3) % colours;
    std::memcpy(out + t * tupleBytes, table.data() + index * tupleBytes, tupleBytes);
  }
}

// "(v0, v1, ...)", full precision.
std::string TupleText(vtkDataArray* scalars, vtkIdType t)
{
  std::string text = "(";
  for (int c = 0; c < scalars->GetNumberOfComponents(); ++c)
  {
    const vtkVariant v = scalars->GetVariantValue(t * scalars->GetNumberOfComponents() + c);
    std::ostringstream value;
    value.precision(17);
    if (v.IsFloat() || v.IsDouble())
    {
      value << v.ToDouble();
    }
    else
    {
      value << v.ToString();
    }
    text += (c ? ", " : "") + value.str();
  }
  return text + ")";
}

bool AllFinite(vtkDataArray* scalars)
{
  const vtkIdType n = scalars->GetNumberOfValues();
  for (vtkIdType v = 0; v < n; ++v)
  {
    if (!std::isfinite(scalars->GetVariantValue(v).ToDouble()))
    {
      return false;
    }
  }
  return true;
}

// Integer types: every output value lies within the input's range of its component. The
// filters blend normalised values in double, (value - lo) / (hi - lo) and back: for 64-bit
// types that round trip is exact only to a few units in the last place of the value range
// (found by this target: DLAA gave 5656987409776646 where the largest input of the component was
// 5656987409776645, in an unsigned 64-bit image normalised by [0, 2^64 - 1]), so those are
// allowed that much outside.
template <typename T>
void CheckWithinInputRange(vtkDataArray* input, vtkDataArray* output, const double range[2])
{
  const int comps = input->GetNumberOfComponents();
  const T* in = static_cast<const T*>(input->GetVoidPointer(0));
  const T* out = static_cast<const T*>(output->GetVoidPointer(0));
  const vtkIdType tuples = input->GetNumberOfTuples();
  for (int c = 0; c < comps; ++c)
  {
    T lo = std::numeric_limits<T>::max();
    T hi = std::numeric_limits<T>::lowest();
    for (vtkIdType t = 0; t < tuples; ++t)
    {
      lo = std::min(lo, in[t * comps + c]);
      hi = std::max(hi, in[t * comps + c]);
    }
    const double slack = sizeof(T) < 8
      ? 0.0
      : 8 * std::numeric_limits<double>::epsilon() *
        std::max({ std::abs(range[0]), std::abs(range[1]), std::abs(static_cast<double>(lo)),
          std::abs(static_cast<double>(hi)) });
    for (vtkIdType t = 0; t < tuples; ++t)
    {
      const T v = out[t * comps + c];
      const bool within = sizeof(T) < 8
        ? v >= lo && v <= hi
        : static_cast<double>(v) >= static_cast<double>(lo) - slack &&
          static_cast<double>(v) <= static_cast<double>(hi) + slack;
      if (!within)
      {
        dprintf(mlaafuzz::ReportFd(), "mlaa fuzz: tuple %lld component %d: %s outside [%s, %s]\n",
          static_cast<long long>(t), c, std::to_string(v).c_str(), std::to_string(lo).c_str(),
          std::to_string(hi).c_str());
        mlaafuzz::Fail("an output value lies outside its component's input range");
      }
    }
  }
}

void CheckIntegerRange(vtkDataArray* input, vtkDataArray* output, const double range[2])
{
  if (input->GetDataType() == VTK_FLOAT || input->GetDataType() == VTK_DOUBLE)
  {
    return;
  }
  switch (input->GetDataType())
  {
    vtkTemplateMacro(CheckWithinInputRange<VTK_TT>(input, output, range));
    default:
      return;
  }
}
} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  mlaafuzz::KeepStderr();
  // One thread: an update costs no thread start-up, and a finding replays the same way.
  vtkSMPTools::SetBackend("Sequential");
  // Messages no observer takes (the pipeline's) go to a string, not the terminal.
  vtkNew<vtkStringOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  ByteReader in(data, size);
  const int flags = in.U8();
  const bool dlaa = flags & 1;
  const bool streamed = flags & 2;
  const bool ownRange = flags & 4;
  const bool palette = flags & 8;
  const int damage = (flags >> 4) & 3;
  const bool withDepth = (flags & 64) && !dlaa;

  const int scalarType = ScalarTypes[in.U8() % ScalarTypeCount];
  const int comps = in.U8() % 6 + 1;
  int dims[3];
  dims[0] = in.U16() % 512 + 1;
  dims[1] = in.U16() % 512 + 1;
  dims[2] = in.U8() % 3 + 1;
  // Large but bounded: the height gives way.
  dims[1] = static_cast<int>(
    std::max<long long>(1, std::min<long long>(dims[1], MaxPoints / (dims[0] * dims[2]))));
  const int x0 = in.I8();
  const int y0 = in.I8();
  const int z0 = in.I8();
  const int extent[6] = { x0, x0 + dims[0] - 1, y0, y0 + dims[1] - 1, z0, z0 + dims[2] - 1 };

  vtkNew<vtkMLAAOptions> mlaaOptions;
  const int preset = in.U8();
  const double threshold = in.Unit();
  const double localContrast = in.U8() / 2.55;
  const int edges = in.U8() % 4;
  const int steps = in.U8() % 128 + 1;
  const int switches = in.U8();
  const int debug = in.U8() % 3;
  if (preset < 4 || preset == 5)
  {
    mlaaOptions->SetPreset(preset < 4 ? preset : vtkMLAAOptions::MAX);
  }
  else
  {
    mlaaOptions->SetThreshold(threshold);
    mlaaOptions->SetLocalContrastFactor(localContrast);
    mlaaOptions->SetMaxSearchSteps(steps);
    mlaaOptions->SetDiagonalDetection(switches & 1);
    mlaaOptions->SetDominantDirectionBlending(switches & 4);
  }
  mlaaOptions->SetEdgeDetection(edges);
  mlaaOptions->SetCornerExtrapolation(switches & 2);
  mlaaOptions->SetPremultipliedAlpha(switches & 8);
  mlaaOptions->SetReconstruction(switches & 16);
  mlaaOptions->SetDebugOutput(debug);

  vtkNew<vtkDLAAOptions> dlaaOptions;
  dlaaOptions->SetEpsilon(in.Unit());
  dlaaOptions->SetLambda(in.U8() / 2.55);
  dlaaOptions->SetLumaFunction(in.U8() % 2);
  dlaaOptions->SetLongEdges(in.U8() & 1);

  const double range[2] = { in.F64(), in.F64() };
  int sub[6];
  for (int a = 0; a < 3; ++a)
  {
    const int start = extent[2 * a] + in.U8() % dims[a];
    sub[2 * a] = start;
    sub[2 * a + 1] = start + in.U8() % (extent[2 * a + 1] - start + 1);
  }
  const bool depthFloat = in.U8() % 2 == 0;

  // The image.
  vtkNew<vtkImageData> image;
  image->SetExtent(const_cast<int*>(extent));
  const vtkIdType points = image->GetNumberOfPoints();
  vtkSmartPointer<vtkDataArray> scalars;
  if (damage == 3)
  {
    scalars = vtkSmartPointer<vtkBitArray>::New();
  }
  else
  {
    scalars = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(scalarType));
  }
  scalars->SetNumberOfComponents(comps);
  scalars->SetNumberOfTuples(damage == 1 ? points - 1 : points);
  scalars->SetName("pixels");
  if (damage != 3)
  {
    FillPixels(in, scalars, palette);
  }
  if (damage != 2)
  {
    image->GetPointData()->SetScalars(scalars);
  }

  vtkNew<vtkImageData> depth;
  if (withDepth)
  {
    depth->SetExtent(const_cast<int*>(extent));
    depth->AllocateScalars(depthFloat ? VTK_FLOAT : VTK_UNSIGNED_CHAR, 1);
    in.Read(depth->GetScalarPointer(),
      static_cast<std::size_t>(points) * depth->GetPointData()->GetScalars()->GetDataTypeSize());
  }

  // The filters: the one that runs on the whole image, and the one that runs on the sub-extent.
  auto makeFilter = [&]() -> vtkSmartPointer<vtkImageAntialiasingAlgorithm>
  {
    vtkSmartPointer<vtkImageAntialiasingAlgorithm> filter;
    if (dlaa)
    {
      auto f = vtkSmartPointer<vtkImageDLAA>::New();
      f->SetOptions(dlaaOptions);
      filter = f;
    }
    else
    {
      auto f = vtkSmartPointer<vtkImageMLAA>::New();
      f->SetOptions(mlaaOptions);
      if (withDepth)
      {
        f->SetDepthInputData(depth);
      }
      filter = f;
    }
    if (ownRange)
    {
      filter->SetValueRange(range);
    }
    filter->SetInputData(image);
    return filter;
  };

  const bool badRange = ownRange && !(std::isfinite(range[0]) && std::isfinite(range[1]) && range[0] < range[1]);
  const bool expectError =
    damage != 0 || comps > 4 || badRange || (!dlaa && edges == vtkMLAAOptions::DEPTH && !withDepth);

  vtkSmartPointer<vtkImageAntialiasingAlgorithm> filter = makeFilter();
  if (std::getenv("MLAA_FUZZ_VERBOSE"))
  {
    // What the bytes made, to see what an input or a corpus reaches.
    std::ostringstream text;
    text << (dlaa ? "vtkImageDLAA" : "vtkImageMLAA") << " on " << dims[0] << " x " << dims[1]
         << " x " << dims[2] << " " << vtkImageScalarTypeNameMacro(scalarType) << " x " << comps
         << " from (" << x0 << ", " << y0 << ", " << z0 << "), damage " << damage
         << (palette ? ", palette" : ", raw") << (withDepth ? ", depth image" : "")
         << (streamed ? ", sub-extent compared" : "") << (expectError ? ", an error expected" : "")
         << "\n";
    (dlaa ? static_cast<vtkObject*>(dlaaOptions) : static_cast<vtkObject*>(mlaaOptions))
      ->PrintSelf(text, vtkIndent(2));
    filter->PrintSelf(text, vtkIndent(2));
    dprintf(mlaafuzz::ReportFd(), "%s", text.str().c_str());
  }
  ErrorCounter errors;
  errors.Observe(filter);
  filter->Update();
  vtkImageData* output = filter->GetOutput();
  vtkDataArray* result = output->GetPointData()->GetScalars();

  if (expectError)
  {
    MLAA_FUZZ_CHECK(errors.Errors > 0, "bad input was not reported as an error");
    MLAA_FUZZ_CHECK(output->GetNumberOfPoints() == 0 || !result || result->GetNumberOfTuples() == 0,
      "bad input gave a non-empty output");
    return 0;
  }
  MLAA_FUZZ_CHECK(errors.Errors == 0, "good input was reported as an error");
  MLAA_FUZZ_CHECK(result != nullptr, "no output scalars");
  int outExtent[6];
  output->GetExtent(outExtent);
  MLAA_FUZZ_CHECK(std::equal(outExtent, outExtent + 6, extent), "the output extent differs");
  MLAA_FUZZ_CHECK(result->GetNumberOfTuples() == points, "one output tuple per point");
  const bool debugOutput = !dlaa && debug != vtkMLAAOptions::NO_DEBUG_OUTPUT;
  if (debugOutput)
  {
    MLAA_FUZZ_CHECK(result->GetDataType() == VTK_UNSIGNED_CHAR && result->GetNumberOfComponents() == 4,
      "a debug output is 8-bit RGBA");
  }
  else
  {
    MLAA_FUZZ_CHECK(result->GetDataType() == scalarType, "the output type differs");
    MLAA_FUZZ_CHECK(result->GetNumberOfComponents() == comps, "the output components differ");
    double effectiveRange[2];
    filter->GetEffectiveValueRange(scalarType, effectiveRange);
    CheckIntegerRange(scalars, result, effectiveRange);
    if ((scalarType == VTK_FLOAT || scalarType == VTK_DOUBLE) && AllFinite(scalars))
    {
      for (vtkIdType t = 0; t < points; ++t)
      {
        for (int c = 0; c < comps; ++c)
        {
          if (!std::isfinite(result->GetComponent(t, c)))
          {
            dprintf(mlaafuzz::ReportFd(), "mlaa fuzz: tuple %lld: %s became %s\n",
              static_cast<long long>(t), TupleText(scalars, t).c_str(),
              TupleText(result, t).c_str());
            mlaafuzz::Fail("finite input gave a NaN or infinite output");
          }
        }
      }
    }
    const int tupleBytes = comps * scalars->GetDataTypeSize();
    const auto* inBytes = static_cast<const unsigned char*>(scalars->GetVoidPointer(0));
    // (Depth edges are edges of another image: the colours are blended there, in floating
    // point, which may change the last bit of a mix of equal values.)
    bool oneColour = dlaa || edges != vtkMLAAOptions::DEPTH;
    for (vtkIdType t = 1; t < points && oneColour; ++t)
    {
      oneColour = std::memcmp(inBytes, inBytes + t * tupleBytes, tupleBytes) == 0;
    }
    if (oneColour)
    {
      const auto* outBytes = static_cast<const unsigned char*>(result->GetVoidPointer(0));
      for (vtkIdType t = 0; t < points; ++t)
      {
        if (std::memcmp(inBytes + t * tupleBytes, outBytes + t * tupleBytes, tupleBytes) != 0)
        {
          dprintf(mlaafuzz::ReportFd(), "mlaa fuzz: tuple %lld: %s became %s\n",
            static_cast<long long>(t), TupleText(scalars, t).c_str(),
            TupleText(result, t).c_str());
          mlaafuzz::Fail("an image of one colour was changed");
        }
      }
    }
  }

  if (streamed)
  {
    vtkSmartPointer<vtkImageAntialiasingAlgorithm> piece = makeFilter();
    ErrorCounter pieceErrors;
    pieceErrors.Observe(piece);
    piece->UpdateExtent(sub);
    MLAA_FUZZ_CHECK(pieceErrors.Errors == 0, "a sub-extent update was reported as an error");
    vtkImageData* pieceOutput = piece->GetOutput();
    const int tupleBytes = result->GetNumberOfComponents() * result->GetDataTypeSize();
    for (int k = sub[4]; k <= sub[5]; ++k)
    {
      for (int j = sub[2]; j <= sub[3]; ++j)
      {
        for (int i = sub[0]; i <= sub[1]; ++i)
        {
          const unsigned char* a = TupleAt(output, i, j, k);
          const unsigned char* b = TupleAt(pieceOutput, i, j, k);
          MLAA_FUZZ_CHECK(b != nullptr, "a sub-extent update does not cover its extent");
          MLAA_FUZZ_CHECK(std::memcmp(a, b, tupleBytes) == 0,
            "a sub-extent differs from the same pixels of the whole image");
        }
      }
    }
  }
  return 0;
}
