// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOpenGLAntialiasingPass
 * @brief   Abstract render pass that antialiases a renderer's image with full-screen shader
 *          passes: the targets and state handling that vtkOpenGLMLAAPass and vtkOpenGLDLAAPass
 *          share.
 *
 * A subclass supplies the antialiasing itself (its own targets and shader passes, which read
 * ColorTexture and write into the renderer's viewport); this class does everything around it, the
 * same way for every method:
 * - the delegate is rendered in place, straight into the target framebuffer and viewport as it
 *   would be without the pass, and its colour is copied (blitted, resolving multisampled targets)
 *   into ColorTexture; the subclass then writes only the pixels it changes. When the renderer is
 *   composited over lower layers, or when the subclass needs the delegate's depth as a texture,
 *   the delegate renders into ColorTexture and DepthTexture instead and the subclass writes
 *   every pixel and its depth back;
 * - layers: a renderer that preserves the colour buffer renders into a texture cleared to
 *   transparent black (premultiplied colour) and its result is composited over the target with
 *   premultiplied "over" blending; its alpha takes part in the antialiasing;
 * - overlays: the overlay step of a vtkRenderStepsPass delegate (text, 2D actors) is drawn after
 *   the antialiasing, untouched, unless AntialiasOverlays is on;
 * - translucency: a vtkRenderStepsPass delegate whose translucent step is VTK's plain
 *   vtkTranslucentPass (its default) draws translucent geometry, at each render, the way the
 *   renderer would without a pass, from its current settings: order-independent translucency
 *   (vtkOrderIndependentTranslucentPass), or with UseDepthPeeling, dual depth peeling
 *   (vtkDualDepthPeelingPass, which with UseDepthPeelingForVolumes also peels the volumes of a
 *   render that has translucent geometry) or, where the renderer reports dual depth peeling
 *   unsupported, vtkDepthPeelingPass, with the renderer's MaximumNumberOfPeels and
 *   OcclusionRatio. The delegate's own translucent step does the drawing inside them and is put
 *   back after each render; a translucent step of any other class (the user's own) is left
 *   alone, as is any other delegate. In a composited renderer (layers),
 *   order-independent translucency leaves the right premultiplied colour but not its coverage in
 *   alpha: the pass keeps the alpha of the opaque steps in a texture of its own and blends the
 *   translucent geometry's coverage into it (one more draw of the translucent geometry);
 * - picking: while a vtkHardwareSelector renders, the renderer is drawn without the delegate and
 *   without antialiasing, as vtkOpenGLRenderer does without a pass, so ids are not blended;
 * - KeepAlpha (whether alpha is part of the result), floating-point targets (the copy is floating
 *   point too), tiled viewports and framebuffer objects of an enclosing pass, window resizes
 *   (targets resized in place), ReleaseGraphicsResources and GetTargetMemorySize.
 * Shaders are full-screen quads whose fragment source has the subclass's #defines in place of
 * //VTK::Antialiasing::Dec (ShaderVariant, ReadyQuad: rebuilt when the defines change).
 *
 * The behaviour of each piece is described in full in vtkOpenGLMLAAPass's class description.
 *
 * @sa vtkOpenGLMLAAPass vtkOpenGLDLAAPass vtkOpenGLFXAAPass
 */

#ifndef vtkOpenGLAntialiasingPass_h
#define vtkOpenGLAntialiasingPass_h

#include "vtkImageProcessingPass.h"
#include "vtkRenderingMLAAModule.h" // For export macro
#include "vtkWeakPointer.h"          // For ResourceWindow

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkDepthPeelingPass;
class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkOrderIndependentTranslucentPass;
class vtkRenderStepsPass;
class vtkRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

class VTKRENDERINGMLAA_EXPORT vtkOpenGLAntialiasingPass : public vtkImageProcessingPass
{
public:
  vtkTypeMacro(vtkOpenGLAntialiasingPass, vtkImageProcessingPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Render the delegate and antialias its image into the current framebuffer and viewport.
   */
  void Render(const vtkRenderState* s) override;

  /**
   * Release every graphics resource of the pass and of its delegate. An application need not
   * call it: the pass releases its GL objects by itself, in the context of the window it last
   * rendered in, when it is destroyed (replaced or removed with vtkRenderer::SetPass and no longer
   * referenced), when it renders in another window than the last (a pass shared by renderers of
   * several windows), and when that window releases its resources (Finalize, destruction). A pass
   * removed from its renderer but kept by the application keeps its targets (and its temporal
   * history) for when it is set again: call this to free them sooner.
   */
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // /@{
  /**
   * Whether the overlay step of a vtkRenderStepsPass delegate (text, scalar bars, 2D actors) is
   * antialiased too. Default off: overlays are drawn after the antialiasing, untouched.
   */
  vtkSetMacro(AntialiasOverlays, bool);
  vtkGetMacro(AntialiasOverlays, bool);
  vtkBooleanMacro(AntialiasOverlays, bool);
  // /@}

  // /@{
  /**
   * Whether the alpha channel of the renderer's image is part of the result (a transparent window
   * read back as RGBA). Default off: the image is treated as opaque, as the screen and an RGB
   * screenshot show it. Renderers that preserve the colour buffer (layers) always keep alpha. What
   * each method does with alpha is described by the subclass.
   */
  vtkSetMacro(KeepAlpha, bool);
  vtkGetMacro(KeepAlpha, bool);
  vtkBooleanMacro(KeepAlpha, bool);
  // /@}

  // /@{
  /**
   * Temporal antialiasing (default off). The pass keeps a history of its results and blends each
   * frame into it:
   * - while neither the camera nor the scene changes, each render is jittered by a sub-pixel
   *   offset (the Sobol sequence, whose first ConvergedFrames points sample the pixel's box
   *   evenly, through the active camera's WindowCenter, put back before the overlays are drawn
   *   and before Render returns) and the history is the exact
   *   running average of these renders since the last change: N renders of a still scene give
   *   the mean of N jittered renders, which converges to the supersampled picture (line widths
   *   and point sizes kept); the first frame of an accumulation is the method's antialiased frame,
   *   not jittered (it may be the first frame of a motion)
   *   (RenderConverged asks for a converged still); once ConvergedFrames frames are accumulated,
   *   further renders of the unchanged scene hold the converged still: neither jittered nor
   *   blended, the same image however many renders follow, the camera left alone;
   * - when the camera moves, the frame (not jittered) is antialiased by the method, and the
   *   history is reprojected with the delegate's depth and the previous and current
   *   view-projection matrices, clamped to the range of the 3 x 3 neighbourhood of the current
   *   frame as rendered, before the method (rejecting what the current frame does not support:
   *   disocclusions, changed shading), and
   *   blended with weight TemporalWeight for the current frame where a pixel's history did not
   *   move, rising to 0.7 where it moved a pixel (each read between pixels blurs the history a
   *   little) and on to 1, the current frame alone, where it moved 16 pixels or more (a history
   *   that moved far is mostly reprojection error), or where the direction the point is seen from
   *   turned 8 degrees or more since the last frame (rising in proportion below that: shading
   *   and silhouettes change with the view, which reprojection does not follow); where the
   *   history moved a pixel or more and is read, a method with a motion frame (DLAA: its frame
   *   without the short-edge blur) is blended with that frame instead, the history smoothing
   *   the edges' staircases itself;
   * - when actors (vtkActor) only move, turn, scale or are shown or hidden, under a still camera,
   *   the frame is not jittered and the history is kept where the method's frame (the pixel's
   *   3 x 3 neighbourhood) is the same as at the last unjittered render (pixels the motion did not reach keep what they accumulated
   *   and do not change), and replaced by the method's frame everywhere else (no ghost); each
   *   pixel keeps its own count of accumulated frames, so when the actors stop, the still
   *   accumulation goes on from it where the history was kept;
   * - the history is reset (the result is the method's frame alone) when the pass is switched on,
   *   on a resize, when the scene changes otherwise (a prop added or removed, another prop than
   *   an actor modified, an actor's mapper, its input, its properties or texture modified, a
   *   light that does not follow the camera modified, the background), when actors move while
   *   the camera moves, and when the camera switches between parallel and perspective
   *   projection.
   * Overlays (the deferred overlay step) are drawn after the blend, neither jittered nor blended.
   * The renderer is rendered into the pass's own textures (its depth is read). Hardware selection
   * renders bypass the pass and leave the history alone. A debug output of the method (MLAA)
   * shows the current frame alone. The camera's parameters are the same after a render as before
   * it; its modified time advances. Switching it on resets the history. With MultiSamples too,
   * the renders whose blend takes the method's frame (a reset, a moving camera or moving actors)
   * render the samples, and the method's frame is their antialiased resolve (see
   * SetMultiSamples; the history is reprojected with the nearest depth of each pixel's samples
   * and clamped to their plain average); the renders of a still accumulation and of a converged
   * still render one sample per pixel (a multisampled render's sample spread would blur the
   * average of the jittered renders), so stills converge as without samples.
   * The history is kept per renderer (a pass shared by several renderers) and, in stereo
   * (vtkRenderWindow::StereoRenderOn), per eye: each eye's renders are a sequence of frames of
   * their own (the right eye's history is dropped when the window renders in mono again).
   */
  virtual void SetTemporal(bool temporal);
  vtkGetMacro(Temporal, bool);
  vtkBooleanMacro(Temporal, bool);
  // /@}

  // /@{
  /**
   * Weight of the current frame in the blend while the camera moves (the history has 1 minus
   * it), for pixels whose history did not move; it rises linearly to 0.7 (or TemporalWeight if
   * larger) for pixels whose history moved one pixel since the last frame, and on to 1 for those
   * that moved 16 pixels or more or whose direction of view turned 8 degrees or more. Smaller is
   * steadier and slower to follow. Default 0.1, clamped to [0.01, 1].
   */
  vtkSetClampMacro(TemporalWeight, double, 0.01, 1.0);
  vtkGetMacro(TemporalWeight, double);
  // /@}

  // /@{
  /**
   * Number of frames of an unchanged scene that RenderConverged accumulates, and after which
   * further renders hold the converged still (raising it resumes the accumulation). Default 16,
   * clamped to [1, 4096]. The still jitter's offsets are placed for this many renders (rounded up
   * to a power of two): they then lie on the centres of as many equal strata of the pixel.
   */
  vtkSetClampMacro(ConvergedFrames, int, 1, 4096);
  vtkGetMacro(ConvergedFrames, int);
  // /@}

  /**
   * Frames averaged in the history since the scene and camera last changed (1 after a reset or a
   * render with a moving camera; 0 before the first temporal render). Where the pass keeps several
   * histories (several renderers, stereo), the fewest of those it rendered last (one render each).
   */
  int GetAccumulatedFrames() const;

  /**
   * Renders `window` until the pass's history holds ConvergedFrames frames of the unchanged scene
   * (a converged still, for a screenshot), at most 2 x ConvergedFrames renders; returns the number
   * of renders. With Temporal off, renders once. Warns when the history did not converge (the
   * pass is not on a renderer of `window`, or the scene changed at every render).
   */
  int RenderConverged(vtkRenderWindow* window);

  /**
   * Discards the history: the next render starts a new accumulation.
   */
  void ResetHistory();

  // /@{
  /**
   * Morphological antialiasing of a multisampled render (SMAA's "S2x" idea): with 2 or more, the
   * delegate renders into a target of that many samples per pixel; each sample set (sample s of
   * every pixel) is antialiased by the method's passes, unchanged, as a single-sample image, and
   * the antialiased sample images are averaged into the renderer's viewport, as a multisample
   * resolve averages samples; where a pixel's samples differ (a geometric edge crosses it), the
   * result is half that average and half the plain average of the samples, which undoes half of
   * the blur the sample positions' spread adds. Edges get both the sub-pixel coverage of
   * multisampling and the method's gradients. Default 0: the single-sample pass (0 and 1 mean the same). Where the
   * OpenGL driver does not offer the count asked for (for the colour and depth formats the pass
   * renders with), the nearest count it offers is used (the smaller of two equally near ones) and
   * a warning says so once per count asked for; GetRenderedMultiSamples() tells which count the
   * last render used (0 for the single-sample renders of a temporal still accumulation). Cost:
   * the method runs once per sample. With Temporal on, see SetTemporal.
   *
   * Everything else works as in the single-sample pass (overlays drawn after, layers, picking,
   * KeepAlpha, viewports, resizes, floating-point targets). Translucent geometry is drawn into
   * the multisampled target with VTK's order-independent translucency, also where the renderer
   * asks for depth peeling (which copies the framebuffer in a way multisampled framebuffers
   * refuse); it blends translucent fragments per pixel, not per sample, so translucent surfaces
   * are antialiased by the method alone, as in the single-sample pass, while opaque geometry
   * behind and around them keeps its samples. In a composited renderer (layers) the alpha of
   * translucent geometry is then what order-independent translucency leaves (the coverage
   * correction of the single-sample pass is not applied).
   */
  vtkSetClampMacro(MultiSamples, int, 0, 16);
  vtkGetMacro(MultiSamples, int);
  // /@}

  /**
   * The number of samples per pixel the last render used: 0 for the single-sample pass, otherwise
   * the supported count nearest to MultiSamples (see SetMultiSamples).
   */
  vtkGetMacro(RenderedMultiSamples, int);

  // /@{
  /**
   * With MultiSamples: whether every sample is shaded on its own (OpenGL sample shading,
   * glMinSampleShading(1)) while the delegate renders into the multisampled target. Default on.
   * Multisampling alone shades a pixel once, at its centre, for all the samples a primitive
   * covers: a sample image then holds, near a primitive's border, colours shaded outside the
   * primitive (textures read past their edge), and texture, colour-map and shading edges inside
   * a primitive are the same in every sample image, as aliased as in the single-sample pass. With
   * sample shading, each sample image is the scene point-sampled at that sample's position, as a
   * render shifted by the sample's offset would be, so the method and the resolve antialias
   * every edge, not only the edges of the geometry; and where a pixel's samples all agree, an
   * edge beside it lies within 1/2 less the largest sample offset of the pixel's border, which
   * MLAA's SampleAreas then also applies to lines whose ends show no sample difference, and the
   * samples' average measures every edge's coverage, which DLAA's ShortEdgesFromSamples relies
   * on (it leaves the short-edge blur out of the sample images). Cost: the
   * fragment shaders run once per sample (as many times as MultiSamples) instead of once per
   * pixel. Needs OpenGL 4.0 (elsewhere the samples are shaded per pixel; a warning says so once).
   * Translucent geometry (order-independent translucency) is still blended per pixel.
   */
  vtkSetMacro(SampleShading, bool);
  vtkGetMacro(SampleShading, bool);
  vtkBooleanMacro(SampleShading, bool);
  // /@}

  /**
   * Whether the last render shaded every sample (MultiSamples and SampleShading, where OpenGL
   * offers sample shading).
   */
  vtkGetMacro(RenderedSampleShading, bool);

  // /@{
  /**
   * For inspection and tests, with MultiSamples: a sample index s >= 0 makes the pass write the
   * plain, not antialiased image of sample s of every pixel (what the method's passes read for
   * that sample) instead of the antialiased resolve. Default -1: the antialiased result.
   */
  vtkSetMacro(DebugSample, int);
  vtkGetMacro(DebugSample, int);
  // /@}

  /**
   * Bytes of GPU memory held by the pass's render targets at the last render: the copy of the
   * delegate's colour, its depth when the pass renders it into its own textures, the alpha kept
   * across order-independent translucency in a composited renderer, the multisampled targets
   * (MultiSamples) and the subclass's targets (not the textures of VTK's translucency passes).
   */
  virtual vtkIdType GetTargetMemorySize();

protected:
  vtkOpenGLAntialiasingPass();
  ~vtkOpenGLAntialiasingPass() override;

  // What one render asks of the subclass's passes.
  struct Frame
  {
    vtkOpenGLRenderWindow* Window = nullptr;
    int X = 0, Y = 0, Width = 0, Height = 0; // the target viewport
    bool Composite = false;                  // composited over the target with premultiplied "over"
    bool UseAlpha = false;                   // alpha is part of the result (Composite or KeepAlpha)
    bool StraightAlpha = false; // the image holds straight alpha (see UsesStraightAlpha)
    bool InPlace = false;       // the target holds the delegate's image: write changed pixels
    bool FloatColor = false;    // ColorTexture is floating point
    // In place, where the target is a framebuffer of the pass (temporal antialiasing's frame):
    // it is bound, its colour attachment 0 is the target, and it may take a depth attachment
    // for a while; null otherwise.
    vtkOpenGLFramebufferObject* OwnTarget = nullptr;
    // Temporal antialiasing with a moving camera, for a method with a motion frame
    // (HasMotionFrame): the target has a second draw buffer (1), holding the delegate's image
    // too when in place, into which the method writes its motion frame.
    bool MotionFrame = false;
    // The VTK type of the colour targets that hold the image (ColorTexture's and the method's
    // frames).
    int ColorType() const { return this->FloatColor ? VTK_FLOAT : VTK_UNSIGNED_CHAR; }
  };

  // /@{
  /** What the subclass implements. */
  // Whether the passes need the delegate's depth as a texture (rules out rendering in place).
  virtual bool NeedsDelegateDepth() { return false; }
  // Whether, with KeepAlpha and no compositing, the image is read as straight alpha.
  virtual bool UsesStraightAlpha() { return false; }
  // Whether the deferred overlays are drawn over the result (not over a debug image, say).
  virtual bool DrawsDeferredOverlays() { return true; }
  // Whether the method writes a motion frame (Frame::MotionFrame) for temporal antialiasing:
  // its result without the filtering that a history reprojected from pixels moving a pixel or
  // more a frame does by itself, which the blend takes where the history moved that far and the
  // edges moved across themselves (vtkAntialiasingTemporalFS.glsl). DLAA's is its frame without
  // the short-edge blur.
  virtual bool HasMotionFrame() { return false; }
  // Creates or resizes the subclass's targets; returns true when one was allocated afresh (the
  // framebuffer objects are then rebuilt).
  virtual bool PrepareMethodTargets(const Frame& frame) = 0;
  // The antialiasing: reads ColorTexture (and DepthTexture unless in place) and writes the target
  // viewport, which is bound as the draw framebuffer.
  virtual bool Antialias(const Frame& frame) = 0;
  // Frees the subclass's GL objects (shader variants, targets). `w` may be null (the window is
  // gone, and its objects were freed with its context): the objects are then only deleted.
  virtual void ReleaseMethodResources(vtkWindow* w) = 0;
  // For the destructor of a concrete subclass: its ReleaseMethodResources, in the context of the
  // window the pass last rendered in (or with none where that window is gone). The base class's
  // destructor releases the rest.
  void ReleaseMethodResourcesOnDestruction();
  // Bytes of the subclass's targets.
  virtual vtkIdType GetMethodTargetMemorySize() = 0;
  // Substitutions in a fragment source beyond //VTK::Antialiasing::Dec (shared snippets).
  virtual void SubstituteShaderSnippets(std::string&) {}

  // With MultiSamples, while Antialias runs on one sample set: its index (-1 otherwise), the
  // offsets of all the samples from the pixel centre in pixels (x, y of sample s at 2 s, 2 s + 1;
  // x right, y up, where the driver places them) and the multisampled colour texture (to tell
  // which pixels' samples differ).
  // Shaded: every sample of every pixel was shaded at its own position and nothing was blended
  // per pixel (SampleShading, and no translucent geometry or volumes in the render), so that
  // where a pixel's samples all agree no edge passes between them.
  struct SampleSet
  {
    int Index = -1;
    std::vector<double> Offsets;
    vtkTextureObject* Colors = nullptr;
    bool Shaded = false;
  };
  const SampleSet& GetCurrentSampleSet() const { return this->CurrentSampleSet; }
  // /@}

  // A full-screen quad and the #defines its fragment shader was built with: the options that change
  // a shader's work select a compile-time variant of its one .glsl source.
  struct ShaderVariant
  {
    vtkOpenGLQuadHelper* Quad = nullptr;
    std::string Defines;
    // Frees the quad helper's graphics resources and the helper itself.
    void Release(vtkWindow* window);
  };
  // Builds the quad helper of a fragment shader with `defines` in place of
  // //VTK::Antialiasing::Dec (rebuilt when they differ from the last build), or binds the
  // existing one. `vs`: a vertex shader of VTK's screen quad (its attributes ndCoordIn and
  // texCoordIn) in place of the helper's own.
  bool ReadyQuad(vtkOpenGLRenderWindow* renWin, ShaderVariant& variant, const char* fs,
    const std::string& defines, const char* vs = nullptr);

  bool AntialiasOverlays = false;
  bool KeepAlpha = false;

  // The set-up of a full-screen pass into a texture: binds WorkFramebuffer with `texture` as its
  // only colour target over width x height (viewport and scissor), blending off, every channel
  // written. Depth is left to the caller.
  void BeginWorkPass(
    vtkOpenGLRenderWindow* renWin, vtkTextureObject* texture, int width, int height);

  vtkOpenGLFramebufferObject* DelegateFramebuffer = nullptr;
  vtkOpenGLFramebufferObject* WorkFramebuffer = nullptr; // for the subclass's passes
  vtkTextureObject* ColorTexture = nullptr;
  vtkTextureObject* DepthTexture = nullptr;

private:
  vtkOpenGLAntialiasingPass(const vtkOpenGLAntialiasingPass&) = delete;
  void operator=(const vtkOpenGLAntialiasingPass&) = delete;

  // The window in whose context the pass's GL objects were made: the one it rendered in last.
  vtkWeakPointer<vtkOpenGLRenderWindow> ResourceWindow;
  // ResourceWindow where its context still holds the pass's GL objects; null where the window is
  // gone, or released its resources while the pass was in none of its renderers.
  vtkOpenGLRenderWindow* LiveResourceWindow() const;
  // Before a render in `renWin`: where the pass last rendered in another window (a pass shared by
  // renderers of several windows), its GL objects belong to that window's context and name
  // nothing, or another object, in this one: they are released there first and made again here.
  // Where their context is gone, they are dropped and made again.
  void UseWindow(vtkOpenGLRenderWindow* renWin);
  // Frees the GL objects of this class (not the subclass's nor the delegate's).
  void ReleaseSharedResources(vtkWindow* w);

  // Creates or resizes the shared targets and the subclass's, and the framebuffer objects (with a
  // depth texture for the delegate when `depth`).
  void PrepareTargets(const Frame& frame, bool depth);
  // Copies the viewport of the target framebuffer (binding and colour buffer) into ColorTexture.
  void CopyTargetToColorTexture(
    const Frame& frame, unsigned int targetBinding, unsigned int targetBuffer);
  // What UseRendererTranslucency changed on a vtkRenderStepsPass delegate, for
  // RestoreDelegateSteps.
  struct StepsChange
  {
    vtkRenderStepsPass* Steps = nullptr;
    vtkRenderPass* Translucent = nullptr; // the step wrapped (held by its wrapper meanwhile)
    vtkRenderPass* Volumetric = nullptr;  // the volume step moved into dual depth peeling
  };
  // Gives the delegate's translucent step the translucency the renderer would use without a pass
  // (see the class description), wrapping the step; returns what it changed. `composite`: the
  // delegate renders into ColorTexture to be composited (see CompositedTranslucency).
  // `multisampled`: it renders into the multisampled targets (MultiSamples), where depth peeling
  // and CompositedTranslucency cannot copy the framebuffer: order-independent translucency, plain.
  StepsChange UseRendererTranslucency(
    const vtkRenderState* s, vtkRenderStepsPass* steps, bool composite, bool multisampled);
  // Puts the delegate's steps back as they were before UseRendererTranslucency.
  void RestoreDelegateSteps(const StepsChange& change);

  // The translucent step of a composited renderer with order-independent translucency: runs
  // RenderCompositedTranslucency.
  class CompositedTranslucency;
  // vtkOrderIndependentTranslucentPass (TranslucencyPass, wrapping `translucent`) leaves the
  // right premultiplied colour in ColorTexture, but an alpha that is not the coverage it was
  // premultiplied with: keeps the alpha before it in AlphaTexture, writes it back afterwards and
  // blends the coverage of `translucent`'s geometry into it.
  void RenderCompositedTranslucency(const vtkRenderState* s, vtkRenderPass* translucent);

  // The translucent steps of UseRendererTranslucency, made when first needed.
  vtkOrderIndependentTranslucentPass* TranslucencyPass = nullptr;
  vtkDepthPeelingPass* PeelingPass = nullptr; // a vtkDualDepthPeelingPass where supported
  CompositedTranslucency* CompositedPass = nullptr;
  vtkTextureObject* AlphaTexture = nullptr;
  ShaderVariant KeepAlphaQuad, RestoreAlphaQuad;

  // Temporal antialiasing (see SetTemporal): its histories, each the owner of its targets, and the
  // steps of a temporal frame (vtkOpenGLAntialiasingPassTemporal.h).
  bool Temporal = false;
  double TemporalWeight = 0.1;
  int ConvergedFrames = 16;
  class TemporalHistory;
  class TemporalHistories;
  std::unique_ptr<TemporalHistories> Histories;

  // Renders the delegate into `color` and `depth` through `fbo` (cleared to transparent black
  // first when compositing over the target).
  void RenderDelegateToTextures(const vtkRenderState* s, vtkOpenGLFramebufferObject* fbo,
    vtkTextureObject* color, vtkTextureObject* depth, int width, int height, bool composite);

  // Multisampled rendering (SetMultiSamples): the owner of its targets and its shaders, and the
  // antialiasing of the sample sets (vtkOpenGLAntialiasingPassSamples.h).
  int MultiSamples = 0;
  int RenderedMultiSamples = 0;
  bool SampleShading = true;
  bool RenderedSampleShading = false;
  int DebugSample = -1;
  class SampleTargets;
  std::unique_ptr<SampleTargets> Samples;
  SampleSet CurrentSampleSet;
};

#endif
