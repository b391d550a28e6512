// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenGLDLAAPass
 * @brief   Render pass that antialiases a renderer's image with directionally localized
 *          antialiasing (DLAA).
 *
 * vtkOpenGLDLAAPass implements the method written down in vtkDLAAOptions's class description
 * (Andreev, "Anti-Aliasing From a Different Perspective", GDC 2011) as two full-screen passes, and
 * computes the same image as the CPU filter vtkImageDLAA within 2/255 on the same input (on an
 * opaque window, the filter run on the RGB screenshot):
 * 1. the short-edge blend masks mx, my of every pixel into an RG32F texture (full floats, so
 *    that their exact 17-pixel means for the long edges follow the CPU's float arithmetic; -1
 *    marks a pixel whose 5-pixel cross holds a colour that is not finite); with LongEdges the
 *    texture extends 8 pixels beyond each side of the image, where masks are computed from
 *    colours clamped to the border (vtkDLAAMasksFS.glsl);
 * 2. the short-edge blur and, with LongEdges, the long-edge masks (exact 17-tap means of the
 *    masks), the noise rejection and the move of the pixel towards the luminosity of the mean
 *    colour along the edge over the step the pixel is on (at most 17 pixels), written into the
 *    renderer's viewport (vtkDLAAFS.glsl). In place,
 *    only the pixels the method changes are written.
 * LongEdges and the luminosity function select compile-time variants of the shaders; Epsilon and
 * Lambda are uniforms. Share one vtkDLAAOptions object with vtkImageDLAA with SetOptions; the
 * pass's modification time includes its options'.
 *
 * Everything around the antialiasing is vtkOpenGLAntialiasingPass's, as for vtkOpenGLMLAAPass: the
 * delegate rendered in place and its colour copied, layers composited with premultiplied "over"
 * (their premultiplied image is filtered as it is), overlays of a vtkRenderStepsPass delegate drawn
 * after the antialiasing (AntialiasOverlays), picking rendered without the pass, floating-point and
 * multisampled targets, viewports, resizes, ReleaseGraphicsResources and GetTargetMemorySize. DLAA
 * finds edges in luminosity alone and filters the four channels
 * alike: with KeepAlpha the alpha channel is filtered with the colour, the image read as it is
 * whatever its alpha convention (so the RGBA result equals vtkImageDLAA on the RGBA screenshot);
 * without it, the filtered alpha is written too but means nothing to an opaque reader.
 *
 * @code
 * vtkNew<vtkRenderStepsPass> steps; vtkNew<vtkOpenGLDLAAPass> dlaa; dlaa->SetDelegatePass(steps);
 * renderer->SetPass(dlaa); renderWindow->SetMultiSamples(0);
 * @endcode
 *
 * @sa vtkDLAAOptions vtkImageDLAA vtkOpenGLAntialiasingPass vtkOpenGLMLAAPass
 */

#ifndef vtkOpenGLDLAAPass_h
#define vtkOpenGLDLAAPass_h

#include "vtkOpenGLAntialiasingPass.h"
#include "vtkRenderingMLAAModule.h" // For export macro

class vtkDLAAOptions;

