// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Steps 5-7 of the method, the isopoint stage. Step 5 (LevelSetIsopoints.cxx, paper §6): rough
// points at the zero crossings of phi between neighbouring samples (filtered by an angle
// criterion), projected by Newton's method onto the zero level of the MLS approximation of phi
// (eq. 14). Step 6 (LevelSetCompletion.cxx, paper Fig. 3): completion on tangent planes. Step 7
// (LevelSetDataRefinement.cxx, ours): the refinement on the data.
#ifndef LevelSetIsopoints_h
#define LevelSetIsopoints_h

#include "IsopointRefinement.h"
#include "LevelSetCommunicator.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace lsi
{

struct IsopointSettings
{
  double MinimumCosine = 0.5; // angle criterion: segment within 60 degrees of the gradient
  bool Completion = true;
  double CellSize = 0.5;       // completion cells and the minimum spacing of output points
  int CompletionHalfCells = 2; // a 5 x 5 grid of cells around each isopoint
  NewtonSettings Newton;
  // The normal is the gradient of a wider fit (this many times n + 1 samples) at the refined
  // point: phi is noisy at the sample scale, and a 27-sample fit gave ~20 degree errors.
  int NormalFitScale = 4;
  // Final refinement on the data: slide each isopoint along its normal to the zero of the MLS
  // fit of f - f_iso over DataFitScale * (n + 1) samples (more samples: smoother under noise),
  // at most DataMaximumMove, and take the normal from that fit's gradient. The fit is quadratic
  // where the data show curvature above their noise (FitLinearOrQuadratic), else linear.
  bool RefineOnData = true;
  int DataFitScale = 2;
  int DataFitOrder = 2; // 2: a quadratic fit (linear where ill-posed), unbiased by curvature
  double DataMaximumMove = 0.5;
  int DataIterations = 3; // at most; fewer once a step is below DataConvergedStep of the move
  // On the SPH field (exact, smooth): reach in kernel supports of the nearest particle, and
  // Newton steps.
  double SPHMaximumMove = 1.0;
  int SPHIterations = 12;
};

/// The data refinement stops once a step is shorter than this fraction of DataMaximumMove
/// (about 1e-4 of a spacing: the steps then shrink quadratically, far below the accuracy).
constexpr double DataConvergedStep = 2e-3;

/// The data refinement gathers a quarter more samples than its fit uses: the fit's samples at
/// the point's end, a fraction of a spacing on, are then still known without a tree search.
constexpr std::size_t DataSpareFraction = 4;

/// An empty slot in IsopointSet::FitSamples (a cloud smaller than the fit).
constexpr std::uint32_t NoSample = ~std::uint32_t(0);

struct IsopointSet
{
  std::vector<double> Points;        // 3 per isopoint
  std::vector<double> Normals;       // 3 per isopoint: unit, pointing out of {phi > 0}
  std::size_t RoughCount = 0;        // zero crossings accepted by the angle criterion
  std::size_t CompletedCount = 0;    // points added by completion (after thinning)
  std::size_t DataRefinedCount = 0;  // points the data refinement moved
  std::size_t DroppedCount = 0;      // points the SPH refinement found no level near, dropped
  std::size_t FreeBoundaryCount = 0; // points added where the cloud ends above the isovalue
  // The data refinement's samples nearest to each final point (FitSize storage indices per
  // point), for the arrays interpolated onto the surface over as many samples: their gather
  // is then not repeated. Empty unless they match Points; whatever moves or drops points after
  // the refinement must clear them.
  // (Uninitialised on resize: the refinement writes every row in parallel.)
  UninitializedVector<std::uint32_t> FitSamples;
  std::size_t FitSize = 0;
  // The data fit's quadratic model at each final point, 9 per point: its gradient, then its
  // Hessian (xx, yy, zz, xy, xz, yz). A later slide onto another isovalue takes its first step
  // from it (LevelSetIsoValueSlide.h). Cleared with FitSamples.
  UninitializedVector<double> FitModels;
};

/// Isopoints per block of the parallel loops, between two abort checks: a block of Newton
/// projections with MLS fits takes a few tens of milliseconds on one core.
constexpr std::size_t IsopointBlock = 8192;

/// The samples whose sign FlipSpuriousPockets flipped, with the values they had.
struct FlippedSamples
{
  std::vector<std::pair<std::uint32_t, double>> Before;
  /// Puts the values back: phi is again what FlipSpuriousPockets was given.
  void Restore(std::vector<double>& phi) const
  {
    for (const auto& sample : this->Before)
    {
      phi[sample.first] = sample.second;
    }
  }
};

/// Removes phi's spurious pockets, in place: a connected region of samples with one sign of phi
/// in which no sample has that sign in the data (`dataOffsets`, f - f_iso) cannot hold a piece
/// of the isosurface, so its sign is flipped and Newton's method is not drawn to zeros around
/// it. (In place, with what it changed returned: a copy of phi would be n fresh values.)
FlippedSamples FlipSpuriousPockets(
  const Neighborhoods& geometry, const std::vector<double>& dataOffsets, std::vector<double>& phi);

/// The isopoints of `phi` (after FlipSpuriousPockets): rough points, one Newton projection
/// per voxel of side CellSize, thinned to one point per voxel. Under MPI only near this rank's
/// own samples (FrontNearOwned). Returns false only when aborted.
bool ExtractIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted,
  const Communicator& ranks = SingleProcess());

