// Isopoints (paper §6): rough points at the zero crossings of phi between neighbouring samples
// (filtered by an angle criterion), Newton refinement onto the zero level of the MLS
// approximation of phi (eq. 14), and completion on tangent planes (Fig. 3) so that the set is
// dense enough for point or splat rendering.
#ifndef LevelSetIsopoints_h
#define LevelSetIsopoints_h

#include "IsopointRefinement.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include <vector>

namespace lsi
{

struct IsopointSettings
{
  double MinimumCosine = 0.5; // angle criterion: segment within 60 degrees of the gradient
  bool Completion = true;
  double CellSize = 0.5;      // completion cells and the minimum spacing of output points
  int CompletionHalfCells = 2; // a 5 x 5 grid of cells around each isopoint
  NewtonSettings Newton;
  // The normal is the gradient of a wider fit (this many times n + 1 samples) at the refined
  // point: phi is noisy at the sample scale, and a 27-sample fit gave ~20 degree errors.
  int NormalFitScale = 4;
  // Final refinement on the data: slide each isopoint along its normal to the zero of the MLS
  // fit of f - f_iso over DataFitScale * (n + 1) samples (more samples: smoother under noise),
  // at most DataMaximumMove, and take the normal from that fit's gradient.
  bool RefineOnData = true;
  int DataFitScale = 2;
  double DataMaximumMove = 0.5;
  int DataIterations = 3;
};

struct IsopointSet
{
  std::vector<double> Points;  // 3 per isopoint
  std::vector<double> Normals; // 3 per isopoint: unit, pointing out of {phi > 0}
  std::size_t RoughCount = 0;     // zero crossings accepted by the angle criterion
  std::size_t CompletedCount = 0; // points added by completion (after thinning)
  double CompletionSeconds = 0.0;
  double DataRefinementSeconds = 0.0;
  std::size_t DataRefinedCount = 0; // points the data refinement moved
};

/// `dataOffsets` is f - f_iso per sample: its sign discards pockets of phi that no sample's
/// data supports, and its values place the points in the final refinement. Returns false only
/// when aborted.
bool ExtractIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const std::vector<double>& dataOffsets, const IsopointSettings& settings, IsopointSet& out,
  const AbortCheck& aborted);

/// The weights of the MLS linear fit at p over the samples nearest to p: the value of the fit
/// is sum_j ValueWeight(j) v_j and its gradient sum_j GradientWeights(j) v_j, for any per-sample
/// values v. Holds scratch space: use one per thread.
class MLSStencil
{
public:
  /// `count`: how many nearest samples enter the fit.
  MLSStencil(const Neighborhoods& geometry, std::size_t count);
  /// Gathers the samples nearest to p.
  void Gather(const Eigen::Vector3d& p);
  /// Builds the weights at p (near where the samples were gathered), with the smallest support
  /// that reaches them all. False if the fit is singular.
  bool Build(const Eigen::Vector3d& p);

  std::size_t Found() const { return this->FoundCount; }
  std::uint32_t Sample(std::size_t j) const { return this->Ids[j]; } // storage index
  double ValueWeight(std::size_t j) const { return this->ValueWeights[j]; }
  const double* GradientWeights(std::size_t j) const { return &this->GradientWeightData[3 * j]; }

private:
  const Neighborhoods& Geometry;
  std::size_t FoundCount = 0;
  double GatherRadius = 0.0;
  Eigen::Vector3d GatherPoint;
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2, GradientWeightData, ValueWeights;
};

/// Value and gradient at p of the MLS linear fit of per-sample values over the samples nearest
/// to p. Holds scratch space: use one per thread.
class MLSEvaluator
{
public:
  /// `count`: how many nearest samples enter the fit (0: the neighbourhood size, n + 1).
  MLSEvaluator(
    const Neighborhoods& geometry, const std::vector<double>& values, std::size_t count = 0);
  bool operator()(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient);
  /// The same in two parts: gather the samples nearest to p, then fit them at any point near p
  /// (for several evaluations along a short path).
  void Gather(const Eigen::Vector3d& p) { this->Stencil.Gather(p); }
  bool FitGathered(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient);

private:
  MLSStencil Stencil;
  const std::vector<double>& Values;
};

} // namespace lsi

#endif
