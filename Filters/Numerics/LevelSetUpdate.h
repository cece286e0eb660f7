// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Per-sample update formulas of the level-set evolution (paper eq. 9 and 13) and of the
// reinitialisation (eq. 10). Plain C++: unit-tested in Testing/Cxx/TestNumerics.cxx.
#ifndef LevelSetUpdate_h
#define LevelSetUpdate_h

#include "LevelSetSplines.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace lsi
{

/// Coefficients of one explicit Euler step of the evolution.
struct EvolutionCoefficients
{
  double TimeStep = 1.0;
  double Epsilon = 1.0;                // width of delta/sign in the main term
  double CurvatureEpsilon = 1.0;       // width of delta in the curvature term (eps')
  double CurvatureWeight = 0.0;        // lambda
  double DistanceRegularization = 0.0; // mu (eq. 13; 0 for the scheme with reinitialisation)
};

/// The main (fitting) term of eq. 9: delta_eps(phi) (sgn(f - f_iso) - sgn_eps(phi)).
/// `delta` and `sign` are the regularised functions, passed in so that the appendix's
/// triangular functions can be checked with the same code.
template <typename DeltaFn, typename SignFn>
double MainTermStep(double phi, double signOfData, double timeStep, DeltaFn delta, SignFn sign)
{
  return phi + timeStep * delta(phi) * (signOfData - sign(phi));
}

/// phi^{k+1} at one sample. `curvature` is div(grad phi / |grad phi|) there, `regularization`
/// is div((|grad phi| - 1) grad phi / |grad phi|) (only used when mu != 0).
inline double EvolvedValue(double phi, double signOfData, double curvature, double regularization,
  const EvolutionCoefficients& c)
{
  const double main = SmoothedDelta(phi, c.Epsilon) * (signOfData - SmoothedSign(phi, c.Epsilon));
  const double smoothing = c.CurvatureWeight * SmoothedDelta(phi, c.CurvatureEpsilon) * curvature;
  return phi + c.TimeStep * (main + smoothing + c.DistanceRegularization * regularization);
}

/// One explicit step of Rosenthal and Linsen's evolution (the paper's eq. 16),
/// d phi / dt + (phi - g) |grad phi| = 0, which drives phi towards g. Here g is the data turned
/// into a first-order distance, (f - f_iso) / |grad f| (the same zero level as f - f_iso, in the
/// units of phi), so the time step is dimensionless: `relaxation` (0 < r <= 1) of the way per
/// step. The change is limited to `maximumStep` (a fraction of the spacing, like a CFL bound).
inline double RosenthalLinsenValue(
  double phi, double gradientNorm, double target, double relaxation, double maximumStep)
{
  double change = -relaxation * (phi - target) * gradientNorm;
  change = std::max(-maximumStep, std::min(maximumStep, change));
  return phi + change;
}

/// Upwind estimate of |grad psi| at a sample for the eikonal equation: the steepest slope
/// towards the zero level, max over the neighbours j closer to it (sign(psi) psi_j < |psi|) of
/// sign(psi) (psi - psi_j) / |x - x_j|. Distance information flows out of the interface, so only
/// those neighbours are used (upwinding). `Floor` is the value of the steepest neighbour: the
/// update may not pass it, which makes the explicit step monotone.
struct UpwindSlope
{
  bool Found = false;
  double Norm = 0.0;
  double Floor = 0.0;
};

template <typename ValueFn, typename SquaredDistanceFn>
UpwindSlope SteepestUpwindSlope(
  double psi, std::size_t count, ValueFn value, SquaredDistanceFn squaredDistance)
{
  // value(j) and squaredDistance(j): the neighbour's value and its squared distance from the
  // sample. Which neighbours lie upwind is as good as random: the loop selects instead of
  // branching, and compares slopes squared and cross-multiplied (one root and division in all),
  // the quotients themselves only in a near tie: the steepest (the first of equals) that
  // comparing the quotients picks, to the bit (TestNumerics), a quarter faster.
  const double sign = psi >= 0.0 ? 1.0 : -1.0;
  double bestRise = 0.0, bestD2 = 1.0; // a slope of 0 until an upwind neighbour is found
  double floor = 0.0;
  bool found = false;
  for (std::size_t j = 0; j < count; ++j)
  {
    const double v = value(j);
    const double d2 = squaredDistance(j);
    const double rise = sign * (psi - v);
    const double left = rise * rise * bestD2, right = bestRise * bestRise * d2;
    const bool upwind = (sign * v < sign * psi) & (d2 > 0.0);
    // Surely steeper, surely not (products in the normal range, apart by more than their
    // rounding), or else as the quotients compare, to the bit.
    const bool comparable = (left >= 1e-290) & (right >= 1e-290);
    bool steeper = upwind & (!found | (comparable & (left > right * (1.0 + 1e-9))));
    if (upwind & found & !steeper & !(comparable & (left * (1.0 + 1e-9) < right)))
    {
      steeper = rise / std::sqrt(d2) > bestRise / std::sqrt(bestD2);
    }
    bestRise = steeper ? rise : bestRise;
    bestD2 = steeper ? d2 : bestD2;
    floor = steeper ? v : floor;
    found = found | steeper;
  }
  UpwindSlope best;
  best.Found = found;
  best.Norm = found ? bestRise / std::sqrt(bestD2) : 0.0;
  best.Floor = floor;
  return best;
}

/// One pseudo-time step of d psi / d tau = S(phi0) (1 - |grad psi|) away from the interface,
/// with |S| = |phi0| / sqrt(phi0^2 + spacing^2) and the sign of psi. The step is limited to
/// [upwind value, psi + pseudoTimeStep] (mirrored for psi < 0): it neither passes the neighbour
/// the information comes from nor grows |psi| faster than distance grows, so it is monotone
/// and cannot amplify (the unlimited explicit step can, next to near-duplicate samples).
inline double ReinitializedValue(
  double psi, double phi0, const UpwindSlope& slope, double spacing, double pseudoTimeStep)
{
  if (!slope.Found)
  {
    return psi; // no neighbour nearer the interface: nothing to propagate from
  }
  const double sign = psi >= 0.0 ? 1.0 : -1.0;
  const double s = std::abs(phi0) / std::sqrt(phi0 * phi0 + spacing * spacing);
  const double magnitude = sign * psi + pseudoTimeStep * s * (1.0 - slope.Norm);
  const double lowest = std::max(0.0, sign * slope.Floor);
  const double highest = sign * psi + pseudoTimeStep;
  return sign * std::min(highest, std::max(lowest, magnitude));
}

/// Distance of a sample next to the interface (a neighbour has the other sign), held fixed
/// during reinitialisation so that the zero level does not move: phi0 / |grad phi0| (first-order
/// estimate; Russo and Smereka's subcell fix), or phi0 if the gradient is too flat to trust.
/// The zero lies between the sample and its nearest neighbour of the other sign, so the
/// distance is at most `oppositeDistance`: a stale value stranded among samples of the other
/// sign is pulled to the interface instead of being held.
inline double InterfaceDistance(double phi0, double gradientNorm, double oppositeDistance)
{
  const double d = gradientNorm > 0.1 ? phi0 / gradientNorm : phi0;
  return std::abs(d) <= oppositeDistance ? d : (d < 0.0 ? -oppositeDistance : oppositeDistance);
}

/// The quantity the paper's MG/AG statistics average: max(|g|, 1/|g|) (1 for a distance).
inline double GradientDeviation(double gradientNorm)
{
  if (!(gradientNorm > 0.0))
  {
    return HUGE_VAL;
  }
  return gradientNorm >= 1.0 ? gradientNorm : 1.0 / gradientNorm;
}

} // namespace lsi

#endif
