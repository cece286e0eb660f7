// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetReinitialization.h"

#include "LevelSetSplines.h"
#include "MovingLeastSquares.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

double ReinitializationHalfWidth(const EvolutionSettings& settings)
{
  const EvolutionCoefficients& c = settings.Coefficients;
  return BandHalfWidth(std::max(c.Epsilon, c.CurvatureEpsilon)) + 2.0 * settings.NeighborhoodRadius;
}

Reinitialization::Reinitialization(const Neighborhoods& geometry, BandCollector& band)
  : Geometry(geometry)
  , Band(band)
{
}

void Reinitialization::Run(
  const EvolutionSettings& settings, std::vector<double>& phi, const Communicator& ranks)
{
  // Only where it matters: the band plus a margin, so that samples about to enter the band
  // already hold a distance; plus one ring of neighbours, so that clamped (stale) values next
  // to the region are repaired as the front approaches them.
  this->Band.Where(phi, ReinitializationHalfWidth(settings), this->Core);
  this->Band.WithNeighbors(this->Core, this->Updated);
  ranks.KeepOwned(this->Updated); // after every step the ghosts take their owners' values
  const std::vector<std::size_t>& region = this->Updated;
  this->Geometry.EnsureNeighbors(region);
  const std::size_t stride = static_cast<std::size_t>(this->Geometry.Stride);
  this->NewValues.resize(region.size());
  UninitializedVector<double>& initial = this->Initial;
  initial.resize(region.size());
  ForEachIn(region, [&](std::size_t k, std::size_t i) { initial[k] = phi[i]; });
  // (Eigen's norm() is the root of its squaredNorm(): the same distances, to the bit.)
  auto squaredDistance = [&](std::size_t i, std::uint32_t j) {
    return (
      Eigen::Vector3d(this->Geometry.Position(i)) - Eigen::Vector3d(this->Geometry.Position(j)))
      .squaredNorm();
  };
  auto distance = [&](std::size_t i, std::uint32_t j) { return std::sqrt(squaredDistance(i, j)); };
  auto positive = [](double value) { return value > 0.0; };
  // Samples with a neighbour of the other sign hold the interface: fix them at their
  // first-order distance; the others are updated by upwind steps.
  UninitializedVector<char>& atInterface = this->AtInterface;
  atInterface.resize(region.size());
  ForEachIn(region, [&](std::size_t k, std::size_t i) {
    const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
    double opposite = HUGE_VAL;
    for (std::size_t m = 1; m < stride; ++m)
    {
      if (positive(phi[ids[m]]) != positive(phi[i]))
      {
        opposite = std::min(opposite, distance(i, ids[m]));
      }
    }
    atInterface[k] = opposite < HUGE_VAL;
    this->NewValues[k] = opposite; // (the interface's new value is made from it below)
  });
  // Only the interface needs a gradient, so only its stencils (it lies inside the evolution's
  // band, which has them already): a stencil for every sample of the region, most of which
  // never read one, cost a third more stencils than a run reads.
  std::vector<std::size_t>& interface = this->Interface;
  IndicesWhere(
    region.size(), [&](std::size_t k) { return atInterface[k] != 0; }, interface);
  for (std::size_t& i : interface)
  {
    i = region[i];
  }
  this->Geometry.EnsureStencils(interface);
  ForEachIn(region, [&](std::size_t k, std::size_t i) {
    if (atInterface[k])
    {
      const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
      const double norm =
        this->Geometry.GradientAt(i, [&](std::size_t m) { return phi[ids[m]]; }).norm();
      this->NewValues[k] = InterfaceDistance(phi[i], norm, this->NewValues[k]);
    }
  });
  ForEachIn(region, [&](std::size_t k, std::size_t i) {
    if (atInterface[k])
    {
      phi[i] = this->NewValues[k];
    }
  });
  ranks.RefreshGhosts(phi);
  for (int step = 0; step < settings.ReinitializationSteps; ++step)
  {
    ForEachIn(region, [&](std::size_t k, std::size_t i) {
      if (atInterface[k])
      {
        this->NewValues[k] = phi[i];
        return;
      }
      const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
      const UpwindSlope slope = SteepestUpwindSlope(
        phi[i], stride, [&](std::size_t m) { return phi[ids[m]]; },
        [&](std::size_t m) { return squaredDistance(i, ids[m]); });
      this->NewValues[k] = ReinitializedValue(
        phi[i], initial[k], slope, settings.Spacing, settings.ReinitializationTimeStep);
    });
    ForEachIn(region, [&](std::size_t k, std::size_t i) { phi[i] = this->NewValues[k]; });
    ranks.RefreshGhosts(phi);
  }
}

} // namespace lsi
