/**
 * @class   vtkMLAARenderView
 * @brief   A ParaView render view that antialiases its final image with MLAA
 *          (vtkOpenGLMLAAPass).
 *
 * vtkMLAARenderView is a vtkPVRenderView (every RenderView property still applies) that, while
 * UseMLAA is on, installs a vtkOpenGLMLAAPass as the image-processing pass of its synchronized
 * renderers. ParaView runs that pass on the final image: in parallel (IceT), after the ranks'
 * images have been composited, on the process that shows or saves the image, so one rank and
 * several give the same result; in serial and built-in sessions, around the whole render. This
 * is the slot vtkPVRenderViewWithEDL and ParaView's tone mapping use.
 *
 * It steps aside where MLAA would be wrong or redundant:
 * - selection and picking: vtkPVRenderView removes the image-processing pass while its hardware
 *   selector renders (and the pass itself renders without antialiasing whenever a selector is
 *   set), so the ids read back are the same with UseMLAA on and off;
 * - FXAA: while UseMLAA is on, the view's FXAA is off, whatever UseFXAA says (it is remembered
 *   and applies again when UseMLAA is turned off), so the two never stack;
 * - tone mapping uses the same slot: while UseMLAA is on, UseToneMapping is remembered but has no
 *   effect; turning UseMLAA off brings tone mapping back if it was asked for.
 *
 * The MLAA settings are those of the vtkMLAAOptions given to SetMLAAOptions (the MLAAOptions
 * proxy's vtkPVMLAAOptions in ParaView), shared with the pass.
 *
 * @sa vtkOpenGLMLAAPass vtkMLAAOptions vtkPVMLAAOptions vtkPVRenderView
 */

#ifndef vtkMLAARenderView_h
#define vtkMLAARenderView_h

#include "vtkNew.h" // For vtkNew
#include "vtkPVRenderView.h"
#include "vtkParaViewMLAAModule.h" // For export macro

class vtkMLAAOptions;
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

  /**
   * FXAA as the user asks for it; it only applies while UseMLAA is off.
   */
  void SetUseFXAA(bool use) override;

  /**
   * Tone mapping as the user asks for it; it only applies while UseMLAA is off (it would take
   * the same image-processing slot).
   */
  void SetUseToneMapping(bool use);

protected:
  vtkMLAARenderView();
  ~vtkMLAARenderView() override;

private:
  vtkMLAARenderView(const vtkMLAARenderView&) = delete;
  void operator=(const vtkMLAARenderView&) = delete;

  // Puts the MLAA pass into the synchronized renderers' image-processing slot, or gives the slot
  // back to tone mapping (or to nothing), and sets FXAA accordingly.
  void UpdatePasses();

  vtkNew<vtkOpenGLMLAAPass> MLAAPass;
  bool UseMLAA = true;
  bool RequestedFXAA = false;
  bool RequestedToneMapping = false;
};

#endif
