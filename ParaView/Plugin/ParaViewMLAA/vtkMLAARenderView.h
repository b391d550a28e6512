// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMLAARenderView
 * @brief   A ParaView render view that antialiases its final image with MLAA
 *          (vtkOpenGLMLAAPass) or DLAA (vtkOpenGLDLAAPass).
 *
 * vtkMLAARenderView is a vtkPVRenderView (every RenderView property still applies) that, while
 * AntialiasingMethod is MLAA, installs a vtkOpenGLMLAAPass as the image-processing pass of its
 * synchronized renderers; while it is DLAA, a vtkOpenGLDLAAPass. The plugin makes it the class
 * of ParaView's ordinary render view (an object-factory override of vtkPVRenderView), where
 * AntialiasingMethod is FXAA_OR_NONE by default, so a view antialiases only when asked to.
 * The older properties UseMLAA and UseDLAA (the plugin's separate "MLAARenderView", kept for
 * scripts and state files that use it) choose the method while AntialiasingMethod is
 * FXAA_OR_NONE: MLAA if UseMLAA is on, else DLAA if UseDLAA is on. ParaView runs that pass on
 * the final image: in parallel (IceT), after the ranks'
 * images have been composited, on the process that shows or saves the image, so one rank and
 * several give the same result; in serial and built-in sessions, around the whole render. This
 * is the slot vtkPVRenderViewWithEDL and ParaView's tone mapping use.
 *
 * It steps aside where MLAA would be wrong or redundant:
 * - selection and picking: vtkPVRenderView removes the image-processing pass while its hardware
 *   selector renders (and the pass itself renders without antialiasing whenever a selector is
 *   set), so the ids read back are the same with UseMLAA on and off;
 * - FXAA: while MLAA or DLAA is on, the view's FXAA is off, whatever UseFXAA says (it is
 *   remembered and applies again when both are off), so the two never stack;
 * - tone mapping uses the same slot: while MLAA or DLAA is on, UseToneMapping is remembered but
 *   has no effect; turning them off brings tone mapping back if it was asked for.
 *
 * Backgrounds under IceT: the pass sees the composited image over transparent black, so the view
 * draws the background under it first: a single colour and a gradient (Background at the bottom,
 * Background2 at the top, as vtkRenderer draws it) are handled. A textured background or a sky
 * box cannot be redrawn there: the view then leaves the image without MLAA or DLAA and warns
 * once (antialiasing against black would blend wrong colours into every silhouette). In serial
 * and built-in sessions the pass reads the rendered image with its background, whatever it is.
 *
 * The settings are those of the vtkMLAAOptions given to SetMLAAOptions (the MLAAOptions proxy's
 * vtkPVMLAAOptions in ParaView) and of the vtkDLAAOptions given to SetDLAAOptions, shared with
 * the passes.
 *
 * @sa vtkOpenGLMLAAPass vtkOpenGLDLAAPass vtkMLAAOptions vtkPVMLAAOptions vtkPVRenderView
 */

#ifndef vtkMLAARenderView_h
#define vtkMLAARenderView_h

#include "vtkNew.h" // For vtkNew
#include "vtkPVRenderView.h"
#include "vtkParaViewMLAAModule.h" // For export macro

class vtkDLAAOptions;
class vtkMLAAOptions;
class vtkOpenGLDLAAPass;
class vtkOpenGLMLAAPass;

class VTKPARAVIEWMLAA_EXPORT vtkMLAARenderView : public vtkPVRenderView
{
public:
  static vtkMLAARenderView* New();
  vtkTypeMacro(vtkMLAARenderView, vtkPVRenderView);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * The values of AntialiasingMethod.
   */
  enum AntialiasingMethods
  {
    FXAA_OR_NONE = 0, ///< the view's own antialiasing: FXAA while UseFXAA is on, else none
    MLAA = 1,         ///< vtkOpenGLMLAAPass on the final image (FXAA held off)
    DLAA = 2          ///< vtkOpenGLDLAAPass on the final image (FXAA held off)
  };

  ///@{
  /**
   * The antialiasing of the final image: FXAA_OR_NONE (default), MLAA or DLAA (Andreev 2011,
   * directionally localized antialiasing). Other values are refused with an error.
   */
  void SetAntialiasingMethod(int method);
  vtkGetMacro(AntialiasingMethod, int);
  ///@}

  /**
   * The method in effect: AntialiasingMethod, or, while it is FXAA_OR_NONE, the one UseMLAA and
   * UseDLAA choose.
   */
  int GetEffectiveAntialiasingMethod();

  ///@{
  /**
   * Whether the alpha channel of the image is part of the antialiased result (both passes'
   * vtkOpenGLAntialiasingPass::KeepAlpha). Default off.
   */
  void SetAntialiasingKeepAlpha(bool keep);
  bool GetAntialiasingKeepAlpha(); // whether both passes keep alpha
  ///@}

  ///@{
  /**
   * Temporal antialiasing in both passes (vtkOpenGLAntialiasingPass::SetTemporal): a still
   * converges over successive renders to the supersampled picture, a moving camera blends a
   * reprojected history. Default off.
   */
  void SetAntialiasingTemporal(bool temporal);
  bool GetAntialiasingTemporal(); // whether both passes are temporal
  ///@}

