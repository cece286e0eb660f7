// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Whether a snapshot's stored densities are the kernel sums of its masses with its smoothing
// lengths, as every SPH code computes them: at particle i, in i's own support (gather, GADGET,
// SWIFT, GIZMO, ChaNGa: rho_i = sum_j m_j W(r_ij, H_i)), in each neighbour's (scatter:
// sum_j m_j W(r_ij, H_j), the interpolant's density at x_i) or their mean (symmetric, Gasoline).
// Measured on real outputs, the code's own convention gives the stored value to float precision
// (median |ln ratio| below 1e-4 for SWIFT and GADGET-4), the others within about 12%. A support
// too short (a softening read as h, h taken for the support where the code's support is gamma h),
// or a density in other units than the masses and lengths, puts every convention far off.
// Plain C++: per-sample numbers in, one ratio out (the loops and ranks are the caller's).
#ifndef DensityConsistency_h
#define DensityConsistency_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace lsi
{

/// ln(kernel sum / stored density) at one particle, for the three conventions.
struct DensityLogRatios
{
  double Gather = 0.0, Scatter = 0.0, Symmetric = 0.0;
};

/// The ratios at a particle, or false when a density or a sum is not positive and finite (a
/// placeholder density, or a particle alone in its support): such particles are not counted.
inline bool LogRatiosOf(double gather, double scatter, double stored, DensityLogRatios& ratios)
{
  auto usable = [](double v) { return v > 0.0 && std::isfinite(v); };
  if (!usable(gather) || !usable(scatter) || !usable(stored))
  {
    return false;
  }
  ratios.Gather = std::log(gather / stored);
  ratios.Scatter = std::log(scatter / stored);
  ratios.Symmetric = std::log(0.5 * (gather + scatter) / stored);
  return true;
}

/// The stored densities against the kernel sums over many particles.
struct DensityMismatch
{
  std::size_t Particles = 0;   // the particles counted
  double MedianLogRatio = 0.0; // of the convention closest to the stored densities
  const char* Convention = ""; // "gather", "scatter" or "symmetric"
  /// The factor between the sums and the stored densities, at least 1 (1: they agree).
  double Factor() const { return std::exp(std::abs(this->MedianLogRatio)); }
};

namespace detail
{
inline double MedianOf(std::vector<double> values)
{
  const std::size_t half = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + half, values.end());
  double median = values[half];
  if (values.size() % 2 == 0)
  {
    // (The mean of the two middle values: the same answer for any order of the input.)
    median = 0.5 * (median + *std::max_element(values.begin(), values.begin() + half));
  }
  return median;
}
} // namespace detail

/// The convention whose median log ratio is closest to 0, from the per-particle log ratios
/// (the same for any order of them: medians). No particles: a mismatch of factor 1.
inline DensityMismatch MedianDensityMismatch(const std::vector<double>& gather,
  const std::vector<double>& scatter, const std::vector<double>& symmetric)
{
  DensityMismatch result;
  result.Particles = gather.size();
  if (gather.empty())
  {
    return result;
  }
  const double medians[3] = { detail::MedianOf(gather), detail::MedianOf(scatter),
    detail::MedianOf(symmetric) };
  const char* names[3] = { "gather", "scatter", "symmetric" };
  int best = 0;
  for (int c = 1; c < 3; ++c)
  {
    best = std::abs(medians[c]) < std::abs(medians[best]) ? c : best;
  }
  result.MedianLogRatio = medians[best];
  result.Convention = names[best];
  return result;
}

} // namespace lsi

#endif
