// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Unit tests of the per-sample numerics (Filters/Numerics), against known answers.
#include "AutomaticParameters.h"
#include "DensityConsistency.h"
#include "IsoValueShift.h"
#include "IsopointRefinement.h"
#include "LevelSetSplines.h"
#include "LevelSetUpdate.h"
#include "MovingLeastSquares.h"
#include "NearestNeighbors.h"
#include "SPHKernels.h"
#include "SpatialOrder.h"
#include "SpatialPartition.h"
#include "Splats.h"
#include "TangentBasis.h"
#include "TangentPlaneCompletion.h"
#include "UninitializedVector.h"

#include "MortonTree.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{
int failures = 0;
void Check(bool ok, const char* what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++failures;
  }
}

void TestSplines()
{
  const double eps = 1.7;
  // sgn' = 2 delta, by central differences, everywhere including the knots.
  for (double x = -4.0 * eps; x <= 4.0 * eps; x += 0.01)
  {
    const double h = 1e-6;
    const double derivative =
      (lsi::SmoothedSign(x + h, eps) - lsi::SmoothedSign(x - h, eps)) / (2 * h);
    Check(std::abs(derivative - 2.0 * lsi::SmoothedDelta(x, eps)) < 1e-6, "sgn' = 2 delta");
  }
  // Continuity at the knots |x| = eps and 2 eps, and the values there.
  for (double u : { 1.0, 2.0 })
  {
    Check(std::abs(lsi::SplineKernel(u - 1e-12) - lsi::SplineKernel(u + 1e-12)) < 1e-9,
      "delta continuous");
    Check(
      std::abs(lsi::SplineKernelIntegral(u - 1e-12) - lsi::SplineKernelIntegral(u + 1e-12)) < 1e-9,
      "sign continuous");
  }
  Check(std::abs(lsi::SplineKernelIntegral(1.0) - 11.0 / 12.0) < 1e-15, "s(1) = 11/12");
  // Limits: sign -> +-1 beyond 2 eps, delta -> 0; odd sign, even delta; unit mass of delta.
  Check(lsi::SmoothedSign(2.0 * eps, eps) == 1.0 && lsi::SmoothedSign(-9.0, eps) == -1.0,
    "sign limits");
  Check(lsi::SmoothedDelta(2.0 * eps, eps) == 0.0 && lsi::SmoothedDelta(5.0, eps) == 0.0,
    "delta support");
  Check(lsi::SmoothedSign(0.0, eps) == 0.0, "sign(0) = 0");
  double mass = 0.0;
  for (double x = -2.0 * eps; x < 2.0 * eps; x += 1e-4)
  {
    mass += lsi::SmoothedDelta(x + 0.5e-4, eps) * 1e-4;
  }
  Check(std::abs(mass - 1.0) < 1e-6, "delta has unit mass");
}

void TestMLS()
{
  // Gradients (and values) of linear fields are exact on scattered neighbourhoods.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    std::vector<double> xyz(3 * 27);
    for (double& v : xyz)
    {
      v = 5.0 + 2.0 * u(random);
    }
    const double c[3] = { xyz[0], xyz[1], xyz[2] };
    double h = 0.0;
    for (int j = 0; j < 27; ++j)
    {
      h = std::max(h,
        std::sqrt(std::pow(xyz[3 * j] - c[0], 2) + std::pow(xyz[3 * j + 1] - c[1], 2) +
          std::pow(xyz[3 * j + 2] - c[2], 2)));
    }
    std::vector<double> g(3 * 27), value(27);
    const bool ok = lsi::BuildLinearStencil(
      c, 27, [&](std::size_t j) { return &xyz[3 * j]; }, h,
      lsi::LinearStencilView{ g.data(), value.data() });
    Check(ok, "regular neighbourhood is not singular");
    const Eigen::Vector3d a(0.3, -1.2, 2.5);
    auto field = [&](std::size_t j) { return a.dot(Eigen::Vector3d(&xyz[3 * j])) + 4.0; };
    const Eigen::Vector3d grad = lsi::ApplyGradientStencil(g.data(), 27, field);
    Check((grad - a).norm() < 1e-10, "MLS gradient exact for a linear field");
    double v = 0.0;
    for (std::size_t j = 0; j < 27; ++j)
    {
      v += value[j] * field(j);
    }
    Check(std::abs(v - field(0)) < 1e-10, "MLS value exact for a linear field");
    // The one-field fit gives what the stencil gives, for a field that is not linear too.
    auto curved = [&](std::size_t j) { return field(j) + std::pow(xyz[3 * j + 1] - 5.0, 2); };
    double direct = 0.0, stencilValue = 0.0;
    Eigen::Vector3d directGradient;
    const bool fitted = lsi::FitLinear(
      c, 27, [&](std::size_t j) { return &xyz[3 * j]; }, curved, h, direct, directGradient);
    for (std::size_t j = 0; j < 27; ++j)
    {
      stencilValue += value[j] * curved(j);
    }
    const Eigen::Vector3d stencilGradient = lsi::ApplyGradientStencil(g.data(), 27, curved);
    Check(fitted && std::abs(direct - stencilValue) < 1e-12 * (1.0 + std::abs(stencilValue)) &&
        (directGradient - stencilGradient).norm() < 1e-12 * (1.0 + stencilGradient.norm()),
      "one-field MLS fit equals the stencil's sums");
    // Divergence of the linear vector field (x, 2y, -z) is 1 + 2 - 1 = 2.
    const double div = lsi::ApplyDivergenceStencil(g.data(), 27, [&](std::size_t j) {
      return Eigen::Vector3d(xyz[3 * j], 2.0 * xyz[3 * j + 1], -xyz[3 * j + 2]);
    });
    Check(std::abs(div - 2.0) < 1e-10, "MLS divergence exact for a linear field");
  }
  {
    // An odd count (the last sample summed alone, beside a padding lane) gives the stencil and
    // the value weights of the same samples plus one beyond the support (weight zero): a stray
    // weight of the padding would show. The value weights are the stencil's value column.
    std::vector<double> xyz;
    for (int j = 0; j < 27; ++j)
    {
      xyz.insert(xyz.end(), { u(random), u(random), u(random) });
    }
    xyz.insert(xyz.end(), { 5.0, 5.0, 5.0 }); // the 28th: beyond h
    const double c[3] = { 0.1, -0.2, 0.05 };
    auto position = [&](std::size_t j) { return &xyz[3 * j]; };
    std::vector<double> oddG(3 * 27), oddV(27), evenG(3 * 28), evenV(28), oddW(27), evenW(28);
    const bool ok = lsi::BuildLinearStencil(
                      c, 27, position, 2.0, lsi::LinearStencilView{ oddG.data(), oddV.data() }) &&
      lsi::BuildLinearStencil(
        c, 28, position, 2.0, lsi::LinearStencilView{ evenG.data(), evenV.data() }) &&
      lsi::LinearValueWeights(c, 27, position, 2.0, oddW.data()) &&
      lsi::LinearValueWeights(c, 28, position, 2.0, evenW.data());
    double difference = std::abs(evenV[27]) + std::abs(evenW[27]);
    for (std::size_t j = 0; j < 27; ++j)
    {
      difference = std::max({ difference, std::abs(oddV[j] - evenV[j]),
        std::abs(oddW[j] - evenW[j]), std::abs(oddW[j] - oddV[j]) });
      for (int d = 0; d < 3; ++d)
      {
        difference = std::max(difference, std::abs(oddG[3 * j + d] - evenG[3 * j + d]));
      }
    }
    Check(ok && difference < 1e-12,
      "an odd count gives the linear stencil and weights of a weightless sample more");
  }
  // Coplanar, collinear and coincident neighbourhoods are reported singular.
  std::vector<double> plane, line, same;
  for (int j = 0; j < 27; ++j)
  {
    plane.insert(plane.end(), { u(random), u(random), 0.0 });
    const double t = u(random);
    line.insert(line.end(), { t, 2 * t, -t });
    same.insert(same.end(), { 1.0, 1.0, 1.0 });
  }
  std::vector<double> g(3 * 27);
  for (const std::vector<double>* xyz : { &plane, &line, &same })
  {
    const double c[3] = { (*xyz)[0], (*xyz)[1], (*xyz)[2] };
    Check(!lsi::BuildLinearStencil(
            c, 27, [&](std::size_t j) { return &(*xyz)[3 * j]; }, 3.0,
            lsi::LinearStencilView{ g.data(), nullptr }),
      "degenerate neighbourhood reported singular");
    double value = 1.0;
    Eigen::Vector3d gradient;
    Check(!lsi::FitLinear(
            c, 27, [&](std::size_t j) { return &(*xyz)[3 * j]; }, [](std::size_t) { return 1.0; },
            3.0, value, gradient) &&
        value == 0.0 && gradient.isZero(),
      "degenerate neighbourhood reported singular by the one-field fit");
  }
  // A NaN position (its weight and entries NaN): the stencil, the one-field fit and the
  // linear-or-quadratic fit all report the fit singular, and none returns NaN.
  std::vector<double> withNaN(plane);
  for (std::size_t k = 0; k < withNaN.size(); ++k)
  {
    withNaN[k] = k % 3 == 2 ? u(random) : withNaN[k]; // a regular cloud, then one NaN
  }
  withNaN[7] = std::nan("");
  const double c[3] = { withNaN[0], withNaN[1], withNaN[2] };
  auto at = [&](std::size_t j) { return &withNaN[3 * j]; };
  double value = 1.0;
  Eigen::Vector3d gradient;
  bool quadratic = true;
  const bool stencil =
    lsi::BuildLinearStencil(c, 27, at, 3.0, lsi::LinearStencilView{ g.data(), nullptr });
  const bool linear = lsi::FitLinear(
    c, 27, at, [](std::size_t) { return 1.0; }, 3.0, value, gradient);
  const bool both = lsi::FitLinearOrQuadratic(
    c, 27, at, [](std::size_t) { return 1.0; }, 3.0, 3.0, value, gradient, quadratic);
  Check(!stencil && !linear && !both && value == 0.0 && gradient.isZero(),
    "a NaN position: every linear fit reports it singular");
}

