// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// SPH smoothing kernels in 3D, written for the support radius H (W = 0 beyond r = H), the
// convention of GADGET's SmoothingLength; a code whose h is not the support (SWIFT's h is
// H / gamma) converts before calling. Each integrates to 1 over its support. Plain C++:
// unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef SPHKernels_h
#define SPHKernels_h

#include <cmath>

namespace lsi
{

enum class SPHKernel
{
  CubicSpline = 0,   // M4, GADGET-2/3/4 and ChaNGa's default
  QuinticSpline = 1, // M6, SWIFT's "Quintic spline (M6)"
  WendlandC2 = 2,    // GIZMO's and many modern codes' choice
};

/// W(r, H) for distance r and support radius H > 0.
inline double SPHKernelValue(SPHKernel kernel, double r, double H)
{
  const double pi = 3.14159265358979323846;
  const double q = r / H;
  if (!(q < 1.0))
  {
    return 0.0;
  }
  const double norm = 1.0 / (H * H * H);
  switch (kernel)
  {
    case SPHKernel::CubicSpline:
      return norm * (8.0 / pi) *
        (q <= 0.5 ? 1.0 - 6.0 * q * q + 6.0 * q * q * q : 2.0 * std::pow(1.0 - q, 3));
    case SPHKernel::QuinticSpline:
    {
      const double a = 1.0 - q, b = 2.0 / 3.0 - q, c = 1.0 / 3.0 - q;
      double w = std::pow(a, 5);
      w -= b > 0.0 ? 6.0 * std::pow(b, 5) : 0.0;
      w += c > 0.0 ? 15.0 * std::pow(c, 5) : 0.0;
      return norm * (2187.0 / (40.0 * pi)) * w;
    }
    case SPHKernel::WendlandC2:
      return norm * (21.0 / (2.0 * pi)) * std::pow(1.0 - q, 4) * (1.0 + 4.0 * q);
  }
  return 0.0;
}

} // namespace lsi

#endif
