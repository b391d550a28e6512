// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkMLAAOptions: defaults, clamping, names, sharing with the filter.
#include "vtkImageMLAA.h"
#include "vtkMLAAOptions.h"
#include "vtkAntialiasingTestUtilities.h"
#include "vtkNew.h"

#include <cstring>
#include <iostream>

#define CHECK(cond)                                                                                \
  do                                                                                               \
  {                                                                                                \
    if (!(cond))                                                                                   \
    {                                                                                              \
      std::cerr << __FILE__ << ":" << __LINE__ << ": check failed: " #cond << std::endl;           \
      return EXIT_FAILURE;                                                                         \
    }                                                                                              \
  } while (false)

int TestMLAAOptions(int, char*[])
{
  vtkNew<vtkMLAAOptions> options;
  // Defaults: the high preset (Lab edges, threshold 0.1, distances up to 32 pixels), which
  // measured best for its cost.
  CHECK(options->GetThreshold() == 0.1);
  CHECK(options->GetEdgeDetection() == vtkMLAAOptions::LAB);
  CHECK(options->GetMaxSearchSteps() == 16);
  CHECK(options->GetMaxDistance() == 32);
  CHECK(options->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT);
  CHECK(options->GetDiagonalDetection());
  CHECK(options->GetLocalContrastFactor() == 2.0);
  CHECK(options->GetDominantDirectionBlending());
  CHECK(!options->GetReconstruction());
  CHECK(options->GetPreset() == vtkMLAAOptions::HIGH);

  // Clamping to the documented ranges.
  options->SetThreshold(-1.0);
  CHECK(options->GetThreshold() == 0.0);
  options->SetThreshold(3.0);
  CHECK(options->GetThreshold() == 1.0);
  options->SetMaxSearchSteps(0);
  CHECK(options->GetMaxSearchSteps() == 1);
  options->SetMaxSearchSteps(1000);
  CHECK(options->GetMaxSearchSteps() == 128);
  CHECK(options->GetMaxDistance() == 256);
  options->SetEdgeDetection(17);
  CHECK(options->GetEdgeDetection() == vtkMLAAOptions::LAB);
  options->SetLocalContrastFactor(-1.0);
  CHECK(options->GetLocalContrastFactor() == 0.0);
  options->SetLocalContrastFactor(1e9);
  CHECK(options->GetLocalContrastFactor() == 100.0);

  // Names used by the command-line tool, both ways.
  for (int mode = vtkMLAAOptions::LUMA; mode <= vtkMLAAOptions::LAB; ++mode)
  {
    CHECK(vtkMLAAOptions::GetEdgeDetectionFromString(
            vtkMLAAOptions::GetEdgeDetectionAsString(mode)) == mode);
  }
  for (int out = vtkMLAAOptions::NO_DEBUG_OUTPUT; out <= vtkMLAAOptions::BLENDING_WEIGHTS; ++out)
  {
    CHECK(vtkMLAAOptions::GetDebugOutputFromString(vtkMLAAOptions::GetDebugOutputAsString(out)) ==
      out);
  }
  CHECK(vtkMLAAOptions::GetEdgeDetectionFromString("lab") == vtkMLAAOptions::LAB);
  CHECK(vtkMLAAOptions::GetEdgeDetectionFromString("Lab") == -1);
  for (int preset = vtkMLAAOptions::LOW; preset <= vtkMLAAOptions::MAX; ++preset)
  {
    CHECK(vtkMLAAOptions::GetPresetFromString(vtkMLAAOptions::GetPresetAsString(preset)) == preset);
  }
  CHECK(std::strcmp(vtkMLAAOptions::GetPresetAsString(-1), "custom") == 0);
  CHECK(vtkMLAAOptions::GetPresetFromString("extreme") == -1);
  CHECK(vtkMLAAOptions::GetEdgeDetectionFromString(nullptr) == -1);
  CHECK(std::strcmp(vtkMLAAOptions::GetDebugOutputAsString(2), "weights") == 0);

  // DeepCopy copies every setting.
  vtkNew<vtkMLAAOptions> copy;
  options->SetThreshold(0.25);
  options->SetDebugOutputToEdges();
  options->DiagonalDetectionOff();
  options->SetLocalContrastFactor(3.5);
  options->DominantDirectionBlendingOff();
  copy->DeepCopy(options);
  CHECK(!copy->GetDominantDirectionBlending());
  CHECK(!copy->GetDiagonalDetection());
  CHECK(copy->GetLocalContrastFactor() == 3.5);
  CHECK(copy->GetThreshold() == 0.25);
  CHECK(copy->GetEdgeDetection() == vtkMLAAOptions::LAB);
  CHECK(copy->GetMaxSearchSteps() == 128);
  CHECK(copy->GetDebugOutput() == vtkMLAAOptions::EDGES);
  options->ReconstructionOn();
  copy->DeepCopy(options);
  CHECK(copy->GetReconstruction());

  // CopyQualitySettings copies what a preset sets and leaves alpha and debug output alone.
  vtkNew<vtkMLAAOptions> quality;
  quality->PremultipliedAlphaOn();
  quality->CopyQualitySettings(options);
  CHECK(quality->GetThreshold() == 0.25 && quality->GetLocalContrastFactor() == 3.5);
  CHECK(quality->GetEdgeDetection() == options->GetEdgeDetection());
  CHECK(quality->GetMaxSearchSteps() == options->GetMaxSearchSteps());
  CHECK(!quality->GetDiagonalDetection() && !quality->GetDominantDirectionBlending());
  CHECK(quality->GetReconstruction());
  CHECK(quality->GetPremultipliedAlpha() && !options->GetPremultipliedAlpha());
  CHECK(quality->GetDebugOutput() == vtkMLAAOptions::NO_DEBUG_OUTPUT);

  // Presets set every quality setting and leave the data's settings alone; later settings
  // override them; the current settings are recognised as a preset or as custom.
  vtkNew<vtkMLAAOptions> preset;
  preset->PremultipliedAlphaOn();
  preset->SetDebugOutputToEdges();
  preset->ReconstructionOn();
  preset->SetPresetToUltra();
  CHECK(preset->GetPreset() == vtkMLAAOptions::ULTRA);
  CHECK(preset->GetEdgeDetection() == vtkMLAAOptions::LAB);
  CHECK(!preset->GetReconstruction()); // only Max reconstructs
  CHECK(preset->GetMaxSearchSteps() == 32);
  CHECK(preset->GetThreshold() == 0.05);
  CHECK(preset->GetPremultipliedAlpha());
  CHECK(preset->GetDebugOutput() == vtkMLAAOptions::EDGES);
  // Max is Ultra with reconstruction; Ultra with reconstruction turned on is recognised as Max.
  vtkNew<vtkMLAAOptions> ultra;
  ultra->SetPresetToUltra();
  preset->SetPresetToMax();
  CHECK(preset->GetPreset() == vtkMLAAOptions::MAX);
  CHECK(preset->GetReconstruction());
  CHECK(std::strcmp(vtkMLAAOptions::GetPresetAsString(vtkMLAAOptions::MAX), "max") == 0);
  ultra->ReconstructionOn();
  CHECK(ultra->GetPreset() == vtkMLAAOptions::MAX);
  CHECK(ultra->GetThreshold() == preset->GetThreshold() &&
    ultra->GetEdgeDetection() == preset->GetEdgeDetection() &&
    ultra->GetMaxSearchSteps() == preset->GetMaxSearchSteps() &&
    ultra->GetLocalContrastFactor() == preset->GetLocalContrastFactor() &&
    ultra->GetDiagonalDetection() == preset->GetDiagonalDetection() &&
    ultra->GetCornerExtrapolation() == preset->GetCornerExtrapolation() &&
    ultra->GetDominantDirectionBlending() == preset->GetDominantDirectionBlending());
  preset->ReconstructionOff();
  CHECK(preset->GetPreset() == vtkMLAAOptions::ULTRA);
  preset->ReconstructionOn();
  preset->SetPresetToLow();
  CHECK(preset->GetPreset() == vtkMLAAOptions::LOW);
  CHECK(!preset->GetReconstruction());
  CHECK(!preset->GetDiagonalDetection());
  preset->SetMaxSearchSteps(5);
  CHECK(preset->GetPreset() == -1);
  preset->SetPresetToHigh();
  CHECK(preset->GetPreset() == vtkMLAAOptions::HIGH);
  const vtkMTimeType presetTime = preset->GetMTime();
  vtkNew<vtkMLAATest::MessageObserver> messages;
  messages->Watch(preset);
  preset->SetPreset(vtkMLAAOptions::MAX + 1); // refused with an error, nothing changes
  CHECK(messages->HasError("not a preset"));
  CHECK(preset->GetPreset() == vtkMLAAOptions::HIGH && preset->GetMTime() == presetTime);

  // A filter owns default options, can share an object, and sees its changes.
  vtkNew<vtkImageMLAA> filter;
  CHECK(filter->GetOptions() != nullptr);
  filter->SetOptions(options);
  CHECK(filter->GetOptions() == options.GetPointer());
  const vtkMTimeType before = filter->GetMTime();
  options->SetThreshold(0.3);
  CHECK(filter->GetMTime() > before);
  filter->SetOptions(nullptr);
  CHECK(filter->GetOptions() != nullptr && filter->GetOptions() != options.GetPointer());
  CHECK(filter->GetOptions()->GetThreshold() == 0.1);
  return EXIT_SUCCESS;
}
