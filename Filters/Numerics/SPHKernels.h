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
  QuarticSpline = 3, // M5, SWIFT's "Quartic spline (M5)"
  WendlandC4 = 4,    // SWIFT's and GADGET-4's "Wendland C4"
  WendlandC6 = 5,    // SWIFT's and GADGET-4's "Wendland C6"
};

/// Every kernel with the name the readers mark it with ("SPHKernel" field data, read back by
/// SPHKernelFromName), the name messages give it, and its support per smoothing length in
/// SWIFT's convention (Dehnen & Aly 2012's 3D gamma = H / h, h twice the kernel's standard
/// deviation), which SWIFT writes as HydroScheme's "Kernel gamma".
struct SPHKernelName
{
  SPHKernel Kernel;
  const char* Marker;
  const char* Label;
  double SwiftGamma;
};
constexpr SPHKernelName SPHKernelNames[] = {
  { SPHKernel::CubicSpline, "CubicSpline", "cubic spline (M4)", 1.825742 },
  { SPHKernel::QuinticSpline, "QuinticSpline", "quintic spline (M6)", 2.195775 },
  { SPHKernel::WendlandC2, "WendlandC2", "Wendland C2", 1.936492 },
  { SPHKernel::QuarticSpline, "QuarticSpline", "quartic spline (M5)", 2.018932 },
  { SPHKernel::WendlandC4, "WendlandC4", "Wendland C4", 2.207940 },
  { SPHKernel::WendlandC6, "WendlandC6", "Wendland C6", 2.449490 },
};

inline const SPHKernelName& NamesOf(SPHKernel kernel)
{
  for (const SPHKernelName& names : SPHKernelNames)
  {
    if (names.Kernel == kernel)
    {
      return names;
    }
  }
  return SPHKernelNames[0];
}

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
    case SPHKernel::QuarticSpline:
    {
      const double a = 1.0 - q, b = 0.6 - q, c = 0.2 - q;
      double w = Power<4>(a);
      w -= b > 0.0 ? 5.0 * Power<4>(b) : 0.0;
      w += c > 0.0 ? 10.0 * Power<4>(c) : 0.0;
      return norm * (15625.0 / (512.0 * pi)) * w;
    }
    case SPHKernel::WendlandC4:
      return norm * (495.0 / (32.0 * pi)) * Power<6>(1.0 - q) *
        (1.0 + 6.0 * q + 35.0 / 3.0 * q * q);
    case SPHKernel::WendlandC6:
      return norm * (1365.0 / (64.0 * pi)) * Power<8>(1.0 - q) *
        (1.0 + 8.0 * q + 25.0 * q * q + 32.0 * q * q * q);
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
    case SPHKernel::QuarticSpline:
    {
      const double a = 1.0 - q, b = 0.6 - q, c = 0.2 - q;
      double w = -4.0 * Power<3>(a);
      w += b > 0.0 ? 20.0 * Power<3>(b) : 0.0;
      w -= c > 0.0 ? 40.0 * Power<3>(c) : 0.0;
      return norm * (15625.0 / (512.0 * pi)) * w;
    }
    case SPHKernel::WendlandC4:
      return norm * (495.0 / (32.0 * pi)) * (-56.0 / 3.0 * q * Power<5>(1.0 - q) * (1.0 + 5.0 * q));
    case SPHKernel::WendlandC6:
      return norm * (1365.0 / (64.0 * pi)) *
        (-22.0 * q * Power<7>(1.0 - q) * (1.0 + 7.0 * q + 16.0 * q * q));
  }
  return 0.0;
}

/// The kernel a snapshot names (SWIFT's HydroScheme "Kernel function": "Cubic spline (M4)",
/// "Quartic spline (M5)", "Quintic spline (M6)", "Wendland C2", "Wendland C4", "Wendland C6"),
/// case and spacing aside. False, and `kernel` untouched, for a name that is none of them.
inline bool SPHKernelFromName(const std::string& name, SPHKernel& kernel)
{
  std::string lower;
  for (char c : name)
  {
    if (!std::isspace(static_cast<unsigned char>(c)) && c != '_' && c != '-')
    {
      lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  const auto has = [&lower](const char* part) { return lower.find(part) != std::string::npos; };
  if (has("wendland"))
  {
    if (has("c2") || has("c4") || has("c6"))
    {
      kernel = has("c2") ? SPHKernel::WendlandC2
        : has("c4")      ? SPHKernel::WendlandC4
                         : SPHKernel::WendlandC6;
      return true;
    }
    return false;
  }
  const bool quartic = has("quartic") || has("m5"), quintic = has("quintic") || has("m6"),
             cubic = has("cubic") || has("m4");
  if (quartic + quintic + cubic != 1)
  {
    return false;
  }
  kernel = quartic ? SPHKernel::QuarticSpline
    : quintic      ? SPHKernel::QuinticSpline
                   : SPHKernel::CubicSpline;
  return true;
}

/// The kernel's shape on q = r / H in [0, 1): W = Normalization<K>() / H^3 * w(q) and
/// dW/dr = Normalization<K>() / H^4 * dw/dq. The same numbers as SPHKernelValue and
/// SPHKernelDerivative, written for loops over many particles: the kernel is chosen once,
/// outside the loop.
template <SPHKernel K>
constexpr double Normalization()
{
  constexpr double pi = 3.14159265358979323846;
  return K == SPHKernel::CubicSpline ? 8.0 / pi
    : K == SPHKernel::QuinticSpline  ? 2187.0 / (40.0 * pi)
    : K == SPHKernel::WendlandC2     ? 21.0 / (2.0 * pi)
    : K == SPHKernel::QuarticSpline  ? 15625.0 / (512.0 * pi)
    : K == SPHKernel::WendlandC4     ? 495.0 / (32.0 * pi)
                                     : 1365.0 / (64.0 * pi);
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
  else if (K == SPHKernel::WendlandC2)
  {
    const double a = 1.0 - q, a3 = a * a * a;
    w = a3 * a * (1.0 + 4.0 * q);
    dw = -20.0 * q * a3;
  }
  else if (K == SPHKernel::QuarticSpline)
  {
    const double a = 1.0 - q, b = 0.6 - q, c = 0.2 - q;
    const double a3 = a * a * a;
    w = a3 * a;
    dw = -4.0 * a3;
    if (b > 0.0)
    {
      const double b3 = b * b * b;
      w -= 5.0 * b3 * b;
      dw += 20.0 * b3;
      if (c > 0.0)
      {
        const double c3 = c * c * c;
        w += 10.0 * c3 * c;
        dw -= 40.0 * c3;
      }
    }
  }
  else if (K == SPHKernel::WendlandC4)
  {
    const double a = 1.0 - q, a5 = Power<5>(a);
    w = a5 * a * (1.0 + 6.0 * q + 35.0 / 3.0 * q * q);
    dw = -56.0 / 3.0 * q * a5 * (1.0 + 5.0 * q);
  }
  else
  {
    const double a = 1.0 - q, a7 = Power<7>(a);
    w = a7 * a * (1.0 + 8.0 * q + 25.0 * q * q + 32.0 * q * q * q);
    dw = -22.0 * q * a7 * (1.0 + 7.0 * q + 16.0 * q * q);
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