/// Neighbour steps, through the front, from a rank's own samples to the farthest ghost whose
/// crossings make isopoints there. A rank keeps the points nearest its own samples (within
/// about one step of them); each point depends on the crossings within about two steps
/// (thinning, projection, completion); the halo is six deep.
constexpr int NearOwnedSteps = 4;

/// `front` less the ghosts more than `steps` neighbour steps from an owned sample, walking
/// through the front's ghosts (one process: `front` as it is). Their points would be made only
/// for the other ranks to keep: about a third of a rank's isopoints.
std::vector<std::size_t> FrontNearOwned(const Neighborhoods& geometry, const Communicator& ranks,
  const std::vector<std::size_t>& front, int steps);

/// Step 6, completion: around each isopoint, the empty cells of a small grid on its tangent
/// plane (Numerics/TangentPlaneCompletion.h) propose new points, projected onto the zero level
/// like the isopoints themselves, so that the set renders without holes. They are added to
/// `out`, thinned with it (existing isopoints keep their voxels). `phi` is the level set the
/// isopoints were extracted from. Returns false only when aborted.
bool CompleteIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

/// Step 7, refinement on the data: the level set only uses the sign of f - f_iso, which places
/// the surface to a fraction of the spacing. Each isopoint of `out` slides along its normal to
/// the zero of the MLS fit of `dataOffsets` (f - f_iso per sample) over DataFitScale (n + 1)
/// samples, at most DataMaximumMove (Numerics/IsopointRefinement.h, SlideOntoDataLevel), and
/// takes its normal from that fit. Returns false only when aborted.
bool RefineIsopointsOnData(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

class SPHField;

/// Step 7 on SPH data: like RefineIsopointsOnData, but onto the SPH field's level `isoValue`
/// (LevelSetSPHField.h), with the kernel's analytic gradient as the normal, and a reach of
/// SPHMaximumMove times the kernel support of the particle nearest to each isopoint.
bool RefineIsopointsOnSPHField(const Neighborhoods& geometry, const SPHField& field,
  double isoValue, const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

/// Whether sample i lies on the edge of the cloud: its neighbours lie to one side, so their
/// centroid is far from it (about 0.75 of the neighbourhood radius for a flat edge, a few
/// hundredths inside). `outward` receives the unit offset from the centroid, out of the cloud.
bool OutwardOfCloud(const Neighborhoods& geometry, std::size_t i, Eigen::Vector3d& outward);

/// Step 7b on SPH data, the free boundary: where the particle cloud itself ends inside the
/// component (a galaxy's edge, a tube's wall), no pair of particles straddles the surface, which
/// lies up to a kernel support beyond the outermost particles, so the steps above leave a hole.
/// From each sample inside the component (`inside`, and `dataOffsets` > 0) on the edge of the
/// cloud (its neighbours to one side), a ray outwards is solved onto the field's level within
/// one support; the points found join `out` at its end (FreeBoundaryCount of them), thinned by
/// voxels (existing points keep theirs). Returns false only when aborted.
bool AddFreeBoundaryPoints(const Neighborhoods& geometry, const SPHField& field, double isoValue,
  const std::vector<char>& inside, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

// Pieces shared by the three steps.

/// The cubic voxel of side `cell` that holds x, as one key (21 bits per axis).
std::uint64_t VoxelKey(const double* x, double cell);

/// Indices (ascending, below `count`) of one point per cubic voxel of side `cell` (point k at
/// pointOf(k), 3 doubles): the first of the `preferred` leading points in the voxel, else the
/// one with the smallest coordinates (the lowest index among equal ones), so the choice does
/// not depend on the order of the points. Removes near-duplicates and bounds the output's
/// density.
template <typename PointOf>
std::vector<std::size_t> ThinnedVoxels(
  std::size_t count, PointOf&& pointOf, double cell, std::size_t preferred = 0)
{
  // The keys are sorted with their points' indices beside them (not the indices by a key looked
  // up elsewhere: a cache miss per comparison); each voxel's points are then one run, in index
  // order, whose winner one scan finds.
  struct Entry
  {
    std::uint64_t Key;
    std::size_t Index;
  };
  UninitializedVector<Entry> entries(count); // (written below, in parallel)
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::size_t i = static_cast<std::size_t>(k);
        entries[i] = { VoxelKey(pointOf(i), cell), i };
      }
    });
  ParallelSort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
    return a.Key < b.Key || (a.Key == b.Key && a.Index < b.Index);
  });
  // The runs in parallel: a piece of the entries takes the runs that begin in it (to their
  // ends), and marks each run's winner; the winners are then listed in index order.
  UninitializedVector<char> won = FilledInParallel<char>(count, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 16384),
    [&](vtkIdType begin, vtkIdType end) {
      std::size_t first = static_cast<std::size_t>(begin);
      while (first > 0 && first < static_cast<std::size_t>(end) &&
        entries[first].Key == entries[first - 1].Key)
      {
        ++first; // this run began in the piece before
      }
      while (first < static_cast<std::size_t>(end))
      {
        std::size_t winner = entries[first].Index, k = first + 1;
        for (; k < count && entries[k].Key == entries[first].Key; ++k)
        {
          // (A preferred point, the lowest index, comes first in its run and keeps the voxel.)
          const double* x = pointOf(entries[k].Index);
          const double* best = pointOf(winner);
          if (winner >= preferred && std::lexicographical_compare(x, x + 3, best, best + 3))
          {
            winner = entries[k].Index;
          }
        }
        won[winner] = 1;
        first = k;
      }
    });
  return IndicesWhere<std::size_t>(count, [&](std::size_t i) { return won[i] != 0; });
}

