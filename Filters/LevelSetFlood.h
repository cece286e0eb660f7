// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 3 of the method, the initial level set by flooding (the default; ours, not the paper's).
// The paper starts from the seed spheres (LevelSetSeedSpheres.h) and lets the front travel to the
// isosurface, which takes tens of iterations. Flooding starts at the answer instead: the
// samples with f > f_iso that are connected to the seeds through the neighbour graph are the
// inside, and phi is the signed distance to the crossings between inside and outside samples.
// The evolution then only has to smooth that front, and it keeps the locality: components
// the seeds do not touch are never inside.
#ifndef LevelSetFlood_h
#define LevelSetFlood_h

#include "LevelSetNeighborhoods.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace lsi
{

struct FloodResult
{
  std::size_t SeedSamples = 0; // seed samples with f > f_iso it started from (this call's)
  bool Aborted = false;        // stopped on request; the inside is then incomplete
};

/// Whether the flood may go from sample `from` to its neighbour `to`, both above the isovalue
/// (none: always). On the SPH field the field between them may dip below the isovalue: two
/// clumps a neighbourhood apart are then two components (FieldStaysAboveBetween).
using FloodEdgeCheck = std::function<bool(std::uint32_t from, std::uint32_t to)>;

/// The flood: marks in `flooded` (one flag per sample) the samples connected to the seeds
/// (`inSeed`) through neighbours with f > f_iso, where `dataOffsets` holds f - f_iso per
/// sample. It goes on from what `flooded` already holds (empty: nothing yet): only the seeds
/// not yet flooded start new searches, so a later round from more seeds (across a periodic
/// box's faces, or from other MPI ranks) costs a pass over the seed flags and what it adds, and
/// the reach is the same as one flood from all the seeds at once. result.SeedSamples counts the
/// seeds with f > f_iso it started from (only this call's).
void FloodFurther(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inSeed, std::vector<char>& flooded, FloodResult& result,
  const AbortCheck& aborted, const FloodEdgeCheck& mayCross = nullptr);

/// The flood's inside from its reach (`flooded`, FloodFurther): outside pockets of fewer than
/// `bubbleSize` samples enclosed by it are noise below the neighbourhood scale, and are filled
/// (taken as inside).
std::vector<char> FilledInside(const Neighborhoods& geometry, const std::vector<char>& flooded,
  std::size_t bubbleSize, FloodResult& result, const AbortCheck& aborted);

/// The initial level set from a flood's `inside` (FilledInside): phi becomes the signed
/// distance (positive inside) to the crossings between inside and outside neighbours (placed
/// where `dataOffsets` interpolates to zero), up to `halfWidth` and clamped to +-halfWidth
/// beyond. Meanwhile a helper thread computes the MLS stencils of the band the evolution
/// starts on. False if aborted (phi then holds no level set).
bool SignedDistanceToCrossings(const Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<char>& inside, double halfWidth,
  std::vector<double>& phi, const AbortCheck& aborted);

} // namespace lsi

#endif
