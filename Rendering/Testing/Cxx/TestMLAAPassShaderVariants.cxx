// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Compile-time shader variants: the options that change a shader's work (edge detection mode,
// Lab included, local contrast adaptation, diagonal detection, dominant-direction blending, the
// search length, alpha handling, debug output, reconstruction and its write-back in place) select #defines prepended to the one .glsl source of each pass,
// and the program is rebuilt when they change, as SMAA does with its presets; they are not
// run-time uniforms. One pass object is rendered with a sequence of option changes:
// - after each change its output equals the CPU filter with the same options (so the variant
//   was rebuilt, not left stale), within 2/255 on all but 0.01 % of the pixels;
// - the program the last quad used (the neighbourhood blending) was built with the expected
//   #defines and declares no uniform for them; and switching back to earlier options reuses the
//   program already built (VTK's shader cache keeps it).
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLShaderCache.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

using namespace vtkMLAATest;

namespace
{
bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}
}

int TestMLAAPassShaderVariants(int, char*[])
{
  SceneWindow scene("glyphs", 400, 300);
  vtkNew<vtkMLAAOptions> options;
  auto pass = UseMLAA(scene.Renderer, options);
  pass->AntialiasOverlaysOn(); // nothing is drawn after the blending quad
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(scene.Window);
  MLAA_CHECK(window != nullptr);
  if (!window)
  {
    return Result();
  }
  vtkNew<MessageObserver> messages;
  messages->Watch(pass);

  struct Step
  {
    const char* What;
    std::function<void()> Apply;
    std::vector<std::string> Defined;    // lines the blending program must have
    std::vector<std::string> NotDefined; // lines it must not have
  };
  const std::vector<Step> steps = {
    { "defaults", [] {}, { "#define MLAA_DEBUG_OUTPUT 0", "#define MLAA_DOMINANT_DIRECTION" },
      { "#define MLAA_STRAIGHT_ALPHA" } },
    { "chapter's blending", [&] { options->DominantDirectionBlendingOff(); },
      { "#define MLAA_DEBUG_OUTPUT 0" }, { "#define MLAA_DOMINANT_DIRECTION" } },
    { "colour edges, 16 steps, no diagonals, no local contrast",
      [&] {
        options->DominantDirectionBlendingOn();
        options->SetEdgeDetectionToColor();
        options->SetMaxSearchSteps(16);
        options->DiagonalDetectionOff();
        options->SetLocalContrastFactor(0.0);
      },
      { "#define MLAA_DOMINANT_DIRECTION" }, {} },
    { "depth edges", [&] {
        options->SetEdgeDetectionToDepth();
        options->SetThreshold(0.005);
        options->DiagonalDetectionOn();
        options->SetLocalContrastFactor(2.0);
        options->SetMaxSearchSteps(8);
      },
      {}, {} },
    { "Lab edges", [&] {
        options->SetEdgeDetectionToLab();
        options->SetThreshold(0.1);
      },
      {}, {} },
    { "Lab edges with reconstruction", [&] { options->ReconstructionOn(); }, {}, {} },
    { "luma edges with reconstruction", [&] { options->SetEdgeDetectionToLuma(); }, {}, {} },
    { "Lab edges again, reconstruction off", [&] {
        options->SetEdgeDetectionToLab();
        options->ReconstructionOff();
      },
      {}, {} },
    { "kept alpha, straight, with reconstruction", [&] {
        options->ReconstructionOn();
        options->SetEdgeDetectionToLuma();
        options->SetThreshold(0.1);
        pass->KeepAlphaOn();
      },
      { "#define MLAA_STRAIGHT_ALPHA" }, {} },
    { "edges debug output", [&] {
        pass->KeepAlphaOff();
        options->SetDebugOutputToEdges();
      },
      { "#define MLAA_DEBUG_OUTPUT 1" }, {} },
    { "weights debug output", [&] { options->SetDebugOutputToBlendingWeights(); },
      { "#define MLAA_DEBUG_OUTPUT 2" }, {} },
    { "defaults again", [&] {
        options->SetDebugOutputToNone();
        options->ReconstructionOff();
      },
      { "#define MLAA_DEBUG_OUTPUT 0", "#define MLAA_DOMINANT_DIRECTION" }, {} },
  };

  vtkShaderProgram* defaultsProgram = nullptr;
  for (const Step& step : steps)
  {
    step.Apply();
    auto gpu = vtkMLAAScenes::Capture(scene.Window, options->GetDebugOutput() != 0);
    // Depth edges and kept alpha are compared with the filter in TestMLAAPassDepthEdges and
    // TestMLAAPassAlpha (they need other inputs).
    const bool compare =
      options->GetEdgeDetection() != vtkMLAAOptions::DEPTH && !pass->GetKeepAlpha();
    const Difference parity =
      compare ? Compare(RunMLAA(scene.Plain, options), gpu, 2.0) : Difference();
    vtkShaderProgram* program = window->GetShaderCache()->GetLastShaderBound();
    const std::string fs =
      program && program->GetFragmentShader() ? program->GetFragmentShader()->GetSource() : "";
    std::cout << step.What << ": ";
    if (compare)
    {
      std::cout << parity.Pixels << " pixels off the CPU filter by more than 2/255" << std::endl;
    }
    else
    {
      std::cout << "rendered (compared with the filter elsewhere)" << std::endl;
    }
    Check(parity.Count >= 0 && parity.Pixels <= 12, step.What, __FILE__, __LINE__);
    Check(Contains(fs, "MLAA pass 3 of 3"), "the blending program was bound last", __FILE__,
      __LINE__);
    for (const std::string& line : step.Defined)
    {
      Check(Contains(fs, line + "\n"), (std::string(step.What) + ": " + line).c_str(), __FILE__,
        __LINE__);
    }
    for (const std::string& line : step.NotDefined)
    {
      Check(!Contains(fs, line + "\n"), (std::string(step.What) + ": no " + line).c_str(),
        __FILE__, __LINE__);
    }
    for (const char* uniform : { "debugOutput", "dominantDirection", "straightAlpha" })
    {
      Check(!Contains(fs, std::string("uniform int ") + uniform) &&
          !Contains(fs, std::string("uniform bool ") + uniform),
        "no run-time option uniform", __FILE__, __LINE__);
    }
    if (std::string(step.What) == "defaults")
    {
      defaultsProgram = program;
    }
    if (std::string(step.What) == "defaults again")
    {
      MLAA_CHECK(program == defaultsProgram);
    }
  }
  MLAA_CHECK(messages->Errors.empty());
  return Result();
}
