// Per-sample update formulas of the level-set evolution (paper eq. 9 and 13) and of the
// reinitialisation (eq. 10). Plain C++: unit-tested in Testing/Cxx/TestLevelSetUpdate.cxx.
#ifndef LevelSetUpdate_h
#define LevelSetUpdate_h

#include "LevelSetSplines.h"

#include <cmath>

namespace lsi
{

/// Coefficients of one explicit Euler step of the evolution.
struct EvolutionCoefficients
{
  double TimeStep = 1.0;
  double Epsilon = 1.0;          // width of delta/sign in the main term
  double CurvatureEpsilon = 1.0; // width of delta in the curvature term (eps')
  double CurvatureWeight = 0.0;  // lambda
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

/// One pseudo-time step of d psi / d tau = S(phi0) (1 - |grad psi|) with the smoothed sign
/// S = phi0 / sqrt(phi0^2 + spacing^2): zero on the interface, so the zero level barely moves.
inline double ReinitializedValue(
  double psi, double phi0, double gradientNorm, double spacing, double pseudoTimeStep)
{
  const double s = phi0 / std::sqrt(phi0 * phi0 + spacing * spacing);
  return psi + pseudoTimeStep * s * (1.0 - gradientNorm);
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
