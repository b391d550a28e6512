// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkMLAAStages.h
 * @brief  The CPU MLAA of vtkImageMLAA on one slice: the stages of the GPU pass, run in order
 *         (internal header).
 *
 * vtkImageMLAA runs, on each z slice, the stages that vtkOpenGLMLAAPass runs as full-screen
 * passes. Each stage is a file pair named after the shader it mirrors:
 *
 * | stage                            | file                          | shader (Rendering/glsl/)        |
 * |----------------------------------|-------------------------------|---------------------------------|
 * | 0. reconstruction (typed, optional) | vtkMLAAReconstruction.h    | vtkMLAAReconstructionFS         |
 * | 1. features (typed)              | vtkAntialiasingKit.h          | the fetches of the edge shader  |
 * | 2. edges                         | vtkMLAAEdgeDetection.h/.cxx   | vtkMLAAEdgeDetectionFS          |
 * | line lengths (long searches)     | vtkMLAALineLengths.h/.cxx     | vtkMLAALineLengths(Init)FS      |
 * | 3. blending weights              | vtkMLAABlendingWeights.h/.cxx | vtkMLAABlendingWeightsFS        |
 * | 4. neighbourhood blending (typed)| vtkMLAANeighborhoodBlending.h/.cxx | vtkMLAANeighborhoodBlendingFS |
 * | CIELAB (for 1 and 0)             | vtkMLAALab.h                  | vtkMLAALab                      |
 *
 * This file is what remains: the slice driver. Halo says how far the stages read beyond the
 * pixels they produce (vtkImageMLAA pads its input request by Halo::Total()); SliceSetup holds
 * everything one slice needs, from the options (ConfigureSlice); SliceBuffers are the full-size
 * buffers reused from slice to slice; RunSlice runs the stages on one slice of any scalar type.
 *
 * Only the features and the blending depend on the scalar type; the edges and weights buffers
 * are laid out as the pass's RG8 edges and RGBA8 blending-weights textures, with the same 8-bit
 * quantisation, so the two back ends compute the same numbers. Features are read row by row into
 * per-task buffers (never a full-size copy of the image); the edges and weights buffers (with,
 * from vtkMLAAOptions::ExactLineLengthsSteps search steps on, the weights' scratch of 16-bit line
 * lengths: 4 bytes per pixel, 12 with DiagonalDetection) are the only full-size buffers besides
 * the output.
 *
 * Rows and columns follow VTK's image layout: y grows towards the top of the displayed image,
 * so "top" is the next row. All coordinates are those of the image's extent.
 *
 * Internal to MLAA::FiltersMLAA (the tests include it); not installed.
 */

#ifndef vtkMLAAStages_h
#define vtkMLAAStages_h

#include "vtkAntialiasingKit.h"
#include "vtkFiltersMLAAModule.h" // For export macro
#include "vtkMLAABlendingWeights.h"
#include "vtkMLAAEdgeDetection.h"
#include "vtkMLAALineLengths.h"
#include "vtkMLAANeighborhoodBlending.h"
#include "vtkMLAAOptions.h"
#include "vtkMLAAReconstruction.h"
#include "vtkType.h"

#include <chrono>
#include <functional>
#include <memory>

