// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The interactive benchmark (issue 16): what a user waits for, on the paper's one-component
// case, this filter against the grid route (SPH interpolation onto a grid, Flying Edges,
// connectivity), side by side in one process on the same particles:
//   - the first run of each, per stage, and its mean distance to the exact surface;
//   - re-runs after an isovalue change (moving 2% and 20% of the inside samples out), a seed
//     move (by half its radius, inside the same component) and a CurvatureWeight change; the
//     grid route re-contours its kept grid (isovalue) or only re-connects (seed); each re-run,
//     of either route, the fastest of 3 from the same state;
//   - the same isovalue changes with QuickIsoValueChanges on, and one of 10% (whether the
//     surface slid; its points, their mean distance to the exact new level and the largest gap
//     from that level's points to them, the Enclosed table's volume and area against the exact
//     level's, and the full method's);
//   - a slider dragged back and forth: 24 quick changes in turn to the small change's isovalue
//     and back, their mean and largest seconds and how many slid, against the grid route's
//     re-contour of the same changes;
//   - output-only changes (to splats, a new SplatScale) against the method's run;
//   - the whole filter with 1 and with 2 threads, with the kernel's seconds and the page faults of
//     each (ProcessUsage.h: on a virtual machine here 11-25 us of kernel time per fault), and
//     what two threads gave the machine's scattered reads just before and just after
//     (ScatteredReads.h);
//   - scaling: a first run at N and at 10 N particles, each in a child process of its own, with
//     its peak resident memory per particle (the particles themselves included), and the
//     profile, per stage, of that first run and of re-runs after the small isovalue change (the
//     quick one, then the full method's).
// Every profile names the filter's stages (input, neighbours, initialisation, evolution,
// isopoints, outputs, particle_outputs) and what the run's time leaves (unattributed).
// Prints a table and writes everything as JSON (--json FILE). Asserts nothing: the targets are
// printed beside the measurements.
//
//   LevelSetInteractive [--samples N] [--scaling-samples M] [--threads T] [--json FILE]
//   LevelSetInteractive --first-run-only N   (the child: prints its measurements on one line)
//   LevelSetInteractive --quick-only CHANGES (quick 10% changes back and forth alone: a profile)
#include "CaseRuns.h"
#include "ExactEnclosed.h"
#include "GridRoute.h"
#include "PeakMemory.h"
#include "ProcessUsage.h"
#include "ScatteredReads.h"
#include "StageClock.h"
#include "SurfaceMetrics.h"
#include "SyntheticCases.h"
#include "SyntheticParticles.h"
#include "vtkLevelSetIsosurface.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace lsi::cases;

// Re-runs take a few hundredths of a second (the grid route's) to a few tenths: each, of either
// route, is timed this many times from the same state and the fastest counts (one timing moved
// by half between runs here).
constexpr int ReRunRepeats = 3;
// First runs on 1 and on 2 threads, the fastest of this many each (3 until 2026-11-26: on a day
// when the same process ran up to 20% apart from run to run, the ratio of the fastest of 3 moved
// by 0.2 between processes).
constexpr int ThreadRepeats = 5;
// Quick isovalue changes in a slider drag, back and forth between two isovalues.
constexpr int SliderChanges = 24;

struct Options
{
  std::size_t Samples = 2000000;
  std::size_t ScalingSamples = 20000000; // 0: no scaling runs
  int Threads = 2;
  std::string Json;
  std::size_t FirstRunOnly = 0; // child mode
  int ThreadsOnly = 0;          // only the 1 against 2 threads comparison, this many runs each
  int QuickOnly = 0;            // only quick 10% changes back and forth, this many
};

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : "0"; };
    if (a == "--samples")
      o.Samples = std::strtoull(next(), nullptr, 10);
    else if (a == "--scaling-samples")
      o.ScalingSamples = std::strtoull(next(), nullptr, 10);
    else if (a == "--threads")
      o.Threads = std::atoi(next());
    else if (a == "--json")
      o.Json = next();
    else if (a == "--first-run-only")
      o.FirstRunOnly = std::strtoull(next(), nullptr, 10);
    else if (a == "--threads-only")
      o.ThreadsOnly = std::atoi(next());
    else if (a == "--quick-only")
      o.QuickOnly = std::atoi(next());
    else
      return false;
  }
  return o.Samples > 0 && o.Threads > 0;
}