// The LDL^T solve of the quadratic fit: the solution of random symmetric positive definite
// systems to rounding; refused when a pivot vanishes (a singular matrix), is negative (an
// indefinite one) or is below the relative threshold (near-singular).
void TestSolveSymmetricDefinite()
{
  using Matrix10 = Eigen::Matrix<double, 10, 10>;
  using Vector10 = Eigen::Matrix<double, 10, 1>;
  std::mt19937 random(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 50; ++trial)
  {
    Matrix10 m;
    for (int i = 0; i < 10; ++i)
    {
      for (int j = 0; j < 10; ++j)
      {
        m(i, j) = u(random);
      }
    }
    const Matrix10 a = m * m.transpose() + 0.1 * Matrix10::Identity();
    Vector10 x, exact;
    for (int i = 0; i < 10; ++i)
    {
      exact[i] = u(random);
    }
    const Vector10 b = a * exact;
    // (Only the lower triangle is read: the upper one is garbage here.)
    Matrix10 lower = a;
    for (int i = 0; i < 10; ++i)
    {
      for (int j = i + 1; j < 10; ++j)
      {
        lower(i, j) = 1e300;
      }
    }
    const bool ok = lsi::SolveSymmetricDefinite(lower, b, 1e-12, x);
    Check(ok && (x - exact).norm() < 1e-8 * exact.norm(),
      "the LDL^T solve of a positive definite system is exact to rounding");
  }
  Matrix10 singular = Matrix10::Identity();
  singular(9, 9) = 0.0;
  Vector10 x = Vector10::Zero();
  const Vector10 b = Vector10::Ones();
  Check(!lsi::SolveSymmetricDefinite(singular, b, 0.0, x), "a zero pivot is refused");
  Matrix10 indefinite = Matrix10::Identity();
  indefinite(4, 4) = -1.0;
  Check(!lsi::SolveSymmetricDefinite(indefinite, b, 0.0, x), "a negative pivot is refused");
  Matrix10 nearSingular = Matrix10::Identity();
  nearSingular(3, 3) = 1e-9;
  Check(!lsi::SolveSymmetricDefinite(nearSingular, b, 1e-7, x) &&
      lsi::SolveSymmetricDefinite(nearSingular, b, 1e-10, x) && std::abs(x[3] - 1e9) < 1e-3,
    "a pivot below the relative threshold is refused, above it solved");
}

void TestQuadraticFit()
{
  // A quadratic field on 54 (or 53: the fit sums samples in pairs, the last one alone)
  // scattered samples: value, gradient and Hessian exact (to rounding) at a point that is not a
  // sample, and the quadratic chosen; a linear field: exact too.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1.0);
  int quadraticOnNoise = 0;
  for (int trial = 0; trial < 20; ++trial)
  {
    const std::size_t count = trial % 2 ? 53 : 54;
    std::vector<double> xyz(3 * count);
    for (double& v : xyz)
    {
      v = 50.0 + 3.0 * u(random);
    }
    const double c[3] = { 50.3, 49.8, 50.1 };
    double h = 0.0;
    for (std::size_t j = 0; j < count; ++j)
    {
      h = std::max(h, (Eigen::Vector3d(&xyz[3 * j]) - Eigen::Vector3d(c)).norm());
    }
    const Eigen::Vector3d a(0.3, -1.2, 2.5);
    Eigen::Matrix3d q;
    q << 1.0, 0.2, -0.4, 0.2, -2.0, 0.3, -0.4, 0.3, 0.5;
    auto quadraticField = [&](const Eigen::Vector3d& x) {
      const Eigen::Vector3d d = x - Eigen::Vector3d(40, 60, 55);
      return d.dot(q * d) + a.dot(d) + 4.0;
    };
    const Eigen::Vector3d centre(c);
    const double exactValue = quadraticField(centre);
    const Eigen::Vector3d exactGradient = 2.0 * q * (centre - Eigen::Vector3d(40, 60, 55)) + a;
    double value = 0.0;
    Eigen::Vector3d gradient;
    bool quadratic = false;
    auto position = [&](std::size_t j) { return &xyz[3 * j]; };
    Eigen::Matrix3d hessian;
    bool ok = lsi::FitLinearOrQuadratic(
      c, count, position,
      [&](std::size_t j) { return quadraticField(Eigen::Vector3d(&xyz[3 * j])); }, h, 3.5, value,
      gradient, quadratic, &hessian);
    Check(ok && quadratic, "a quadratic field chooses the quadratic fit");
    Check((hessian - 2.0 * q).norm() < 1e-8 * q.norm(),
      "the quadratic fit's Hessian is exact for a quadratic field");
    Check(std::abs(value - exactValue) < 1e-8 * std::abs(exactValue),
      "the quadratic fit's value is exact for a quadratic field");
    Check((gradient - exactGradient).norm() < 1e-8 * exactGradient.norm(),
      "the quadratic fit's gradient is exact for a quadratic field");
    auto linearField = [&](std::size_t j) { return a.dot(Eigen::Vector3d(&xyz[3 * j])) + 4.0; };
    ok = lsi::FitLinearOrQuadratic(
      c, count, position, linearField, h, 3.5, value, gradient, quadratic);
    Check(ok && std::abs(value - (a.dot(centre) + 4.0)) < 1e-9 && (gradient - a).norm() < 1e-9,
      "a linear field is fitted exactly");
    // A linear field with noise: the quadratic terms explain only noise, and the test should
    // keep the linear fit (an F test at the 1% point errs about once in a hundred).
    std::vector<double> noisy(count);
    for (std::size_t j = 0; j < count; ++j)
    {
      noisy[j] = linearField(j) + 0.5 * noise(random);
    }
    ok = lsi::FitLinearOrQuadratic(
      c, count, position, [&](std::size_t j) { return noisy[j]; }, h, 3.5, value, gradient,
      quadratic);
    Check(ok, "a noisy linear field is fitted");
    quadraticOnNoise += quadratic ? 1 : 0;
  }
  std::cout << "quadratic fits chosen on noise: " << quadraticOnNoise << " of 20\n";
  Check(quadraticOnNoise <= 2, "noise alone rarely selects the quadratic fit");
  {
    // An odd count (the last sample summed alone) fits as the same samples plus one beyond the
    // support (weight zero): on a curved, noisy field, where any stray weight would show.
    std::vector<double> xyz;
    for (int j = 0; j < 53; ++j)
    {
      xyz.insert(xyz.end(), { u(random), u(random), u(random) });
    }
    xyz.insert(xyz.end(), { 5.0, 5.0, 5.0 }); // the 54th: beyond h
    std::vector<double> f;
    for (std::size_t j = 0; j < 54; ++j)
    {
      const double* x = &xyz[3 * j];
      f.push_back(x[0] * x[0] - 2.0 * x[1] * x[2] + 0.3 * x[2] + 0.05 * noise(random));
    }
    const double c[3] = { 0.1, -0.2, 0.05 };
    auto position = [&](std::size_t j) { return &xyz[3 * j]; };
    auto value = [&](std::size_t j) { return f[j]; };
    double odd = 0.0, even = 0.0;
    Eigen::Vector3d oddGradient, evenGradient;
    Eigen::Matrix3d oddHessian, evenHessian;
    bool oddQuadratic = false, evenQuadratic = false;
    const bool oddOk = lsi::FitLinearOrQuadratic(
      c, 53, position, value, 2.0, 3.5, odd, oddGradient, oddQuadratic, &oddHessian);
    const bool evenOk = lsi::FitLinearOrQuadratic(
      c, 54, position, value, 2.0, 3.5, even, evenGradient, evenQuadratic, &evenHessian);
    Check(oddOk && evenOk && oddQuadratic && evenQuadratic && std::abs(odd - even) < 1e-12 &&
        (oddGradient - evenGradient).norm() < 1e-12 && (oddHessian - evenHessian).norm() < 1e-11,
      "an odd count fits as with a weightless sample more");
  }
  // Too few samples, or samples on a plane: the quadratic is ill-posed, the linear fit remains
  // (or fails where it is singular too).
  std::vector<double> plane;
  for (int j = 0; j < 30; ++j)
  {
    plane.insert(plane.end(), { u(random), u(random), 0.0 });
  }
  double value;
  Eigen::Vector3d gradient;
  bool quadratic = true;
  Check(!lsi::FitLinearOrQuadratic(
          &plane[0], 30, [&](std::size_t j) { return &plane[3 * j]; },
          [](std::size_t) { return 1.0; }, 3.0, 3.5, value, gradient, quadratic) &&
      !quadratic,
    "a planar neighbourhood is singular for both fits");
}

