// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Moving-least-squares linear fits at arbitrary points (not only at samples): the fit of phi
// that Newton's method projects onto (paper eq. 14), the fit of f - f_iso that the data
// refinement slides along, and the fit that interpolates the input's arrays onto the surface.
// The weights come from Numerics/MovingLeastSquares.h; this adds the neighbour gathering.
#ifndef LevelSetMLSFit_h
#define LevelSetMLSFit_h

#include "LevelSetNeighborhoods.h"

#include <Eigen/Dense>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace lsi
{

/// The weights of the MLS linear fit at p over the samples nearest to p: the value of the fit
/// is sum_j ValueWeight(j) v_j and its gradient sum_j GradientWeights(j) v_j, for any per-sample
/// values v. Holds scratch space: use one per thread.
class MLSStencil
{
public:
  /// `count`: how many nearest samples enter the fit. `spare`: how many more to gather and
  /// hold, so that the count nearest to a point a short way off are still known among them
  /// (Gather then needs no tree search there).
  MLSStencil(const Neighborhoods& geometry, std::size_t count, std::size_t spare = 0);
  /// Gathers the samples nearest to p.
  void Gather(const Eigen::Vector3d& p);
  /// Takes `ids` (count storage indices, at most the fit's count) as what Gather(p) found: the
  /// caller vouches that they are the samples nearest to p (kept from an earlier gather at p).
  /// The state is then Gather(p)'s, except that the next Gather searches the tree.
  void UseGathered(const Eigen::Vector3d& p, const std::uint32_t* ids, std::size_t count);
  /// Builds the weights at p (near where the samples were gathered), with the smallest support
  /// that reaches them all. False if the fit is singular.
  bool Build(const Eigen::Vector3d& p);

  std::size_t Found() const { return this->FoundCount; }
  /// The support that reaches every gathered sample from p.
  double SupportAt(const Eigen::Vector3d& p) const;
  std::uint32_t Sample(std::size_t j) const { return this->Ids[j]; } // storage index
  const double* Position(std::size_t j) const { return this->Geometry.Position(this->Ids[j]); }
  double ValueWeight(std::size_t j) const { return this->ValueWeights[j]; }
  const double* GradientWeights(std::size_t j) const { return &this->GradientWeightData[3 * j]; }

private:
  bool Regather(const Eigen::Vector3d& p);
  void SortGathered();

  const Neighborhoods& Geometry;
  const std::size_t Count, Spare;
  std::size_t FoundCount = 0; // the fit's samples: the first FoundCount of the Held
  std::size_t Held = 0;
  double GatherRadius = 0.0; // of the last gather (0 before the first)
  Eigen::Vector3d GatherPoint = Eigen::Vector3d::Zero();
  // The last tree search: every sample it did not gather is at least OuterRadius from its
  // centre (the distance of the first one left out).
  double OuterRadius = 0.0;
  Eigen::Vector3d OuterCenter = Eigen::Vector3d::Zero();
  // The gathered samples (Held of them, nearest first), then the nearest one left out.
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2, GradientWeightData, ValueWeights;
  std::vector<std::pair<double, std::uint32_t>> Sorted;
};

/// Value and gradient at p of the MLS linear fit of per-sample values over the samples nearest
/// to p. Holds scratch space: use one per thread.
class MLSEvaluator
{
public:
  /// `count`: how many nearest samples enter the fit (0: the neighbourhood size, n + 1);
  /// `quadratic`: fit a quadratic where the data support one (FitLinearOrQuadratic); `spare`:
  /// see MLSStencil.
  MLSEvaluator(const Neighborhoods& geometry, const std::vector<double>& values,
    std::size_t count = 0, bool quadratic = false, std::size_t spare = 0);
  bool operator()(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient);
  /// The same in two parts: gather the samples nearest to p, then fit them at any point near p
  /// (for several evaluations along a short path).
  void Gather(const Eigen::Vector3d& p) { this->Stencil.Gather(p); }
  const MLSStencil& Gathered() const { return this->Stencil; }
  /// Takes `ids` as the samples nearest to p (MLSStencil::UseGathered).
  void UseGathered(const Eigen::Vector3d& p, const std::uint32_t* ids, std::size_t count)
  {
    this->Stencil.UseGathered(p, ids, count);
  }
  bool FitGathered(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient);
  /// The same with the fit's Hessian (zero where the fit is linear).
  bool FitGathered(
    const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient, Eigen::Matrix3d& hessian);

  /// Evaluations so far that used the quadratic fit, and all evaluations.
  std::size_t QuadraticFits = 0, Fits = 0;

private:
  MLSStencil Stencil;
  const std::vector<double>& Values;
  bool Quadratic = false;
};

} // namespace lsi

#endif
