// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// SPH smoothing kernels in 3D, written for the support radius H (W = 0 beyond r = H), the
// convention of GADGET's SmoothingLength; a code whose h is not the support (SWIFT's h is
// H / gamma) converts before calling. Each integrates to 1 over its support. Plain C++:
// unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef SPHKernels_h
#define SPHKernels_h

#include <cctype>
#include <cmath>
#include <string>

namespace lsi
{

enum class SPHKernel
{
  CubicSpline = 0,   // M4, GADGET-2/3/4 and ChaNGa's default
  QuinticSpline = 1, // M6, SWIFT's "Quintic spline (M6)"
  WendlandC2 = 2,    // GIZMO's and many modern codes' choice
};

/// x^N by multiplications (std::pow is a library call, and these run billions of times).
template <int N>
inline double Power(double x)
{
  double result = 1.0;
  for (int i = 0; i < N; ++i)
  {
    result *= x;
  }
  return result;
}

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
        (q <= 0.5 ? 1.0 - 6.0 * q * q + 6.0 * q * q * q : 2.0 * Power<3>(1.0 - q));
    case SPHKernel::QuinticSpline:
    {
      const double a = 1.0 - q, b = 2.0 / 3.0 - q, c = 1.0 / 3.0 - q;
      double w = Power<5>(a);
      w -= b > 0.0 ? 6.0 * Power<5>(b) : 0.0;
      w += c > 0.0 ? 15.0 * Power<5>(c) : 0.0;
      return norm * (2187.0 / (40.0 * pi)) * w;
    }
    case SPHKernel::WendlandC2:
      return norm * (21.0 / (2.0 * pi)) * Power<4>(1.0 - q) * (1.0 + 4.0 * q);
  }
  return 0.0;
}

/// dW/dr (r, H): the radial derivative, <= 0 on [0, H), 0 beyond. The gradient of W(|x - x_j|, H)
/// with respect to x is dW/dr * (x - x_j) / r (and 0 at r = 0, where every kernel is flat).
inline double SPHKernelDerivative(SPHKernel kernel, double r, double H)
{
  const double pi = 3.14159265358979323846;
  const double q = r / H;
  if (!(q < 1.0))
  {
    return 0.0;
  }
  const double norm = 1.0 / (H * H * H * H); // d/dr = (1/H) d/dq
  switch (kernel)
  {
    case SPHKernel::CubicSpline:
      return norm * (8.0 / pi) *
        (q <= 0.5 ? -12.0 * q + 18.0 * q * q : -6.0 * (1.0 - q) * (1.0 - q));
    case SPHKernel::QuinticSpline:
    {
      const double a = 1.0 - q, b = 2.0 / 3.0 - q, c = 1.0 / 3.0 - q;
      double w = -5.0 * Power<4>(a);
      w += b > 0.0 ? 30.0 * Power<4>(b) : 0.0;
      w -= c > 0.0 ? 75.0 * Power<4>(c) : 0.0;
      return norm * (2187.0 / (40.0 * pi)) * w;
    }
    case SPHKernel::WendlandC2:
      return norm * (21.0 / (2.0 * pi)) * (-20.0 * q * Power<3>(1.0 - q));
  }
  return 0.0;
}

/// The kernel a snapshot names (SWIFT's HydroScheme "Kernel function", e.g. "Quintic spline
/// (M6)", "Wendland C2"), or `fallback` when the name is none of the three.
inline SPHKernel SPHKernelFromName(const std::string& name, SPHKernel fallback)
{
  std::string lower(name);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (lower.find("quintic") != std::string::npos || lower.find("m6") != std::string::npos)
  {
    return SPHKernel::QuinticSpline;
  }
  if (lower.find("wendland") != std::string::npos && lower.find("c2") != std::string::npos)
  {
    return SPHKernel::WendlandC2;
  }
  if (lower.find("cubic") != std::string::npos || lower.find("m4") != std::string::npos)
  {
    return SPHKernel::CubicSpline;
  }
  return fallback;
}

/// The kernel's shape on q = r / H in [0, 1): W = Normalization<K>() / H^3 * w(q) and
/// dW/dr = Normalization<K>() / H^4 * dw/dq. The same numbers as SPHKernelValue and
/// SPHKernelDerivative, written for loops over many particles: the kernel is chosen once,
/// outside the loop.
template <SPHKernel K>
constexpr double Normalization()
{
  return K == SPHKernel::CubicSpline ? 8.0 / 3.14159265358979323846
    : K == SPHKernel::QuinticSpline  ? 2187.0 / (40.0 * 3.14159265358979323846)
                                     : 21.0 / (2.0 * 3.14159265358979323846);
}

template <SPHKernel K>
inline void KernelShape(double q, double& w, double& dw)
{
  if (K == SPHKernel::CubicSpline)
  {
    if (q <= 0.5)
    {
      w = 1.0 - 6.0 * q * q + 6.0 * q * q * q;
      dw = -12.0 * q + 18.0 * q * q;
    }
    else
    {
      const double a = 1.0 - q;
      w = 2.0 * a * a * a;
      dw = -6.0 * a * a;
    }
  }
  else if (K == SPHKernel::QuinticSpline)
  {
    const double a = 1.0 - q, b = 2.0 / 3.0 - q, c = 1.0 / 3.0 - q;
    const double a4 = Power<4>(a);
    w = a4 * a;
    dw = -5.0 * a4;
    if (b > 0.0)
    {
      const double b4 = Power<4>(b);
      w -= 6.0 * b4 * b;
      dw += 30.0 * b4;
      if (c > 0.0)
      {
        const double c4 = Power<4>(c);
        w += 15.0 * c4 * c;
        dw -= 75.0 * c4;
      }
    }
  }
  else
  {
    const double a = 1.0 - q, a3 = a * a * a;
    w = a3 * a * (1.0 + 4.0 * q);
    dw = -20.0 * q * a3;
  }
}

/// Adds c W(|x - xj|, H) to `value` and its gradient in x to `gradient` (3 doubles).
inline void AccumulateKernel(SPHKernel kernel, const double* x, const double* xj, double H,
  double c, double& value, double* gradient)
{
  const double d[3] = { x[0] - xj[0], x[1] - xj[1], x[2] - xj[2] };
  const double r2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  if (!(r2 < H * H))
  {
    return;
  }
  const double r = std::sqrt(r2);
  value += c * SPHKernelValue(kernel, r, H);
  if (r > 0.0)
  {
    const double slope = c * SPHKernelDerivative(kernel, r, H) / r;
    for (int k = 0; k < 3; ++k)
    {
      gradient[k] += slope * d[k];
    }
  }
}

} // namespace lsi

#endif