// Appendix, Theorem 1, with the theorem's own triangular delta and sign of support alpha.
void TestTheorem1()
{
  const double alpha = 2.0;
  auto delta = [&](double x) {
    return std::abs(x) < alpha ? (alpha - std::abs(x)) / (alpha * alpha) : 0.0;
  };
  auto sign = [&](double x) {
    return std::abs(x) < alpha ? x * (2 * alpha - std::abs(x)) / (alpha * alpha) : lsi::Sign(x);
  };
  // 1D: phi0(x) = -x (decreasing), f - f_iso = 0.3 - x.
  auto run = [&](double dt, int steps, bool& monotone, double& worstLimitError) {
    std::vector<double> xs, phi;
    for (double x = -3.0; x <= 3.0; x += 0.01)
    {
      xs.push_back(x);
      phi.push_back(-x);
    }
    monotone = true;
    for (int k = 0; k < steps; ++k)
    {
      for (std::size_t i = 0; i < xs.size(); ++i)
      {
        phi[i] = lsi::MainTermStep(phi[i], lsi::Sign(0.3 - xs[i]), dt, delta, sign);
      }
      for (std::size_t i = 1; i < xs.size(); ++i)
      {
        monotone = monotone && phi[i] <= phi[i - 1] + 1e-12;
      }
    }
    worstLimitError = 0.0;
    for (std::size_t i = 0; i < xs.size(); ++i)
    {
      const double limit = std::abs(xs[i]) < alpha ? alpha * lsi::Sign(0.3 - xs[i]) : -xs[i];
      if (std::abs(std::abs(xs[i]) - alpha) > 0.02 && std::abs(xs[i] - 0.3) > 0.02)
      {
        worstLimitError = std::max(worstLimitError, std::abs(phi[i] - limit));
      }
    }
  };
  bool monotone;
  double error;
  run(0.95 * alpha * alpha / 3.0, 4000, monotone, error);
  Check(monotone, "Theorem 1: dt < alpha^2/3 keeps phi monotone");
  Check(error < 0.05, "Theorem 1: phi converges to alpha sgn(f - f_iso) inside the support");
  run(0.95 * alpha * alpha, 50, monotone, error);
  Check(!monotone, "Theorem 1 is sharp: dt near alpha^2 loses monotonicity");
  // The corrected splines at the paper's largest recommended step, 0.6 eps^2 (the appendix's
  // 4 eps^2 / 3, from alpha = 2 eps, is only approximate for them and fails here).
  const double eps = 1.0;
  std::vector<double> phi;
  for (double x = -3.0; x <= 3.0; x += 0.01)
  {
    phi.push_back(-x);
  }
  bool splineMonotone = true;
  for (int k = 0; k < 500; ++k)
  {
    for (std::size_t i = 0; i < phi.size(); ++i)
    {
      const double x = -3.0 + 0.01 * i;
      phi[i] = lsi::MainTermStep(
        phi[i], lsi::Sign(0.3 - x), 0.6 * eps * eps,
        [&](double p) { return lsi::SmoothedDelta(p, eps); },
        [&](double p) { return lsi::SmoothedSign(p, eps); });
    }
    for (std::size_t i = 1; i < phi.size(); ++i)
    {
      splineMonotone = splineMonotone && phi[i] <= phi[i - 1] + 1e-12;
    }
  }
  Check(splineMonotone, "splines: dt = 0.6 eps^2 keeps phi monotone");
  // Automatic parameters sit inside the paper's bounds.
  const lsi::AutomaticChoice c = lsi::ChooseParameters(1.0, 0.05);
  Check(c.TimeStep >= 0.3 * c.Epsilon * c.Epsilon && c.TimeStep <= 0.6 * c.Epsilon * c.Epsilon,
    "automatic dt in [0.3, 0.6] eps^2");
  Check(lsi::ChooseParameters(1.0, 1.0).TimeStep * 1.0 < 0.5, "automatic lambda dt < 0.5");
  // No unit of length: at spacing s every length-valued choice is s times the one at spacing 1,
  // dt s^2 times, and the curvature coefficient lambda s (so lambda dt delta kappa scales as s).
  for (double s : { 1e-3, 7.0, 1e3 })
  {
    for (double lambda : { 0.05, 1.0 })
    {
      const lsi::AutomaticChoice one = lsi::ChooseParameters(1.0, lambda);
      const lsi::AutomaticChoice scaled = lsi::ChooseParameters(s, lambda);
      Check(std::abs(scaled.Epsilon / (s * one.Epsilon) - 1.0) < 1e-12 &&
          std::abs(scaled.TimeStep / (s * s * one.TimeStep) - 1.0) < 1e-12 &&
          std::abs(scaled.ReinitializationTimeStep / (s * one.ReinitializationTimeStep) - 1.0) <
            1e-12 &&
          std::abs(lsi::CurvatureWeightForSpacing(lambda, s) /
              (s * lsi::CurvatureWeightForSpacing(lambda, 1.0)) -
            1.0) < 1e-12,
        "automatic parameters scale with the spacing (no unit of length)");
    }
  }
}

void TestReinitialization()
{
  // Upwind slope of an exact 1D distance (neighbours at +-1 of psi = 5) is 1: nothing moves.
  auto unit = [](std::size_t) { return 1.0; }; // (squared distances)
  auto neighbors = [](double a, double b) {
    return [a, b](std::size_t j) { return j == 0 ? a : b; };
  };
  lsi::UpwindSlope s = lsi::SteepestUpwindSlope(5.0, 2, neighbors(4.0, 6.0), unit);
  Check(s.Found && std::abs(s.Norm - 1.0) < 1e-15, "upwind slope of a distance is 1");
  Check(lsi::ReinitializedValue(5.0, 5.0, s, 1.0, 0.5) == 5.0, "a distance is a fixed point");
  // Too steep (psi = 9 next to 4): decreases, but never below the upwind value.
  s = lsi::SteepestUpwindSlope(9.0, 2, neighbors(4.0, 10.0), unit);
  const double next = lsi::ReinitializedValue(9.0, 9.0, s, 1.0, 100.0);
  Check(next < 9.0 && next >= 4.0, "steep psi decreases, bounded by the upwind value");
  // Too flat: grows by at most the pseudo-time step. Negative side mirrors.
  s = lsi::SteepestUpwindSlope(4.1, 2, neighbors(4.0, 4.2), unit);
  Check(lsi::ReinitializedValue(4.1, 4.1, s, 1.0, 0.5) <= 4.6 + 1e-12, "growth bounded");
  s = lsi::SteepestUpwindSlope(-9.0, 2, neighbors(-4.0, -10.0), unit);
  const double negative = lsi::ReinitializedValue(-9.0, -9.0, s, 1.0, 100.0);
  Check(negative > -9.0 && negative <= -4.0, "negative side mirrors");
  // The steepest upwind slope as the quotients sign (psi - v) / |x - x_j| pick it (the first
  // of equals), to the bit: random neighbours, slopes equal or a rounding or a millionth apart,
  // at lengths of 1, 1e-80 (the products compared then fall below the normal range) and 1e80.
  auto quotientsPick = [](double psi, const std::vector<double>& v, const std::vector<double>& d2) {
    lsi::UpwindSlope best;
    const double sign = psi >= 0.0 ? 1.0 : -1.0;
    for (std::size_t j = 0; j < v.size(); ++j)
    {
      const double d = std::sqrt(d2[j]);
      if (!(sign * v[j] < sign * psi) || !(d > 0.0))
      {
        continue;
      }
      const double slope = sign * (psi - v[j]) / d;
      if (!best.Found || slope > best.Norm)
      {
        best = lsi::UpwindSlope{ true, slope, v[j] };
      }
    }
    return best;
  };
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::size_t differ = 0, cases = 0;
  for (const double length : { 1.0, 1e-80, 1e80 })
  {
    for (int trial = 0; trial < 20000; ++trial)
    {
      const double psi = length * uniform(random);
      std::vector<double> v(26), d2(26);
      for (std::size_t j = 0; j < v.size(); ++j)
      {
        const double d = length * (0.5 + std::abs(uniform(random)));
        d2[j] = d * d;
        v[j] = psi - (trial % 3 == 0 ? 1.0 : uniform(random)) * d; // (equal slopes every third)
        if (j % 5 == 4)
        {
          // The one before at twice the distance and rise (the same slope), a rounding
          // steeper, or at the same distance a millionth steeper.
          const double scale = trial % 3 == 0 ? 2.0 : (trial % 3 == 1 ? 1.0 + 1e-12 : 1.0 + 1e-6);
          v[j] = psi - scale * (psi - v[j - 1]);
          d2[j] = (trial % 3 == 2 ? 1.0 : scale * scale) * d2[j - 1];
        }
      }
      const lsi::UpwindSlope a = lsi::SteepestUpwindSlope(
        psi, v.size(), [&](std::size_t j) { return v[j]; }, [&](std::size_t j) { return d2[j]; });
      const lsi::UpwindSlope b = quotientsPick(psi, v, d2);
      differ += a.Found != b.Found || a.Norm != b.Norm || a.Floor != b.Floor;
      ++cases;
    }
  }
  const std::string picked = "the steepest upwind slope is the quotients' pick, to the bit (" +
    std::to_string(differ) + " of " + std::to_string(cases) + " differ)";
  Check(differ == 0, picked.c_str());
  Check(lsi::InterfaceDistance(0.6, 2.0, 1.0) == 0.3, "interface distance phi / |grad phi|");
  Check(lsi::InterfaceDistance(-28.0, 1.0, 2.5) == -2.5,
    "interface distance at most the distance to the other side");
}

