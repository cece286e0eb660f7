// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The comparison benchmark: on one analytic case, in one process run and on the same particles,
// runs the level-set filter (default parameters, and the paper's seed-sphere start), the
// Rosenthal-Linsen scheme (EvolutionScheme 2), and the grid route a ParaView user takes today
// (SPH interpolation, Flying Edges, connectivity). Reports seconds per stage, iterations, peak
// memory and accuracy against the exact surface, as a table and as JSON (--json FILE). Method
// "delaunay" (not run unless named: minutes at 200,000 samples) adds Delaunay 3D + Contour.
//
//   LevelSetCompare --case one-component|multi-component|adaptive-noisy [--samples N]
//     [--methods a,b,...] [--threads T] [--json FILE] [--compare-threads]
#include "CaseRuns.h"
#include "DelaunayRoute.h"
#include "GridRoute.h"
#include "PeakMemory.h"
#include "SurfaceMetrics.h"
#include "SyntheticCases.h"
#include "SyntheticParticles.h"
#include "vtkLevelSetIsosurface.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTable.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using namespace lsi::cases;

struct Options
{
  std::string CaseName = "one-component";
  std::size_t Samples = 2000000;
  std::uint64_t Seed = 1;
  int Threads = 0;
  std::vector<std::string> Methods = { "level-set", "level-set-unrefined", "level-set-seed-spheres",
    "rosenthal-linsen", "rosenthal-linsen-seed-spheres", "grid-route" };
  std::string Json;
  bool CompareThreads = false;
};

struct MethodResult
{
  std::string Name;
  double Seconds = 0.0;
  int Iterations = -1; // -1: not iterative
  bool Converged = true;
  double PeakBytes = -1.0;
  std::vector<std::pair<std::string, double>> Stages; // seconds per stage
  std::vector<double> IterationSeconds;
  SurfaceMetrics Metrics;
};

bool Parse(int argc, char* argv[], Options& o)
{
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto next = [&]() -> std::string { return i + 1 < argc ? argv[++i] : ""; };
    if (a == "--case")
      o.CaseName = next();
    else if (a == "--samples")
      o.Samples = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--seed")
      o.Seed = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--threads")
      o.Threads = std::atoi(next().c_str());
    else if (a == "--json")
      o.Json = next();
    else if (a == "--compare-threads")
      o.CompareThreads = true;
    else if (a == "--methods")
    {
      o.Methods.clear();
      std::stringstream list(next());
      std::string m;
      while (std::getline(list, m, ','))
      {
        o.Methods.push_back(m);
      }
    }
    else
    {
      std::cerr << "unknown option " << a << "\n";
      return false;
    }
  }
  return true;
}

void Configure(vtkLevelSetIsosurface* filter, const Case& c, int threads)
{
  SetCaseInputs(filter, c);
  filter->SetNumberOfThreads(threads);
}

MethodResult RunFilter(const std::string& name, vtkPolyData* particles, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double spacing, int threads)
{
  MethodResult r;
  r.Name = name;
  vtkNew<vtkLevelSetIsosurface> filter;
  filter->SetInputData(particles);
  Configure(filter, c, threads);
  if (name.find("rosenthal-linsen") == 0)
  {
    filter->SetEvolutionScheme(vtkLevelSetIsosurface::ROSENTHAL_LINSEN);
  }
  if (name.find("seed-spheres") != std::string::npos)
  {
    filter->SetInitialization(vtkLevelSetIsosurface::SEED_SPHERES);
  }
  if (name.find("unrefined") != std::string::npos)
  {
    filter->SetDataRefinement(false);
  }
  lsi::ResetPeakMemory();
  r.Metrics = RunAndMeasure(filter, c, samples, spacing, r.Seconds);
  r.PeakBytes = lsi::PeakMemoryBytes();
  r.Iterations = filter->GetNumberOfIterationsPerformed();
  r.Converged = filter->GetConverged();
  r.Stages = { { "neighbours", filter->GetNeighborSearchSeconds() },
    { "stencils", filter->GetStencilSeconds() },
    { "initialisation", filter->GetInitializationSeconds() },
    { "evolution", filter->GetEvolutionSeconds() },
    { "isopoints",
      filter->GetIsopointSeconds() - filter->GetCompletionSeconds() -
        filter->GetDataRefinementSeconds() },
    { "completion", filter->GetCompletionSeconds() },
    { "data-refinement", filter->GetDataRefinementSeconds() },
    { "output", filter->GetOutputSeconds() } };
  vtkTable* table = vtkTable::SafeDownCast(filter->GetOutputDataObject(2));
  for (vtkIdType row = 0; table && row < table->GetNumberOfRows(); ++row)
  {
    r.IterationSeconds.push_back(table->GetValueByName(row, "Seconds").ToDouble());
  }
  return r;
}

