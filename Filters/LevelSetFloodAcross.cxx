// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetFloodAcross.h"

#include "LevelSetFlood.h"
#include "LevelSetPeriodicImages.h"

namespace lsi
{

bool FloodAcross(const Neighborhoods& geometry, const Communicator& ranks,
  const std::vector<vtkIdType>& original, vtkIdType originalCount,
  const std::vector<double>& dataOffsets, std::vector<char>& inSeed, std::vector<char>& inside,
  double& seedSamples, const AbortCheck& aborted, const FloodEdgeCheck& mayCross)
{
  // The flood's reach grows round by round (each round floods only from its new seeds); the
  // pockets are filled once, in the whole reach.
  std::vector<char> flooded;
  auto reached = [&](std::size_t i) { return flooded[i] != 0; };
  // This rank's flood, followed through the box's faces until no image adds a seed. Each round
  // adds at least one seed, which is never added again: the rounds end.
  auto floodHere = [&]() {
    FloodResult flood;
    FloodFurther(geometry, dataOffsets, inSeed, flooded, flood, aborted, mayCross);
    while (!flood.Aborted && !original.empty() &&
      SeedImagesOfReached(original, originalCount, dataOffsets, reached, inSeed))
    {
      FloodResult again;
      FloodFurther(geometry, dataOffsets, inSeed, flooded, again, aborted, mayCross);
      flood.Aborted = again.Aborted;
    }
    return flood;
  };
  const FloodResult first = floodHere();
  if (!ranks.All(!first.Aborted))
  {
    return false;
  }
  seedSamples = ranks.Sum(static_cast<double>(first.SeedSamples));
  // Under MPI: seeds where another rank's flood reached this rank's samples (and the other way),
  // then every rank floods on from them, until no rank adds a seed (as above, the rounds end).
  while (ranks.Distributed() && SeedWhereRanksReached(ranks, dataOffsets, reached, inSeed) != 0.0)
  {
    if (!ranks.All(!floodHere().Aborted))
    {
      return false;
    }
  }
  FloodResult filled;
  inside =
    FilledInside(geometry, flooded, static_cast<std::size_t>(geometry.Stride), filled, aborted);
  return ranks.All(!filled.Aborted);
}

} // namespace lsi
