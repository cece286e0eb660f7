// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The flood of the seeds' component where the samples are not one cloud: in a periodic box a
// particle and its images are one particle, and under MPI each rank holds its own samples and
// ghosts of its neighbours'. The method's flood and a quick re-run's both go across this way, so
// both find the component one process would find on the whole cloud.
#ifndef LevelSetFloodAcross_h
#define LevelSetFloodAcross_h

#include "LevelSetCommunicator.h"
#include "LevelSetFlood.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include "vtkType.h"

#include <vector>

namespace lsi
{

/// Floods from `inSeed` (FloodFurther, then FilledInside into `inside`) until the component is
/// whole. In a periodic box (`original`: OriginalIds, empty outside one) where the flood reached
/// a particle it seeds the particle's images, and the flood goes on from them, until no new
/// particle joins (a component that wraps through several faces takes a round per face it
/// crosses). Under MPI, where a rank's flood reached another rank's samples they are seeded
/// there and every rank floods on, until no rank adds a seed: the ranks' neighbour graphs,
/// joined at the ghosts, are the serial graph. Each round floods only from its new seeds, and
/// adds seeds that are never added again, so the rounds end, after at most as many as there are
/// seeds to add. `seedSamples`: the first flood's seed samples with f > f_iso, summed over the
/// ranks. The ghosts' sides are left as this rank's flood found them. False (on every rank)
/// when some rank's flood stopped on request: the inside is then incomplete. `mayCross`: which
/// neighbours above the isovalue the flood goes between (FloodFurther; none: all).
bool FloodAcross(const Neighborhoods& geometry, const Communicator& ranks,
  const std::vector<vtkIdType>& original, vtkIdType originalCount,
  const std::vector<double>& dataOffsets, std::vector<char>& inSeed, std::vector<char>& inside,
  double& seedSamples, const AbortCheck& aborted, const FloodEdgeCheck& mayCross = nullptr);

} // namespace lsi

#endif
