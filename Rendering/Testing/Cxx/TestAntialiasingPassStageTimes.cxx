// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkOpenGLAntialiasingPass in VTK's render timings (vtkRenderTimerLog), for every method of
// PassMethods(): with the window's timings on, a render logs an event named after the pass's
// class, holding "delegate" and "antialiasing" events, and the latter each stage of the method
// (MLAA: change mask, edges, local contrast, blending weights, neighbourhood blending; DLAA: edge
// masks, filter) and, with Temporal on, the temporal stages; the image is the same as with the
// timings off, and with them off nothing is logged.
#include "vtkAntialiasingRenderTestUtilities.h"

#include "vtkRenderTimerLog.h"

#include <set>
#include <string>
#include <vector>

using namespace vtkMLAATest;

namespace
{
// The paths of the events below the pass's own event ("antialiasing/edges"), over the ready
// frames of the log.
void CollectStages(const vtkRenderTimerLog::Event& event, const std::string& pass,
  const std::string& path, bool inside, std::set<std::string>& stages)
{
  if (inside)
  {
    stages.insert(path + event.Name);
  }
  const bool isPass = !inside && event.Name == pass;
  for (const auto& child : event.Events)
  {
    CollectStages(child, pass, inside ? path + event.Name + "/" : std::string(),
      inside || isPass, stages);
  }
}

std::set<std::string> RenderTimed(vtkRenderWindow* window, const std::string& pass)
{
  vtkRenderTimerLog* log = window->GetRenderTimer();
  std::set<std::string> stages;
  log->LoggingEnabledOn();
  window->Render();
  // The timed frame is ready once a later one has begun and its queries have answered.
  for (int i = 0; i < 10 && stages.empty(); ++i)
  {
    window->Render();
    window->WaitForCompletion();
    while (log->FrameReady())
    {
      for (const auto& event : log->PopFirstReadyFrame().Events)
      {
        CollectStages(event, pass, std::string(), false, stages);
      }
    }
  }
  log->LoggingEnabledOff();
  while (log->FrameReady())
  {
    log->PopFirstReadyFrame();
  }
  return stages;
}

void CheckStages(const std::set<std::string>& stages, const std::set<std::string>& expected)
{
  for (const auto& stage : stages)
  {
    std::cout << "  " << stage << std::endl;
  }
  for (const auto& stage : expected)
  {
    MLAA_CHECK(stages.count(stage) == 1);
    if (!stages.count(stage))
    {
      std::cerr << "missing stage: " << stage << std::endl;
    }
  }
}
}

int TestAntialiasingPassStageTimes(int, char*[])
{
  ForEachPassMethod([](const PassMethod& method, MessageObserver* messages) {
    auto window = vtkMLAAScenes::NewOffscreenWindow(200, 150);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkMLAAScenes::Build("silhouettes", renderer);
    vtkOpenGLAntialiasingPass* pass = method.Use(renderer);
    messages->Watch(pass);
    vtkRenderTimerLog* log = window->GetRenderTimer();
    if (!log->IsSupported())
    {
      std::cout << "render timings not supported here: not checked" << std::endl;
      StopPass(renderer, window);
      return;
    }

    // Timings off: nothing logged.
    auto plain = vtkMLAAScenes::Capture(window);
    window->Render();
    window->Render();
    MLAA_CHECK(!log->FrameReady());

    const bool mlaa = std::string(pass->GetClassName()) == "vtkOpenGLMLAAPass";
    std::set<std::string> expected = { "delegate", "antialiasing" };
    const std::vector<std::string> methodStages = mlaa
      ? std::vector<std::string>{ "change mask", "edges", "local contrast", "blending weights",
          "neighbourhood blending" }
      : std::vector<std::string>{ "edge masks", "mask tiles", "corner candidates", "corners",
          "filter" };
    for (const std::string& stage : methodStages)
    {
      expected.insert("antialiasing/" + stage);
    }
    CheckStages(RenderTimed(window, pass->GetClassName()), expected);
    // The same image with the timings on.
    log->LoggingEnabledOn();
    auto timed = vtkMLAAScenes::Capture(window);
    log->LoggingEnabledOff();
    MLAA_CHECK(Compare(plain, timed, 0.0).Count == 0);

    // Temporal, the camera moving: the method's stages, then the history's.
    pass->TemporalOn();
    window->Render();
    renderer->GetActiveCamera()->Azimuth(1.0);
    expected.insert({ "antialiasing/temporal", "antialiasing/temporal/history copy and mask",
      "antialiasing/temporal/blend",
      "antialiasing/temporal output" });
    CheckStages(RenderTimed(window, pass->GetClassName()), expected);
    StopPass(renderer, window);
  });
  return Result();
}