void TestIsopoints()
{
  // Newton onto the unit sphere from an approximation phi(p) = 1 - |p| (exact gradient).
  auto sphere = [](const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient) {
    value = 1.0 - p.norm();
    gradient = -p.normalized();
    return true;
  };
  lsi::NewtonSettings settings;
  settings.MaximumDistance = 2.0;
  for (const Eigen::Vector3d& start :
    { Eigen::Vector3d(0.3, 0.4, 0.2), Eigen::Vector3d(1.5, -0.2, 0.7), Eigen::Vector3d(0, 0, 1.9) })
  {
    Eigen::Vector3d p = start, g;
    Check(lsi::ProjectOntoZeroLevel(p, g, sphere, settings) && std::abs(p.norm() - 1.0) < 1e-6,
      "Newton projects onto the sphere");
    Check((p.normalized() - start.normalized()).norm() < 1e-9, "projection along the normal");
  }
  Eigen::Vector3d far(10, 0, 0), g;
  Check(!lsi::ProjectOntoZeroLevel(far, g, sphere, settings), "trust region rejects far points");
  // Linear zero crossing and the angle criterion.
  const Eigen::Vector3d z =
    lsi::ZeroCrossing(Eigen::Vector3d(0, 0, 0), 1.0, Eigen::Vector3d(4, 0, 0), -3.0);
  Check((z - Eigen::Vector3d(1, 0, 0)).norm() < 1e-15, "zero crossing by interpolation");
  Check(lsi::AlignedWithGradient(Eigen::Vector3d(1, 0.2, 0), Eigen::Vector3d(1, 0, 0), 0.5),
    "aligned pair accepted");
  Check(!lsi::AlignedWithGradient(Eigen::Vector3d(0.1, 1, 0), Eigen::Vector3d(1, 0, 0), 0.5),
    "tangential pair rejected");
}

void TestCompletion()
{
  // Plane z = 0, isopoint at the origin, neighbours fill the +x half: the empty cells are the
  // 10 of the 5 x 5 grid with u < 0, all on the plane.
  std::vector<Eigen::Vector3d> neighbors;
  for (int u = 1; u <= 2; ++u)
  {
    for (int v = -2; v <= 2; ++v)
    {
      neighbors.emplace_back(0.5 * u, 0.5 * v, 0.01);
    }
  }
  neighbors.emplace_back(0.0, 0.0, 3.0); // another sheet: ignored
  std::vector<Eigen::Vector3d> cells;
  const Eigen::Vector3d n(0, 0, 1);
  lsi::EmptyTangentCells(
    Eigen::Vector3d::Zero(), n, 0.5, 2, 0.5, neighbors.size(),
    [&](std::size_t j) { return neighbors[j]; }, cells);
  Check(cells.size() == 25 - 1 - 10, "empty cells counted");
  for (const Eigen::Vector3d& c : cells)
  {
    Check(std::abs(c.z()) < 1e-12, "candidates lie on the tangent plane");
  }
  Eigen::Vector3d e1, e2;
  lsi::TangentBasis(Eigen::Vector3d(1, 2, 3).normalized(), e1, e2);
  Check(std::abs(e1.dot(e2)) < 1e-12 && std::abs(e1.norm() - 1) < 1e-12 &&
      std::abs(e1.dot(Eigen::Vector3d(1, 2, 3))) < 1e-12,
    "orthonormal tangent basis");
}
} // namespace

void TestSpatialOrder()
{
  // Interleaving: bit b of axis k lands on bit 3 b + k.
  Check(lsi::SpreadBits21(0x1fffff) == 0x1249249249249249ULL, "spread of all 21 bits");
  Check(lsi::SpreadBits21(5) == ((1ULL << 0) | (1ULL << 6)), "spread of 0b101");
  const double lower[3] = { 0, 0, 0 }, size[3] = { 1, 1, 1 };
  const double a[3] = { 0.1, 0.1, 0.1 }, b[3] = { 0.9, 0.1, 0.1 }, c[3] = { 0.1, 0.9, 0.9 };
  Check(lsi::MortonKey(a, lower, size) < lsi::MortonKey(b, lower, size) &&
      lsi::MortonKey(b, lower, size) < lsi::MortonKey(c, lower, size),
    "Morton order: x varies fastest, z slowest");
  // Points of one octant are contiguous in Morton order; the packed words sort fully.
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<std::uint64_t> words;
  std::vector<int> octantOf;
  for (int i = 0; i < 100000; ++i)
  {
    const double x[3] = { unit(random), unit(random), unit(random) };
    octantOf.push_back((x[0] >= 0.5) + 2 * (x[1] >= 0.5) + 4 * (x[2] >= 0.5));
    words.push_back(lsi::PackedMortonKey(x, lower, size, static_cast<std::uint32_t>(i)));
  }
  std::vector<std::uint64_t> sorted = words, scratch;
  const std::vector<std::uint64_t> unsortedCopy = words;
  lsi::RadixSortPacked(sorted, scratch);
  std::sort(words.begin(), words.end());
  Check(sorted == words, "radix sort of packed words = std::sort");
  std::vector<std::uint64_t> inPieces = unsortedCopy;
  lsi::RadixSortPacked(inPieces, scratch, 7); // pieces run in turn: the same words
  Check(inPieces == words, "radix sort in 7 pieces = in one");
  bool contiguous = true;
  for (std::size_t i = 1; i < sorted.size(); ++i)
  {
    contiguous = contiguous &&
      octantOf[static_cast<std::uint32_t>(sorted[i])] >=
        octantOf[static_cast<std::uint32_t>(sorted[i - 1])];
  }
  Check(contiguous, "Morton order keeps octants contiguous");
}

// The kd-tree built from Morton order answers like brute force, on a uniform cloud, a clustered
// one, one where a quarter of the points share one x, and two where most points lie in one
// Morton cell (cut at medians; the larger one in jobs), 40 of them at one spot; the reordered
// points and oldIndex describe the same cloud.
void TestMortonTree()
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int cloud = 0; cloud < 5; ++cloud)
  {
    // Cloud 4: a crowded cell larger than the tree cuts in parallel jobs (PointCloudIndex's
    // ParallelCell), 150,000 points.
    const std::size_t n = cloud == 4 ? 150000 : 5000;
    std::vector<double> original(3 * n);
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        original[3 * i + a] = cloud == 1          ? std::pow(unit(random), 3.0) * normal(random)
          : (cloud == 3 || cloud == 4) && i > 100 ? 0.25 + (i < 140 ? 0.0 : 1e-7 * unit(random))
                                                  : unit(random);
      }
      if (cloud == 2 && i % 4 == 0)
      {
        original[3 * i] = 0.5;
      }
    }
    lsi::UninitializedVector<double> xyz(original.begin(), original.end());
    lsi::UninitializedVector<std::uint32_t> oldIndex;
    const std::unique_ptr<lsi::PointCloudIndex> index = lsi::MortonTree(xyz, oldIndex);
    bool samePoints = oldIndex.size() == n;
    std::vector<char> seen(n, 0);
    for (std::size_t i = 0; samePoints && i < n; ++i)
    {
      samePoints =
        !seen[oldIndex[i]] && std::equal(&xyz[3 * i], &xyz[3 * i] + 3, &original[3 * oldIndex[i]]);
      seen[oldIndex[i]] = 1;
    }
    Check(samePoints, "Morton tree: points moved, none lost");
    bool sameAnswers = true;
    const std::size_t k = 28;
    std::vector<std::uint32_t> ids(k);
    std::vector<double> d2(k), all(n);
    for (int q = 0; q < 300; ++q)
    {
      // Queries anywhere, and at the points themselves (inside the dense cell for cloud 3).
      double query[3] = { unit(random), unit(random), unit(random) };
      if (q % 2)
      {
        std::copy(&xyz[3 * (q * 16 % n)], &xyz[3 * (q * 16 % n)] + 3, query);
      }
      for (std::size_t j = 0; j < n; ++j)
      {
        all[j] = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          all[j] += (xyz[3 * j + a] - query[a]) * (xyz[3 * j + a] - query[a]);
        }
      }
      std::nth_element(all.begin(), all.begin() + (k - 1), all.end());
      const bool found =
        index->Nearest(query, k, ids.data(), d2.data()) == k && d2[k - 1] == all[k - 1];
      const double bound = std::max(1.01 * all[k - 1], 1e-300);
      const bool within = index->NearestWithin(query, k, bound, ids.data(), d2.data()) == k;
      sameAnswers = sameAnswers && found && within && d2[k - 1] == all[k - 1];
    }
    const std::string what =
      "Morton tree (cloud " + std::to_string(cloud) + "): k-th nearest distance equals brute force";
    Check(sameAnswers, what.c_str());
  }
}

// A gather of the k + 1 nearest points at c serves a nearby point p when StillNearest says so:
// then p's k nearest (by brute force) are exactly the k gathered at c. Steps from tiny to a
// spacing, so that the check both holds and fails.
void TestStillNearest()
{
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const std::size_t n = 4000, k = 27;
  std::vector<double> xyz(3 * n);
  for (double& v : xyz)
  {
    v = unit(random);
  }
  auto nearest = [&](const double* q, std::size_t count) {
    std::vector<std::pair<double, std::uint32_t>> all(n);
    for (std::size_t j = 0; j < n; ++j)
    {
      double d2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        d2 += (xyz[3 * j + a] - q[a]) * (xyz[3 * j + a] - q[a]);
      }
      all[j] = { d2, static_cast<std::uint32_t>(j) };
    }
    std::partial_sort(all.begin(), all.begin() + static_cast<std::ptrdiff_t>(count), all.end());
    all.resize(count);
    return all;
  };
  std::size_t held = 0, failed = 0, wrong = 0;
  for (int trial = 0; trial < 400; ++trial)
  {
    const double c[3] = { 0.2 + 0.6 * unit(random), 0.2 + 0.6 * unit(random),
      0.2 + 0.6 * unit(random) };
    const auto gathered = nearest(c, k + 1);
    const double outer = std::sqrt(gathered[k].first);
    const double length = 0.06 * std::pow(10.0, -3.0 * unit(random)); // spacing ~0.06
    double p[3], step2 = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      const double d = length * (2.0 * unit(random) - 1.0);
      p[a] = c[a] + d;
      step2 += d * d;
    }
    double farthest2 = 0.0;
    std::vector<std::uint32_t> kept;
    for (std::size_t m = 0; m < k; ++m)
    {
      const std::uint32_t j = gathered[m].second;
      double d2 = 0.0;
      for (int a = 0; a < 3; ++a)
      {
        d2 += (xyz[3 * j + a] - p[a]) * (xyz[3 * j + a] - p[a]);
      }
      farthest2 = std::max(farthest2, d2);
      kept.push_back(j);
    }
    if (!lsi::StillNearest(std::sqrt(farthest2), std::sqrt(step2), outer))
    {
      ++failed;
      continue;
    }
    ++held;
    std::vector<std::uint32_t> truth;
    for (const auto& entry : nearest(p, k))
    {
      truth.push_back(entry.second);
    }
    std::sort(kept.begin(), kept.end());
    std::sort(truth.begin(), truth.end());
    wrong += kept == truth ? 0 : 1;
  }
  const std::string what = "a gather still nearest when StillNearest holds (" +
    std::to_string(held) + " held, " + std::to_string(failed) + " did not, " +
    std::to_string(wrong) + " wrong)";
  std::cout << what << "\n";
  Check(held > 50 && failed > 50 && wrong == 0, what.c_str());
}