namespace vtkMLAAStages
{
// The kit's names (Rect, Progress, FeatureReader, ...) are this namespace's too.
using namespace vtkAntialiasingKit;

//------------------------------------------------------------------------------
/**
 * How far, in pixels along x and y, each stage reads beyond the pixels it produces, for given
 * options. An output pixel depends on input pixels up to Total() away; vtkImageMLAA pads its
 * input request by that much, which makes streamed results equal unstreamed ones.
 * - Blending: 1. A pixel blends with its four neighbours, by its own weights and by those of
 *   its right and lower neighbours.
 * - Search: the blending weights of a pixel read edgels along its line up to
 *   vtkMLAAOptions::GetMaxDistance() pixels away and the crossing edge one further (section
 *   4.3.1): vtkMLAAOptions::GetSearchReach(). The diagonal search follows up to GetMaxDistance()
 *   units and reads the edgels two pixels past the last one: GetSearchReach() + 2. With
 *   CornerExtrapolation, the next run past a line's end, which lies up to GetSearchReach() away,
 *   is searched too: twice GetSearchReach() (+ 2 with diagonals).
 * - Edges: an edgel compares its two pixels, which the search reach above already counts; local
 *   contrast adaptation also looks at the other boundaries of those pixels, one pixel further,
 *   which is padded by 2.
 * - Reconstruction: vtkMLAATopology::ReconstructionReach (4) with
 *   vtkMLAAOptions::Reconstruction (a reconstructed pixel depends on its eight neighbours, Biri
 *   et al. section 4.3, on whether they are gaps, the thin line rule, and on their coverage
 *   windows of radius 3), else 0.
 */
struct Halo
{
  int Blending = 0;
  int Search = 0;
  int Edges = 0;
  int Reconstruction = 0;
  int Total() const
  {
    return this->Blending + this->Search + this->Edges + this->Reconstruction;
  }
};
VTKFILTERSMLAA_EXPORT Halo ComputeHalo(vtkMLAAOptions* options);

//------------------------------------------------------------------------------
// The stages on one slice.

// Normalised depth values of one row of the depth image, for depth edges: floating-point depths
// as they are (a z-buffer in [0, 1]), integer ones by the range of their type.
template <typename T>
void NormaliseDepthRow(const void* row, vtkIdType pixelStride, int width, double* out)
{
  double lo = 0.0;
  double hi = 1.0;
  if (!std::is_floating_point<T>::value)
  {
    lo = static_cast<double>(std::numeric_limits<T>::lowest());
    hi = static_cast<double>(std::numeric_limits<T>::max());
  }
  const T* p = static_cast<const T*>(row);
  for (int x = 0; x < width; ++x, p += pixelStride)
  {
    out[x] = (static_cast<double>(*p) - lo) / (hi - lo);
  }
}

// The depth image of one slice, read row by row.
struct DepthRows
{
  const char* Origin = nullptr; // the first available pixel of the slice
  vtkIdType RowBytes = 0;
  vtkIdType PixelStride = 0; // in values
  void (*Normalise)(const void*, vtkIdType, int, double*) = nullptr;
};

/** Everything one z slice of any type needs. */
struct SliceSetup
{
  Rect Whole;  // the image: reads beyond it are clamped to it, as GPU texture reads are
  Rect Input;  // the pixels available (the requested extent, padded, within the input)
  Rect Output; // the pixels to produce
  int DebugOutput = vtkMLAAOptions::NO_DEBUG_OUTPUT;
  FeatureLayout Layout;
  EdgeSettings Edges;
  WeightSettings Weights;
  bool Dominant = true;
  bool PremultipliedAlpha = false;
  bool Reconstruction = false; // vtkMLAAOptions::Reconstruction (stage 0)
  double Lo = 0.0; // normalisation: value -> (value - Lo) / (Hi - Lo)
  double Hi = 1.0;

  /**
   * The pixels whose blending weights the output needs: its own, and those of the row below it
   * and the column right of it, which its blending reads; within the available pixels.
   */
  /** The settings of stage 0 (vtkMLAAReconstruction.h) for this slice. */
  ReconstructionSettings GetReconstruction() const
  {
    return ReconstructionSettings{ this->Input, this->Layout.Components, this->Edges.Threshold,
      this->Lo, this->Hi };
  }
  Rect WeightsExtent() const
  {
    return Rect{ this->Output.X0, this->Output.X1 + 1, this->Output.Y0 - 1, this->Output.Y1 }
      .Intersect(this->Input);
  }
  /**
   * The rows the stages go through on one slice (reconstruction, edges, weights, blending), for
   * progress.
   */
  vtkIdType RowsOfWork() const
  {
    return static_cast<vtkIdType>(this->Input.Height()) * (this->Reconstruction ? 2 : 1) +
      this->WeightsExtent().Height() + this->Output.Height();
  }
};

//------------------------------------------------------------------------------
/** The full-size buffers of the stages, reused from slice to slice. */
struct SliceBuffers
{
  ByteBuffer Reconstructed; // the reconstructed pixels of the slice, with Reconstruction only
  EdgesBuffer Edges;
  WeightsBuffer Weights;