/// ThinnedVoxels over `points` (3 doubles each).
std::vector<std::size_t> ThinByVoxels(
  const std::vector<double>& points, double cell, std::size_t preferred = 0);

/// Appends the selected points and their normals to `out`.
void AppendSelected(const std::vector<double>& points, const std::vector<double>& normals,
  const std::vector<std::size_t>& selected, IsopointSet& out);

/// Keeps the selected points (ascending indices) with their normals and, when both have one row
/// per point, their fits' samples and models (else neither): the arrays are interpolated over
/// those samples.
void KeepSelected(IsopointSet& isopoints, const std::vector<std::size_t>& selected);

/// Indices where `valid` is set.
std::vector<std::size_t> ValidIndices(const std::vector<char>& valid);

/// Projects the valid candidate points onto the zero level of phi's MLS fit, in place; `valid`
/// says which converged. Normals point along -grad phi: out of the region phi > 0, which is the
/// region f > f_iso. Returns false if aborted.
bool ProjectCandidates(const Neighborhoods& geometry, const std::vector<double>& phi,
  const NewtonSettings& newton, int normalFitScale, std::vector<double>& points,
  std::vector<double>& normals, std::vector<char>& valid, const AbortCheck& aborted);

/// The wide fit of phi only matters for the output normals; the data refinement replaces them.
inline int NormalFitScaleFor(const IsopointSettings& settings)
{
  return settings.RefineOnData ? 1 : settings.NormalFitScale;
}

} // namespace lsi

#endif