MethodResult RunGrid(vtkPolyData* particles, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double surfaceSpacing, int threads)
{
  MethodResult r;
  r.Name = "grid-route";
  lsi::ResetPeakMemory();
  lsi::GridRouteResult grid;
  r.Metrics = RunAndMeasureGridRoute(particles, c, samples, surfaceSpacing, threads, grid);
  r.PeakBytes = lsi::PeakMemoryBytes();
  r.Seconds = grid.TotalSeconds();
  r.Stages = { { "sph-interpolation", grid.InterpolationSeconds },
    { "flying-edges", grid.ContourSeconds }, { "connectivity", grid.ConnectivitySeconds } };
  return r;
}

MethodResult RunDelaunay(vtkPolyData* particles, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double surfaceSpacing)
{
  MethodResult r;
  r.Name = "delaunay";
  lsi::ResetPeakMemory();
  DelaunayRouteResult route;
  r.Metrics = RunAndMeasureDelaunayRoute(particles, c, samples, surfaceSpacing, route);
  r.PeakBytes = lsi::PeakMemoryBytes();
  r.Seconds = route.TotalSeconds();
  r.Stages = { { "delaunay-3d", route.TetrahedraSeconds }, { "contour", route.ContourSeconds },
    { "connectivity-normals", route.ConnectivitySeconds } };
  return r;
}

std::string JsonString(const std::string& s)
{
  return "\"" + s + "\"";
}

void WriteJson(const std::string& path, const Options& o, const Case& c, double spacing,
  const std::vector<MethodResult>& results)
{
  std::ofstream out(path);
  out << std::setprecision(6);
  out << "{\n  \"case\": " << JsonString(c.Name) << ",\n  \"samples\": " << o.Samples
      << ",\n  \"surface_spacing\": " << spacing << ",\n  \"methods\": [\n";
  for (std::size_t k = 0; k < results.size(); ++k)
  {
    const MethodResult& r = results[k];
    const SurfaceMetrics& m = r.Metrics;
    out << "    {\"name\": " << JsonString(r.Name) << ", \"seconds\": " << r.Seconds
        << ", \"iterations\": " << r.Iterations
        << ", \"converged\": " << (r.Converged ? "true" : "false")
        << ", \"peak_memory_bytes\": " << r.PeakBytes << ", \"mean_distance\": " << m.MeanDistance
        << ", \"p99_distance\": " << m.Percentile99Distance
        << ", \"mean_normal_error_degrees\": " << m.MeanNormalAngleDegrees
        << ", \"coverage\": " << m.CoveredFraction << ", \"points\": " << m.Isopoints
        << ", \"points_on_unseeded_components\": " << m.UnseededIsopoints << ", \"stages\": {";
    for (std::size_t s = 0; s < r.Stages.size(); ++s)
    {
      out << (s ? ", " : "") << JsonString(r.Stages[s].first) << ": " << r.Stages[s].second;
    }
    out << "}, \"iteration_seconds\": [";
    for (std::size_t s = 0; s < r.IterationSeconds.size(); ++s)
    {
      out << (s ? ", " : "") << r.IterationSeconds[s];
    }
    out << "]}" << (k + 1 < results.size() ? "," : "") << "\n";
  }
  out << "  ]\n}\n";
}
} // namespace

