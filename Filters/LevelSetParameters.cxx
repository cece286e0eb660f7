// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetParameters.h"

#include "AutomaticParameters.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <array>

namespace lsi
{

std::vector<std::uint32_t> OwnedRadiusSample(
  const Neighborhoods& geometry, const Communicator& ranks)
{
  double owned = static_cast<double>(geometry.NumberOfSamples);
  for (std::size_t i = 0; i < geometry.NumberOfSamples && ranks.Distributed(); ++i)
  {
    owned -= ranks.Owns(i) ? 0.0 : 1.0;
  }
  const std::uint64_t every = RadiusSampleEvery(ranks.Sum(owned));
  return geometry.RadiusSampleWhere(every, [&](std::size_t i) { return ranks.Owns(i); });
}

SurfaceScale ScaleAtSurface(
  const Neighborhoods& geometry, const std::vector<double>& dataOffsets, const Communicator& ranks)
{
  // Sums: of the radii at the surface, their count, and of all radii and theirs; over the
  // fixed sample of the particles (InRadiusSample), the same whatever the ranks.
  // In parallel, in fixed chunks added in order: the same sums on any number of threads.
  const std::vector<std::uint32_t> sample = OwnedRadiusSample(geometry, ranks);
  geometry.EnsureFixedSampleRows();
  constexpr std::size_t Chunk = 4096;
  std::vector<std::array<double, 4>> parts((sample.size() + Chunk - 1) / Chunk);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(parts.size()), 1, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType c = first; c < last; ++c)
      {
        std::array<double, 4>& part = parts[static_cast<std::size_t>(c)];
        part.fill(0.0);
        const std::size_t end = std::min(sample.size(), (static_cast<std::size_t>(c) + 1) * Chunk);
        for (std::size_t k = static_cast<std::size_t>(c) * Chunk; k < end; ++k)
        {
          const std::size_t i = sample[k];
          const Neighborhoods::SampleRow row = geometry.FixedSampleRow(i);
          const double sign = Sign(dataOffsets[i]);
          part[2] += row.Radius;
          part[3] += 1.0;
          for (int m = 1; m < geometry.Stride; ++m)
          {
            if (Sign(dataOffsets[row.Ids[m]]) != sign)
            {
              part[0] += row.Radius;
              part[1] += 1.0;
              break;
            }
          }
        }
      }
    });
  double sums[4] = { 0.0, 0.0, 0.0, 0.0 };
  for (const std::array<double, 4>& part : parts)
  {
    for (int k = 0; k < 4; ++k)
    {
      sums[k] += part[k];
    }
  }
  ranks.Sum(sums, 4);
  const double sum = sums[0], count = sums[1];
  SurfaceScale scale;
  scale.NeighborhoodRadius = count > 0.0 ? sum / count : sums[2] / sums[3];
  scale.Spacing = SpacingFromNeighborhoodRadius(scale.NeighborhoodRadius, geometry.Stride - 1);
  return scale;
}

EvolutionSettings ChooseEvolutionSettings(
  const RequestedParameters& requested, const SurfaceScale& scale)
{
  const AutomaticChoice automatic = ChooseParameters(scale.Spacing, requested.CurvatureWeight);
  EvolutionSettings settings;
  EvolutionCoefficients& c = settings.Coefficients;
  c.Epsilon = requested.Epsilon > 0.0 ? requested.Epsilon : automatic.Epsilon;
  c.CurvatureEpsilon = requested.CurvatureEpsilon > 0.0 ? requested.CurvatureEpsilon : c.Epsilon;
  c.TimeStep = requested.TimeStep > 0.0
    ? requested.TimeStep
    : AutomaticTimeStep(c.Epsilon, requested.CurvatureWeight, scale.Spacing);
  c.CurvatureWeight = CurvatureWeightForSpacing(requested.CurvatureWeight, scale.Spacing);
  c.DistanceRegularization =
    requested.Method == Scheme::WithoutReinitialization ? requested.DistanceRegularization : 0.0;
  settings.Method = requested.Method;
  settings.MaximumStep = 0.5 * scale.Spacing;
  settings.ReinitializationSteps = requested.ReinitializationSteps;
  settings.ReinitializationTimeStep = automatic.ReinitializationTimeStep;
  settings.Spacing = scale.Spacing;
  settings.NeighborhoodRadius = scale.NeighborhoodRadius;
  settings.MaximumIterations = requested.MaximumIterations;
  settings.ConvergenceTolerance = requested.ConvergenceTolerance;
  return settings;
}

