// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSeedSpheres.h"

#include "LevelSetParallel.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lsi
{

namespace
{
// Signed distance to the inside of the axis-aligned box `box` (positive inside).
double DistanceInsideBox(const double x[3], const double box[6])
{
  double d = DBL_MAX;
  for (int k = 0; k < 3; ++k)
  {
    d = std::min(d, std::min(x[k] - box[2 * k], box[2 * k + 1] - x[k]));
  }
  return d;
}
} // namespace

std::vector<double> SeedSpheres(const double center[3], double radius,
  const std::vector<double>& additional, const double bounds[6])
{
  if (radius < 0.0)
  {
    radius =
      0.1 * std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  }
  std::vector<double> spheres;
  if (radius > 0.0)
  {
    spheres = { center[0], center[1], center[2], radius }; // (insert: GCC 12 warned falsely)
    spheres.insert(spheres.end(), additional.begin(), additional.end());
  }
  return spheres;
}

SeedSphereStart SeedSphereDistance(const Neighborhoods& geometry,
  const std::vector<double>& spheres, const double bounds[6], double margin,
  std::vector<double>& phi, const Communicator& ranks)
{
  double box[6];
  for (int k = 0; k < 3; ++k)
  {
    box[2 * k] = bounds[2 * k] - margin;
    box[2 * k + 1] = bounds[2 * k + 1] + margin;
  }
  const std::size_t n = geometry.NumberOfSamples;
  SeedSphereStart start;
  start.InSeed.resize(n);
  start.SamplesPerSphere.assign(spheres.size() / 4, 0);
  ResizeMappedInParallel(phi, n);
  const std::size_t sphereCount = spheres.size() / 4;
  vtkSMPThreadLocal<std::vector<std::size_t>> localCounts(std::vector<std::size_t>(sphereCount, 0));
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 1024), [&](vtkIdType begin, vtkIdType end) {
      std::vector<std::size_t>& counts = localCounts.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double* x = geometry.Position(static_cast<std::size_t>(i));
        double seed = spheres.empty() ? DBL_MAX : -DBL_MAX;
        for (std::size_t s = 0; s < spheres.size(); s += 4)
        {
          const double d = spheres[s + 3] -
            std::sqrt((x[0] - spheres[s]) * (x[0] - spheres[s]) +
              (x[1] - spheres[s + 1]) * (x[1] - spheres[s + 1]) +
              (x[2] - spheres[s + 2]) * (x[2] - spheres[s + 2]));
          counts[s / 4] += d > 0.0 && ranks.Owns(static_cast<std::size_t>(i));
          seed = std::max(seed, d);
        }
        start.InSeed[i] = spheres.empty() || seed > 0.0;
        phi[i] = std::min(seed, DistanceInsideBox(x, box));
      }
    });
  for (const std::vector<std::size_t>& counts : localCounts)
  {
    for (std::size_t s = 0; s < sphereCount; ++s)
    {
      start.SamplesPerSphere[s] += counts[s];
    }
  }
  std::vector<double> counts(start.SamplesPerSphere.begin(), start.SamplesPerSphere.end());
  ranks.Sum(counts.data(), static_cast<int>(counts.size()));
  start.SamplesPerSphere.assign(counts.begin(), counts.end());
  return start;
}

} // namespace lsi
