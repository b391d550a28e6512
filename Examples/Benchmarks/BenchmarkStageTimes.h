// SPDX-FileCopyrightText: Copyright (c) the vtkMLAA developers
// SPDX-License-Identifier: BSD-3-Clause
// Stage timings for the benchmarks: the passes time each of their stages as an event of the
// window's render timings (vtkRenderTimerLog; TimedStage in
// Rendering/vtkOpenGLAntialiasingPassInternals.h), waiting for the GL work at every start and end
// of a stage while the timings are on. VTK's own vtkRenderTimerLog (vtkOpenGLRenderTimerLog) reads
// GL timestamp queries, which time a GPU's work; llvmpipe answers them when it queues them, not
// when its rasteriser runs, so there its stages read near zero. WallClockRenderTimerLog times the
// same events with the steady clock instead (which the waits make exact on any implementation);
// UseWallClockRenderTimings() makes new windows use it.
#ifndef BenchmarkStageTimes_h
#define BenchmarkStageTimes_h

#include "vtkObjectFactory.h"
#include "vtkRenderTimerLog.h"
#include "vtkVersionMacros.h"

#include <chrono>
#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mlaaBenchmark
{

class WallClockRenderTimerLog : public vtkRenderTimerLog
{
public:
  static WallClockRenderTimerLog* New()
  {
    auto* log = new WallClockRenderTimerLog;
    log->InitializeObjectBase();
    return log;
  }
  vtkTypeMacro(WallClockRenderTimerLog, vtkRenderTimerLog);

  bool IsSupported() override { return true; }

  void MarkFrame() override
  {
    if (!this->LoggingEnabled)
    {
      return;
    }
    const vtkTypeUInt64 now = Now();
    while (!this->Open.empty()) // events left open end with the frame
    {
      this->Deepest().EndTime = now;
      this->Open.pop_back();
    }
    if (!this->Current.Events.empty())
    {
      this->Ready.push_back(std::move(this->Current));
    }
    this->Current = Frame();
  }

  void MarkStartEvent(const std::string& name) override
  {
    if (!this->LoggingEnabled)
    {
      return;
    }
    std::vector<Event>& siblings = this->Open.empty() ? this->Current.Events : this->Deepest().Events;
    Event event;
    event.Name = name;
    event.StartTime = Now();
    event.EndTime = event.StartTime;
    siblings.push_back(std::move(event));
    this->Open.push_back(siblings.size() - 1);
  }

  void MarkEndEvent() override
  {
    if (!this->LoggingEnabled || this->Open.empty())
    {
      return;
    }
    this->Deepest().EndTime = Now();
    this->Open.pop_back();
  }

  bool FrameReady() override { return this->LoggingEnabled && !this->Ready.empty(); }

  Frame PopFirstReadyFrame() override
  {
    if (this->Ready.empty())
    {
      return Frame();
    }
    Frame frame = std::move(this->Ready.front());
    this->Ready.pop_front();
    return frame;
  }

private:
  static vtkTypeUInt64 Now()
  {
    return static_cast<vtkTypeUInt64>(std::chrono::duration_cast<std::chrono::nanoseconds>(
      std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
  }
  // The innermost open event (Open holds the index of each open event among its siblings).
  Event& Deepest()
  {
    Event* event = &this->Current.Events[this->Open.front()];
    for (size_t level = 1; level < this->Open.size(); ++level)
    {
      event = &event->Events[this->Open[level]];
    }
    return *event;
  }

  Frame Current;
  std::vector<size_t> Open;
  std::deque<Frame> Ready;
};

class WallClockTimerLogFactory : public vtkObjectFactory
{
public:
  static WallClockTimerLogFactory* New()
  {
    auto* factory = new WallClockTimerLogFactory;
    factory->InitializeObjectBase();
    return factory;
  }
  vtkTypeMacro(WallClockTimerLogFactory, vtkObjectFactory);
  const char* GetVTKSourceVersion() override { return VTK_SOURCE_VERSION; }
  const char* GetDescription() override { return "mlaa benchmarks: wall-clock render timings"; }

protected:
  WallClockTimerLogFactory()
  {
    this->RegisterOverride("vtkRenderTimerLog", "WallClockRenderTimerLog",
      "render timings by the steady clock", 1,
      []() -> vtkObject* { return WallClockRenderTimerLog::New(); });
  }
};

// Windows created from now on time their render events with the steady clock.
inline void UseWallClockRenderTimings()
{
  vtkObjectFactory::SetAllEnableFlags(0, "vtkRenderTimerLog");
  auto* factory = WallClockTimerLogFactory::New();
  vtkObjectFactory::RegisterFactory(factory);
  factory->Delete();
}

// The events under `event` inside an event named `pass` (the class name a pass times itself as),
// each with its path below that event ("antialiasing/edges"), added to `totals` (milliseconds,
// and how many).
inline void AddStageTimes(const vtkRenderTimerLog::Event& event, const std::string& pass,
  const std::string& path, bool inside, std::map<std::string, std::pair<double, int>>& totals)
{
  const bool isPass = !inside && event.Name == pass;
  if (inside)
  {
    auto& total = totals[path + event.Name];
    total.first += event.ElapsedTimeMilliseconds();
    total.second += 1;
  }
  const std::string childPath = inside ? path + event.Name + "/" : std::string();
  for (const auto& child : event.Events)
  {
    AddStageTimes(child, pass, childPath, inside || isPass, totals);
  }
}

} // namespace mlaaBenchmark

#endif