// Named numbers, printed in insertion order and written as one flat JSON object.
class Report
{
public:
  void Add(const std::string& key, double value) { this->Values.emplace_back(key, value); }
  void Print(std::ostream& out) const
  {
    for (const auto& kv : this->Values)
    {
      out << std::left << std::setw(52) << kv.first << " " << kv.second << "\n";
    }
  }
  void WriteJson(const std::string& file) const
  {
    std::ofstream out(file);
    out << std::setprecision(6) << "{\n";
    for (std::size_t k = 0; k < this->Values.size(); ++k)
    {
      out << "  \"" << this->Values[k].first << "\": " << this->Values[k].second
          << (k + 1 < this->Values.size() ? ",\n" : "\n");
    }
    out << "}\n";
  }

private:
  std::vector<std::pair<std::string, double>> Values;
};

void Configure(vtkLevelSetIsosurface* filter, const Case& c, int threads)
{
  SetCaseInputs(filter, c);
  filter->SetNumberOfThreads(threads);
  filter->SetOutputTypeToIsopoints(); // accuracy is measured on the isopoints
}

// The filter's own stage times of its last run, in the order StageNames lists them, and what
// the run's `total` seconds leave (the pipeline, the last run's bookkeeping).
const std::array<const char*, 8> StageNames = { "input", "neighbours", "initialisation",
  "evolution", "isopoints", "outputs", "particle_outputs", "unattributed" };
std::array<double, 8> Stages(vtkLevelSetIsosurface* filter, double total)
{
  std::array<double, 8> s = { filter->GetInputSeconds(), filter->GetNeighborSearchSeconds(),
    filter->GetInitializationSeconds(), filter->GetEvolutionSeconds(), filter->GetIsopointSeconds(),
    filter->GetOutputSeconds(), filter->GetParticleOutputSeconds(), 0.0 };
  s[7] = total;
  for (std::size_t k = 0; k + 1 < s.size(); ++k)
  {
    s[7] -= s[k];
  }
  return s;
}
void AddStages(Report& report, const std::string& prefix, const std::array<double, 8>& stages)
{
  for (std::size_t k = 0; k < stages.size(); ++k)
  {
    report.Add(prefix + StageNames[k] + "_s", stages[k]);
  }
}

double TimedUpdate(vtkLevelSetIsosurface* filter)
{
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  return SecondsSince(start);
}

// The isovalues above `isoValue` with `fractions` of the samples above it between them and it.
std::vector<double> IsoValuesAbove(
  vtkPolyData* particles, double isoValue, const std::vector<double>& fractions)
{
  vtkDataArray* f = particles->GetPointData()->GetScalars();
  std::vector<double> above;
  for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
  {
    if (f->GetTuple1(i) > isoValue)
    {
      above.push_back(f->GetTuple1(i));
    }
  }
  std::sort(above.begin(), above.end());
  std::vector<double> values;
  for (double fraction : fractions)
  {
    const std::size_t k = static_cast<std::size_t>(fraction * above.size());
    values.push_back(above.empty() ? isoValue : above[std::min(k, above.size() - 1)]);
  }
  return values;
}

// The mean distance of the points of `surface` to the exact level {f = isoValue} of `c`, to
// first order (|f - f_iso| / |grad f|).
double MeanLevelDistance(const Case& c, vtkPolyData* surface, double isoValue)
{
  const vtkIdType count = surface->GetNumberOfPoints();
  double sum = 0.0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    Eigen::Vector3d p;
    surface->GetPoint(i, p.data());
    sum += std::abs(c.Value(p) - isoValue) / c.Gradient(p).norm();
  }
  return count ? sum / static_cast<double>(count) : 0.0;
}

// What a child process measures at one size.
struct ChildRun
{
  double Seconds = 0.0, Bytes = 0.0, Points = 0.0; // first run; peak memory after it
  std::array<double, 8> Stages{};                  // of the first run
  double ReRunSeconds = 0.0;                       // after the small isovalue change
  std::array<double, 8> ReRunStages{};
  double QuickSeconds = 0.0, Slid = 0.0; // the same change with QuickIsoValueChanges
  std::array<double, 8> QuickStages{};
};

