// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Point completion (paper §6, Fig. 3): around an isopoint, lay a small grid of cells on the
// tangent plane, project the neighbouring isopoints onto it, and propose a new point at the
// centre of every empty cell (to be refined by Newton's method afterwards).
// Plain C++/Eigen: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef TangentPlaneCompletion_h
#define TangentPlaneCompletion_h

#include "TangentBasis.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>
#include <vector>

namespace lsi
{

/// Appends to `candidates` the centres of the empty cells of a (2 halfCells + 1)^2 grid of
/// square cells of side `cell`, centred on p in the plane orthogonal to the unit normal n.
/// A cell is occupied when a neighbour (given by `neighbor(j)`, j < count) within
/// `normalTolerance` of the plane projects into it (points further off the plane belong to
/// another sheet of the surface); the centre cell holds p itself.
template <typename NeighborFn>
void EmptyTangentCells(const Eigen::Vector3d& p, const Eigen::Vector3d& n, double cell,
  int halfCells, double normalTolerance, std::size_t count, NeighborFn neighbor,
  std::vector<Eigen::Vector3d>& candidates)
{
  const int side = 2 * halfCells + 1;
  std::vector<char> occupied(static_cast<std::size_t>(side * side), 0);
  occupied[static_cast<std::size_t>(halfCells * side + halfCells)] = 1;
  Eigen::Vector3d e1, e2;
  TangentBasis(n, e1, e2);
  for (std::size_t j = 0; j < count; ++j)
  {
    const Eigen::Vector3d d = neighbor(j) - p;
    if (std::abs(d.dot(n)) > normalTolerance)
    {
      continue;
    }
    const int u = static_cast<int>(std::floor(d.dot(e1) / cell + 0.5)) + halfCells;
    const int v = static_cast<int>(std::floor(d.dot(e2) / cell + 0.5)) + halfCells;
    if (u >= 0 && u < side && v >= 0 && v < side)
    {
      occupied[static_cast<std::size_t>(v * side + u)] = 1;
    }
  }
  for (int v = 0; v < side; ++v)
  {
    for (int u = 0; u < side; ++u)
    {
      if (!occupied[static_cast<std::size_t>(v * side + u)])
      {
        candidates.push_back(p + ((u - halfCells) * cell) * e1 + ((v - halfCells) * cell) * e2);
      }
    }
  }
}

} // namespace lsi

#endif
