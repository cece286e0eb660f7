// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSPHFieldChecks.h"

#include "LevelSetParameters.h"

#include "vtkDataArray.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>

namespace lsi
{
namespace
{
// About how many particles next to the surface the stored densities are compared at.
constexpr double DensityCheckParticles = 1024;

} // namespace

std::vector<std::uint32_t> SamplesNextToSurface(const Neighborhoods& geometry,
  const std::vector<double>& values, double isoValue, const Communicator& ranks)
{
  const std::vector<std::uint32_t> sample = OwnedRadiusSample(geometry, ranks);
  std::vector<std::uint32_t> near;
  for (const std::uint32_t i : sample)
  {
    const bool above = values[geometry.Order[i]] > isoValue;
    const Neighborhoods::SampleRow row = geometry.FixedSampleRow(i);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      if ((values[geometry.Order[row.Ids[m]]] > isoValue) != above)
      {
        near.push_back(i);
        break;
      }
    }
  }
  return ranks.Sum(static_cast<double>(near.size())) == 0.0 ? sample : near;
}

double MedianSupportPerNeighborhoodRadius(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<std::uint32_t>& nextToSurface, const Communicator& ranks)
{
  std::vector<double> supports, radii;
  for (const std::uint32_t i : nextToSurface)
  {
    supports.push_back(field.Support(i));
    radii.push_back(geometry.FixedSampleRow(i).Radius);
  }
  ranks.GatherAll(supports);
  ranks.GatherAll(radii);
  if (supports.empty())
  {
    return 1.0;
  }
  const std::size_t half = supports.size() / 2;
  std::nth_element(supports.begin(), supports.begin() + half, supports.end());
  std::nth_element(radii.begin(), radii.begin() + half, radii.end());
  return radii[half] > 0.0 ? supports[half] / radii[half] : 1.0;
}

DensityMismatch StoredDensityMismatch(const Neighborhoods& geometry, const SPHField& field,
  const SPHFieldArrays& arrays, const std::vector<std::uint32_t>& nextToSurface,
  const Communicator& ranks)
{
  std::vector<std::uint32_t> near;
  if (arrays.Density)
  {
    near = nextToSurface;
    // A median is known to within a few percent of the ratios' spread from a thousand
    // particles: 1 to 2 times DensityCheckParticles of them, chosen by position (the same on
    // any rank). Each costs two walks of the hierarchy, about 10 microseconds.
    const double all = ranks.Sum(static_cast<double>(near.size()));
    const auto every = static_cast<std::uint64_t>(all / DensityCheckParticles);
    if (every > 1)
    {
      near.erase(std::remove_if(near.begin(), near.end(),
                   [&](std::uint32_t i) { return (geometry.PositionHash(i) >> 32) % every != 0; }),
        near.end());
    }
  }
  // Each particle's ratios on its own (a few dozen kernel evaluations each), in parallel; the
  // medians do not depend on the order.
  std::vector<DensityLogRatios> ratios(near.size());
  std::vector<char> counted(near.size(), 0);
  vtkDataArray* mass = arrays.Mass;
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(near.size()), 256, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::uint32_t i = near[static_cast<std::size_t>(k)];
        double gather = 0.0, scatter = 0.0;
        field.KernelSumsAt(
          i, [&](std::uint32_t j) { return mass->GetTuple1(geometry.Order[j]); }, gather, scatter);
        const double stored = arrays.Density->GetTuple1(geometry.Order[i]);
        counted[k] = LogRatiosOf(gather, scatter, stored, ratios[k]) ? 1 : 0;
      }
    });
  std::vector<double> gather, scatter, symmetric;
  for (std::size_t k = 0; k < near.size(); ++k)
  {
    if (counted[k])
    {
      gather.push_back(ratios[k].Gather);
      scatter.push_back(ratios[k].Scatter);
      symmetric.push_back(ratios[k].Symmetric);
    }
  }
  ranks.GatherAll(gather);
  ranks.GatherAll(scatter);
  ranks.GatherAll(symmetric);
  return MedianDensityMismatch(gather, scatter, symmetric);
}

} // namespace lsi
