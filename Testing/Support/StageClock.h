// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Where a run's wall and CPU seconds go, stage by stage, read from the filter's progress events
// (each stage reports over its own part of [0, 1]). With the CPU seconds of all the process's
// threads, a stage on two threads shows apart what a serial part costs (CPU seconds below twice
// the wall's) and what the threads cost each other (more CPU seconds than on one thread).
#ifndef StageClock_h
#define StageClock_h

#include "vtkCommand.h"

#include <array>
#include <chrono>
#include <ctime>

namespace lsi
{
namespace cases
{

constexpr std::array<const char*, 5> ProgressStageNames = { "neighbours", "initialisation",
  "evolution", "isopoints", "outputs" };

/// The stage a progress value falls in: the ranges of Filters/vtkLevelSetIsosurfaceInternals.h
/// ("neighbours" holds the input's checks and the SPH field's sums too, "outputs" the surface,
/// the splats and the particle outputs).
inline std::size_t ProgressStage(double progress)
{
  return progress < 0.35 ? 0 : progress < 0.45 ? 1 : progress < 0.8 ? 2 : progress < 0.92 ? 3 : 4;
}

/// CPU seconds of all the process's threads.
inline double ProcessCpuSeconds()
{
  timespec now;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

/// Observes a filter's StartEvent, ProgressEvent and EndEvent (all on the calling thread): the
/// time between two events counts to the stage of the first. Sums over every run it observes.
class StageClock : public vtkCommand
{
public:
  static StageClock* New() { return new StageClock; }
  void Observe(vtkObject* filter)
  {
    filter->AddObserver(vtkCommand::StartEvent, this);
    filter->AddObserver(vtkCommand::ProgressEvent, this);
    filter->AddObserver(vtkCommand::EndEvent, this);
  }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const auto now = std::chrono::steady_clock::now();
    const double cpu = ProcessCpuSeconds();
    if (this->Running)
    {
      this->Wall[this->Stage] += std::chrono::duration<double>(now - this->LastWall).count();
      this->Cpu[this->Stage] += cpu - this->LastCpu;
    }
    this->Running = event != vtkCommand::EndEvent;
    if (event == vtkCommand::StartEvent)
    {
      this->Stage = 0;
    }
    else if (event == vtkCommand::ProgressEvent && data)
    {
      this->Stage = ProgressStage(*static_cast<double*>(data));
    }
    this->LastWall = now;
    this->LastCpu = cpu;
  }
  std::array<double, ProgressStageNames.size()> Wall{}, Cpu{};

private:
  bool Running = false;
  std::size_t Stage = 0;
  std::chrono::steady_clock::time_point LastWall;
  double LastCpu = 0.0;
};

} // namespace cases
} // namespace lsi

#endif