// The points of a side x side x side unit lattice.
lsi::UninitializedVector<double> Lattice(int side)
{
  lsi::UninitializedVector<double> xyz;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y)
      for (int z = 0; z < side; ++z)
        xyz.insert(xyz.end(), { double(x), double(y), double(z) });
  return xyz;
}

// The neighbour lists are computed when first needed, some with a search bounded by a nearby
// sample's radius (LevelSetNeighborhoods): the bound must not change the list, not even which of
// several samples at the same distance comes last. On a lattice, 10 neighbours cut through the
// shell of 12 at distance sqrt(2).
void TestBoundedSearchKeepsTies()
{
  lsi::UninitializedVector<double> xyz = Lattice(14);
  lsi::UninitializedVector<std::uint32_t> oldIndex;
  const std::unique_ptr<lsi::PointCloudIndex> tree = lsi::MortonTree(xyz, oldIndex);
  const lsi::PointCloudIndex& index = *tree;
  const std::size_t n = xyz.size() / 3, k = 11;
  std::vector<std::uint32_t> ids(k), bounded(k);
  std::vector<double> d2(k), boundedD2(k);
  std::size_t compared = 0, same = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    index.Nearest(&xyz[3 * i], k, ids.data(), d2.data());
    for (const double factor : { 1.0, 1.2, 2.0, 9.0 })
    {
      if (index.NearestWithin(
            &xyz[3 * i], k, factor * d2[k - 1] * 1.0000001, bounded.data(), boundedD2.data()) == k)
      {
        ++compared;
        same += ids == bounded && d2 == boundedD2 ? 1 : 0;
      }
    }
  }
  const std::string what =
    "a bounded search keeps the unbounded one's neighbours, ties included (" +
    std::to_string(same) + " of " + std::to_string(compared) + ")";
  Check(compared == 4 * n && same == compared, what.c_str());
}

// Nearest and NearestWithin walk the tree themselves (PointCloudIndex::SearchNearest): they must
// return what nanoflann's own search of the same tree returns, the same indices in the same
// order and the same distances to the bit. On a lattice (shells of equal distances, cut by k),
// with a lump of 40 coincident points (a leaf of more than 16), queries at points and between
// them, k up to 150 (past the set kept on the stack), without a bound and with bounds that do and
// do not hold k points; and on a tree built by nanoflann (not from Morton order).
void TestSearchMatchesNanoflann()
{
  lsi::UninitializedVector<double> xyz = Lattice(12);
  for (int c = 0; c < 40; ++c)
  {
    xyz.insert(xyz.end(), { 3.0, 4.0, 5.0 });
  }
  const std::vector<double> plain(xyz.begin(), xyz.end());
  lsi::UninitializedVector<std::uint32_t> oldIndex;
  const std::unique_ptr<lsi::PointCloudIndex> morton = lsi::MortonTree(xyz, oldIndex);
  const std::unique_ptr<lsi::PointCloudIndex> built = lsi::IndexOfPoints(plain);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> offset(-0.6, 0.6);
  std::size_t compared = 0, same = 0, full = 0;
  for (const lsi::PointCloudIndex* index : { morton.get(), built.get() })
  {
    const std::vector<double> points =
      index == morton.get() ? std::vector<double>(xyz.begin(), xyz.end()) : plain;
    const std::size_t n = points.size() / 3;
    for (const std::size_t k : { 1, 11, 28, 54, 70, 150 })
    {
      std::vector<std::uint32_t> ids(k), reference(k);
      std::vector<double> d2(k), referenceD2(k);
      for (std::size_t q = 0; q < n; q += 5)
      {
        double query[3] = { points[3 * q], points[3 * q + 1], points[3 * q + 2] };
        if (q % 2)
        {
          for (double& x : query)
          {
            x += offset(random);
          }
        }
        for (const double bound : { DBL_MAX, 0.5, 2.0, 4.0, 9.0 })
        {
          const std::size_t found = bound == DBL_MAX
            ? index->Nearest(query, k, ids.data(), d2.data())
            : index->NearestWithin(query, k, bound, ids.data(), d2.data());
          const std::size_t expected =
            index->NanoflannNearest(query, k, bound, reference.data(), referenceD2.data());
          ++compared;
          full += found == k ? 1 : 0;
          same += found == expected &&
              std::equal(ids.begin(), ids.begin() + found, reference.begin()) &&
              std::equal(d2.begin(), d2.begin() + found, referenceD2.begin())
            ? 1
            : 0;
        }
      }
    }
  }
  const std::string what = "the tree's own k-nearest walk returns nanoflann's answers (" +
    std::to_string(same) + " of " + std::to_string(compared) + " searches, " +
    std::to_string(full) + " with k found)";
  Check(same == compared && full > compared / 3 && full < compared, what.c_str());
}

// AnyWithin (the slide's look for clamped samples near a point): on a lattice, whether a point
// with an accepted index lies strictly within the radius, against a scan of every point; and the
// walk stops at the first accepted point.
void TestAnyWithin()
{
  lsi::UninitializedVector<double> xyz = Lattice(10);
  lsi::UninitializedVector<std::uint32_t> oldIndex;
  const std::unique_ptr<lsi::PointCloudIndex> tree = lsi::MortonTree(xyz, oldIndex);
  const std::size_t n = xyz.size() / 3;
  std::size_t agreed = 0, asked = 0, found = 0;
  for (const double radius : { 0.5, 1.0, 1.7, 3.2 })
  {
    for (std::size_t q = 0; q < n; q += 7)
    {
      const double query[3] = { xyz[3 * q] + 0.3, xyz[3 * q + 1] - 0.2, xyz[3 * q + 2] + 0.1 };
      auto accepted = [](std::uint32_t i) { return i % 5 == 3; };
      bool scanned = false;
      for (std::size_t i = 0; i < n; ++i)
      {
        double d2 = 0.0;
        for (int d = 0; d < 3; ++d)
          d2 += (xyz[3 * i + d] - query[d]) * (xyz[3 * i + d] - query[d]);
        scanned = scanned || (d2 < radius * radius && accepted(static_cast<std::uint32_t>(i)));
      }
      int afterAccepted = 0; // points offered after one was accepted: the walk must stop
      bool taken = false;
      const bool any = tree->AnyWithin(query, radius * radius, [&](std::uint32_t i, double d2) {
        afterAccepted += taken ? 1 : 0;
        taken = taken || accepted(i);
        return accepted(i) && d2 < radius * radius;
      });
      agreed += any == scanned && afterAccepted == 0 ? 1 : 0;
      found += any ? 1 : 0;
      ++asked;
    }
  }
  const std::string what = "AnyWithin agrees with a scan of every point (" +
    std::to_string(agreed) + " of " + std::to_string(asked) + ", " + std::to_string(found) +
    " found)";
  Check(agreed == asked && found > 0 && found < asked, what.c_str());
}

void TestRosenthalLinsen()
{
  // phi relaxes towards g by the rate, and never by more than the step bound.
  Check(std::abs(lsi::RosenthalLinsenValue(1.0, 1.0, 0.0, 0.5, 10.0) - 0.5) < 1e-15,
    "half-way towards the target");
  Check(lsi::RosenthalLinsenValue(2.0, 1.0, 2.0, 0.5, 10.0) == 2.0, "the target is a fixed point");
  Check(
    std::abs(lsi::RosenthalLinsenValue(0.0, 1.0, 10.0, 0.5, 0.3) - 0.3) < 1e-15, "step bounded");
}

