// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMLAAOptions.h"

#include "vtkAntialiasingOptionsHelpers.h"

#include "vtkObjectFactory.h"

#include <cstring>

vtkStandardNewMacro(vtkMLAAOptions);

namespace
{
const char* const EdgeDetectionNames[] = { "luma", "color", "depth", "lab" };
const char* const DebugOutputNames[] = { "none", "edges", "weights" };
const char* const PresetNames[] = { "low", "medium", "high", "ultra", "max" };

// The quality settings of each preset (see the class description).
struct PresetSettings
{
  double Threshold;
  double LocalContrastFactor;
  int EdgeDetection;
  int MaxSearchSteps;
  bool DiagonalDetection;
  bool CornerExtrapolation;
  bool DominantDirectionBlending;
  bool Reconstruction;
};
const PresetSettings PresetTable[] = {
  { 0.15, 2.0, vtkMLAAOptions::LUMA, 4, false, false, true, false }, // low
  { 0.1, 2.0, vtkMLAAOptions::LUMA, 8, true, false, true, false },   // medium
  { 0.1, 2.0, vtkMLAAOptions::LAB, 16, true, false, true, false },   // high
  { 0.05, 2.0, vtkMLAAOptions::LAB, 32, true, false, true, false },  // ultra
  { 0.05, 2.0, vtkMLAAOptions::LAB, 32, true, false, true, true },   // max
};
}

//------------------------------------------------------------------------------
const char* vtkMLAAOptions::GetEdgeDetectionAsString(int mode)
{
  return (mode >= LUMA && mode <= LAB) ? EdgeDetectionNames[mode] : "unknown";
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetEdgeDetectionFromString(const char* name)
{
  return vtkAntialiasingInternal::IndexOfName(EdgeDetectionNames, name);
}

//------------------------------------------------------------------------------
const char* vtkMLAAOptions::GetDebugOutputAsString(int output)
{
  return (output >= NO_DEBUG_OUTPUT && output <= BLENDING_WEIGHTS) ? DebugOutputNames[output]
                                                                   : "unknown";
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetDebugOutputFromString(const char* name)
{
  return vtkAntialiasingInternal::IndexOfName(DebugOutputNames, name);
}

//------------------------------------------------------------------------------
const char* vtkMLAAOptions::GetPresetAsString(int preset)
{
  if (preset == -1)
  {
    return "custom";
  }
  return (preset >= LOW && preset <= MAX) ? PresetNames[preset] : "unknown";
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetPresetFromString(const char* name)
{
  return vtkAntialiasingInternal::IndexOfName(PresetNames, name);
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::SetPreset(int preset)
{
  if (preset < LOW || preset > MAX)
  {
    vtkErrorMacro("SetPreset: " << preset << " is not a preset (LOW, MEDIUM, HIGH, ULTRA or MAX).");
    return;
  }
  const PresetSettings& p = PresetTable[preset];
  this->SetThreshold(p.Threshold);
  this->SetLocalContrastFactor(p.LocalContrastFactor);
  this->SetEdgeDetection(p.EdgeDetection);
  this->SetMaxSearchSteps(p.MaxSearchSteps);
  this->SetDiagonalDetection(p.DiagonalDetection);
  this->SetCornerExtrapolation(p.CornerExtrapolation);
  this->SetDominantDirectionBlending(p.DominantDirectionBlending);
  this->SetReconstruction(p.Reconstruction);
}

//------------------------------------------------------------------------------
int vtkMLAAOptions::GetPreset()
{
  for (int preset = LOW; preset <= MAX; ++preset)
  {
    const PresetSettings& p = PresetTable[preset];
    if (this->Threshold == p.Threshold && this->LocalContrastFactor == p.LocalContrastFactor &&
      this->EdgeDetection == p.EdgeDetection && this->MaxSearchSteps == p.MaxSearchSteps &&
      this->DiagonalDetection == p.DiagonalDetection &&
      this->CornerExtrapolation == p.CornerExtrapolation &&
      this->DominantDirectionBlending == p.DominantDirectionBlending &&
      this->Reconstruction == p.Reconstruction)
    {
      return preset;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::DeepCopy(vtkMLAAOptions* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->CopyQualitySettings(other);
  this->SetDebugOutput(other->DebugOutput);
  this->SetPremultipliedAlpha(other->PremultipliedAlpha);
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::CopyQualitySettings(vtkMLAAOptions* other)
{
  if (!other || other == this)
  {
    return;
  }
  this->SetThreshold(other->Threshold);
  this->SetLocalContrastFactor(other->LocalContrastFactor);
  this->SetEdgeDetection(other->EdgeDetection);
  this->SetMaxSearchSteps(other->MaxSearchSteps);
  this->SetDiagonalDetection(other->DiagonalDetection);
  this->SetCornerExtrapolation(other->CornerExtrapolation);
  this->SetDominantDirectionBlending(other->DominantDirectionBlending);
  this->SetReconstruction(other->Reconstruction);
}

//------------------------------------------------------------------------------
bool vtkMLAAOptions::Assign(vtkObject* owner, vtkMLAAOptions*& member, vtkMLAAOptions* options)
{
  return vtkAntialiasingInternal::AssignOwned(owner, member, options);
}

//------------------------------------------------------------------------------
void vtkMLAAOptions::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Threshold: " << this->Threshold << "\n";
  os << indent << "LocalContrastFactor: " << this->LocalContrastFactor << "\n";
  os << indent << "EdgeDetection: " << GetEdgeDetectionAsString(this->EdgeDetection) << "\n";
  os << indent << "MaxSearchSteps: " << this->MaxSearchSteps << "\n";
  os << indent << "DebugOutput: " << GetDebugOutputAsString(this->DebugOutput) << "\n";
  os << indent << "DiagonalDetection: " << (this->DiagonalDetection ? "On" : "Off") << "\n";
  os << indent << "CornerExtrapolation: " << (this->CornerExtrapolation ? "On" : "Off") << "\n";
  os << indent << "DominantDirectionBlending: " << (this->DominantDirectionBlending ? "On" : "Off")
     << "\n";
  os << indent << "PremultipliedAlpha: " << (this->PremultipliedAlpha ? "On" : "Off") << "\n";
  os << indent << "Reconstruction: " << (this->Reconstruction ? "On" : "Off") << "\n";
  os << indent << "Preset: " << GetPresetAsString(this->GetPreset()) << "\n";
}