// The first run on fresh filters on the same particles, 1 against 2 threads (the fastest of
// `repeats` runs each, taken in turn), with how busy each kept its cores (a 1-thread run below 1
// lost time to the machine), into `report`; returns the two times. Just before and just after,
// what two threads gave the machine's scattered reads (ScatteredReads.h): the ceiling, at that
// time, for the filter's memory-bound stages.
std::array<double, 2> AddThreadComparison(
  Report& report, vtkPolyData* particles, const OneComponentCase& c, int repeats)
{
  lsi::ScatteredReads reads;
  report.Add("machine.scattered_reads_two_thread_ratio_before", reads.TwoThreadRatio(repeats));
  std::array<double, 2> busy{};
  // Each stage's fastest time over the runs (each stage's own noise weighs less than in the
  // fastest run's stages).
  std::array<std::array<double, 8>, 2> stages{};
  stages[0].fill(HUGE_VAL);
  stages[1].fill(HUGE_VAL);
  // And each stage's wall and CPU seconds summed over the runs, from the progress events.
  vtkSmartPointer<StageClock> clock;
  std::array<vtkSmartPointer<StageClock>, 2> clocks = { vtkSmartPointer<StageClock>::New(),
    vtkSmartPointer<StageClock>::New() };
  // And what the kernel did for each run (system seconds, page faults), summed per thread count.
  lsi::ProcessUsage before;
  std::array<lsi::ProcessUsage, 2> kernel{};
  const std::array<double, 2> seconds = SecondsWithOneAndTwoThreads(
    particles,
    [&](vtkLevelSetIsosurface* timed) {
      SetCaseInputs(timed, c);
      clock = vtkSmartPointer<StageClock>::New();
      clock->Observe(timed);
      before = lsi::ProcessUsage::Now();
    },
    repeats, &busy,
    [&](int threads, vtkLevelSetIsosurface* timed, double wall) {
      const lsi::ProcessUsage used = lsi::ProcessUsage::Now() - before;
      kernel[threads - 1].SystemSeconds += used.SystemSeconds;
      kernel[threads - 1].MinorFaults += used.MinorFaults;
      const std::array<double, 8> run = Stages(timed, wall);
      for (std::size_t k = 0; k < run.size(); ++k)
      {
        stages[threads - 1][k] = std::min(stages[threads - 1][k], run[k]);
      }
      for (std::size_t k = 0; k < ProgressStageNames.size(); ++k)
      {
        clocks[threads - 1]->Wall[k] += clock->Wall[k];
        clocks[threads - 1]->Cpu[k] += clock->Cpu[k];
      }
    });
  report.Add("machine.scattered_reads_two_thread_ratio_after", reads.TwoThreadRatio(repeats));
  report.Add("level_set.one_thread_s", seconds[0]);
  report.Add("level_set.two_threads_s", seconds[1]);
  report.Add("level_set.one_thread_busy_fraction", busy[0]);
  report.Add("level_set.two_threads_busy_fraction", busy[1]);
  // Per run, over all the runs: the kernel's seconds (all threads) and the page faults.
  for (int t = 0; t < 2; ++t)
  {
    const std::string name = t == 0 ? "level_set.one_thread" : "level_set.two_threads";
    report.Add(name + "_system_s_per_run", kernel[t].SystemSeconds / repeats);
    report.Add(name + "_page_faults_per_run", kernel[t].MinorFaults / repeats);
  }
  // Each stage's own ratio: where the serial parts are (the lists and stencils that one stage
  // computes ahead on a spare thread, another computes on one thread: read stages together).
  for (std::size_t k = 0; k < StageNames.size(); ++k)
  {
    report.Add(std::string("level_set.two_threads_speedup.") + StageNames[k],
      stages[1][k] > 0.0 ? stages[0][k] / stages[1][k] : 0.0);
  }
  AddStages(report, "level_set.one_thread.", stages[0]);
  AddStages(report, "level_set.two_threads.", stages[1]);
  // By progress ranges, over all the runs: on two threads, how busy each stage kept the cores
  // (below 1: serial parts) and its CPU seconds against one thread's (above 1: the threads slow
  // each other, or work that only two threads do).
  for (std::size_t k = 0; k < ProgressStageNames.size(); ++k)
  {
    const std::string name = ProgressStageNames[k];
    report.Add("level_set.two_threads_busy_fraction." + name,
      clocks[1]->Wall[k] > 0.0 ? clocks[1]->Cpu[k] / (2.0 * clocks[1]->Wall[k]) : 0.0);
    report.Add("level_set.two_threads_cpu_ratio." + name,
      clocks[0]->Cpu[k] > 0.0 ? clocks[1]->Cpu[k] / clocks[0]->Cpu[k] : 0.0);
  }
  return seconds;
}

// The thread comparison alone (--threads-only REPEATS): for comparing builds side by side.
int ThreadsOnly(std::size_t samples, int repeats)
{
  OneComponentCase c;
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(c, c.Samples(samples, 1));
  Report report;
  report.Add("samples", static_cast<double>(samples));
  const std::array<double, 2> seconds = AddThreadComparison(report, particles, c, repeats);
  report.Add("target.two_thread_speedup (>= 1.85)", seconds[0] / seconds[1]);
  report.Print(std::cout);
  return EXIT_SUCCESS;
}

