// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Runs vtkLevelSetIsosurface on one analytic case and reports accuracy against the exact
// surface and time, per stage and per iteration: the benchmark quoted in the README and
// RESULTS.md (--samples 2000000). The tests with thresholds are Testing/Cxx/TestAccuracy.cxx.
#include "CaseRuns.h"
#include "SurfaceMetrics.h"
#include "SyntheticCases.h"
#include "SyntheticParticles.h"
#include "vtkLevelSetIsosurface.h"

#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkXMLPolyDataWriter.h"

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

namespace
{
using namespace lsi::cases;

struct Options
{
  std::string CaseName = "one-component";
  std::size_t Samples = 200000;
  std::uint64_t Seed = 1;
  bool PaperParameters = false;
  int Scheme = 0;
  int Initialization = 1; // flood
  int Threads = 0;
  int MaximumIterations = 500;
  bool Completion = true;
  bool CompareThreads = false;
  bool PrintTable = false;
  bool Periodic = false; // the case's box as a periodic box (its images, the periodic route)
  std::string WriteVtp;
  // Explicit overrides (negative: keep the filter's default or the paper's value).
  double Epsilon = -1, CurvatureEpsilon = -1, TimeStep = -1, CurvatureWeight = -1;
  int ReinitializationSteps = -1;
};

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> const char* { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--case")
      o.CaseName = next();
    else if (a == "--samples")
      o.Samples = std::strtoull(next(), nullptr, 10);
    else if (a == "--seed")
      o.Seed = std::strtoull(next(), nullptr, 10);
    else if (a == "--paper-parameters")
      o.PaperParameters = true;
    else if (a == "--scheme")
      o.Scheme = std::atoi(next());
    else if (a == "--initialization")
    {
      const std::string v = next();
      if (v != "flood" && v != "seed-spheres")
      {
        std::cerr << "--initialization takes flood or seed-spheres\n";
        return false;
      }
      o.Initialization = v == "flood" ? 1 : 0;
    }
    else if (a == "--threads")
      o.Threads = std::atoi(next());
    else if (a == "--max-iterations")
      o.MaximumIterations = std::atoi(next());
    else if (a == "--no-completion")
      o.Completion = false;
    else if (a == "--compare-threads")
      o.CompareThreads = true;
    else if (a == "--periodic")
      o.Periodic = true;
    else if (a == "--print-table")
      o.PrintTable = true;
    else if (a == "--write-vtp")
      o.WriteVtp = next();
    else if (a == "--epsilon")
      o.Epsilon = std::atof(next());
    else if (a == "--curvature-epsilon")
      o.CurvatureEpsilon = std::atof(next());
    else if (a == "--time-step")
      o.TimeStep = std::atof(next());
    else if (a == "--lambda")
      o.CurvatureWeight = std::atof(next());
    else if (a == "--reinitialization-steps")
      o.ReinitializationSteps = std::atoi(next());
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return false;
    }
  }
  return true;
}

void Configure(vtkLevelSetIsosurface* filter, const Case& c, const Options& o)
{
  SetCaseInputs(filter, c);
  filter->SetEvolutionScheme(o.Scheme);
  filter->SetInitialization(o.Initialization);
  filter->SetMaximumNumberOfIterations(o.MaximumIterations);
  filter->SetCompletion(o.Completion);
  filter->SetNumberOfThreads(o.Threads);
  if (o.PaperParameters)
  {
    SetPaperParameters(filter, c);
  }
  if (o.Epsilon >= 0)
    filter->SetEpsilon(o.Epsilon);
  if (o.CurvatureEpsilon >= 0)
    filter->SetCurvatureEpsilon(o.CurvatureEpsilon);
  if (o.TimeStep >= 0)
    filter->SetTimeStep(o.TimeStep);
  if (o.CurvatureWeight >= 0)
    filter->SetCurvatureWeight(o.CurvatureWeight);
  if (o.ReinitializationSteps >= 0)
    filter->SetReinitializationSteps(o.ReinitializationSteps);
}

} // namespace