// SolveOnLine: onto the level of a field that flattens (a Gaussian bump, level at r = 1), from
// inside and from far outside where Newton's first step overshoots; false when the level is out
// of reach, and for a zero or infinite reach (it must return, not loop).
void TestSolveOnLine()
{
  const double level = std::exp(-1.0);
  auto bump = [&](const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient) {
    const double e = std::exp(-p.squaredNorm());
    value = e - level;
    gradient = -2.0 * e * p;
    return true;
  };
  const Eigen::Vector3d out(1, 0, 0);
  Eigen::Vector3d g;
  bool ok = true;
  for (double start : { 0.6, 0.9, 1.6, 2.5 })
  {
    Eigen::Vector3d p(start, 0, 0);
    ok = ok && lsi::SolveOnLine(p, out, bump, 3.0, 1e-12, g) && std::abs(p.x() - 1.0) < 1e-9;
  }
  Check(ok, "SolveOnLine reaches the level from inside and from the flat outside");
  // From the flat outside the level is bracketed, and narrowed far below a coarse tolerance (a
  // result anywhere in a bracket 1e-3 wide would depend on where the search started): two
  // starts 1e-13 apart land within 1e-12 of the level and of each other.
  {
    Eigen::Vector3d a(2.9, 0, 0), b(2.9 + 1e-13, 0, 0);
    const bool solved =
      lsi::SolveOnLine(a, out, bump, 3.0, 1e-3, g) && lsi::SolveOnLine(b, out, bump, 3.0, 1e-3, g);
    Check(solved && std::abs(a.x() - 1.0) < 1e-12 && std::abs(a.x() - b.x()) < 1e-12,
      "SolveOnLine: a bracketed level found far within the tolerance");
  }
  Eigen::Vector3d p(0.2, 0, 0);
  Check(!lsi::SolveOnLine(p, out, bump, 0.3, 1e-12, g) && p.x() == 0.2,
    "SolveOnLine: false (p unchanged) when the level is out of reach");
  Check(!lsi::SolveOnLine(p, out, bump, 0.0, 1e-12, g) &&
      !lsi::SolveOnLine(p, out, bump, std::numeric_limits<double>::infinity(), 1e-12, g) &&
      !lsi::SolveOnLine(p, out, bump, std::nan(""), 1e-12, g),
    "SolveOnLine: false for a zero, infinite or NaN reach");
  // Newton's steps only: from just inside they converge, to the same point as the full solve;
  // from the flat outside the first step overshoots, so only the bracketing finds the level.
  Eigen::Vector3d full(0.9, 0, 0), newton(0.9, 0, 0), gFull, gNewton;
  Check(lsi::SolveOnLine(full, out, bump, 3.0, 1e-12, gFull) &&
      lsi::SolveOnLine(newton, out, bump, 3.0, 1e-12, gNewton, true) && newton == full &&
      gNewton == gFull,
    "SolveOnLine, Newton only: the same point to the bit where Newton's steps converge");
  p = Eigen::Vector3d(2.5, 0, 0);
  Check(!lsi::SolveOnLine(p, out, bump, 3.0, 1e-12, g, true) && p.x() == 2.5 &&
      lsi::SolveOnLine(p, out, bump, 3.0, 1e-12, g) && std::abs(p.x() - 1.0) < 1e-9,
    "SolveOnLine, Newton only: false (p unchanged) where only the bracketing finds the level");
}

void TestSlideOntoDataLevel()
{
  // f - f_iso = 0.3 - x (a plane at x = 0.3, f larger at smaller x): the outward normal is +x.
  // From the origin the point must slide to x = 0.3 along the normal, wherever the line starts.
  auto plane = [](const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient,
                 Eigen::Matrix3d& hessian) {
    value = 0.3 - p.x();
    gradient = Eigen::Vector3d(-1, 0, 0);
    hessian.setZero();
    return true;
  };
  Eigen::Vector3d p(0.0, 0.2, -0.1), g;
  Check(lsi::SlideOntoDataLevel(p, Eigen::Vector3d(1, 0, 0), plane, 1.0, 3, g) &&
      (p - Eigen::Vector3d(0.3, 0.2, -0.1)).norm() < 1e-12,
    "slides onto a plane exactly");
  p = Eigen::Vector3d(0.0, 0.0, 0.0);
  Check(lsi::SlideOntoDataLevel(p, Eigen::Vector3d(1, 0, 0), plane, 0.1, 3, g) &&
      std::abs(p.x() - 0.1) < 1e-12,
    "the move is bounded");
  // Along a tilted normal the line meets the plane at x = 0.3 too (Newton on the line).
  const Eigen::Vector3d tilted = Eigen::Vector3d(1, 1, 0).normalized();
  p = Eigen::Vector3d(0.0, 0.0, 0.0);
  Check(lsi::SlideOntoDataLevel(p, tilted, plane, 1.0, 3, g) && std::abs(p.x() - 0.3) < 1e-12,
    "slides along the given normal");
  // A sphere, f - f_iso = 1 - |x|: from 1.2 along the radial normal, converges to radius 1.
  auto sphere = [](const Eigen::Vector3d& q, double& value, Eigen::Vector3d& gradient,
                  Eigen::Matrix3d& hessian) {
    value = 1.0 - q.norm();
    gradient = -q.normalized();
    hessian = -(Eigen::Matrix3d::Identity() - gradient * gradient.transpose()) / q.norm();
    return true;
  };
  p = Eigen::Vector3d(1.2, 0, 0);
  Check(lsi::SlideOntoDataLevel(p, Eigen::Vector3d(1, 0, 0), sphere, 0.5, 3, g) &&
      std::abs(p.norm() - 1.0) < 1e-12,
    "slides onto a sphere");
  // A field quadratic along the line, f - f_iso = 1 - |x|^2, from 1.4 off the radial line: each
  // step solves the quadratic model, so the first lands on the zero; the second is then below
  // the tolerance and ends the slide. Newton's step alone (curvature ignored) would stop about
  // 0.1 short of it.
  int evaluations = 0;
  auto paraboloid = [&](const Eigen::Vector3d& q, double& value, Eigen::Vector3d& gradient,
                      Eigen::Matrix3d& hessian) {
    ++evaluations;
    value = 1.0 - q.squaredNorm();
    gradient = -2.0 * q;
    hessian = -2.0 * Eigen::Matrix3d::Identity();
    return true;
  };
  const Eigen::Vector3d along = Eigen::Vector3d(1, 0.5, 0).normalized();
  const Eigen::Vector3d from(0.2, -0.1, 0.0);
  p = from + 1.4 * along;
  Check(lsi::SlideOntoDataLevel(p, along, paraboloid, 1.0, 3, g, 1e-9) &&
      std::abs(p.squaredNorm() - 1.0) < 1e-12 && evaluations == 2 &&
      ((p - from).normalized() - along).norm() < 1e-12,
    "a quadratic field: on the zero after one step, and stops after the next");
  // Data whose gradient contradicts the normal: refused, point unchanged.
  p = Eigen::Vector3d(0, 0, 0);
  Check(!lsi::SlideOntoDataLevel(p, Eigen::Vector3d(-1, 0, 0), plane, 1.0, 3, g) && p.norm() == 0.0,
    "refuses a contradicting gradient");
}

