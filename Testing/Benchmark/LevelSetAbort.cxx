// How fast Abort stops the filter: on the paper's one-component case (2M samples by default),
// a fresh filter runs in a worker thread and the main thread sets AbortExecute after a chosen
// delay, as ParaView's Abort button does. Reports, for each delay, the progress the filter had
// reported (which stage it was in) and the seconds until Update() returned, and checks that the
// aborted run left empty outputs.
//   LevelSetAbort [--samples N] [--delays 0.3,1,2,...] [--check-latency SECONDS]
#include "BenchmarkSupport.h"
#include "SyntheticParticles.h"

#include "vtkCommand.h"

#include <atomic>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

namespace
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

const char* StageAt(double progress)
{
  // The filter's progress ranges (vtkLevelSetIsosurface::Execute).
  if (progress < 0.35) return "neighbours";
  if (progress < 0.45) return "initialisation";
  if (progress < 0.8) return "evolution";
  if (progress < 0.92) return "isopoints";
  return "output";
}
} // namespace

int main(int argc, char* argv[])
{
  std::size_t samples = 2000000;
  std::vector<double> delays = { 0.3, 1.0, 1.8, 2.6, 3.2, 3.6, 4.0, 4.4, 4.8 };
  double checkLatency = -1.0;
  for (int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--samples" && a + 1 < argc)
    {
      samples = std::strtoull(argv[++a], nullptr, 10);
    }
    else if (arg == "--delays" && a + 1 < argc)
    {
      delays.clear();
      std::stringstream list(argv[++a]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        delays.push_back(std::atof(item.c_str()));
      }
    }
    else if (arg == "--check-latency" && a + 1 < argc)
    {
      checkLatency = std::atof(argv[++a]);
    }
    else
    {
      std::cerr << "usage: LevelSetAbort [--samples N] [--delays 0.3,1,...] [--check-latency S]\n";
      return EXIT_FAILURE;
    }
  }
  const auto c = lsi::cases::MakeCase("one-component");
  vtkSmartPointer<vtkPolyData> particles = lsi::cases::MakeParticles(*c, c->Samples(samples, 1));

  // The full run, for reference.
  double fullSeconds = 0.0;
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    lsi::cases::SetCaseInputs(filter, *c);
    const auto start = std::chrono::steady_clock::now();
    filter->Update();
    fullSeconds = lsi::cases::SecondsSince(start);
  }
  std::cout << "one-component, " << samples << " samples, default parameters: a full run takes "
            << std::fixed << std::setprecision(3) << fullSeconds << " s\n\n";
  std::cout << "| abort after (s) | progress then | stage | returned after (s) | outputs empty |\n"
            << "|---|---|---|---|---|\n";
  double worst = 0.0;
  bool allEmpty = true;
  for (double delay : delays)
  {
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(particles);
    lsi::cases::SetCaseInputs(filter, *c);
    vtkNew<ProgressRecorder> progress;
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
    std::atomic<bool> done{ false };
    std::thread worker([&]() {
      filter->Update();
      done = true;
    });
    const auto start = std::chrono::steady_clock::now();
    while (!done && lsi::cases::SecondsSince(start) < delay)
    {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    if (done)
    {
      worker.join();
      std::cout << "| " << delay << " | finished before the abort | | | |\n";
      continue;
    }
    const double progressAtAbort = progress->Progress;
    const auto abortTime = std::chrono::steady_clock::now();
    filter->SetAbortExecute(1);
    worker.join();
    const double latency = lsi::cases::SecondsSince(abortTime);
    const bool empty = filter->GetOutput(0)->GetNumberOfPoints() == 0;
    // The filter checks for abort after reporting progress 1; output after an abort means the
    // abort came too late, after that last check, and the run completed.
    const bool completed = progress->Progress >= 1.0;
    allEmpty = allEmpty && (empty || completed);
    worst = std::max(worst, latency);
    std::cout << "| " << delay << " | " << progressAtAbort << " | " << StageAt(progressAtAbort)
              << " | " << latency << " | "
              << (empty ? "yes" : completed ? "no: finished before the abort" : "no") << " |\n";
  }
  std::cout << "\nlongest time from Abort to return: " << worst << " s\n";
  if (!allEmpty)
  {
    std::cerr << "FAILED: an aborted run left output\n";
    return EXIT_FAILURE;
  }
  if (checkLatency > 0.0 && worst > checkLatency)
  {
    std::cerr << "FAILED: Abort took " << worst << " s (limit " << checkLatency << " s)\n";
    return EXIT_FAILURE;
  }
  return EXIT_SUCCESS;
}
