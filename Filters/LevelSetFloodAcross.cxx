// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetFloodAcross.h"

#include "LevelSetFlood.h"
#include "LevelSetPeriodicImages.h"

namespace lsi
{

FloodAcrossEnd FloodAcross(const Neighborhoods& geometry, const Communicator& ranks,
  const std::vector<vtkIdType>& original, vtkIdType originalCount,
  const std::vector<double>& dataOffsets, std::vector<char>& inSeed, std::vector<char>& inside,
  double& seedSamples, const AbortCheck& aborted)
{
  const std::size_t bubbleSize = static_cast<std::size_t>(geometry.Stride);
  auto reached = [&](std::size_t i) { return inside[i] != 0; };
  // This rank's flood, followed through the box's faces (its seed count is the first round's).
  auto floodHere = [&]() {
    FloodResult flood;
    inside = FloodedInside(geometry, dataOffsets, inSeed, bubbleSize, flood, aborted);
    for (int round = 0; !flood.Aborted && !original.empty() && round < FloodRoundsAcrossFaces &&
         SeedImagesOfReached(original, originalCount, dataOffsets, reached, inSeed);
         ++round)
    {
      FloodResult again;
      inside = FloodedInside(geometry, dataOffsets, inSeed, bubbleSize, again, aborted);
      flood.Aborted = again.Aborted;
    }
    return flood;
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
  // Under MPI: seeds where another rank's flood reached this rank's samples (and the other way),
  // then every rank floods again; FloodRoundsAcrossRanks floods in all at most.
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