// The tangent basis: (u, v, n) orthonormal and right-handed for any unit n, including normals
// along the axes and with equal components (the tie-breaking cases); splat corners lie in the
// tangent plane at the given radius.
void TestTangentBasis()
{
  const double s = 1.0 / std::sqrt(2.0), t = 1.0 / std::sqrt(3.0);
  const Eigen::Vector3d normals[] = { { 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { s, s, 0 },
    { 0, s, -s }, { s, 0, s }, { t, t, t }, { -t, t, -t },
    Eigen::Vector3d(0.3, -0.5, 0.8).normalized() };
  double worst = 0.0;
  for (const Eigen::Vector3d& n : normals)
  {
    Eigen::Vector3d u, v;
    lsi::TangentBasis(n, u, v);
    worst = std::max({ worst, std::abs(u.norm() - 1.0), std::abs(v.norm() - 1.0),
      std::abs(u.dot(v)), std::abs(u.dot(n)), std::abs(v.dot(n)), (u.cross(v) - n).norm() });
    double corners[3 * 8];
    lsi::DiskCorners(Eigen::Vector3d(1, 2, 3), n, 0.5, 8, corners);
    for (int k = 0; k < 8; ++k)
    {
      const Eigen::Vector3d d = Eigen::Vector3d(&corners[3 * k]) - Eigen::Vector3d(1, 2, 3);
      worst = std::max({ worst, std::abs(d.dot(n)), std::abs(d.norm() - 0.5) });
    }
  }
  std::cout << "tangent basis: largest error " << worst << "\n";
  Check(worst < 1e-14, "tangent basis orthonormal and right-handed, splat corners in the plane");
}

// Each SPH kernel integrates to 1 over its support (4 pi int W r^2 dr, Simpson's rule), for two
// support radii (the kernel scales as 1 / H^3), and is positive inside, zero at and beyond H.
void TestSPHKernels()
{
  for (const lsi::SPHKernelName& names : lsi::SPHKernelNames)
  {
    const lsi::SPHKernel kernel = names.Kernel;
    for (double H : { 1.0, 0.003 })
    {
      const int steps = 3000; // even
      double integral = 0.0;
      for (int s = 0; s <= steps; ++s)
      {
        const double r = H * s / steps;
        const double weight = (s == 0 || s == steps) ? 1.0 : (s % 2 ? 4.0 : 2.0);
        integral +=
          weight * 4.0 * 3.14159265358979323846 * r * r * lsi::SPHKernelValue(kernel, r, H);
      }
      integral *= H / steps / 3.0;
      std::cout << "SPH kernel " << static_cast<int>(kernel) << ", H " << H << ": integral "
                << integral << "\n";
      Check(std::abs(integral - 1.0) < 1e-6, "SPH kernel integrates to 1");
    }
    // SWIFT's h is twice the kernel's standard deviation (Dehnen & Aly 2012): gamma = H / (2
    // sigma), sigma^2 = <r^2> / 3 over the kernel.
    double secondMoment = 0.0;
    const int steps = 3000;
    for (int s = 0; s <= steps; ++s)
    {
      const double r = static_cast<double>(s) / steps;
      const double weight = (s == 0 || s == steps) ? 1.0 : (s % 2 ? 4.0 : 2.0);
      secondMoment +=
        weight * 4.0 * 3.14159265358979323846 * r * r * r * r * lsi::SPHKernelValue(kernel, r, 1.0);
    }
    secondMoment /= 3.0 * steps;
    const double gamma = 1.0 / (2.0 * std::sqrt(secondMoment / 3.0));
    std::cout << names.Label << ": H / (2 sigma) " << gamma << ", SWIFT's gamma "
              << names.SwiftGamma << "\n";
    Check(std::abs(gamma - names.SwiftGamma) < 1e-6, "SWIFT's gamma is H / (2 sigma)");
    // Known values of the published forms at q = 0 and q = 1/2 (support 1): cubic spline
    // 8/pi and 8/pi * 1/4; quintic (3^7 / (40 pi)) (1 - 6 (2/3)^5 + 15 (1/3)^5) and
    // (3^7 / (40 pi)) ((1/2)^5 - 6 (1/6)^5); Wendland C2 21/(2 pi) and 21/(2 pi) 3/16;
    // quartic (5^6 / (512 pi)) 0.368 (Dehnen & Aly's W(0) coefficient) and
    // (5^6 / (512 pi)) (1/2)^4 - 5 (1/10)^4); Wendland C4 495/(32 pi) and
    // 495/(32 pi) (1/2)^6 (1 + 3 + 35/12); Wendland C6 1365/(64 pi) and
    // 1365/(64 pi) (1/2)^8 (1 + 4 + 25/4 + 4).
    const double pi = 3.14159265358979323846, quintic = 2187.0 / (40.0 * pi),
                 quartic = 15625.0 / (512.0 * pi), c4 = 495.0 / (32.0 * pi),
                 c6 = 1365.0 / (64.0 * pi);
    const double expected[6][2] = { { 8.0 / pi, 2.0 / pi },
      { quintic * (1.0 - 6.0 * std::pow(2.0 / 3.0, 5) + 15.0 * std::pow(1.0 / 3.0, 5)),
        quintic * (std::pow(0.5, 5) - 6.0 * std::pow(1.0 / 6.0, 5)) },
      { 21.0 / (2.0 * pi), 21.0 / (2.0 * pi) * 3.0 / 16.0 },
      { quartic * 0.368, quartic * (std::pow(0.5, 4) - 5.0 * std::pow(0.1, 4)) },
      { c4, c4 * std::pow(0.5, 6) * (4.0 + 35.0 / 12.0) },
      { c6, c6 * std::pow(0.5, 8) * (9.0 + 25.0 / 4.0) } };
    const int k = static_cast<int>(kernel);
    Check(std::abs(lsi::SPHKernelValue(kernel, 0.0, 1.0) - expected[k][0]) < 1e-12 &&
        std::abs(lsi::SPHKernelValue(kernel, 0.5, 1.0) - expected[k][1]) < 1e-12,
      "SPH kernel values at q = 0 and 1/2");
    Check(lsi::SPHKernelValue(kernel, 0.999, 1.0) > 0.0 &&
        lsi::SPHKernelValue(kernel, 1.0, 1.0) == 0.0 &&
        lsi::SPHKernelValue(kernel, 2.0, 1.0) == 0.0,
      "SPH kernel positive inside its support, zero at and beyond it");
  }
}

// dW/dr against central differences of W, at points of every piece of each kernel; the
// gradient AccumulateKernel adds against differences of the value it adds; names as SWIFT
// writes them.
void TestSPHKernelGradients()
{
  double worst = 0.0;
  for (const lsi::SPHKernelName& names : lsi::SPHKernelNames)
  {
    const lsi::SPHKernel kernel = names.Kernel;
    for (double H : { 1.0, 0.003 })
    {
      for (double q : { 0.1, 0.15, 0.3, 0.45, 0.5, 0.55, 0.7, 0.9, 0.99 })
      {
        const double r = q * H, step = 1e-6 * H;
        const double numeric =
          (lsi::SPHKernelValue(kernel, r + step, H) - lsi::SPHKernelValue(kernel, r - step, H)) /
          (2.0 * step);
        const double analytic = lsi::SPHKernelDerivative(kernel, r, H);
        const double scale = lsi::SPHKernelValue(kernel, 0.0, H) / H;
        worst = std::max(worst, std::abs(numeric - analytic) / scale);
      }
    }
    const double x[3] = { 0.31, -0.2, 0.15 }, xj[3] = { 0.0, 0.05, 0.0 };
    double value = 0.0, gradient[3] = { 0, 0, 0 };
    lsi::AccumulateKernel(kernel, x, xj, 0.8, 2.5, value, gradient);
    for (int k = 0; k < 3; ++k)
    {
      double xp[3] = { x[0], x[1], x[2] }, xm[3] = { x[0], x[1], x[2] };
      xp[k] += 1e-6;
      xm[k] -= 1e-6;
      double vp = 0.0, vm = 0.0, unused[3] = { 0, 0, 0 };
      lsi::AccumulateKernel(kernel, xp, xj, 0.8, 2.5, vp, unused);
      lsi::AccumulateKernel(kernel, xm, xj, 0.8, 2.5, vm, unused);
      worst = std::max(worst, std::abs((vp - vm) / 2e-6 - gradient[k]) / (2.5 * 10.0));
    }
  }
  // The loop form (KernelShape) gives the same numbers as the reference form.
  double shapeWorst = 0.0;
  auto compare = [&shapeWorst](auto shape) {
    constexpr lsi::SPHKernel K = decltype(shape)::value;
    const double c = lsi::Normalization<K>(), H = 0.7;
    for (double q = 0.0; q < 1.0; q += 0.01)
    {
      double w, dw;
      const double r = q * H;
      lsi::KernelShape<K>(q, w, dw);
      shapeWorst = std::max(shapeWorst,
        std::abs(c * w / (H * H * H) - lsi::SPHKernelValue(K, r, H)) +
          std::abs(c * dw / (H * H * H * H) - lsi::SPHKernelDerivative(K, r, H)));
    }
  };
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::CubicSpline>());
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::QuinticSpline>());
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::WendlandC2>());
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::QuarticSpline>());
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::WendlandC4>());
  compare(std::integral_constant<lsi::SPHKernel, lsi::SPHKernel::WendlandC6>());
  std::cout << "SPH kernel loop form: worst difference " << shapeWorst << "\n";
  Check(shapeWorst < 1e-12, "KernelShape equals SPHKernelValue and SPHKernelDerivative");
  std::cout << "SPH kernel derivatives: worst relative difference " << worst << "\n";
  Check(worst < 1e-6, "SPH kernel derivative matches differences of the kernel");
  // Every name SWIFT's kernel_hydro.h writes, and the markers, read back; others are refused.
  const std::pair<const char*, lsi::SPHKernel> names[] = { { "Cubic spline (M4)",
                                                             lsi::SPHKernel::CubicSpline },
    { "Quartic spline (M5)", lsi::SPHKernel::QuarticSpline },
    { "Quintic spline (M6)", lsi::SPHKernel::QuinticSpline },
    { "Wendland C2", lsi::SPHKernel::WendlandC2 }, { "Wendland C4", lsi::SPHKernel::WendlandC4 },
    { "Wendland C6", lsi::SPHKernel::WendlandC6 }, { "wendland_c4", lsi::SPHKernel::WendlandC4 } };
  bool namesRead = true;
  for (const auto& name : names)
  {
    lsi::SPHKernel read = lsi::SPHKernel::CubicSpline, marked = lsi::SPHKernel::CubicSpline;
    namesRead = namesRead && lsi::SPHKernelFromName(name.first, read) && read == name.second &&
      lsi::SPHKernelFromName(lsi::NamesOf(name.second).Marker, marked) && marked == name.second;
  }
  lsi::SPHKernel untouched = lsi::SPHKernel::WendlandC6;
  for (const char* other : { "Gaussian", "Wendland C8", "", "cubic or quintic" })
  {
    namesRead = namesRead && !lsi::SPHKernelFromName(other, untouched);
  }
  Check(
    namesRead && untouched == lsi::SPHKernel::WendlandC6, "SPH kernel names as SWIFT writes them");
}

// The level set after an isovalue change, on f = 20 - r (|grad f| = 1) and f = 5 (20 - r): phi
// drops by the change over |grad f|, capped at the largest move either way; a zero gradient
// moves it by the cap in the change's direction.
void TestIsoValueShift()
{
  Check(std::abs(lsi::LevelSetAfterIsoValueChange(1.0, 0.1, 1.0, 1.0) - 0.9) < 1e-15,
    "raising f_iso by 0.1 where |grad f| = 1 lowers phi by 0.1");
  Check(std::abs(lsi::LevelSetAfterIsoValueChange(1.0, 0.1, 5.0, 1.0) - 0.98) < 1e-15,
    "where |grad f| = 5 the level moves a fifth as far");
  Check(std::abs(lsi::LevelSetAfterIsoValueChange(-2.0, -0.3, 1.0, 1.0) + 1.7) < 1e-15,
    "lowering f_iso raises phi");
  Check(lsi::LevelSetAfterIsoValueChange(0.0, 10.0, 1.0, 0.5) == -0.5 &&
      lsi::LevelSetAfterIsoValueChange(0.0, -10.0, 1e-3, 0.5) == 0.5,
    "the move is capped at the largest move of the surface");
  Check(lsi::LevelSetAfterIsoValueChange(0.0, 0.2, 0.0, 0.5) == -0.5,
    "a zero gradient moves phi by the cap, in the change's direction");
}

