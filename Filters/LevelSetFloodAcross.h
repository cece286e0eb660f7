// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The flood of the seeds' component where the samples are not one cloud: in a periodic box a
// particle and its images are one particle, and under MPI each rank holds its own samples and
// ghosts of its neighbours'. The method's flood and a quick re-run's both go across this way
// (FloodedInside in rounds), so both find the component one process would find on the whole
// cloud.
#ifndef LevelSetFloodAcross_h
#define LevelSetFloodAcross_h

#include "LevelSetCommunicator.h"
#include "LevelSetFlood.h"
#include "LevelSetPeriodicImages.h"

#include <vector>

namespace lsi
{

/// How FloodAcross ended (the same on every rank).
enum class FloodAcrossEnd
{
  Whole,        // no flood reached a new particle: the component is complete
  Aborted,      // some rank's flood stopped on request
  StillCrossing // still crossing between ranks after FloodRoundsAcrossRanks floods
};

/// Floods from `inSeed` until the component is whole. `floodOnce()` floods this rank's samples
/// from `inSeed` and returns its FloodResult; `reached(i)` says whether the last flood reached
/// sample i. In a periodic box (`original`: OriginalIds, empty outside one) where the flood
/// reached a particle it seeds the particle's images, and the flood runs again, until no new
/// particle joins (a component that wraps through several faces takes a few rounds, at most
/// FloodRoundsAcrossFaces). Under MPI, where a rank's flood reached another rank's samples they
/// are seeded there and every rank floods again, until no rank adds a seed: the ranks' neighbour
/// graphs, joined at the ghosts, are the serial graph. `seedSamples`: the first flood's seed
/// samples, summed over the ranks. The ghosts' sides are left as this rank's flood found them.
template <typename FloodOnce, typename Reached>
FloodAcrossEnd FloodAcross(const Communicator& ranks, const std::vector<vtkIdType>& original,
  vtkIdType originalCount, const std::vector<double>& dataOffsets, std::vector<char>& inSeed,
  FloodOnce&& floodOnce, Reached&& reached, double& seedSamples)
{
  // This rank's flood, followed through the box's faces.
  auto floodHere = [&]() {
    const FloodResult flood = floodOnce();
    bool aborted = flood.Aborted;
    for (int round = 0; !aborted && !original.empty() && round < FloodRoundsAcrossFaces &&
         SeedImagesOfReached(original, originalCount, dataOffsets, reached, inSeed);
         ++round)
    {
      aborted = floodOnce().Aborted;
    }
    return aborted ? FloodResult{ 0, 0, 0, true } : flood;
  };
  const FloodResult first = floodHere();
  if (!ranks.All(!first.Aborted))
  {
    return FloodAcrossEnd::Aborted;
  }
  seedSamples = ranks.Sum(static_cast<double>(first.SeedSamples));
  if (!ranks.Distributed())
  {
    return FloodAcrossEnd::Whole;
  }
  for (int floods = 1; SeedWhereRanksReached(ranks, dataOffsets, reached, inSeed) != 0.0; ++floods)
  {
    if (floods == FloodRoundsAcrossRanks(ranks))
    {
      return FloodAcrossEnd::StillCrossing;
    }
    if (!ranks.All(!floodHere().Aborted))
    {
      return FloodAcrossEnd::Aborted;
    }
  }
  return FloodAcrossEnd::Whole;
}

} // namespace lsi

#endif
