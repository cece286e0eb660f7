// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Under MPI, the surface against which the Enclosed table measures a rank's particles.
// A particle near the surface counts in part, by its height over the tangent plane of the
// surface point nearest to it within two shell widths (SurfaceDistance). In one process that
// point is one of the run's points; under MPI a rank holds the points it keeps (together every
// rank's are the serial run's) and those it found beyond them, from neighbourhoods its halo
// cuts: slightly off, and missing where a sparse particle's two shell widths reach past the
// halo (a galaxy's outer star on 2 ranks: a volume 2e-4 off). So each rank measures against
// every rank's kept points within reach of its particles.
#ifndef LevelSetEnclosedSurface_h
#define LevelSetEnclosedSurface_h

#include "LevelSetCommunicator.h"
#include "LevelSetIsopoints.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetPeriodicImages.h"

#include <vector>

namespace lsi
{

/// Every rank's kept points (`kept` here: the points this rank keeps) within two shell widths
/// (neighbourhood radii) of this rank's owned samples that measure their distance to the
/// surface (|phi| at most two shell widths), with their normals: this rank's first, then the
/// others' in rank order. In a periodic box (`periodic`) a point counts when one of its images
/// is within reach; the points are given in the cell (the Enclosed table makes their images).
void KeptSurfaceWithinReach(const Communicator& ranks, const Neighborhoods& geometry,
  const std::vector<double>& phi, const IsopointSet& kept, const PeriodicBox& periodic,
  std::vector<double>& points, std::vector<double>& normals);

} // namespace lsi

#endif