  /** The bytes the buffers hold. */
  size_t GetCapacity() const
  {
    return this->Reconstructed.GetCapacity() + this->Edges.Data.GetCapacity() +
      this->Weights.Data.GetCapacity() + this->Weights.Scratch.GetCapacity();
  }
};

/**
 * SliceBuffers shared by every vtkImageMLAA of the process, so that a new filter per image (the
 * mlaa tool's batches, vtkmlaa.antialias_array, the ParaView filter, most image pipelines) runs
 * with buffers whose pages are already mapped, as a filter updated again and again does: a
 * fresh page costs from under a microsecond to over ten depending on the machine, which at
 * 1920 x 1080 came to more than the stages themselves. AcquireSliceBuffers() takes the buffers
 * most recently given back (or new ones); the lease gives them back when it is destroyed. At
 * most RetainedBytes are kept between updates (the most recently returned first); buffers
 * beyond that are freed.
 */
constexpr size_t RetainedBytes = size_t(64) << 20;
struct ReturnSliceBuffers
{
  VTKFILTERSMLAA_EXPORT void operator()(SliceBuffers* buffers) const;
};
using SliceBuffersLease = std::unique_ptr<SliceBuffers, ReturnSliceBuffers>;
VTKFILTERSMLAA_EXPORT SliceBuffersLease AcquireSliceBuffers();
/** The bytes kept between updates now (for tests). */
VTKFILTERSMLAA_EXPORT size_t GetRetainedSliceBufferBytes();

/** Wall-clock seconds spent in each stage, summed over the slices run with it. */
struct StageTimes
{
  double Reconstruction = 0.0;   // with vtkMLAAOptions::Reconstruction only
  double FeaturesAndEdges = 0.0; // features are read row by row inside edge detection
  double BlendingWeights = 0.0;
  double Blending = 0.0; // neighbourhood blending or the debug image
};

/**
 * The stages on one slice of an image of type T (reconstruction first, when
 * setup.Reconstruction): `input` points at the first pixel of
 * setup.Input (rows `inputRowStride` values apart), `output` (or `debug`, for a debug image) at
 * the first pixel of setup.Output (rows packed). `times`, if given, collects the stages' times.
 */
template <typename T>
void RunSlice(const SliceSetup& setup, const T* input, vtkIdType inputRowStride,
  const DepthRows& depth, T* output, unsigned char* debug, SliceBuffers& buffers,
  Progress& progress, StageTimes* times = nullptr)
{
  using Clock = std::chrono::steady_clock;
  auto t0 = Clock::now();
  auto lap = [&t0, times](double StageTimes::*stage) {
    const auto t1 = Clock::now();
    if (times)
    {
      times->*stage += std::chrono::duration<double>(t1 - t0).count();
    }
    t0 = t1;
  };
  using Acc = AccumulatorType<T>;
  const Rect& in = setup.Input;
  const int c = setup.Layout.Components;

  // Stage 0: reconstruction, into a copy of the available pixels that then replaces the input.
  if (setup.Reconstruction)
  {
    buffers.Reconstructed.Reserve(
      sizeof(T) * static_cast<size_t>(c) * in.Width() * std::max(in.Height(), 0));
    T* reconstructed = reinterpret_cast<T*>(buffers.Reconstructed.Get());
    Reconstruct<T>(
      setup.GetReconstruction(), input, inputRowStride, reconstructed, progress);
    lap(&StageTimes::Reconstruction);
    if (progress.Aborted())
    {
      return;
    }
    input = reconstructed;
    inputRowStride = static_cast<vtkIdType>(in.Width()) * c;
  }
  auto pixel = [&](int x, int y) {
    return input + static_cast<vtkIdType>(y - in.Y0) * inputRowStride +
      static_cast<vtkIdType>(x - in.X0) * c;
  };

  // Stages 1 and 2: features, read row by row, and edges.
  const FeatureReader<T, Acc> reader(
    setup.Layout, static_cast<Acc>(setup.Lo), static_cast<Acc>(1.0 / (setup.Hi - setup.Lo)));
  const std::function<void(int, Acc*)> readRow = [&](int y, Acc* features) {
    const double* depthRow = nullptr;
    if (depth.Normalise)
    {
      // One row of normalised depths per thread, kept from row to row.
      static thread_local std::vector<double> depthValues;
      depthValues.resize(in.Width());
      depth.Normalise(depth.Origin + (y - in.Y0) * depth.RowBytes, depth.PixelStride, in.Width(),
        depthValues.data());
      depthRow = depthValues.data();
    }
    reader.Row(pixel(in.X0, y), in.Width(), depthRow, features);
  };
  buffers.Edges.Allocate(in);
  DetectEdges<Acc>(readRow, setup.Layout.Count, setup.Edges, buffers.Edges, progress);
  lap(&StageTimes::FeaturesAndEdges);

  // Stage 3: blending weights of the output pixels and of the pixels whose weights their
  // blending reads (the row below and the column right of them).
  const Rect& out = setup.Output;
  buffers.Weights.Allocate(setup.WeightsExtent());
  if (progress.Aborted())
  {
    return;
  }
  ComputeBlendingWeights(buffers.Edges, setup.Whole, setup.Weights, buffers.Weights, progress);
  lap(&StageTimes::BlendingWeights);
  if (progress.Aborted())
  {
    return;
  }

  // Stage 4: neighbourhood blending, or a debug image.
  if (debug)
  {
    WriteDebugImage(setup.DebugOutput, buffers.Edges, buffers.Weights, out, debug);
    progress.RowsDone(out.Height());
    lap(&StageTimes::Blending);
    return;
  }
  BlendSettings blend;
  blend.Dominant = setup.Dominant;
  blend.StraightAlpha = setup.Layout.HasAlpha && !setup.PremultipliedAlpha;
  blend.AlphaLo = setup.Lo;
  blend.AlphaInverseRange = 1.0 / (setup.Hi - setup.Lo);
  vtkSMPTools::For(0, out.Height(), RowsPerTask, [&](vtkIdType begin, vtkIdType end) {
    if (progress.Aborted())
    {
      return;
    }
    for (vtkIdType i = begin; i < end; ++i)
    {
      BlendRow<T, Acc>(out.Y0 + static_cast<int>(i), out, c, buffers.Edges, buffers.Weights, blend, pixel,
        output + i * out.Width() * c);
    }
    progress.RowsDone(end - begin);
  });
  lap(&StageTimes::Blending);
}

/**
 * A SliceSetup's settings from the options, for an image of `components` components normalised
 * by [lo, hi]; the rectangles are left to the caller.
 */
VTKFILTERSMLAA_EXPORT void ConfigureSlice(
  vtkMLAAOptions* options, int components, double lo, double hi, SliceSetup& setup);
}

#endif
