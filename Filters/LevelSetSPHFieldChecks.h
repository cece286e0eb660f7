// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Whether the smoothing lengths an input carries describe its particles, measured before the
// SPH field is trusted with the surface: the supports against the sampling, and the stored
// densities against the kernel sums of the masses (Numerics/DensityConsistency.h). Both on the
// particles next to the surface among the fixed sample of OwnedRadiusSample: the same numbers
// on any number of ranks.
#ifndef LevelSetSPHFieldChecks_h
#define LevelSetSPHFieldChecks_h

#include "DensityConsistency.h"
#include "LevelSetCommunicator.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetSPHField.h"

#include <cstdint>
#include <vector>

namespace lsi
{

/// This rank's samples of the fixed sample (OwnedRadiusSample) next to the surface: a
/// neighbour on the other side of `isoValue` in `values` (input order); all of them if there is
/// none on any rank. Both checks below are measured on them.
std::vector<std::uint32_t> SamplesNextToSurface(const Neighborhoods& geometry,
  const std::vector<double>& values, double isoValue, const Communicator& ranks = SingleProcess());

/// The median kernel support over the median neighbourhood radius (distance to the n-th
/// neighbour), among the samples next to the surface: about 1 or more for real SPH data, far
/// less for placeholder smoothing lengths or ones that vanish at the surface, where the field
/// cannot resolve it.
double MedianSupportPerNeighborhoodRadius(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<std::uint32_t>& nextToSurface, const Communicator& ranks = SingleProcess());

/// The stored densities (arrays.Density) against the kernel sums of the masses at the samples
/// next to the surface, in the convention closest to them (MedianDensityMismatch). Particles
/// whose stored density is not positive and finite are not counted; no stored densities: no
/// particles counted (a factor of 1).
DensityMismatch StoredDensityMismatch(const Neighborhoods& geometry, const SPHField& field,
  const SPHFieldArrays& arrays, const std::vector<std::uint32_t>& nextToSurface,
  const Communicator& ranks = SingleProcess());

} // namespace lsi

#endif
