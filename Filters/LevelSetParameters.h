// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 2 of the method, the numerical parameters (paper §4.4): every length (eps, the time
// step, the band, the completion cells, Newton's reach) comes from the mean sample spacing of
// the samples that straddle the isovalue, or from the user where a property is set.
#ifndef LevelSetParameters_h
#define LevelSetParameters_h

#include "LevelSetCommunicator.h"
#include "LevelSetEvolutionSettings.h"
#include "LevelSetIsopoints.h"
#include "LevelSetNeighborhoods.h"

#include <string>
#include <vector>

namespace lsi
{

/// What the user asked for (the filter's properties); 0 for a length or a step means automatic.
struct RequestedParameters
{
  double Epsilon = 0.0;
  double CurvatureEpsilon = 0.0; // 0: equal to eps
  double TimeStep = 0.0;
  double CurvatureWeight = 0.05;
  double DistanceRegularization = 0.1; // used by Scheme::WithoutReinitialization only
  Scheme Method = Scheme::WithReinitialization;
  int ReinitializationSteps = 2;
  int MaximumIterations = 500;
  double ConvergenceTolerance = 1e-4;
  bool Completion = true;
  bool DataRefinement = true;
};

/// The owned samples of the fixed sample of about RadiusSampleSize particles over all ranks
/// (Neighborhoods::InRadiusSample) that global scales are measured on (their lists:
/// Neighborhoods::FixedSampleRow).
std::vector<std::uint32_t> OwnedRadiusSample(
  const Neighborhoods& geometry, const Communicator& ranks = SingleProcess());

/// The sampling scale where the surface is.
struct SurfaceScale
{
  double NeighborhoodRadius = 0.0; // mean h_i over the samples next to the isovalue
  double Spacing = 0.0;            // the mean sample spacing that radius implies
};

/// Adaptive data (SPH) is sampled far more densely in some places than at the isosurface, so
/// the scale is measured on the samples with a neighbour on the other side of the isovalue
/// (by the sign of `dataOffsets`, f - f_iso per sample), or on all samples if there is none;
/// both among the fixed sample of OwnedRadiusSample (every particle up to 131,072 particles).
SurfaceScale ScaleAtSurface(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const Communicator& ranks = SingleProcess());

EvolutionSettings ChooseEvolutionSettings(
  const RequestedParameters& requested, const SurfaceScale& scale);

/// What is wrong with the user's lengths and steps for this sampling, in words for warnings:
/// a TimeStep above the scheme's stability bound (it is lowered to the bound in `settings`), an
/// Epsilon narrower than half a spacing (the data force then sees no sample and the front does
/// not move) or wider than 20 spacings, a TimeStep too small for the seed-sphere front to reach
/// the surface within MaximumIterations, and a DistanceRegularization x TimeStep above the squared
/// spacing (scheme 1). All are ratios to the spacing: unit-free.
std::vector<std::string> EvolutionConcerns(const RequestedParameters& requested,
  const SurfaceScale& scale, EvolutionSettings& settings, bool seedSphereStart);

IsopointSettings ChooseIsopointSettings(
  const RequestedParameters& requested, const SurfaceScale& scale);

} // namespace lsi

#endif
