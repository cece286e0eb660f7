// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// How fast Abort stops the filter: on the paper's one-component case, a fresh filter runs in a
// worker thread and the main thread sets AbortExecute after a chosen delay, as ParaView's Abort
// button does. Shared by Testing/Cxx/TestAbortLatency.cxx (which asserts) and
// Benchmarks/LevelSetAbort.cxx (which reports).
#ifndef AbortLatency_h
#define AbortLatency_h

#include "CaseRuns.h"
#include "StageClock.h"
#include "SyntheticParticles.h"

#include "vtkCommand.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <iomanip>
#include <ostream>
#include <thread>
#include <vector>

namespace lsi
{
namespace cases
{

// Remembers the last progress the filter reported (from the worker thread).
class ProgressRecorder : public vtkCommand
{
public:
  static ProgressRecorder* New() { return new ProgressRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Progress = *static_cast<double*>(data);
  }
  std::atomic<double> Progress{ 0.0 };
};

inline const char* StageAt(double progress)
{
  return ProgressStageNames[ProgressStage(progress)];
}
struct AbortLatencies
{
  double LongestSeconds = 0.0; // from Abort to the return of Update()
  bool OutputsEmpty = true;    // every aborted run left empty outputs
};

/// For each delay, aborts a run on `samples` particles after that many seconds and writes a
/// Markdown row to `table`: the progress then (which stage), the seconds until Update()
/// returned, and whether the outputs were empty.
inline AbortLatencies MeasureAbortLatencies(
  std::size_t samples, const std::vector<double>& delays, std::ostream& table)
{
  const auto c = MakeCase("one-component");
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, c->Samples(samples, 1));

  // The full run, for reference.
  double fullSeconds = 0.0;
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    SetCaseInputs(filter, *c);
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    fullSeconds = SecondsSince(start);
  }
  table << "one-component, " << samples << " samples, default parameters: a full run takes "
        << std::fixed << std::setprecision(3) << fullSeconds << " s\n\n";
  table << "| abort after (s) | progress then | stage | returned after (s) | outputs empty |\n"
        << "|---|---|---|---|---|\n";
  AbortLatencies result;
  double& worst = result.LongestSeconds;
  bool& allEmpty = result.OutputsEmpty;
  for (double delay : delays)
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    SetCaseInputs(filter, *c);
    vtkNew<ProgressRecorder> progress;
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
    std::atomic<bool> done{ false };
    std::thread worker([&]() {
      filter->Update();
      done = true;
    });
    const auto start = std::chrono::steady_clock::now();
    while (!done && SecondsSince(start) < delay)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (done)
    {
      worker.join();
      table << "| " << delay << " | finished before the abort | | | |\n";
      continue;
    }
    const double progressAtAbort = progress->Progress;
    const auto abortTime = std::chrono::steady_clock::now();
    filter->SetAbortExecute(1);
    worker.join();
    const double latency = SecondsSince(abortTime);
    const bool empty = filter->GetOutput(0)->GetNumberOfPoints() == 0;
    // The filter checks for abort after reporting progress 1; output after an abort means the
    // abort came too late, after that last check, and the run completed.
    const bool completed = progress->Progress >= 1.0;
    allEmpty = allEmpty && (empty || completed);
    worst = std::max(worst, latency);
    table << "| " << delay << " | " << progressAtAbort << " | " << StageAt(progressAtAbort) << " | "
          << latency << " | "
          << (empty          ? "yes"
                 : completed ? "no: finished before the abort"
                             : "no")
          << " |\n";
  }
  return result;
}

} // namespace cases
} // namespace lsi

#endif
