// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenGLMLAAPass
 * @brief   Render pass that antialiases a renderer's image with morphological antialiasing.
 *
 * vtkOpenGLMLAAPass renders its delegate into the renderer's viewport as it would be rendered
 * without the pass, copies the colour into a texture, then runs the three full-screen passes of
 * Jimenez et al., "Practical Morphological Antialiasing" (GPU Pro 2, sections 4.2 to 4.4) and
 * writes the pixels that blending changes back into the viewport (in place). With depth edges,
 * and for renderers that are composited over lower layers (below), the delegate is rendered
 * into a colour and a depth texture of the pass instead, and every pixel and its depth are
 * written back. The passes:
 * 0. with vtkMLAAOptions::Reconstruction only, topological reconstruction (Biri et al.,
 *    "Morphological antialiasing and topological reconstruction", section 4) into a copy of the
 *    colour texture, which the later passes read instead; the selection table comes from
 *    vtkMLAATopology. In place, the reconstructed pixels are written back too;
 * 1. edge detection into an RG8 edges texture (luma, colour, CIELAB or the delegate's depth); pixels
 *    without an edge are marked in a depth buffer so that the second pass skips them (the
 *    chapter's stencil trick); with a LocalContrastFactor, a second run of the edge shader on
 *    the edge pixels only drops edges much fainter than a neighbouring one;
 * 2. blending weights into an RGBA8 texture: distance search reading two edgels per bilinear
 *    fetch and stopping at crossing edges (or, with LineLengths, line lengths counted beforehand
 *    by recursive doubling), crossing edges read with a quarter-pixel offset, and
 *    the area texture of vtkMLAAAreaTexture, uploaded once per maximum distance; with
 *    DiagonalDetection, staircases of one-pixel steps are followed texel by texel (or, with
 *    LineLengths, through counts of their units made beforehand) and take their weights from
 *    vtkMLAAAreaTexture's diagonal table;
 * 3. blending of each pixel with its four neighbours (along the dominant line only at a
 *    staircase's corner, with DominantDirectionBlending).
 * It reads the same vtkMLAAOptions as the CPU filter vtkImageMLAA (share one object with
 * SetOptions), and the two produce the same image within 2/255 on the same input (on an opaque
 * window, the filter run on the RGB screenshot). The shaders are in
 * Rendering/glsl/vtkMLAA*FS.glsl; the options that change their work (edge detection mode, alpha
 * edges, local contrast adaptation, search length, diagonal detection, dominant-direction
 * blending, straight alpha, debug output) select compile-time variants of each (#defines
 * prepended to the source; a quad is rebuilt when they change), thresholds are uniforms.
 *
 * Use it in place of the renderer's default passes:
 * @code
 * vtkNew<vtkRenderStepsPass> steps;
 * vtkNew<vtkOpenGLMLAAPass> mlaa;
 * mlaa->SetDelegatePass(steps);
 * renderer->SetPass(mlaa);
 * renderWindow->SetMultiSamples(0); // MLAA replaces multisampling
 * @endcode
 *
 * Overlays: when the delegate is a vtkRenderStepsPass, its overlay step (text, scalar bars, 2D
 * actors) is by default drawn after the antialiasing, straight into the target, so text is not
 * blurred (as vtkOpenGLRenderer does with its built-in FXAA). AntialiasOverlaysOn() antialiases
 * them with the rest. Other delegates are antialiased as a whole. Props that draw part of
 * themselves in the opaque step (the colour bar of a vtkScalarBarActor, say) are antialiased there
 * as they would be by the renderer's FXAA. With a debug output, deferred overlays are not drawn
 * over the debug image.
 *
 * Framebuffers: the pass draws into whatever framebuffer and viewport the renderer draws into,
 * so several renderers, viewports, window resizes, tiled rendering and multisampled windows (the
 * copy is resolved) work. When the target is a floating-point framebuffer (for example under
 * vtkToneMappingPass), the pass's copy is floating point too. Thresholds apply to normalised
 * colours (1 = full intensity).
 *
 * Alpha: VTK's framebuffer always has an alpha channel; a renderer clears it to its
 * BackgroundAlpha (default 0) with its background colour, geometry writes alpha 1, and VTK's
 * blending (source alpha, one minus source alpha for colour; one, one minus source alpha for
 * alpha) draws translucent geometry over it. What the pass reads and writes:
 * - By default (KeepAlpha off) the image is opaque to its reader (the screen, an RGB
 *   screenshot): edges are found in the colour alone, exactly as vtkImageMLAA finds them in the
 *   RGB screenshot, and the four channels are blended with the same weights.
 * - With KeepAlpha on, alpha changes are edges too, and the blending honours
 *   vtkMLAAOptions::PremultipliedAlpha. Off (the default, straight alpha): the framebuffer is
 *   read as straight colour, which is what VTK leaves for opaque geometry over a transparent
 *   background of any colour (the background colour sits under alpha 0 and means nothing);
 *   colours are premultiplied, blended, and divided by the blended alpha again, so a silhouette
 *   gets a soft alpha border of its own colour and no fringe of the background colour, and the
 *   result is written back as straight colour (pixels without an edge unchanged). On: the
 *   framebuffer is read and written as premultiplied colour, which is what VTK's blending
 *   leaves over a transparent black background (translucent geometry included); it is blended
 *   as it is.
 * - A renderer that preserves the colour buffer (layers) renders into a texture of its own,
 *   cleared to transparent black, so its image is premultiplied whatever the options; it keeps
 *   alpha and is composited over the target (below).
 *
 * Layers: a renderer that preserves the colour buffer (any renderer on a layer above 0, or one
 * with SetPreserveColorBuffer(1)) draws over what lower layers and earlier renderers drew. The
 * pass then renders its delegate into a texture cleared to transparent black (so VTK's blending
 * leaves premultiplied colour in it), antialiases it with alpha taking part in edge detection,
 * and composites the result over the target with premultiplied "over" blending (one, one minus
 * source alpha): pixels where the renderer drew nothing keep their colour exactly, and its
 * antialiased silhouettes blend into what lies below. Such a renderer renders into a depth
 * buffer of its own, so its depth test does not see what lower layers left in the window's
 * (SetPreserveDepthBuffer(1) has no effect on it).
 *
 * Picking: while a vtkHardwareSelector renders (renderer->GetSelector() is set; this includes
 * vtkRenderedAreaPicker and vtkHardwareSelector::Select), the colour buffer holds encoded ids,
 * which must not be blended. The pass then renders as the renderer does without a pass (camera,
 * lights and vtkRenderer's geometry update, which hands the props to the selector) straight into
 * the target, without its delegate, so selections give the same ids with and without it.
 *
 * Only VTK's OpenGL abstractions are used (vtkOpenGLRenderWindow state, vtkTextureObject,
 * vtkOpenGLFramebufferObject, vtkOpenGLQuadHelper), so the pass runs on GLX, EGL and OSMesa
 * builds alike. ReleaseGraphicsResources frees every GL object it created.
 *
 * The targets and state handling above (in place or into the pass's textures, layers, overlays,
 * picking, KeepAlpha, framebuffers, resources) are vtkOpenGLAntialiasingPass's, shared with
 * vtkOpenGLDLAAPass; this class adds the MLAA passes.
 *
 * @sa vtkMLAAOptions vtkImageMLAA vtkMLAAAreaTexture vtkOpenGLAntialiasingPass vtkOpenGLFXAAPass
 */

#ifndef vtkOpenGLMLAAPass_h
#define vtkOpenGLMLAAPass_h

#include "vtkOpenGLAntialiasingPass.h"
#include "vtkRenderingMLAAModule.h" // For export macro

#include <vector> // For std::vector

class vtkMLAAOptions;
class vtkTextureObject;

class VTKRENDERINGMLAA_EXPORT vtkOpenGLMLAAPass : public vtkOpenGLAntialiasingPass
{
public:
  static vtkOpenGLMLAAPass* New();
  vtkTypeMacro(vtkOpenGLMLAAPass, vtkOpenGLAntialiasingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Render, ReleaseGraphicsResources and AntialiasOverlays are vtkOpenGLAntialiasingPass's; so
  // is KeepAlpha, whose meaning for MLAA is below.

  ///@{
  /**
   * The MLAA settings, shared in meaning (and, if wished, in object) with vtkImageMLAA. Never
   * null: a pass starts with its own default options; setting nullptr restores fresh defaults.
   */
  vtkGetObjectMacro(Options, vtkMLAAOptions);
  virtual void SetOptions(vtkMLAAOptions* options);
  ///@}

  // KeepAlpha (vtkOpenGLAntialiasingPass), for MLAA: whether the alpha channel of the
  // renderer's image is part of the result: a window with a
  // transparent background (renderer BackgroundAlpha below 1) read back as RGBA
  // (vtkWindowToImageFilter::SetInputBufferTypeToRGBA) or composited by the application.
  // Default off: the image is treated as opaque, as the screen and an RGB screenshot show it;
  // edges are found in the colour alone, so the RGB result equals vtkImageMLAA on the RGB
  // screenshot (VTK's framebuffer holds alpha 0 on the background and 1 on geometry whatever
  // their colours, which would otherwise make edges nobody sees). On: alpha changes are edges
  // too, and colours are blended with their coverage, in the convention of
  // vtkMLAAOptions::PremultipliedAlpha (see the class description). Renderers that preserve the
  // colour buffer (layers) always keep alpha. VTK 9.1's GetAlphaBitPlanes() reports the bits of
  // the window's framebuffer (8 on every offscreen window), not whether alpha is wanted, so the
  // pass cannot tell by itself.

  ///@{
  /**
   * How the blending-weights pass finds the distances from a pixel to the two ends of its
   * horizontal and vertical lines (section 4.3.1; up to vtkMLAAOptions::GetMaxDistance() pixels
   * each way). Both give the same integers, hence the same image, and both equal vtkImageMLAA's:
   * - SEARCH_LOOP: each pixel with an edge searches along its lines, two edgels per bilinear
   *   fetch (Jimenez et al., Listing 4.3), stopping at the line's end; its cost grows with the
   *   length of the lines, up to MaxSearchSteps fetches per direction.
   * - RECURSIVE_DOUBLING: the lengths of every line are counted beforehand by recursive doubling
   *   (Biri et al., "Practical morphological antialiasing on the GPU", section 3.3): an
   *   initialisation pass and ceil(log4(GetMaxDistance())) passes (levels 1, 4, 16, 64) of
   *   three fetches per direction over the edge pixels, into two RGBA16F textures (16 bytes per
   *   pixel together), which the weights pass reads once. Its cost grows with the logarithm of
   *   the maximum distance, not with the lines.
   * - AUTOMATIC (default): the rule both back ends share,
   *   vtkMLAAOptions::GetCountsExactLineLengths(): RECURSIVE_DOUBLING from
   *   vtkMLAAOptions::ExactLineLengthsSteps search steps on, SEARCH_LOOP below.
   * The same choice applies to the staircases of vtkMLAAOptions::DiagonalDetection: with
   * SEARCH_LOOP each unit searches its staircase one unit per read (up to GetMaxDistance() units
   * each way); with RECURSIVE_DOUBLING the pass that initialises the doubling also counts, for
   * each unit, the units that follow it up to a reach of about the square root of
   * GetMaxDistance() (into an RG8 texture, 2 bytes per pixel), and the weights pass follows a
   * staircase one read per reach. (Counting them without the doubling would cost a pass of its
   * own, which on llvmpipe costs more on common scenes than the searches it saves.)
   */
  enum LineLengthMethods
  {
    AUTOMATIC = 0,
    SEARCH_LOOP = 1,
    RECURSIVE_DOUBLING = 2
  };
  vtkSetClampMacro(LineLengths, int, AUTOMATIC, RECURSIVE_DOUBLING);
  vtkGetMacro(LineLengths, int);
  void SetLineLengthsToAutomatic() { this->SetLineLengths(AUTOMATIC); }
  void SetLineLengthsToSearchLoop() { this->SetLineLengths(SEARCH_LOOP); }
  void SetLineLengthsToRecursiveDoubling() { this->SetLineLengths(RECURSIVE_DOUBLING); }
  static const char* GetLineLengthsAsString(int method);
  ///@}

  /**
   * Whether the next render counts line lengths by recursive doubling: LineLengths, with
   * AUTOMATIC resolved for the current options.
   */
  bool GetUsesRecursiveDoubling();

  ///@{
  /**
   * With vtkOpenGLAntialiasingPass::SetMultiSamples: whether the areas of each sample set are
   * taken for the whole pixel (default on). Each sample set is the scene seen at one sample
   * position of every pixel; the line that MLAA finds in it is moved by that sample's offset
   * from the pixel centre (the driver's sample positions) before its areas are read
   * (vtkMLAAAreaTexture::ComputeAreas with offsets), wherever a pixel on either side of the
   * edgel has samples that differ (a geometric edge crosses it). Elsewhere the samples were
   * shaded at the pixel centre and the usual table applies, except that where a pixel at an end
   * of the line has differing samples, the edge runs between the two pixels' sample patterns
   * and their areas are limited to the gap between those patterns and the pixel border (1/8
   * with 4 samples). U shapes (both ends of the line step to the same side: bumps, dots, ends of
   * thin lines) keep the usual areas. When every sample was shaded on its own
   * (vtkOpenGLAntialiasingPass::SampleShading, with no translucent geometry or volumes in the
   * render), samples that agree bound every edge, not only geometric ones: a line whose edgel
   * pixels' samples agree is limited to that gap where a pixel at one of its ends has the edge
   * across its samples (a step), and takes no ramp where none has (the edge lies within the gap
   * of the pixel border all along). The average of the sample sets then approaches the
   * pixel's coverage along edges instead of blurring it by the spread of the sample positions
   * (docs/measurements.md, "Multisampled renders"). Off: each sample set is antialiased exactly
   * as the single-sample pass, and so as vtkImageMLAA, would (the CPU filter has no samples).
   * Orthogonal lines only: staircases of vtkMLAAOptions::DiagonalDetection and ends halved by
   * CornerExtrapolation keep the usual areas.
   */
  vtkSetMacro(SampleAreas, bool);
  vtkGetMacro(SampleAreas, bool);
  vtkBooleanMacro(SampleAreas, bool);
  ///@}

  /**
   * Bytes of GPU memory held by the pass's render targets at the last render (the copy of the
   * delegate's colour, its reconstructed copy with vtkMLAAOptions::Reconstruction, and of its
   * depth when the pass renders it into its own textures, edges, blending weights, the pixel
   * mask, the area textures and, with recursive doubling, the two line-lengths textures and the
   * two diagonal-lengths textures).
   */
  vtkIdType GetTargetMemorySize() override;

  /**
   * Bytes of the MLAA-specific targets alone (edges and blending-weights textures), the figure
   * the chapter quotes relative to the back buffer (1.5 times an RGBA8 back buffer).
   */
  vtkIdType GetMLAATargetMemorySize();

protected:
  vtkOpenGLMLAAPass();
  ~vtkOpenGLMLAAPass() override;

  vtkMLAAOptions* Options = nullptr;
  int LineLengths = AUTOMATIC;
  bool SampleAreas = true;

  // The hooks of vtkOpenGLAntialiasingPass.
  bool NeedsDelegateDepth() override;
  bool UsesStraightAlpha() override;
  bool DrawsDeferredOverlays() override;
  bool PrepareMethodTargets(const Frame& frame) override;
  bool Antialias(const Frame& frame) override;
  void ReleaseMethodResources(vtkWindow* w) override;
  vtkIdType GetMethodTargetMemorySize() override;
  void SubstituteShaderSnippets(std::string& source) override;

private:
  vtkOpenGLMLAAPass(const vtkOpenGLMLAAPass&) = delete;
  void operator=(const vtkOpenGLMLAAPass&) = delete;

  // Passes 1 and 2 into EdgesTexture and WeightsTexture.
  // With `markBlended`, the change mask also marks the pixels the blending may change that the
  // edge detection does not need (BlendThroughTexture).
  bool ComputeEdgesAndWeights(
    vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha, bool markBlended);
  // The line lengths by recursive doubling into one of LengthsTextures (`lengths`) and, with
  // diagonal detection, in the initialisation pass the counts of the units that follow each
  // staircase unit, up to GetStaircaseCountReach() each way, into StaircaseCountsTexture (from
  // which the weights pass follows a staircase one read per reach,
  // vtkMLAALineLengthsInitFS.glsl); on the pixels of the mask (the MLAA framebuffer is bound
  // with the mask and depth test EQUAL).
  bool CountLines(vtkOpenGLRenderWindow* renWin, vtkTextureObject*& lengths);
  // Whether the next render counts staircase units (CountLines): recursive doubling with
  // diagonal detection; StaircaseCountsTexture is kept while it does.
  bool GetCountsStaircases();
  // The reach of the counts of staircase units for the current maximum distance.
  int GetStaircaseCountReach();
  // Pass 3 (or a debug output) into the target viewport, composited over it with premultiplied
  // alpha when `composite`.
  // With `straightAlpha`, colours are premultiplied before blending and divided by alpha after.
  // `inPlace`: the target holds the delegate's image; only blended pixels are written, with
  // `throughTexture` by BlendThroughTexture.
  bool Blend(vtkOpenGLRenderWindow* renWin, int x, int y, int width, int height, bool composite,
    bool straightAlpha, bool inPlace, bool throughTexture, vtkOpenGLFramebufferObject* ownTarget);
  // In place: the source image and its blended pixels into BlendedTexture, then into the target
  // viewport (the blending run on the pixels the change mask marked only); a target of the
  // pass's own (Frame::OwnTarget) is blended into directly, with the mask as its depth.
  bool BlendThroughTexture(vtkOpenGLRenderWindow* renWin, int x, int y, int width, int height,
    vtkOpenGLFramebufferObject* ownTarget);
  // The images the edge detection programs read (all the change mask reads).
  void SetEdgeTextures(vtkShaderProgram* program);
  // The uniforms of the detection and local contrast programs: the images and the options.
  void SetEdgeUniforms(vtkShaderProgram* program);
  // Whether the edge detection reads the sRGB linearisation from a table (CIELAB edges on an
  // 8-bit source, MLAA_SRGB_TABLE).
  bool UsesSrgbTable();
  // The image the edge detection and the blending read: ReconstructedTexture with
  // vtkMLAAOptions::Reconstruction, else ColorTexture.
  vtkTextureObject* GetSourceTexture();
  // Pass 0, topological reconstruction (vtkMLAAReconstructionFS), into ReconstructedTexture.
  bool Reconstruct(vtkOpenGLRenderWindow* renWin, int width, int height, bool useAlpha);
  // In place, the reconstructed pixels drawn into the target viewport before the blending
  // (which writes back only the pixels it blends).
  bool WriteBackReconstruction(
    vtkOpenGLRenderWindow* renWin, int x, int y, int width, int height, bool useAlpha);
  // The uniforms of both reconstruction programs (the selection table of vtkMLAATopology).
  void SetReconstructionUniforms(vtkShaderProgram* program);

  vtkTextureObject* EdgesTexture = nullptr;
  vtkTextureObject* WeightsTexture = nullptr;
  vtkTextureObject* MaskTexture = nullptr;
  vtkTextureObject* AreaTexture = nullptr;
  vtkTextureObject* DiagonalAreaTexture = nullptr;
  vtkTextureObject* LengthsTextures[2] = { nullptr, nullptr }; // RGBA16F, ping-pong
  vtkTextureObject* StaircaseCountsTexture = nullptr; // RG8, with doubling and diagonals
  vtkTextureObject* ReconstructedTexture = nullptr; // with vtkMLAAOptions::Reconstruction only
  vtkTextureObject* BlendedTexture = nullptr; // in place: BlendThroughTexture's image
  int AreaTextureMaxDistance = 0;
  // With MultiSamples and SampleAreas: the area tables of each sample's offsets, stacked
  // (sample s: rows 2 s T to (2 s + 1) T - 1 for horizontal lines, the next T for vertical
  // ones, T the area texture's size), and the offsets and maximum distance they were made for.
  vtkTextureObject* SampleAreaTexture = nullptr;
  std::vector<double> SampleAreaOffsets;
  int SampleAreaMaxDistance = 0;
  // Uploads SampleAreaTexture for the current sample set's count when its offsets changed.
  void PrepareSampleAreas(vtkOpenGLRenderWindow* renWin, const SampleSet& set);
  ShaderVariant ReconstructionQuad;
  ShaderVariant WriteBackQuad;
  ShaderVariant ChangeMaskQuad;
  ShaderVariant EdgesQuad;
  ShaderVariant LocalContrastQuad;
  ShaderVariant WeightsQuad;
  ShaderVariant LengthsInitQuad;
  ShaderVariant LengthsQuad;
  ShaderVariant BlendQuad;
};

#endif