// Quick 10% isovalue changes alone (--quick-only CHANGES): a first run with QuickIsoValueChanges
// on, then CHANGES quick changes in turn to the isovalue that moves 10% of the inside samples out
// and back (each one slides as far), their seconds per stage: for profiling the slide and for
// comparing builds side by side.
int QuickOnly(std::size_t samples, int threads, int changes)
{
  OneComponentCase c;
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(c, c.Samples(samples, 1));
  const double medium = IsoValuesAbove(particles, c.IsoValue, { 0.1 })[0];
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  Configure(filter, c, threads);
  filter->QuickIsoValueChangesOn();
  Report report;
  report.Add("level_set.first_run_s", TimedUpdate(filter));
  std::array<double, 8> sums{};
  double total = 0.0, fastest = HUGE_VAL, slid = 0.0;
  for (int k = 1; k <= changes; ++k)
  {
    filter->SetIsoValue(k % 2 ? medium : c.IsoValue);
    const double seconds = TimedUpdate(filter);
    const std::array<double, 8> stages = Stages(filter, seconds);
    for (std::size_t s = 0; s < sums.size(); ++s)
    {
      sums[s] += stages[s] / changes;
    }
    total += seconds / changes;
    fastest = std::min(fastest, seconds);
    slid += filter->GetSlidLastSurface() ? 1.0 : 0.0;
  }
  report.Add("level_set.quick_changes", changes);
  report.Add("level_set.quick_changes_slid", slid);
  report.Add("level_set.quick_change_mean_s", total);
  report.Add("level_set.quick_change_fastest_s", fastest);
  AddStages(report, "level_set.quick_change_mean.", sums);
  report.Print(std::cout);
  return slid == changes ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Child mode: a first run at `samples` (with QuickIsoValueChanges on, so that it keeps what a
// slide needs), the particle arrays freed of everything else, its peak memory, then the small
// isovalue change, slid, and the method's re-run at that isovalue; prints them on one line.
int FirstRunOnly(std::size_t samples, int threads)
{
  OneComponentCase c;
  vtkSmartPointer<vtkPolyData> particles;
  {
    const std::vector<Eigen::Vector3d> positions = c.Samples(samples, 1);
    particles = MakeParticles(c, positions);
  }
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  Configure(filter, c, threads);
  filter->QuickIsoValueChangesOn();
  const double seconds = TimedUpdate(filter);
  const double bytes = static_cast<double>(lsi::PeakMemoryBytes());
  const vtkIdType points = filter->GetOutput(0)->GetNumberOfPoints();
  const std::array<double, 8> stages = Stages(filter, seconds);
  filter->SetIsoValue(IsoValuesAbove(particles, c.IsoValue, { 0.02 })[0]);
  const double quick = TimedUpdate(filter);
  const bool slid = filter->GetSlidLastSurface();
  const std::array<double, 8> quickStages = Stages(filter, quick);
  filter->QuickIsoValueChangesOff(); // the method at the new isovalue (neighbours kept)
  const double reRun = TimedUpdate(filter);
  const std::array<double, 8> reRunStages = Stages(filter, reRun);
  std::cout << seconds << " " << bytes << " " << points;
  for (double v : stages)
  {
    std::cout << " " << v;
  }
  std::cout << " " << reRun;
  for (double v : reRunStages)
  {
    std::cout << " " << v;
  }
  std::cout << " " << quick << " " << (slid ? 1 : 0);
  for (double v : quickStages)
  {
    std::cout << " " << v;
  }
  std::cout << "\n";
  return points > 0 && filter->GetOutput(0)->GetNumberOfPoints() > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

// Runs this program in child mode; false if it failed.
bool RunChild(const char* self, std::size_t samples, int threads, ChildRun& run)
{
  std::ostringstream command;
  command << "'" << self << "' --first-run-only " << samples << " --threads " << threads;
  FILE* pipe = popen(command.str().c_str(), "r");
  if (!pipe)
  {
    return false;
  }
  bool read = std::fscanf(pipe, "%lf %lf %lf", &run.Seconds, &run.Bytes, &run.Points) == 3;
  for (double& v : run.Stages)
  {
    read = read && std::fscanf(pipe, "%lf", &v) == 1;
  }
  read = read && std::fscanf(pipe, "%lf", &run.ReRunSeconds) == 1;
  for (double& v : run.ReRunStages)
  {
    read = read && std::fscanf(pipe, "%lf", &v) == 1;
  }
  read = read && std::fscanf(pipe, "%lf %lf", &run.QuickSeconds, &run.Slid) == 2;
  for (double& v : run.QuickStages)
  {
    read = read && std::fscanf(pipe, "%lf", &v) == 1;
  }
  return pclose(pipe) == 0 && read;
}

} // namespace

int main(int argc, char* argv[])
{
  Options o;
  if (!Parse(argc, argv, o))
  {
    std::cerr << "usage: LevelSetInteractive [--samples N] [--scaling-samples M] [--threads T] "
                 "[--json FILE] [--threads-only REPEATS] [--quick-only CHANGES]\n";
    return EXIT_FAILURE;
  }
  if (o.FirstRunOnly)
  {
    return FirstRunOnly(o.FirstRunOnly, o.Threads);
  }
  if (o.ThreadsOnly > 0)
  {
    return ThreadsOnly(o.Samples, o.ThreadsOnly);
  }
  if (o.QuickOnly > 0)
  {
    return QuickOnly(o.Samples, o.Threads, o.QuickOnly);
  }
  Report report;
  OneComponentCase c;
  const std::vector<Eigen::Vector3d> samples = c.Samples(o.Samples, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(c, samples);
  const double surfaceSpacing = c.SurfaceSpacing(o.Samples);
  // Isovalue changes that move 2% and 20% of the samples inside the surface across it (a
  // small and a large step): unit-free, and meaningful whatever the tails of the values.
  // (And one between, for the quick changes: whether it slides.)
  const std::vector<double> isoValues = IsoValuesAbove(particles, c.IsoValue, { 0.02, 0.2, 0.1 });
  report.Add("samples", static_cast<double>(o.Samples));
  report.Add("threads", o.Threads);

  // The grid route: first run, then an isovalue change and a seed move.
  const std::vector<Eigen::Vector3d> seeds = SeedCentres(c);
  std::vector<Eigen::Vector3d> movedSeeds = seeds;
  movedSeeds[0].x() += 0.5 * c.Seeds[0].Radius;
  lsi::GridRouteSession grid(particles, "f", MeanSpacingOverBounds(particles), o.Threads);
  const double gridInterpolation = grid.Interpolate();
  const double gridContour = grid.Contour(c.IsoValue);
  const double gridConnect = grid.Connect(seeds);
  std::vector<double> gridPoints, gridNormals;
  lsi::TriangleVertices(grid.GetMesh(), gridPoints, gridNormals);
  const SurfaceMetrics gridMetrics =
    MeasureGridSurface(c, gridPoints, gridNormals, samples, surfaceSpacing);
  const double gridFirst = gridInterpolation + gridContour + gridConnect;
  // Each re-run of either route, the fastest of ReRunRepeats, each from the first run's state.
  auto gridReContour = [&](double isoValue) {
    double fastest = HUGE_VAL;
    for (int r = 0; r < ReRunRepeats; ++r)
    {
      grid.Contour(c.IsoValue);
      grid.Connect(seeds);
      fastest = std::min(fastest, grid.Contour(isoValue) + grid.Connect(seeds));
    }
    return fastest;
  };
  const double gridIsoSmall = gridReContour(isoValues[0]);
  const double gridIsoLarge = gridReContour(isoValues[1]);
  const double gridIsoMedium = gridReContour(isoValues[2]);
  grid.Contour(c.IsoValue);
  double gridSeed = HUGE_VAL;
  for (int r = 0; r < ReRunRepeats; ++r)
  {
    grid.Connect(seeds);
    gridSeed = std::min(gridSeed, grid.Connect(movedSeeds));
  }
  report.Add("grid_route.first_run_s", gridFirst);
  report.Add("grid_route.interpolation_s", gridInterpolation);
  report.Add("grid_route.contour_s", gridContour);
  report.Add("grid_route.connectivity_s", gridConnect);
  report.Add("grid_route.grid_points", static_cast<double>(grid.GetGridPoints()));
  report.Add("grid_route.mean_distance_spacings", gridMetrics.MeanDistance);
  report.Add("grid_route.isovalue_change_small_s", gridIsoSmall);
  report.Add("grid_route.isovalue_change_large_s", gridIsoLarge);
  report.Add("grid_route.isovalue_change_medium_s", gridIsoMedium);
  report.Add("grid_route.seed_move_s", gridSeed);

  // This filter: first run, then the same changes, each from the first run's settings.
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  Configure(filter, c, o.Threads);
  double first = 0.0;
  const SurfaceMetrics metrics = RunAndMeasure(filter, c, samples, surfaceSpacing, first);
  report.Add("level_set.first_run_s", first);
  AddStages(report, "level_set.first_run.", Stages(filter, first));
  report.Add("level_set.mean_distance_spacings", metrics.MeanDistance);
  report.Add("level_set.isopoints", static_cast<double>(metrics.Isopoints));

  // A re-run from the first run's state (`prepare` restores it), the fastest of ReRunRepeats,
  // with that run's stages.
  auto fastestReRun = [&](const std::function<void()>& prepare, const std::function<void()>& change,
                        std::array<double, 8>& stages) {
    double fastest = HUGE_VAL;
    for (int r = 0; r < ReRunRepeats; ++r)
    {
      prepare();
      TimedUpdate(filter);
      change();
      const double seconds = TimedUpdate(filter);
      if (seconds < fastest)
      {
        fastest = seconds;
        stages = Stages(filter, seconds);
      }
    }
    return fastest;
  };
  auto atCaseIsoValue = [&]() { filter->SetIsoValue(c.IsoValue); };
  std::array<double, 8> isoSmallStages{}, isoLargeStages{}, seedStages{};
  const double isoSmall = fastestReRun(
    atCaseIsoValue, [&]() { filter->SetIsoValue(isoValues[0]); }, isoSmallStages);
  AddStages(report, "level_set.isovalue_change_small.", isoSmallStages);
  const double isoLarge = fastestReRun(
    atCaseIsoValue, [&]() { filter->SetIsoValue(isoValues[1]); }, isoLargeStages);
  filter->SetIsoValue(c.IsoValue);
  const double seed = fastestReRun([&]() { filter->SetSeedCenter(seeds[0].data()); },
    [&]() { filter->SetSeedCenter(movedSeeds[0].data()); }, seedStages);
  AddStages(report, "level_set.seed_move.", seedStages);
  filter->SetSeedCenter(seeds[0].data());
  TimedUpdate(filter);
  const double fullDistance = MeanLevelDistance(c, filter->GetOutput(0), c.IsoValue);

  // The same isovalue changes with QuickIsoValueChanges on (the last surface slid onto the new
  // level when the checks allow), each from a full run at the case's isovalue; the mean
  // distance of the slid points to the exact new level, and the full method's there.
  filter->SetQuickIsoValueChanges(true);
  std::array<double, 3> quick{};
  std::array<SurfaceMetrics, 3> quickMetrics, methodMetrics;
  // The output's isopoints against the exact surface at `isoValue`: their distance to it, and
  // how far its points (near samples, projected) are from an isopoint.
  auto measureAt = [&](double isoValue) {
    OneComponentCase atIsoValue = c;
    atIsoValue.IsoValue = isoValue;
    std::vector<double> points, normals;
    IsopointArrays(filter->GetOutput(0), points, normals);
    return MeasureSurface(atIsoValue, points, normals, samples, surfaceSpacing);
  };
  std::array<bool, 3> slid{};
  std::array<std::array<double, 8>, 3> quickStages{};
  // What each surface encloses (the Enclosed table's total row): the slid one's, the method's,
  // and the exact level's.
  auto enclosedOf = [&]() {
    vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
    Enclosed e;
    if (table && table->GetNumberOfRows() > 0)
    {
      e.Volume = table->GetValueByName(table->GetNumberOfRows() - 1, "Volume").ToDouble();
      e.Area = table->GetValueByName(table->GetNumberOfRows() - 1, "SurfaceArea").ToDouble();
    }
    return e;
  };
  std::array<Enclosed, 3> quickEnclosed, methodEnclosed, exactEnclosed;
  for (std::size_t k = 0; k < 3; ++k)
  {
    // Each from the full method at the case's isovalue (Modified: not a slide back), which keeps
    // what a slide needs.
    quick[k] = fastestReRun(
      [&]() {
        filter->SetIsoValue(c.IsoValue);
        filter->Modified();
      },
      [&]() { filter->SetIsoValue(isoValues[k]); }, quickStages[k]);
    slid[k] = filter->GetSlidLastSurface();
    quickMetrics[k] = measureAt(isoValues[k]);
    quickEnclosed[k] = enclosedOf();
    filter->SetQuickIsoValueChanges(false); // the full method at the new isovalue, to compare
    TimedUpdate(filter);
    methodMetrics[k] = measureAt(isoValues[k]);
    methodEnclosed[k] = enclosedOf();
    exactEnclosed[k] = ExactEnclosed(c, isoValues[k]);
    filter->SetQuickIsoValueChanges(true);
  }
  // A slider dragged back and forth: SliderChanges quick changes between the case's isovalue
  // and the small change's, from a full run; each one's seconds (mean and largest) and how many
  // slid, against the grid route's re-contour of the same changes (mean).
  filter->SetIsoValue(c.IsoValue);
  filter->Modified();
  TimedUpdate(filter);
  double sliderSum = 0.0, sliderLargest = 0.0, sliderSlid = 0.0, gridSliderSum = 0.0;
  for (int k = 1; k <= SliderChanges; ++k)
  {
    const double isoValue = k % 2 ? isoValues[0] : c.IsoValue;
    filter->SetIsoValue(isoValue);
    const double seconds = TimedUpdate(filter);
    sliderSum += seconds;
    sliderLargest = std::max(sliderLargest, seconds);
    sliderSlid += filter->GetSlidLastSurface() ? 1.0 : 0.0;
    gridSliderSum += grid.Contour(isoValue) + grid.Connect(seeds);
  }
  filter->SetQuickIsoValueChanges(false);
  filter->SetIsoValue(c.IsoValue);
  TimedUpdate(filter);

  filter->SetCurvatureWeight(2.0 * filter->GetCurvatureWeight() + 0.05);
  const double curvature = TimedUpdate(filter);

  // Output-only changes (port 0 remade from the last run's points): isopoints to splats, and a
  // new SplatScale; each against the method's run at the same settings (Modified: all again).
  std::array<double, 8> outputTypeStages{}, splatScaleStages{}, unused{};
  const double toSplats = fastestReRun([&]() { filter->SetOutputTypeToIsopoints(); },
    [&]() { filter->SetOutputTypeToSplats(); }, outputTypeStages);
  const vtkIdType remadeSplats = filter->GetOutput(0)->GetNumberOfCells();
  const double toSplatsMethod = fastestReRun([&]() { filter->SetOutputTypeToIsopoints(); },
    [&]() {
      filter->SetOutputTypeToSplats();
      filter->Modified();
    },
    unused);
  const vtkIdType methodSplats = filter->GetOutput(0)->GetNumberOfCells();
  const double scale = filter->GetSplatScale();
  const double splatScale = fastestReRun([&]() { filter->SetSplatScale(scale); },
    [&]() { filter->SetSplatScale(1.5 * scale); }, splatScaleStages);
  filter->SetSplatScale(scale);
  filter->SetOutputTypeToIsopoints();
  report.Add("level_set.isovalue_change_small_s", isoSmall);
  report.Add("level_set.isovalue_change_large_s", isoLarge);
  report.Add("level_set.seed_move_s", seed);
  report.Add("level_set.curvature_weight_change_s", curvature);
  report.Add("level_set.level_distance_spacings", fullDistance / surfaceSpacing);
  report.Add("level_set.slider_changes", SliderChanges);
  report.Add("level_set.slider_slid", sliderSlid);
  report.Add("level_set.slider_mean_s", sliderSum / SliderChanges);
  report.Add("level_set.slider_largest_s", sliderLargest);
  report.Add("grid_route.slider_mean_s", gridSliderSum / SliderChanges);
  report.Add("level_set.output_type_change_s", toSplats);
  AddStages(report, "level_set.output_type_change.", outputTypeStages);
  report.Add("level_set.output_type_change_method_s", toSplatsMethod);
  // The remade splats and the method's are the same surface: their cell counts agree.
  report.Add("level_set.output_type_change_splats", static_cast<double>(remadeSplats));
  report.Add("level_set.output_type_change_method_splats", static_cast<double>(methodSplats));
  report.Add("level_set.splat_scale_change_s", splatScale);
  AddStages(report, "level_set.splat_scale_change.", splatScaleStages);
  const char* sizes[3] = { "small", "large", "medium" };
  for (std::size_t k = 0; k < 3; ++k)
  {
    const std::string prefix = std::string("level_set.quick_isovalue_change_") + sizes[k];
    report.Add(prefix + "_s", quick[k]);
    report.Add(prefix + ".slid", slid[k] ? 1.0 : 0.0);
    AddStages(report, prefix + ".", quickStages[k]);
    report.Add(prefix + ".level_distance_spacings", quickMetrics[k].MeanDistance / surfaceSpacing);
    report.Add(
      prefix + ".method_level_distance_spacings", methodMetrics[k].MeanDistance / surfaceSpacing);
    report.Add(prefix + ".surface_distance_spacings",
      quickMetrics[k].MeanDistanceOverSurface / surfaceSpacing);
    report.Add(prefix + ".method_surface_distance_spacings",
      methodMetrics[k].MeanDistanceOverSurface / surfaceSpacing);
    report.Add(prefix + ".isopoints", static_cast<double>(quickMetrics[k].Isopoints));
    report.Add(prefix + ".method_isopoints", static_cast<double>(methodMetrics[k].Isopoints));
    report.Add(prefix + ".largest_gap_spacings", quickMetrics[k].MaxGapToIsopoint / surfaceSpacing);
    report.Add(
      prefix + ".method_largest_gap_spacings", methodMetrics[k].MaxGapToIsopoint / surfaceSpacing);
    // The Enclosed table's volume and surface area against the exact level's, relative.
    const Enclosed& exact = exactEnclosed[k];
    report.Add(prefix + ".volume_error", quickEnclosed[k].Volume / exact.Volume - 1.0);
    report.Add(prefix + ".method_volume_error", methodEnclosed[k].Volume / exact.Volume - 1.0);
    report.Add(prefix + ".area_error", quickEnclosed[k].Area / exact.Area - 1.0);
    report.Add(prefix + ".method_area_error", methodEnclosed[k].Area / exact.Area - 1.0);
  }

  // Threads.
  const std::array<double, 2> threads = AddThreadComparison(report, particles, c, ThreadRepeats);

  // Scaling, each size in a process of its own (peak memory is per process), with the profile
  // of its first run and of a re-run after the small isovalue change.
  ChildRun small, large;
  const bool scaled = o.ScalingSamples > 0 && RunChild(argv[0], o.Samples, o.Threads, small) &&
    RunChild(argv[0], o.ScalingSamples, o.Threads, large);
  if (scaled)
  {
    for (const auto& size : { std::make_pair("small", &small), std::make_pair("large", &large) })
    {
      const std::string prefix = std::string("scaling.") + size.first;
      const ChildRun& run = *size.second;
      const double samples =
        static_cast<double>(size.second == &small ? o.Samples : o.ScalingSamples);
      report.Add(prefix + "_samples", samples);
      report.Add(prefix + "_first_run_s", run.Seconds);
      report.Add(prefix + "_bytes_per_particle", run.Bytes / samples);
      AddStages(report, prefix + "_first_run.", run.Stages);
      report.Add(prefix + "_isovalue_change_small_s", run.ReRunSeconds);
      AddStages(report, prefix + "_isovalue_change_small.", run.ReRunStages);
      report.Add(prefix + "_quick_isovalue_change_small_s", run.QuickSeconds);
      report.Add(prefix + "_quick_isovalue_change_small.slid", run.Slid);
      AddStages(report, prefix + "_quick_isovalue_change_small.", run.QuickStages);
    }
  }
  const double smallSeconds = small.Seconds, largeSeconds = large.Seconds, largeBytes = large.Bytes;

  // The targets, as ratios.
  report.Add("target.first_run_speedup (>= 10)", gridFirst / first);
  report.Add("target.accuracy_ratio_grid_over_level_set (>= 1)",
    gridMetrics.MeanDistance / metrics.MeanDistance);
  report.Add("target.isovalue_change_small_over_grid (<= 5)", isoSmall / gridIsoSmall);
  report.Add("target.isovalue_change_large_over_grid (<= 5)", isoLarge / gridIsoLarge);
  report.Add("target.quick_isovalue_change_small_over_grid (<= 5)", quick[0] / gridIsoSmall);
  report.Add("target.quick_isovalue_change_medium_over_grid (<= 5)", quick[2] / gridIsoMedium);
  report.Add("target.quick_isovalue_change_large_over_grid (<= 5)", quick[1] / gridIsoLarge);
  report.Add("target.seed_move_over_grid (<= 5)", seed / gridSeed);
  report.Add("target.slider_mean_over_grid (<= 5)", sliderSum / gridSliderSum);
  report.Add("target.two_thread_speedup (>= 1.85)", threads[0] / threads[1]);
  if (scaled)
  {
    report.Add("target.large_over_small_time (<= 10.5)", largeSeconds / smallSeconds);
    report.Add("target.large_bytes_per_particle (<= 250)", largeBytes / o.ScalingSamples);
  }
  std::cout << std::setprecision(4);
  report.Print(std::cout);
  if (!o.Json.empty())
  {
    report.WriteJson(o.Json);
  }
  return metrics.Isopoints > 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
