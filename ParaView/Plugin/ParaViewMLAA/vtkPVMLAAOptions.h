// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkPVMLAAOptions
 * @brief   The vtkMLAAOptions behind ParaView's MLAA properties: settings and a quality preset
 *          that can be set in any order.
 *
 * vtkMLAAOptions applies a preset at once (SetPreset overwrites the quality settings) and lets
 * later settings override it. ParaView pushes the properties of a proxy in an order of its own
 * (and all of them again when a state file is loaded), so a preset property that simply called
 * SetPreset would win or lose against the other properties by accident. This subclass keeps the
 * two apart instead:
 * - the quality properties (Threshold, LocalContrastFactor, EdgeDetection, MaxSearchSteps,
 *   DiagonalDetection, CornerExtrapolation, DominantDirectionBlending, Reconstruction) set the
 *   "custom" settings, through the Set*Setting methods;
 * - QualityPreset is CUSTOM (-1, the default: the custom settings apply) or one of
 *   vtkMLAAOptions::Presets (that preset's settings apply, whatever the custom ones are).
 * The effective settings, which vtkImageMLAA and vtkOpenGLMLAAPass read through the
 * vtkMLAAOptions interface, are recomputed from both after every change; PremultipliedAlpha
 * and DebugOutput describe the data and the output, are outside presets (as in
 * vtkMLAAOptions) and are set directly.
 *
 * Outside ParaView, use vtkMLAAOptions itself.
 *
 * @sa vtkMLAAOptions vtkImageMLAA vtkMLAARenderView
 */

#ifndef vtkPVMLAAOptions_h
#define vtkPVMLAAOptions_h

#include "vtkMLAAOptions.h"
#include "vtkNew.h"                 // For vtkNew
#include "vtkParaViewMLAAModule.h" // For export macro

class VTKPARAVIEWMLAA_EXPORT vtkPVMLAAOptions : public vtkMLAAOptions
{
public:
  static vtkPVMLAAOptions* New();
  vtkTypeMacro(vtkPVMLAAOptions, vtkMLAAOptions);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** QualityPreset's value for "no preset: the custom settings apply". */
  static constexpr int CUSTOM = -1;

  ///@{
  /**
   * CUSTOM (-1, default) or a vtkMLAAOptions preset (LOW, MEDIUM, HIGH, ULTRA, MAX) whose quality
   * settings replace the custom ones while it is chosen. Other values are refused with an error.
   */
  void SetQualityPreset(int preset);
  vtkGetMacro(QualityPreset, int);
  ///@}

  ///@{
  /**
   * The custom quality settings: what the effective settings are while QualityPreset is CUSTOM.
   * Ranges and meanings are vtkMLAAOptions's (out-of-range values are clamped the same way).
   */
  void SetThresholdSetting(double value);
  void SetLocalContrastFactorSetting(double value);
  void SetEdgeDetectionSetting(int mode);
  void SetMaxSearchStepsSetting(int steps);
  void SetDiagonalDetectionSetting(bool on);
  void SetCornerExtrapolationSetting(bool on);
  void SetDominantDirectionBlendingSetting(bool on);
  void SetReconstructionSetting(bool on);
  vtkMLAAOptions* GetCustomSettings() { return this->Custom; }
  ///@}

protected:
  vtkPVMLAAOptions();
  ~vtkPVMLAAOptions() override = default;

private:
  vtkPVMLAAOptions(const vtkPVMLAAOptions&) = delete;
  void operator=(const vtkPVMLAAOptions&) = delete;

  // Makes the effective quality settings those of the preset, or the custom ones.
  void UpdateEffectiveSettings();

  vtkNew<vtkMLAAOptions> Custom;
  int QualityPreset = CUSTOM;
};

#endif
