// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Isopoints (paper §6): zero crossings of phi between neighbouring samples, the angle
// criterion that keeps only pairs roughly along the gradient, and Newton's projection onto
// the zero level of a local approximation (eq. 14).
// Plain C++/Eigen: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef IsopointRefinement_h
#define IsopointRefinement_h

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace lsi
{

/// Point where the linear interpolation of phi between (xi, phii) and (xj, phij) is zero.
/// Requires phii and phij of opposite signs (or one of them zero).
inline Eigen::Vector3d ZeroCrossing(
  const Eigen::Vector3d& xi, double phii, const Eigen::Vector3d& xj, double phij)
{
  const double t = phii / (phii - phij);
  return xi + t * (xj - xi);
}

/// Angle criterion: accept a pair when the segment direction makes an angle with the
/// gradient whose cosine (in absolute value) is at least `minimumCosine`.
inline bool AlignedWithGradient(
  const Eigen::Vector3d& direction, const Eigen::Vector3d& gradient, double minimumCosine)
{
  const double denominator = direction.norm() * gradient.norm();
  if (!(denominator > 0.0))
  {
    return false;
  }
  return std::abs(direction.dot(gradient)) >= minimumCosine * denominator;
}

struct NewtonSettings
{
  int MaximumIterations = 8;
  double Tolerance = 1e-6;      // stop when the step is shorter than this
  double MaximumDistance = 1.0; // fail when the point wanders further than this from its start
};

/// Newton's method p <- p - phi(p) grad phi(p) / |grad phi(p)|^2 on an approximation given by
/// `evaluate(p, value, gradient) -> bool`. On success p lies on the zero level and `gradient` is
/// the approximation's gradient there. Returns false if the evaluation fails, the gradient
/// vanishes, the point leaves the trust region, or it does not converge.
template <typename EvaluateFn>
bool ProjectOntoZeroLevel(
  Eigen::Vector3d& p, Eigen::Vector3d& gradient, EvaluateFn evaluate, const NewtonSettings& s)
{
  const Eigen::Vector3d start = p;
  double value = 0.0;
  for (int iteration = 0; iteration < s.MaximumIterations; ++iteration)
  {
    if (!evaluate(p, value, gradient))
    {
      return false;
    }
    const double g2 = gradient.squaredNorm();
    if (!(g2 > 0.0) || !std::isfinite(value))
    {
      return false;
    }
    const Eigen::Vector3d step = (value / g2) * gradient;
    p -= step;
    if ((p - start).norm() > s.MaximumDistance)
    {
      return false;
    }
    if (step.norm() < s.Tolerance)
    {
      return evaluate(p, value, gradient) && gradient.squaredNorm() > 0.0;
    }
  }
  return false;
}

/// A quadratic model's gradient and Hessian at a point, packed in ModelSize doubles: the
/// gradient, then the Hessian's xx, yy, zz, xy, xz, yz (IsopointSet::FitModels).
constexpr std::size_t ModelSize = 9;

inline void StoreModel(const Eigen::Vector3d& gradient, const Eigen::Matrix3d& hessian, double* out)
{
  const double packed[ModelSize] = { gradient[0], gradient[1], gradient[2], hessian(0, 0),
    hessian(1, 1), hessian(2, 2), hessian(0, 1), hessian(0, 2), hessian(1, 2) };
  std::copy(packed, packed + ModelSize, out);
}

inline void LoadModel(const double* in, Eigen::Vector3d& gradient, Eigen::Matrix3d& hessian)
{
  gradient << in[0], in[1], in[2];
  hessian << in[3], in[6], in[7], in[6], in[4], in[8], in[7], in[8], in[5];
}

/// The step s to the zero nearest to s = 0 of value + slope s + curvature s^2 / 2 along a line
/// (slope > 0): the stable form of the quadratic's root, or Newton's step when the curvature
/// vanishes or the quadratic has no zero.
inline double StepToQuadraticZero(double value, double slope, double curvature)
{
  const double discriminant = slope * slope - 2.0 * curvature * value;
  return std::isfinite(curvature) && discriminant >= 0.0
    ? -2.0 * value / (slope + std::sqrt(discriminant))
    : -value / slope;
}

/// Moves p along the fixed direction `normal` (unit, pointing out of f > f_iso) to where the
/// data's approximation `evaluate(p, value, gradient, hessian)` of f - f_iso vanishes, but never
/// further than `maximumMove` from where it started: the level set already located the surface
/// to a fraction of the spacing, and the data only sharpen it. Each step solves the local
/// quadratic model along the line (value, slope and the Hessian's curvature along it; Newton's
/// step where the Hessian is zero or the model has no zero), so a curved field costs no extra
/// step. Stops after `iterations` steps, or after a step no longer than `tolerance`. `gradient`
/// is the approximation's at the last point it was evaluated. Returns false (p unchanged) when
/// the data's gradient does not point across the surface the way the level set says.
template <typename EvaluateFn>
bool SlideOntoDataLevel(Eigen::Vector3d& p, const Eigen::Vector3d& normal, EvaluateFn evaluate,
  double maximumMove, int iterations, Eigen::Vector3d& dataGradient, double tolerance = 0.0)
{
  const Eigen::Vector3d start = p;
  double offset = 0.0; // signed distance moved along -normal (into f > f_iso)
  for (int k = 0; k < iterations; ++k)
  {
    double value;
    Eigen::Matrix3d hessian;
    if (!evaluate(start - offset * normal, value, dataGradient, hessian))
    {
      return false;
    }
    const double slope = -dataGradient.dot(normal); // d f / d offset
    if (!(slope > 0.0) || !std::isfinite(value))
    {
      return false;
    }
    const double step = StepToQuadraticZero(value, slope, normal.dot(hessian * normal));
    const double next = std::max(-maximumMove, std::min(maximumMove, offset + step));
    const bool converged = std::abs(next - offset) <= tolerance;
    offset = next;
    if (converged)
    {
      break;
    }
  }
  p = start - offset * normal;
  return true;
}

/// Moves p along the line through it with direction `normal` (unit, pointing out of
/// f > f_iso) to a zero of `evaluate` (f - f_iso and its gradient) no further than `reach`,
/// to within `tolerance` along the line. Newton's steps first; when they do not converge inside
/// the reach (the field flattens beyond the outermost particles, where Newton overshoots), the
/// zero nearest to p is bracketed by steps of reach/16, reach/8, ... on both sides and found by
/// regula falsi (Illinois). `gradient` is the field's gradient at the result. Returns false
/// (p unchanged) when no zero lies within the reach, and with `newtonOnly` also when Newton's
/// steps alone do not converge inside it (the caller then tries a longer reach).
template <typename EvaluateFn>
bool SolveOnLine(Eigen::Vector3d& p, const Eigen::Vector3d& normal, EvaluateFn evaluate,
  double reach, double tolerance, Eigen::Vector3d& gradient, bool newtonOnly = false)
{
  if (!(reach > 0.0) || !std::isfinite(reach) || !(tolerance > 0.0))
  {
    return false; // no line to search (a zero or infinite splat radius, say)
  }
  const Eigen::Vector3d start = p;
  // g(t) = f(start - t normal) - f_iso, and its derivative along t.
  auto g = [&](double t, double& value, double& slope) {
    if (!evaluate(Eigen::Vector3d(start - t * normal), value, gradient) || !std::isfinite(value))
    {
      return false;
    }
    slope = -gradient.dot(normal);
    return true;
  };
  double value0, slope;
  if (!g(0.0, value0, slope))
  {
    return false;
  }
  double t = 0.0, value = value0;
  for (int k = 0; k < 8; ++k)
  {
    if (!(std::abs(slope) > 0.0))
    {
      break;
    }
    const double step = -value / slope;
    t += step;
    if (!(std::abs(t) <= reach) || !g(t, value, slope))
    {
      break;
    }
    if (std::abs(step) <= tolerance)
    {
      p = start - t * normal;
      return true;
    }
  }
  if (newtonOnly)
  {
    return false;
  }
  if (value0 == 0.0)
  {
    return g(0.0, value, slope);
  }
  // Bracket the zero nearest to the start.
  double a = 0.0, ga = value0, b = 0.0, gb = 0.0;
  bool bracketed = false;
  double previous[2] = { 0.0, 0.0 }, previousValue[2] = { value0, value0 };
  for (double step = reach / 16.0; !bracketed && step <= reach * (1.0 + 1e-12); step *= 2.0)
  {
    for (int side = 0; side < 2 && !bracketed; ++side)
    {
      const double ts = side == 0 ? step : -step;
      double gs;
      if (!g(ts, gs, slope))
      {
        continue;
      }
      if ((gs > 0.0) != (value0 > 0.0) || gs == 0.0)
      {
        a = previous[side];
        ga = previousValue[side];
        b = ts;
        gb = gs;
        bracketed = true;
      }
      previous[side] = ts;
      previousValue[side] = gs;
    }
  }
  if (!bracketed)
  {
    return false;
  }
  // Illinois: regula falsi that halves the value at an end kept twice in a row. Narrowed far
  // below `tolerance`: Newton's last step leaves an error of about its square, and a bracket
  // left `tolerance` wide would put the result anywhere in it, by where the search started
  // (under MPI, by the rank that found the point: 1e-6 splat radii apart).
  const double narrow = 1e-6 * tolerance;
  int side = 0;
  for (int k = 0; k < 60 && std::abs(b - a) > narrow; ++k)
  {
    const double c = (a * gb - b * ga) / (gb - ga);
    double gc;
    if (!g(c, gc, slope))
    {
      return false;
    }
    if (gc == 0.0)
    {
      a = b = c;
      break;
    }
    if ((gc > 0.0) == (gb > 0.0))
    {
      b = c;
      gb = gc;
      ga = side == -1 ? 0.5 * ga : ga;
      side = -1;
    }
    else
    {
      a = c;
      ga = gc;
      gb = side == 1 ? 0.5 * gb : gb;
      side = 1;
    }
  }
  t = 0.5 * (a + b);
  p = start - t * normal;
  return g(t, value, slope);
}

} // namespace lsi

#endif
