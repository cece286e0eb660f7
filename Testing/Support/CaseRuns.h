// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Running the filter and the grid route on an analytic case and scoring them against its exact
// surface: shared by the accuracy tests (Testing/Cxx) and the benchmarks (Benchmarks/). Uses
// only public headers: the filter's, VTK's and the synthetic cases' (Data/Synthetic).
#ifndef CaseRuns_h
#define CaseRuns_h

#include "GridRoute.h"
#include "SurfaceMetrics.h"
#include "SyntheticCases.h"
#include "vtkLevelSetIsosurface.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <ctime>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lsi
{
namespace cases
{

/// The case's array ("f"), isovalue and seeds (first sphere main, the others additional).
inline void SetCaseInputs(vtkLevelSetIsosurface* filter, const Case& c)
{
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  filter->SetIsoValue(c.IsoValue);
  filter->SetSeedCenter(c.Seeds[0].Center.data());
  filter->SetSeedRadius(c.Seeds[0].Radius);
  for (std::size_t s = 1; s < c.Seeds.size(); ++s)
  {
    const Sphere3& seed = c.Seeds[s];
    filter->AddAdditionalSeed(seed.Center.x(), seed.Center.y(), seed.Center.z(), seed.Radius);
  }
}

inline double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Coordinates and "Normals" of the filter's isopoint output, 3 values per point each.
inline void IsopointArrays(
  vtkPolyData* isopoints, std::vector<double>& points, std::vector<double>& normals)
{
  const vtkIdType m = isopoints->GetNumberOfPoints();
  points.resize(3 * m);
  normals.assign(3 * m, 0.0);
  vtkDataArray* n = isopoints->GetPointData()->GetArray("Normals");
  for (vtkIdType i = 0; i < m; ++i)
  {
    isopoints->GetPoint(i, &points[3 * i]);
    if (n)
    {
      n->GetTuple(i, &normals[3 * i]);
    }
  }
}

/// The paper's own parameters (§8.2 and §8.3), absolute: tuned for its spacing of 1.
inline void SetPaperParameters(vtkLevelSetIsosurface* filter, const Case& c)
{
  const bool one = c.Name == "one-component";
  filter->SetTimeStep(one ? 1.0 : 1.25);
  filter->SetEpsilon(one ? 4.0 : 3.5);
  filter->SetCurvatureEpsilon(5.0);
  filter->SetCurvatureWeight(one ? 0.15 : 0.01);
  filter->SetReinitializationSteps(2);
}

/// Updates `filter` (already given the particles and configured) with isopoint output and
/// scores its isopoints against the exact surface of `c`; `seconds` receives the run's time.
inline SurfaceMetrics RunAndMeasure(vtkLevelSetIsosurface* filter, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double spacing, double& seconds)
{
  filter->SetOutputTypeToIsopoints(); // accuracy is measured on the isopoints themselves
  const auto start = std::chrono::steady_clock::now();
  filter->Update();
  seconds = SecondsSince(start);
  std::vector<double> points, normals;
  IsopointArrays(filter->GetOutput(0), points, normals);
  return MeasureSurface(c, points, normals, samples, spacing);
}

/// The grid route's spatial step and grid spacing: the mean sample spacing over the data
/// bounds, (volume / N)^(1/3).
inline double MeanSpacingOverBounds(vtkPolyData* particles)
{
  double bounds[6];
  particles->GetBounds(bounds);
  return std::cbrt((bounds[1] - bounds[0]) * (bounds[3] - bounds[2]) * (bounds[5] - bounds[4]) /
    static_cast<double>(particles->GetNumberOfPoints()));
}

/// The centres of the case's seed spheres.
inline std::vector<Eigen::Vector3d> SeedCentres(const Case& c)
{
  std::vector<Eigen::Vector3d> seeds;
  for (const Sphere3& s : c.Seeds)
  {
    seeds.push_back(s.Center);
  }
  return seeds;
}

/// Scores a grid-route mesh like the filter's isopoints (its normals oriented out of
/// f > f_iso like ours).
inline SurfaceMetrics MeasureGridSurface(const Case& c, const std::vector<double>& points,
  std::vector<double> normals, const std::vector<Eigen::Vector3d>& samples, double surfaceSpacing)
{
  double alignment = 0.0;
  for (std::size_t i = 0; i < normals.size() / 3; ++i)
  {
    const Eigen::Vector3d g = c.Gradient(Eigen::Vector3d(&points[3 * i]));
    alignment += Eigen::Vector3d(&normals[3 * i]).dot(-g);
  }
  if (alignment < 0.0)
  {
    for (double& v : normals)
    {
      v = -v;
    }
  }
  return MeasureSurface(c, points, normals, samples, surfaceSpacing);
}

/// The grid route on the case's particles ("f"), scored like the filter.
inline SurfaceMetrics RunAndMeasureGridRoute(vtkPolyData* particles, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double surfaceSpacing, int threads,
  GridRouteResult& grid)
{
  grid = RunGridRoute(
    particles, "f", c.IsoValue, SeedCentres(c), MeanSpacingOverBounds(particles), threads);
  return MeasureGridSurface(c, grid.Points, grid.Normals, samples, surfaceSpacing);
}

/// Seconds of a whole filter run with 1 and with 2 threads (fresh filters, same particles);
/// `configure` sets everything but the input and the thread count. `busy`, if given, receives
/// for each the busy fraction of its fastest run: the process's CPU seconds over the threads
/// times the wall seconds. On one thread below 1 means the machine gave the process less than a
/// core (other load, a virtual machine's host); on two it also counts the serial parts.
/// `each`, if given, sees every run (its thread count, the filter after it, its wall seconds):
/// for the stages' own times.
inline std::array<double, 2> SecondsWithOneAndTwoThreads(vtkPolyData* particles,
  const std::function<void(vtkLevelSetIsosurface*)>& configure, int repeats = 1,
  std::array<double, 2>* busy = nullptr,
  const std::function<void(int, vtkLevelSetIsosurface*, double)>& each = nullptr)
{
  // The fastest of `repeats` runs each, 1 and 2 threads taken in turn, so that the machine's
  // noise (up to 10% from run to run here) weighs less on the ratio.
  std::array<double, 2> seconds = { HUGE_VAL, HUGE_VAL };
  std::array<double, 2> fraction = { 0.0, 0.0 };
  for (int repeat = 0; repeat < repeats; ++repeat)
  {
    for (int threads = 1; threads <= 2; ++threads)
    {
      vtkNew<vtkLevelSetIsosurface> filter;
      filter->SetInputData(particles);
      filter->SetOutputTypeToIsopoints();
      configure(filter);
      filter->SetNumberOfThreads(threads);
      const std::clock_t cpuStart = std::clock(); // all of the process's threads
      const auto start = std::chrono::steady_clock::now();
      filter->Update();
      const double wall = SecondsSince(start);
      const double cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
      if (wall < seconds[threads - 1])
      {
        seconds[threads - 1] = wall;
        fraction[threads - 1] = cpu / (threads * wall);
      }
      if (each)
      {
        each(threads, filter, wall);
      }
    }
  }
  if (busy)
  {
    *busy = fraction;
  }
  return seconds;
}

} // namespace cases
} // namespace lsi

#endif
