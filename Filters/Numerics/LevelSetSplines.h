// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Smoothed delta and sign functions of the level-set equation (paper §4.2, corrected in
// shared/docs/method.md). Plain C++, no VTK: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef LevelSetSplines_h
#define LevelSetSplines_h

#include <cmath>

namespace lsi
{

/// Cubic B-spline kernel d(u), support [0, 2], d(0) = 2/3.
inline double SplineKernel(double u)
{
  u = std::abs(u);
  if (u <= 1.0)
  {
    return (4.0 - 6.0 * u * u + 3.0 * u * u * u) / 6.0;
  }
  if (u <= 2.0)
  {
    const double t = 2.0 - u;
    return t * t * t / 6.0;
  }
  return 0.0;
}

/// Integral of the kernel: s(u) with s(0) = 0, s(u >= 2) = 1, s' = 2 d.
inline double SplineKernelIntegral(double u)
{
  u = std::abs(u);
  if (u <= 1.0)
  {
    return (16.0 * u - 8.0 * u * u * u + 3.0 * u * u * u * u) / 12.0;
  }
  if (u <= 2.0)
  {
    const double t = 2.0 - u;
    return 1.0 - t * t * t * t / 12.0;
  }
  return 1.0;
}

/// delta_eps(x) = d(|x|/eps)/eps. Non-zero only for |x| < 2 eps: the "band".
inline double SmoothedDelta(double x, double eps)
{
  return SplineKernel(x / eps) / eps;
}

/// sgn_eps(x) = sign(x) s(|x|/eps), so that d/dx sgn_eps = 2 delta_eps exactly.
inline double SmoothedSign(double x, double eps)
{
  const double s = SplineKernelIntegral(x / eps);
  return x < 0.0 ? -s : s;
}

/// Half width of the band where SmoothedDelta(., eps) is non-zero.
inline double BandHalfWidth(double eps)
{
  return 2.0 * eps;
}

/// The sign of f - f_iso used by the forcing term (0 exactly on the isovalue).
inline double Sign(double x)
{
  return x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
}

} // namespace lsi

#endif
