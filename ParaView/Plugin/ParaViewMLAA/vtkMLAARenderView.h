// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkMLAARenderView
 * @brief   A ParaView render view that antialiases its final image with MLAA
 *          (vtkOpenGLMLAAPass) or DLAA (vtkOpenGLDLAAPass).
 *
 * vtkMLAARenderView is a vtkPVRenderView (every RenderView property still applies) that, while
 * UseMLAA is on, installs a vtkOpenGLMLAAPass as the image-processing pass of its synchronized
 * renderers; while UseMLAA is off and UseDLAA on, a vtkOpenGLDLAAPass (MLAA wins when both are
 * on). ParaView runs that pass on the final image: in parallel (IceT), after the ranks'
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

  ///@{
  /**
   * Whether the final image is antialiased by MLAA. Default on.
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
   * Whether the final image is antialiased by DLAA while UseMLAA is off. Default off.
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
   * Remembered (vtkPVRenderView has no getter) for GetSolidBackground.
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
  // The view's background colour, as vtkPVRenderView::UpdateBackground chooses it; false when
  // the background is not one colour (gradient, texture, sky box).
  bool GetSolidBackground(double colour[3]);
  // Whether the image-processing slot holds the view's pass (MLAA or DLAA).
  bool UsesOwnPass();

  class vtkSlotPass;
  vtkNew<vtkSlotPass> SlotPass;
  vtkNew<vtkOpenGLMLAAPass> MLAAPass;
  vtkNew<vtkOpenGLDLAAPass> DLAAPass;
  bool UseMLAA = true;
  bool UseDLAA = false;
  int BackgroundMode = vtkPVRenderView::DEFAULT;
  bool RequestedFXAA = false;
  bool RequestedToneMapping = false;
};

#endif
