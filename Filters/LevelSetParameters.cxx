// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetParameters.h"

#include "AutomaticParameters.h"

namespace lsi
{

SurfaceScale ScaleAtSurface(const Neighborhoods& geometry, const std::vector<double>& dataSign)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      if (dataSign[ids[m]] != dataSign[i])
      {
        sum += geometry.Radius[i];
        ++count;
        break;
      }
    }
  }
  SurfaceScale scale;
  scale.NeighborhoodRadius = count ? sum / count : geometry.MeanRadius;
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