class VTKRENDERINGMLAA_EXPORT vtkOpenGLDLAAPass : public vtkOpenGLAntialiasingPass
{
public:
  static vtkOpenGLDLAAPass* New();
  vtkTypeMacro(vtkOpenGLDLAAPass, vtkOpenGLAntialiasingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // /@{
  /**
   * The DLAA settings, shared in meaning (and, if wished, in object) with vtkImageDLAA. Never null:
   * a pass starts with its own default options; setting nullptr restores fresh defaults.
   */
  vtkGetObjectMacro(Options, vtkDLAAOptions);
  virtual void SetOptions(vtkDLAAOptions* options);
  // /@}

  /**
   * The pass's modification time includes that of its options, so a change of the options counts as
   * a change of the pass.
   */
  vtkMTimeType GetMTime() override;

  ///@{
  /**
   * With vtkOpenGLAntialiasingPass::SetMultiSamples and every sample shaded on its own
   * (vtkOpenGLAntialiasingPass::SampleShading, with no translucent geometry or volumes in the
   * render): whether the short edges take their softening from the samples (default on). The
   * short-edge blur (vtkDLAAOptions, step 1) stands in for the coverage of pixels that an edge
   * crosses, which one sample per pixel cannot see; with several samples each sample image is the
   * scene point-sampled at its own position, and the average of the sample images measures that
   * coverage. Blurring each sample image as well blurs the edges twice. On: each sample image gets
   * the long-edge step alone (vtkDLAAOptions::LongEdges), which still finds the gradients along
   * nearly horizontal and vertical edges that a few samples a pixel cannot resolve; and the step
   * is taken only where some pixel of its window has samples that differ (a step of the edge
   * crosses their sample patterns), so that sides that lie on pixel borders and end at corners
   * or junctions (voxels, bars) stay as rendered. Off: each sample image is filtered exactly as the
   * single-sample pass, and so as vtkImageDLAA, would. Measured in docs/measurements.md
   * ("DLAA with samples: the short edges from the samples").
   */
  vtkSetMacro(ShortEdgesFromSamples, bool);
  vtkGetMacro(ShortEdgesFromSamples, bool);
  vtkBooleanMacro(ShortEdgesFromSamples, bool);
  ///@}

  /**
   * Bytes of the DLAA-specific targets alone: the RG32F masks texture (8 bytes per pixel, of an
   * image 16 pixels wider and higher with LongEdges) and, with LongEdges, the 8-bit texture of
   * one byte per tile of 8 x 8 masks.
   */
  vtkIdType GetDLAATargetMemorySize();

protected:
  vtkOpenGLDLAAPass();
  ~vtkOpenGLDLAAPass() override;

  vtkDLAAOptions* Options = nullptr;
  bool ShortEdgesFromSamples = true;

  // The hooks of vtkOpenGLAntialiasingPass.
  bool PrepareMethodTargets(const Frame& frame) override;
  bool Antialias(const Frame& frame) override;
  void ReleaseMethodResources(vtkWindow* w) override;
  vtkIdType GetMethodTargetMemorySize() override;
  void SubstituteShaderSnippets(std::string& source) override;
  // Temporal antialiasing's motion frame: the frame with long edges only (no short-edge blur).
  bool HasMotionFrame() override { return true; }

private:
  vtkOpenGLDLAAPass(const vtkOpenGLDLAAPass&) = delete;
  void operator=(const vtkOpenGLDLAAPass&) = delete;

  // Pixels of MasksTexture beyond each side of the image: 8 with long edges, else 0.
  int GetMasksPadding();
  // Pass 1 into MasksTexture, with LongEdges its tiles into TilesTexture, and the sides of
  // corners into CornersTexture.
  bool ComputeMasks(const Frame& frame);
  // The sides of corners (vtkDLAACornersFS.glsl): the candidates into CornersMask, then the test.
  bool ComputeCorners(const Frame& frame);
  // One draw of vtkDLAACornersFS.glsl (`variant` built with `defines`), over squares when
  // `vertexShader` (vtkDLAATilesVS) is given, else over the whole image; timed as `stageName`.
  bool DrawCorners(const Frame& frame, ShaderVariant& variant, const std::string& defines,
    const char* vertexShader, const char* stageName);
  // Which tiles of 8 x 8 masks hold a mask other than 0 (vtkDLAATilesFS.glsl).
  bool ComputeTiles(const Frame& frame);
  // Pass 2 into the target viewport.
  bool Filter(const Frame& frame);
  // Draws `variant` (with vtkDLAATilesVS) over the squares of tiles with a mask other than 0
  // within `margin` tiles.
  void DrawSquares(ShaderVariant& variant, const Frame& frame, int margin);

  vtkTextureObject* MasksTexture = nullptr;
  vtkTextureObject* TilesTexture = nullptr;
  vtkTextureObject* CornersTexture = nullptr; // RGBA8, the image's size
  vtkTextureObject* CornersMask = nullptr;    // 16-bit depth: the candidates for the corners pass
  ShaderVariant MasksQuad;
  ShaderVariant TilesQuad;
  ShaderVariant CornerCandidatesQuad;
  ShaderVariant CornersQuad;
  ShaderVariant FilterQuad;      // over the whole viewport
  ShaderVariant FilterTilesQuad; // in place with LongEdges: a quad per square of tiles
                                 // (vtkDLAATilesVS)
};

#endif
