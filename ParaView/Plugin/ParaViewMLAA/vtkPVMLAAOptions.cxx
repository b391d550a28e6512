// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkPVMLAAOptions.h"

#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkPVMLAAOptions);

//------------------------------------------------------------------------------
vtkPVMLAAOptions::vtkPVMLAAOptions()
{
  // Both start at vtkMLAAOptions's defaults; this keeps them equal should those change.
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetQualityPreset(int preset)
{
  if (preset != CUSTOM && (preset < LOW || preset > MAX))
  {
    vtkErrorMacro("SetQualityPreset: " << preset
                                       << " is neither CUSTOM (-1) nor a preset (LOW, MEDIUM, "
                                          "HIGH, ULTRA or MAX).");
    return;
  }
  if (preset != this->QualityPreset)
  {
    this->QualityPreset = preset;
    this->Modified();
    this->UpdateEffectiveSettings();
  }
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetThresholdSetting(double value)
{
  this->Custom->SetThreshold(value);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetLocalContrastFactorSetting(double value)
{
  this->Custom->SetLocalContrastFactor(value);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetEdgeDetectionSetting(int mode)
{
  this->Custom->SetEdgeDetection(mode);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetMaxSearchStepsSetting(int steps)
{
  this->Custom->SetMaxSearchSteps(steps);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetDiagonalDetectionSetting(bool on)
{
  this->Custom->SetDiagonalDetection(on);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetCornerExtrapolationSetting(bool on)
{
  this->Custom->SetCornerExtrapolation(on);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetDominantDirectionBlendingSetting(bool on)
{
  this->Custom->SetDominantDirectionBlending(on);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::SetReconstructionSetting(bool on)
{
  this->Custom->SetReconstruction(on);
  this->UpdateEffectiveSettings();
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::UpdateEffectiveSettings()
{
  // The setters only call Modified() when a value changes, so an update that changes nothing
  // leaves the filter's and the pass's results valid.
  this->CopyQualitySettings(this->Custom);
  if (this->QualityPreset != CUSTOM)
  {
    this->SetPreset(this->QualityPreset);
  }
}

//------------------------------------------------------------------------------
void vtkPVMLAAOptions::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "QualityPreset: " << GetPresetAsString(this->QualityPreset) << "\n";
  os << indent << "CustomSettings:\n";
  this->Custom->PrintSelf(os, indent.GetNextIndent());
}
