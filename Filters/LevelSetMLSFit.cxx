// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetMLSFit.h"

#include "MovingLeastSquares.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

MLSStencil::MLSStencil(const Neighborhoods& geometry, std::size_t count)
  : Geometry(geometry)
  , Ids(std::min(count, geometry.NumberOfSamples))
  , D2(Ids.size())
  , GradientWeightData(3 * Ids.size())
  , ValueWeights(Ids.size())
{
}

void MLSStencil::Gather(const Eigen::Vector3d& p)
{
  // Consecutive gathers are usually near each other (isopoints come in the samples' spatial
  // order): the last gather's samples all lie within its radius plus the step from p, so the
  // search can be bounded by that (slightly widened against rounding) and still finds the same
  // samples, ties included (TestNumerics). A long step searches without a bound.
  const std::size_t k = this->Ids.size();
  const double step = (p - this->GatherPoint).norm();
  const double bound = this->GatherRadius + step;
  this->FoundCount = 0;
  if (this->GatherRadius > 0.0 && step < 2.0 * this->GatherRadius && this->PreviousFound == k)
  {
    this->FoundCount = this->Geometry.Index->NearestWithin(
      p.data(), k, bound * bound * (1.0 + 1e-9), this->Ids.data(), this->D2.data());
  }
  if (this->FoundCount < k)
  {
    this->FoundCount =
      this->Geometry.Index->Nearest(p.data(), k, this->Ids.data(), this->D2.data());
  }
  this->PreviousFound = this->FoundCount;
  this->GatherRadius =
    std::sqrt(*std::max_element(this->D2.begin(), this->D2.begin() + this->FoundCount));
  this->GatherPoint = p;
}

double MLSStencil::SupportAt(const Eigen::Vector3d& p) const
{
  // The support must still reach all gathered samples from p (the weight vanishes at h).
  double h = this->GatherRadius;
  if (p != this->GatherPoint)
  {
    double h2 = 0.0;
    for (std::size_t j = 0; j < this->FoundCount; ++j)
    {
      h2 = std::max(h2, (Eigen::Vector3d(this->Geometry.Position(this->Ids[j])) - p).squaredNorm());
    }
    h = std::max(h, std::sqrt(h2));
  }
  return h;
}

bool MLSStencil::Build(const Eigen::Vector3d& p)
{
  const std::size_t k = this->FoundCount;
  const double h = this->SupportAt(p);
  return BuildLinearStencil(
    p.data(), k, [&](std::size_t j) { return this->Geometry.Position(this->Ids[j]); }, h,
    LinearStencilView{ this->GradientWeightData.data(), this->ValueWeights.data() });
}

MLSEvaluator::MLSEvaluator(const Neighborhoods& geometry, const std::vector<double>& values,
  std::size_t count, bool quadratic)
  : Stencil(geometry, count ? count : static_cast<std::size_t>(geometry.Stride))
  , Values(values)
  , Quadratic(quadratic)
{
}

bool MLSEvaluator::operator()(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient)
{
  this->Stencil.Gather(p);
  return this->FitGathered(p, value, gradient);
}

bool MLSEvaluator::FitGathered(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient)
{
  if (this->Quadratic)
  {
    // The 1% point of F(6, 30): the curvature terms are kept where the data show them.
    constexpr double CriticalF = 3.5;
    const MLSStencil& s = this->Stencil;
    bool quadratic = false;
    const bool ok = FitLinearOrQuadratic(
      p.data(), s.Found(), [&](std::size_t j) { return s.Position(j); },
      [&](std::size_t j) { return this->Values[s.Sample(j)]; }, s.SupportAt(p), CriticalF, value,
      gradient, quadratic);
    this->Fits += ok ? 1 : 0;
    this->QuadraticFits += quadratic ? 1 : 0;
    return ok;
  }
  if (!this->Stencil.Build(p))
  {
    return false;
  }
  value = 0.0;
  gradient.setZero();
  for (std::size_t j = 0; j < this->Stencil.Found(); ++j)
  {
    const double v = this->Values[this->Stencil.Sample(j)];
    value += this->Stencil.ValueWeight(j) * v;
    gradient += v * Eigen::Vector3d(this->Stencil.GradientWeights(j));
  }
  return true;
}

} // namespace lsi