  ///@{
  /**
   * Samples per pixel for MLAA and DLAA (both passes' vtkOpenGLAntialiasingPass::MultiSamples):
   * 0, the default, antialiases the single-sample image; 2, 4 or 8 renders each process's image
   * with that many samples and runs the method on each sample set before averaging. Where the
   * process renders over transparent black for compositing (IceT, several ranks) or for a client
   * (pvserver), the slot's delegate pastes an image that is already composited, one sample per
   * pixel: the passes then run single-sample, and the view warns once.
   */
  void SetAntialiasingMultiSamples(int samples);
  vtkGetMacro(AntialiasingMultiSamples, int);
  ///@}

  ///@{
  /**
   * With AntialiasingMultiSamples: whether every sample is shaded at its own position (both
   * passes' vtkOpenGLAntialiasingPass::SampleShading), so that texture and colour edges are
   * sampled too, at the cost of shading each pixel once per sample. Default on.
   */
  vtkSetMacro(AntialiasingSampleShading, bool);
  vtkGetMacro(AntialiasingSampleShading, bool);
  ///@}

  ///@{
  /**
   * Renders per still render while AntialiasingTemporal is on and MLAA or DLAA is in effect
   * (the passes' ConvergedFrames): a still render (a screenshot, the render after interaction)
   * renders this many times, so that it shows the converged still. The same number on every
   * process, so that parallel and client-server renders stay paired. Default 16, at least 1.
   */
  void SetAntialiasingConvergedFrames(int frames);
  int GetAntialiasingConvergedFrames();
  ///@}

  /**
   * A still render: with AntialiasingTemporal on and MLAA or DLAA in effect,
   * AntialiasingConvergedFrames renders; otherwise vtkPVRenderView's.
   */
  void StillRender() override;

  ///@{
  /**
   * How the MLAA pass finds line lengths (vtkOpenGLMLAAPass::SetLineLengths: AUTOMATIC,
   * SEARCH_LOOP or RECURSIVE_DOUBLING). Default AUTOMATIC. The image is the same with each.
   */
  void SetMLAALineLengths(int method);
  int GetMLAALineLengths();
  ///@}

  ///@{
  /**
   * The older switch of the separate MLAA view: while AntialiasingMethod is FXAA_OR_NONE, MLAA
   * antialiases the final image when this is on. Default off (the MLAARenderView proxy turns it
   * on).
   */
  void SetUseMLAA(bool use);
  vtkGetMacro(UseMLAA, bool);
  ///@}

  ///@{
  /**
   * The settings of the pass (never null: the pass's own defaults until set; nullptr restores
   * fresh defaults).
   */
  void SetMLAAOptions(vtkMLAAOptions* options);
  vtkMLAAOptions* GetMLAAOptions();
  ///@}

  /**
   * The pass itself, for what the options do not cover (vtkOpenGLMLAAPass::SetLineLengths).
   */
  vtkOpenGLMLAAPass* GetMLAAPass() { return this->MLAAPass; }

  ///@{
  /**
   * The older switch for DLAA: while AntialiasingMethod is FXAA_OR_NONE and UseMLAA is off, DLAA
   * antialiases the final image when this is on. Default off.
   */
  void SetUseDLAA(bool use);
  vtkGetMacro(UseDLAA, bool);
  ///@}

  ///@{
  /**
   * The settings of the DLAA pass (never null, as for MLAA).
   */
  void SetDLAAOptions(vtkDLAAOptions* options);
  vtkDLAAOptions* GetDLAAOptions();
  ///@}

  vtkOpenGLDLAAPass* GetDLAAPass() { return this->DLAAPass; }

  /**
   * FXAA as the user asks for it; it only applies while MLAA and DLAA are off.
   */
  void SetUseFXAA(bool use) override;

  /**
   * Tone mapping as the user asks for it; it only applies while MLAA and DLAA are off (it would
   * take the same image-processing slot).
   */
  void SetUseToneMapping(bool use);

  /**
   * Remembered (vtkPVRenderView has no getter) for GetDrawableBackground.
   */
  void SetBackgroundColorMode(int mode) override;

protected:
  vtkMLAARenderView();
  ~vtkMLAARenderView() override;

private:
  vtkMLAARenderView(const vtkMLAARenderView&) = delete;
  void operator=(const vtkMLAARenderView&) = delete;

  // Puts the MLAA or DLAA pass into the synchronized renderers' image-processing slot, or gives
  // the slot back to tone mapping (or to nothing), and sets FXAA accordingly.
  void UpdatePasses();
  // The view's background as vtkPVRenderView::UpdateBackground chooses it: its bottom and top
  // colours (equal unless a gradient) and true, or false when it is a texture or a sky box,
  // which cannot be drawn under the composited image.
  bool GetDrawableBackground(double bottom[3], double top[3]);
  // Warns, once per background mode, that the view does not antialias under IceT with it.
  void WarnUndrawableBackground();
  // Whether the image-processing slot holds the view's pass (MLAA or DLAA).
  bool UsesOwnPass();

  class vtkSlotPass;
  vtkNew<vtkSlotPass> SlotPass;
  vtkNew<vtkOpenGLMLAAPass> MLAAPass;
  vtkNew<vtkOpenGLDLAAPass> DLAAPass;
  int AntialiasingMethod = FXAA_OR_NONE;
  bool UseMLAA = false;
  int AntialiasingMultiSamples = 0;
  bool AntialiasingSampleShading = true;
  bool WarnedSingleSampleComposite = false;
  // The passes' MultiSamples for this render: 0 where the image is composited (see
  // SetAntialiasingMultiSamples), warning once.
  int GetRenderMultiSamples(bool composited);
  bool UseDLAA = false;
  int WarnedBackgroundMode = -1;
  int BackgroundMode = vtkPVRenderView::DEFAULT;
  bool RequestedFXAA = false;
  bool RequestedToneMapping = false;
};

#endif