std::vector<std::string> EvolutionConcerns(const RequestedParameters& requested,
  const SurfaceScale& scale, EvolutionSettings& settings, bool seedSphereStart)
{
  std::vector<std::string> concerns;
  EvolutionCoefficients& c = settings.Coefficients;
  const double spacing = scale.Spacing;
  const double epsilonInSpacings = c.Epsilon / spacing;
  if (requested.Epsilon > 0.0 && epsilonInSpacings < 0.5)
  {
    concerns.push_back("Epsilon " + std::to_string(c.Epsilon) + " is " +
      std::to_string(epsilonInSpacings) +
      " sample spacings: narrower than half a spacing, the data force sees almost no sample and "
      "the front stays where it started. Use 0 (automatic: 2.5 spacings).");
  }
  if (requested.Epsilon > 0.0 && epsilonInSpacings > 20.0)
  {
    concerns.push_back("Epsilon " + std::to_string(c.Epsilon) + " is " +
      std::to_string(epsilonInSpacings) +
      " sample spacings: the surface is smoothed over that width. Use 0 (automatic).");
  }
  // The scheme's bounds: the paper's appendix (dt < 4 eps^2 / 3) and the curvature term's
  // (lambda dt <= 0.5 spacing^2, lambda the weight in the update).
  double stable =
    4.0 / 3.0 * std::min(c.Epsilon, c.CurvatureEpsilon) * std::min(c.Epsilon, c.CurvatureEpsilon);
  if (c.CurvatureWeight > 0.0)
  {
    stable = std::min(stable, 0.5 * spacing * spacing / c.CurvatureWeight);
  }
  if (requested.TimeStep > 0.0 && c.TimeStep > stable)
  {
    concerns.push_back("TimeStep " + std::to_string(c.TimeStep) +
      " exceeds the evolution's stability bound " + std::to_string(stable) +
      " (4/3 Epsilon^2, and CurvatureWeight x TimeStep <= spacing^2 / 2): using the bound.");
    c.TimeStep = stable;
  }
  // The front moves about TimeStep / Epsilon per iteration under the data force.
  const double reach = settings.MaximumIterations * c.TimeStep / c.Epsilon / spacing;
  if (seedSphereStart && requested.TimeStep > 0.0 && reach < 2.0)
  {
    concerns.push_back("TimeStep " + std::to_string(c.TimeStep) +
      " lets the front move at most about " + std::to_string(reach) +
      " sample spacings in MaximumNumberOfIterations: from the seed spheres it cannot reach the "
      "surface. Use 0 (automatic), or the flood start.");
  }
  if (settings.Method == Scheme::WithoutReinitialization &&
    c.DistanceRegularization * c.TimeStep > spacing * spacing)
  {
    concerns.push_back("DistanceRegularization x TimeStep = " +
      std::to_string(c.DistanceRegularization * c.TimeStep) +
      " exceeds the squared spacing: the reinitialisation-free scheme (eq. 13) is unstable there "
      "(the defaults give 0.28). Lower DistanceRegularization or TimeStep.");
  }
  return concerns;
}

IsopointSettings ChooseIsopointSettings(
  const RequestedParameters& requested, const SurfaceScale& scale)
{
  IsopointSettings settings;
  settings.Completion = requested.Completion;
  settings.CellSize = 0.5 * scale.Spacing;
  settings.Newton.Tolerance = 1e-4 * scale.Spacing;
  settings.Newton.MaximumDistance = 1.0 * scale.Spacing;
  settings.RefineOnData = requested.DataRefinement;
  settings.DataMaximumMove = 0.5 * scale.Spacing;
  return settings;
}

} // namespace lsi