// The per-sample arrays of UninitializedVector.h hold what resize() would have put there: the
// kept elements and the given value (pages mapped ahead or not); explicit values are written.
void TestSampleArrays()
{
  for (const std::size_t count : { std::size_t(10), std::size_t(300000), std::size_t(1) << 21 })
  {
    std::vector<double> values = { 1.5, -2.0, 3.25 };
    lsi::ResizeMapped(values, count, 7.0);
    bool kept =
      values.size() == count && values[0] == 1.5 && values[1] == -2.0 && values[2] == 3.25;
    bool filled = std::all_of(values.begin() + 3, values.end(), [](double v) { return v == 7.0; });
    Check(kept && filled, "ResizeMapped keeps the elements and fills the new ones");
    lsi::ResizeMapped(values, 2);
    Check(values.size() == 2 && values[1] == -2.0, "ResizeMapped shrinks like resize");
    std::vector<std::uint32_t> ids;
    lsi::ResizeMapped(ids, count);
    Check(std::all_of(ids.begin(), ids.end(), [](std::uint32_t v) { return v == 0; }),
      "ResizeMapped value-initialises by default");
    lsi::UninitializedVector<double> explicitValues(count, -1.25);
    Check(std::all_of(
            explicitValues.begin(), explicitValues.end(), [](double v) { return v == -1.25; }),
      "UninitializedVector writes explicit values");
  }
  // Written memory, mapped again over a range that starts and ends inside pages: unchanged.
  std::vector<char> written(std::size_t(3) << 20, 'x');
  lsi::MapPagesNow(written.data() + 3, written.size() - 10);
  lsi::MapPagesNow(written.data(), 10);
  Check(std::all_of(written.begin(), written.end(), [](char c) { return c == 'x'; }),
    "MapPagesNow leaves the contents as they are");
  // Huge pages asked for over written memory, over ranges that start and end inside 2 MB blocks
  // or hold none, and over a vector's capacity before it is filled: contents unchanged.
  std::vector<double> dense(std::size_t(5) << 18, 2.5);
  lsi::AdviseHugePages(dense.data() + 1, dense.size() * sizeof(double) - 16);
  lsi::AdviseHugePages(dense.data(), 100);
  lsi::AdviseHugePages(nullptr, 0);
  Check(std::all_of(dense.begin(), dense.end(), [](double v) { return v == 2.5; }),
    "AdviseHugePages leaves the contents as they are");
  lsi::UninitializedVector<std::uint64_t> fresh;
  fresh.reserve(std::size_t(1) << 20);
  lsi::AdviseHugePages(fresh);
  lsi::ResizeMapped(fresh, std::size_t(1) << 20, std::uint64_t(9));
  Check(std::all_of(fresh.begin(), fresh.end(), [](std::uint64_t v) { return v == 9; }),
    "a vector filled after AdviseHugePages holds its values");
}

// The stored densities against the kernel sums: log ratios per particle in the three
// conventions, unusable particles left out, and the convention whose median is nearest 0.
void TestDensityConsistency()
{
  lsi::DensityLogRatios r;
  Check(lsi::LogRatiosOf(2.0, 4.0, 2.0, r) && r.Gather == 0.0 &&
      std::abs(r.Scatter - std::log(2.0)) < 1e-15 && std::abs(r.Symmetric - std::log(1.5)) < 1e-15,
    "density ratios: gather 2 / 2, scatter 4 / 2, symmetric 3 / 2, as logarithms");
  Check(!lsi::LogRatiosOf(2.0, 4.0, 0.0, r) && !lsi::LogRatiosOf(2.0, 4.0, std::nan(""), r) &&
      !lsi::LogRatiosOf(0.0, 4.0, 2.0, r) && !lsi::LogRatiosOf(2.0, HUGE_VAL, 2.0, r),
    "density ratios: a zero, NaN or infinite density or sum is not counted");
  const std::vector<double> gather = { 0.01, -0.02, 0.5, 0.03 }, scatter(4, 0.3),
                            symmetric(4, -0.1);
  const lsi::DensityMismatch m = lsi::MedianDensityMismatch(gather, scatter, symmetric);
  Check(m.Particles == 4 && std::abs(m.MedianLogRatio - 0.02) < 1e-15 &&
      std::string(m.Convention) == "gather" && std::abs(m.Factor() - std::exp(0.02)) < 1e-15,
    "density mismatch: the gather median (0.01 + 0.03) / 2, nearest 0 of 0.02, 0.3, -0.1");
  const std::vector<double> shuffled = { 0.5, 0.03, -0.02, 0.01 };
  const lsi::DensityMismatch n = lsi::MedianDensityMismatch(scatter, shuffled, { -0.4, 0.2, -0.3 });
  Check(n.MedianLogRatio == m.MedianLogRatio && std::string(n.Convention) == "scatter",
    "density mismatch: the same median in any order, whichever convention it is");
  const lsi::DensityMismatch both = lsi::MedianDensityMismatch({ -0.7 }, { 0.8 }, { 0.75 });
  Check(both.MedianLogRatio == -0.7 && std::abs(both.Factor() - std::exp(0.7)) < 1e-15,
    "density mismatch: sums below the stored densities give a factor above 1 too");
  Check(lsi::MedianDensityMismatch({}, {}, {}).Factor() == 1.0,
    "density mismatch: no particles, a factor of 1");
}

// The partition of space over ranks: parts of about equal weight, every sample of a part on its
// side of each cut (the parts' boxes do not overlap), weights counted (a sample standing for
// many particles), repeated coordinates, fewer samples than parts, one part.
void TestSpatialPartition()
{
  std::mt19937 random(5);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<double> xyz, weights;
  for (int k = 0; k < 6000; ++k)
  {
    // A dense clump and a sparse background: equal counts need unequal volumes.
    const bool clump = k % 3 != 0;
    for (int d = 0; d < 3; ++d)
    {
      xyz.push_back(clump ? 0.3 + 0.05 * uniform(random) : uniform(random) * (d == 0 ? 4 : 1));
    }
    weights.push_back(1.0);
  }
  for (int parts : { 1, 2, 3, 5, 8 })
  {
    const lsi::SpatialPartition partition(xyz, weights, parts);
    std::vector<double> count(parts, 0.0);
    std::vector<double> box(6 * parts);
    for (int p = 0; p < parts; ++p)
    {
      box[6 * p] = box[6 * p + 2] = box[6 * p + 4] = HUGE_VAL;
      box[6 * p + 1] = box[6 * p + 3] = box[6 * p + 5] = -HUGE_VAL;
    }
    bool inRange = true;
    for (std::size_t k = 0; k < weights.size(); ++k)
    {
      const int p = partition.PartOf(&xyz[3 * k]);
      inRange = inRange && p >= 0 && p < parts;
      if (!inRange)
      {
        break;
      }
      count[p] += 1.0;
      for (int d = 0; d < 3; ++d)
      {
        box[6 * p + 2 * d] = std::min(box[6 * p + 2 * d], xyz[3 * k + d]);
        box[6 * p + 2 * d + 1] = std::max(box[6 * p + 2 * d + 1], xyz[3 * k + d]);
      }
    }
    Check(inRange, "spatial partition: every sample in a part");
    const double mean = 6000.0 / parts;
    Check(*std::max_element(count.begin(), count.end()) <= 1.01 * mean + 1 &&
        *std::min_element(count.begin(), count.end()) >= 0.99 * mean - 1,
      "spatial partition: parts of equal counts to 1%");
    bool apart = true;
    for (int a = 0; a < parts; ++a)
    {
      for (int b = a + 1; b < parts; ++b)
      {
        bool overlap = true;
        for (int d = 0; d < 3; ++d)
        {
          overlap = overlap && box[6 * a + 2 * d] <= box[6 * b + 2 * d + 1] &&
            box[6 * b + 2 * d] <= box[6 * a + 2 * d + 1];
        }
        apart = apart && !overlap;
      }
    }
    Check(apart, "spatial partition: the parts' boxes do not overlap");
  }
  // Weights: the first half of the samples (x < 0.5) stands for three times as many particles,
  // so the cut into two lies in it, where a quarter of the samples are on its left.
  std::vector<double> line, heavy;
  for (int k = 0; k < 1000; ++k)
  {
    line.insert(line.end(), { (k + 0.5) / 1000.0, 0.0, 0.0 });
    heavy.push_back(k < 500 ? 3.0 : 1.0);
  }
  const lsi::SpatialPartition weighted(line, heavy, 2);
  int left = 0;
  for (int k = 0; k < 1000; ++k)
  {
    left += weighted.PartOf(&line[3 * k]) == 0 ? 1 : 0;
  }
  Check(left >= 330 && left <= 336, "spatial partition: weighted halves (333 samples left)");
  // Every sample at one place, and fewer samples than parts: valid parts, none left out.
  const std::vector<double> same = { 1, 2, 3, 1, 2, 3, 1, 2, 3 }, ones = { 1, 1, 1 };
  const lsi::SpatialPartition repeated(same, ones, 4);
  const double elsewhere[3] = { -5, 7, 0 };
  const int p = repeated.PartOf(same.data()), q = repeated.PartOf(elsewhere);
  Check(p >= 0 && p < 4 && q >= 0 && q < 4, "spatial partition: repeated samples, 4 parts");
  const lsi::SpatialPartition none({}, {}, 3);
  const int r = none.PartOf(elsewhere);
  Check(r >= 0 && r < 3, "spatial partition: no samples");
}

int main()
{
  TestSampleArrays();
  TestDensityConsistency();
  TestIsoValueShift();
  TestTangentBasis();
  TestSPHKernels();
  TestSPHKernelGradients();
  TestSpatialOrder();
  TestSpatialPartition();
  TestMortonTree();
  TestStillNearest();
  TestBoundedSearchKeepsTies();
  TestSearchMatchesNanoflann();
  TestAnyWithin();
  TestRosenthalLinsen();
  TestSlideOntoDataLevel();
  TestSolveOnLine();
  TestSplines();
  TestMLS();
  TestSolveSymmetricDefinite();
  TestQuadraticFit();
  TestTheorem1();
  TestReinitialization();
  TestIsopoints();
  TestCompletion();
  std::cout << (failures ? "numerics tests FAILED\n" : "numerics tests passed\n");
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
