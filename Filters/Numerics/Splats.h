// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Oriented splats for rendering a point set with normals as a closed surface: each point becomes
// a small regular polygon (a disk) in its tangent plane, large enough that the disks of
// neighbouring points overlap. Plain C++/Eigen: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef Splats_h
#define Splats_h

#include "TangentBasis.h"

#include <Eigen/Dense>

#include <cmath>
#include <cstddef>

namespace lsi
{

/// Splat radius from the squared distances to a point's nearest other points (closest first):
/// `factor` times the distance to the last of them. On a surface sampled at spacing s, the
/// 6th neighbour is about 1.3 s away, so the disks overlap their neighbours' with room to spare
/// where the sampling is uneven; the factor is checked by the rendering-coverage test.
inline double SplatRadiusFromNeighbors(
  const double* squaredDistances, std::size_t count, double factor)
{
  return count ? factor * std::sqrt(squaredDistances[count - 1]) : 0.0;
}

/// Writes the `sides` corners of the regular polygon of circumradius `radius` centred at c in
/// the plane normal to n, counter-clockwise seen from the side n points to (so the polygon's
/// own normal is n), as 3 * sides doubles.
inline void DiskCorners(
  const Eigen::Vector3d& c, const Eigen::Vector3d& n, double radius, int sides, double* out)
{
  Eigen::Vector3d u, v;
  TangentBasis(n, u, v);
  const double step = 2.0 * 3.14159265358979323846 / sides;
  for (int s = 0; s < sides; ++s)
  {
    const Eigen::Vector3d x = c + radius * (std::cos(s * step) * u + std::sin(s * step) * v);
    out[3 * s + 0] = x[0];
    out[3 * s + 1] = x[1];
    out[3 * s + 2] = x[2];
  }
}

} // namespace lsi

#endif
