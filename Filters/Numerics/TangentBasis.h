// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// An orthonormal basis of the plane tangent to a unit normal: the splats' corners and the
// completion's grid are laid out in it. Plain C++/Eigen: unit-tested in
// Testing/Cxx/TestNumerics.cxx.
#ifndef TangentBasis_h
#define TangentBasis_h

#include <Eigen/Dense>

#include <cmath>

namespace lsi
{

/// Two unit vectors u, v that make (u, v, n) a right-handed orthonormal basis. `n` must be unit.
inline void TangentBasis(const Eigen::Vector3d& n, Eigen::Vector3d& u, Eigen::Vector3d& v)
{
  // Cross with the axis least aligned with n (the first such axis on ties): never
  // near-parallel, so never ill-conditioned.
  Eigen::Vector3d axis = Eigen::Vector3d::Zero();
  int smallest = 0;
  for (int d = 1; d < 3; ++d)
  {
    if (std::abs(n[d]) < std::abs(n[smallest]))
    {
      smallest = d;
    }
  }
  axis[smallest] = 1.0;
  u = n.cross(axis).normalized();
  v = n.cross(u);
}

} // namespace lsi

#endif
