// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetMLSFit.h"

#include "MovingLeastSquares.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

namespace
{
double SquaredDistance(const Eigen::Vector3d& p, const double* x)
{
  double sum = 0.0;
  for (int d = 0; d < 3; ++d)
  {
    const double diff = p[d] - x[d];
    sum += diff * diff;
  }
  return sum;
}
} // namespace

MLSStencil::MLSStencil(const Neighborhoods& geometry, std::size_t count, std::size_t spare)
  : Geometry(geometry)
  , Count(std::min(count, geometry.NumberOfSamples))
  , Spare(spare)
  // The spares, then one more: how far the next one is.
  , Ids(std::min(count + spare + 1, geometry.NumberOfSamples))
  , D2(Ids.size())
  , GradientWeightData(3 * Count)
  , ValueWeights(Count)
{
}

void MLSStencil::Gather(const Eigen::Vector3d& p)
{
  if (this->FoundCount > 0 && this->Regather(p))
  {
    return;
  }
  // Consecutive gathers are usually near each other (isopoints come in the samples' spatial
  // order): the last gather's k + 1 samples all lie within its outer radius plus the step from
  // p, so the search can be bounded by that (slightly widened against rounding) and still finds
  // the same samples, ties included (TestNumerics). A bounded search that finds k + 1 samples
  // has found the nearest, so a tighter bound is tried first: the density rarely changes by
  // 1.2^3 between neighbouring gathers. A long step searches without a bound.
  const std::size_t wanted = this->Ids.size();        // k + spares + 1, or the whole cloud
  const double step = (p - this->OuterCenter).norm(); // from where the last search was made
  std::size_t found = 0;
  if (this->FoundCount > 0 && this->OuterRadius < HUGE_VAL && step < this->OuterRadius)
  {
    const double bound = this->OuterRadius + step, tight = 1.2 * this->OuterRadius;
    if (tight < bound)
    {
      found = this->Geometry.Index->NearestWithin(
        p.data(), wanted, tight * tight, this->Ids.data(), this->D2.data());
    }
    if (found < wanted)
    {
      found = this->Geometry.Index->NearestWithin(
        p.data(), wanted, bound * bound * (1.0 + 1e-9), this->Ids.data(), this->D2.data());
    }
  }
  if (found < wanted)
  {
    found = this->Geometry.Index->Nearest(p.data(), wanted, this->Ids.data(), this->D2.data());
  }
  const std::size_t holdable = this->Count + this->Spare;
  this->Held = std::min(found, holdable);
  this->FoundCount = std::min(this->Held, this->Count);
  this->OuterRadius = found > holdable ? std::sqrt(this->D2[holdable]) : HUGE_VAL;
  this->OuterCenter = p;
  this->SortGathered();
  this->GatherPoint = p;
}

void MLSStencil::UseGathered(const Eigen::Vector3d& p, const std::uint32_t* ids, std::size_t count)
{
  this->FoundCount = this->Held = std::min(count, this->Count);
  for (std::size_t j = 0; j < this->FoundCount; ++j)
  {
    this->Ids[j] = ids[j];
    this->D2[j] = SquaredDistance(p, this->Geometry.Position(ids[j]));
  }
  this->OuterRadius = 0.0; // nothing known beyond them: the next gather searches
  this->OuterCenter = p;
  this->SortGathered();
  this->GatherPoint = p;
}

bool MLSStencil::Regather(const Eigen::Vector3d& p)
{
  // The k nearest to p among the samples held (the gathered ones and the spares) are still p's
  // k nearest (StillNearest) across the short last steps of a projection, or a short slide:
  // the fit there needs no tree search.
  const double step = (p - this->OuterCenter).norm();
  // A step beyond the margin between the held samples and the first one left out seldom keeps
  // them the nearest: search instead (exact either way), sparing the sort.
  if (!(step < this->OuterRadius - this->GatherRadius))
  {
    return false;
  }
  for (std::size_t j = 0; j < this->Held; ++j)
  {
    this->D2[j] = SquaredDistance(p, this->Geometry.Position(this->Ids[j]));
  }
  this->SortGathered();
  if (!StillNearest(this->GatherRadius, step, this->OuterRadius))
  {
    return false;
  }
  this->GatherPoint = p;
  return true;
}

void MLSStencil::SortGathered()
{
  // By distance, then by index: the order (and so the fit's rounding) does not depend on
  // whether the samples came from the tree or from the last gather. (Samples kept from a fit
  // at the same point come in that order already: a slide's, say.)
  bool sorted = true;
  for (std::size_t j = 1; j < this->Held && sorted; ++j)
  {
    sorted = this->D2[j - 1] < this->D2[j] ||
      (this->D2[j - 1] == this->D2[j] && this->Ids[j - 1] <= this->Ids[j]);
  }
  if (sorted)
  {
    this->GatherRadius = this->FoundCount ? std::sqrt(this->D2[this->FoundCount - 1]) : 0.0;
    return;
  }
  this->Sorted.clear();
  for (std::size_t j = 0; j < this->Held; ++j)
  {
    this->Sorted.emplace_back(this->D2[j], this->Ids[j]);
  }
  std::sort(this->Sorted.begin(), this->Sorted.end());
  for (std::size_t j = 0; j < this->Held; ++j)
  {
    this->D2[j] = this->Sorted[j].first;
    this->Ids[j] = this->Sorted[j].second;
  }
  this->GatherRadius = this->FoundCount ? std::sqrt(this->D2[this->FoundCount - 1]) : 0.0;
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
  std::size_t count, bool quadratic, std::size_t spare)
  : Stencil(geometry, count ? count : static_cast<std::size_t>(geometry.Stride), spare)
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
  Eigen::Matrix3d hessian;
  return this->FitGathered(p, value, gradient, hessian);
}

bool MLSEvaluator::FitGathered(
  const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient, Eigen::Matrix3d& hessian)
{
  hessian.setZero();
  if (this->Quadratic)
  {
    // The 1% point of F(6, 30): the curvature terms are kept where the data show them.
    constexpr double CriticalF = 3.5;
    const MLSStencil& s = this->Stencil;
    bool quadratic = false;
    const bool ok = FitLinearOrQuadratic(
      p.data(), s.Found(), [&](std::size_t j) { return s.Position(j); },
      [&](std::size_t j) { return this->Values[s.Sample(j)]; }, s.SupportAt(p), CriticalF, value,
      gradient, quadratic, &hessian);
    this->Fits += ok ? 1 : 0;
    this->QuadraticFits += quadratic ? 1 : 0;
    return ok;
  }
  const MLSStencil& s = this->Stencil;
  return FitLinear(
    p.data(), s.Found(), [&](std::size_t j) { return s.Position(j); },
    [&](std::size_t j) { return this->Values[s.Sample(j)]; }, s.SupportAt(p), value, gradient);
}

} // namespace lsi