int main(int argc, char* argv[])
{
  Options o;
  std::unique_ptr<Case> c;
  if (!Parse(argc, argv, o) || !(c = MakeCase(o.CaseName)))
  {
    std::cerr << "usage: LevelSetCompare --case one-component|multi-component|adaptive-noisy "
                 "[--samples N] [--methods a,b] [--threads T] [--json FILE] [--compare-threads]\n";
    return EXIT_FAILURE;
  }
  const std::vector<Eigen::Vector3d> samples = c->Samples(o.Samples, o.Seed);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  const double spacing = c->SurfaceSpacing(o.Samples);

  std::vector<MethodResult> results;
  for (const std::string& method : o.Methods)
  {
    if (method == "grid-route")
    {
      results.push_back(RunGrid(particles, *c, samples, spacing, o.Threads));
    }
    else if (method == "delaunay")
    {
      results.push_back(RunDelaunay(particles, *c, samples, spacing));
    }
    else if (method == "level-set" || method == "level-set-seed-spheres" ||
      method == "level-set-unrefined" || method == "rosenthal-linsen" ||
      method == "rosenthal-linsen-seed-spheres" || method == "rosenthal-linsen-unrefined")
    {
      results.push_back(RunFilter(method, particles, *c, samples, spacing, o.Threads));
    }
    else
    {
      std::cerr << "unknown method " << method << "\n";
      return EXIT_FAILURE;
    }
  }

  std::cout << std::setprecision(4) << "case " << c->Name << ", " << o.Samples
            << " samples, mean sample spacing on the exact surface " << spacing
            << " (distances below are in the data's units)\n\n";
  std::cout << "| method | seconds | iterations | s/iteration | peak GB | mean distance | "
               "99th pct distance | normal error (deg) | coverage | points |\n"
               "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MethodResult& r : results)
  {
    const SurfaceMetrics& m = r.Metrics;
    double iterationSum = 0.0;
    for (double s : r.IterationSeconds)
    {
      iterationSum += s;
    }
    std::cout << "| " << r.Name << " | " << r.Seconds << " | ";
    if (r.Iterations >= 0)
    {
      std::cout << r.Iterations << (r.Converged ? "" : " (limit)") << " | "
                << (r.IterationSeconds.empty() ? 0.0 : iterationSum / r.IterationSeconds.size());
    }
    else
    {
      std::cout << "- | -";
    }
    std::cout << " | " << r.PeakBytes / 1e9 << " | " << m.MeanDistance << " | "
              << m.Percentile99Distance << " | " << m.MeanNormalAngleDegrees << " | "
              << m.CoveredFraction << " | " << m.Isopoints << " |\n";
  }
  std::cout << "\nstages (seconds):\n";
  for (const MethodResult& r : results)
  {
    std::cout << "  " << r.Name << ":";
    for (const auto& stage : r.Stages)
    {
      std::cout << " " << stage.first << " " << stage.second;
    }
    if (!r.IterationSeconds.empty())
    {
      std::cout << "; per iteration:";
      for (double s : r.IterationSeconds)
      {
        std::cout << " " << s;
      }
    }
    std::cout << "\n";
  }
  if (o.CompareThreads)
  {
    const std::array<double, 2> seconds = SecondsWithOneAndTwoThreads(
      particles, [&](vtkLevelSetIsosurface* timed) { SetCaseInputs(timed, *c); });
    std::cout << "\nwhole filter, 1 thread: " << seconds[0] << " s, 2 threads: " << seconds[1]
              << " s, speed-up " << seconds[0] / seconds[1] << "\n";
  }
  if (!o.Json.empty())
  {
    WriteJson(o.Json, o, *c, spacing, results);
    std::cout << "\nwrote " << o.Json << "\n";
  }
  return EXIT_SUCCESS;
}
