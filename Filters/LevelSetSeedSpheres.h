// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 3 of the method, the seeds: the spheres that pick the components to extract, and the
// paper's initial level set, the signed distance to their union (paper §5). The flood start
// (LevelSetFlood.h, the default) uses the same spheres to find its sources.
#ifndef LevelSetSeedSpheres_h
#define LevelSetSeedSpheres_h

#include "LevelSetCommunicator.h"
#include "LevelSetNeighborhoods.h"

#include <cstddef>
#include <vector>

namespace lsi
{

/// The seed spheres, 4 numbers each (cx, cy, cz, r): the main sphere, then the additional ones.
/// A main radius of 0 means no sphere at all (the whole data set is the seed); a negative one
/// means a tenth of the largest extent of `bounds`.
std::vector<double> SeedSpheres(const double center[3], double radius,
  const std::vector<double>& additional, const double bounds[6]);

struct SeedSphereStart
{
  std::vector<char> InSeed; // per sample: inside some sphere (every sample when there is none)
  std::vector<std::size_t> SamplesPerSphere;
};

/// The paper's start: phi = the signed distance to the union of `spheres` (positive inside), cut
/// to `bounds` grown by `margin`, so that a seed larger than the data still has a front. No
/// sphere seeds the whole box.
SeedSphereStart SeedSphereDistance(const Neighborhoods& geometry,
  const std::vector<double>& spheres, const double bounds[6], double margin,
  std::vector<double>& phi, const Communicator& ranks = SingleProcess());

} // namespace lsi

#endif