int main(int argc, char* argv[])
{
  Options o;
  std::unique_ptr<Case> c;
  if (!Parse(argc, argv, o) || !(c = MakeCase(o.CaseName)))
  {
    std::cerr
      << "usage: LevelSetBenchmark [--case one-component|multi-component|adaptive-noisy|sphere] "
         "[--samples N] [--paper-parameters] [--scheme 0|1] [--threads T] [--periodic] ...\n";
    return EXIT_FAILURE;
  }
  const std::vector<Eigen::Vector3d> samples = c->Samples(o.Samples, o.Seed);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  if (o.Periodic) // "BoxSize" as the HDF5 reader passes it: the box [BoxMin, BoxMax)
  {
    vtkNew<vtkDoubleArray> size;
    size->SetName("BoxSize");
    size->SetNumberOfComponents(3);
    const Eigen::Vector3d extent = c->BoxMax - c->BoxMin;
    size->InsertNextTuple(extent.data());
    particles->GetFieldData()->AddArray(size);
  }
  const double spacing = c->SurfaceSpacing(o.Samples);

  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  Configure(filter, *c, o);
  double total = 0.0;
  const SurfaceMetrics m = RunAndMeasure(filter, *c, samples, spacing, total);
  vtkPolyData* isopoints = filter->GetOutput(0);
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  if (!isopoints || isopoints->GetNumberOfPoints() == 0 || !table)
  {
    std::cerr << "the filter produced no isopoints\n";
    return EXIT_FAILURE;
  }

  const int iterations = filter->GetNumberOfIterationsPerformed();
  std::cout << std::setprecision(4);
  std::cout << "case: " << c->Name << "\nsamples: " << o.Samples
            << "\nparameters: " << (o.PaperParameters ? "paper" : "default")
            << "\nscheme: " << o.Scheme
            << "\ninitialization: " << (o.Initialization ? "flood" : "seed spheres")
            << "\nmean sample spacing on the exact surface: " << spacing
            << "\nmean sample spacing (filter): " << filter->GetMeanSampleSpacing()
            << "\neps, eps', dt: " << filter->GetEffectiveEpsilon() << ", "
            << filter->GetEffectiveCurvatureEpsilon() << ", " << filter->GetEffectiveTimeStep()
            << "\niterations: " << iterations
            << (filter->GetConverged() ? " (converged)" : " (limit)")
            << "\nseconds total: " << total << "\nseconds input: " << filter->GetInputSeconds()
            << "\nseconds neighbours: " << filter->GetNeighborSearchSeconds() << " (sort "
            << filter->GetSpatialSortSeconds() << ", nearest "
            << filter->GetNearestNeighborSeconds() << " of which tree "
            << filter->GetTreeBuildSeconds() << ", stencils " << filter->GetStencilSeconds()
            << ")\nseconds initialisation: " << filter->GetInitializationSeconds()
            << "\nseconds evolution: " << filter->GetEvolutionSeconds()
            << "\nseconds per iteration: "
            << (iterations ? filter->GetEvolutionSeconds() / iterations : 0.0)
            << "\nseconds isopoints: " << filter->GetIsopointSeconds() << " (completion "
            << filter->GetCompletionSeconds() << ", refinement on the data "
            << filter->GetDataRefinementSeconds()
            << ")\nseconds outputs: " << filter->GetOutputSeconds()
            << "\nseconds particle outputs: " << filter->GetParticleOutputSeconds()
            << "\nisopoints: " << m.Isopoints << "\nmean distance L: " << m.MeanDistance
            << "\n99th percentile distance: " << m.Percentile99Distance
            << "\nmean normal angle error (deg): " << m.MeanNormalAngleDegrees
            << "\nmax | |n| - 1 |: " << m.MaxNormalLengthError
            << "\nisopoints on unseeded components: " << m.UnseededIsopoints
            << "\nexact surface probes: " << m.SurfaceProbes
            << "\nlargest probe-to-isopoint gap: " << m.MaxGapToIsopoint
            << "\nprobes within one spacing: " << m.CoveredFraction << "\n";
  if (o.PrintTable)
  {
    std::cout
      << "Iteration SignMismatch MaxGradientDeviation MeanGradientDeviation BandSize Seconds\n";
    for (vtkIdType r = 0; r < table->GetNumberOfRows(); ++r)
    {
      for (vtkIdType col = 0; col < table->GetNumberOfColumns(); ++col)
      {
        std::cout << table->GetValue(r, col).ToDouble() << (col + 1 < 6 ? " " : "\n");
      }
    }
  }
  if (!o.WriteVtp.empty())
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(isopoints);
    writer->SetDataModeToBinary(); // appended mode is unreadable by Debian 12's ParaView 5.11
    writer->SetFileName(o.WriteVtp.c_str());
    writer->Write();
  }
  if (o.CompareThreads)
  {
    const std::array<double, 2> seconds = SecondsWithOneAndTwoThreads(
      particles, [&](vtkLevelSetIsosurface* timed) { Configure(timed, *c, o); });
    std::cout << "seconds with 1 thread: " << seconds[0]
              << "\nseconds with 2 threads: " << seconds[1]
              << "\nspeed-up 2 threads / 1 thread: " << seconds[0] / seconds[1] << "\n";
  }

  return EXIT_SUCCESS;
}
