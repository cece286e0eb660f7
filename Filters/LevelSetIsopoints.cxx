// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetIsopoints.h"

#include "LevelSetMLSFit.h"
#include "MovingLeastSquares.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>

namespace lsi
{

std::uint64_t VoxelKey(const double* x, double cell)
{
  std::uint64_t key = 0;
  for (int d = 0; d < 3; ++d)
  {
    const auto v = static_cast<std::int64_t>(std::floor(x[d] / cell)) + (1 << 20);
    key = (key << 21) | (static_cast<std::uint64_t>(v) & ((1u << 21) - 1));
  }
  return key;
}

std::vector<std::size_t> ThinByVoxels(
  const std::vector<double>& points, double cell, std::size_t preferred)
{
  return ThinnedVoxels(
    points.size() / 3, [&](std::size_t k) { return &points[3 * k]; }, cell, preferred);
}

void AppendSelected(const std::vector<double>& points, const std::vector<double>& normals,
  const std::vector<std::size_t>& selected, IsopointSet& out)
{
  out.Points.reserve(out.Points.size() + 3 * selected.size());
  out.Normals.reserve(out.Normals.size() + 3 * selected.size());
  for (std::size_t i : selected)
  {
    out.Points.insert(out.Points.end(), &points[3 * i], &points[3 * i + 3]);
    out.Normals.insert(out.Normals.end(), &normals[3 * i], &normals[3 * i + 3]);
  }
}

void KeepSelected(IsopointSet& isopoints, const std::vector<std::size_t>& selected)
{
  const std::size_t count = isopoints.Points.size() / 3;
  // Each per-point array compacted in place (the selected indices ascend).
  auto keepRows = [&](auto& rows, std::size_t width) {
    if (width == 0 || rows.size() != width * count)
    {
      rows.clear();
      return;
    }
    std::size_t next = 0;
    for (const std::size_t i : selected)
    {
      std::copy(rows.begin() + static_cast<std::ptrdiff_t>(width * i),
        rows.begin() + static_cast<std::ptrdiff_t>(width * (i + 1)),
        rows.begin() + static_cast<std::ptrdiff_t>(width * next++));
    }
    rows.resize(width * selected.size());
  };
  // (The fits' rows are kept together or not at all.)
  const std::size_t fit = isopoints.FitSize;
  const bool withFits = fit > 0 && isopoints.FitSamples.size() == fit * count &&
    isopoints.FitModels.size() == ModelSize * count;
  keepRows(isopoints.Points, 3);
  keepRows(isopoints.Normals, 3);
  keepRows(isopoints.FitSamples, withFits ? fit : 0);
  keepRows(isopoints.FitModels, withFits ? ModelSize : 0);
}

std::vector<std::size_t> ValidIndices(const std::vector<char>& valid)
{
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < valid.size(); ++i)
  {
    if (valid[i])
    {
      indices.push_back(i);
    }
  }
  return indices;
}

bool ProjectCandidates(const Neighborhoods& geometry, const std::vector<double>& phi,
  const NewtonSettings& newton, int normalFitScale, std::vector<double>& points,
  std::vector<double>& normals, std::vector<char>& valid, const AbortCheck& aborted)
{
  const std::size_t normalFitCount = std::min<std::size_t>(
    geometry.NumberOfSamples, static_cast<std::size_t>(normalFitScale) * geometry.Stride);
  vtkSMPThreadLocal<std::shared_ptr<MLSEvaluator>> evaluators, normalEvaluators;
  const std::size_t count = points.size() / 3;
  normals.assign(3 * count, 0.0);
  // Only the valid candidates, listed: they can be a few in each block of candidates (the
  // completion's, after thinning, 38,000 of 569,000 at 2M samples), and blocks of a few points
  // leave one thread idle at the end of each.
  const std::vector<std::size_t> listed = ValidIndices(valid);
  auto refine = [&](std::size_t first, std::size_t last) {
    std::shared_ptr<MLSEvaluator>& evaluator = evaluators.Local();
    std::shared_ptr<MLSEvaluator>& normalEvaluator = normalEvaluators.Local();
    if (!evaluator)
    {
      evaluator.reset(new MLSEvaluator(geometry, phi));
      normalEvaluator.reset(new MLSEvaluator(geometry, phi, normalFitCount));
    }
    for (std::size_t k = first; k < last; ++k)
    {
      const std::size_t i = listed[k];
      Eigen::Vector3d p(&points[3 * i]);
      Eigen::Vector3d gradient;
      valid[i] = ProjectOntoZeroLevel(p, gradient, *evaluator, newton);
      if (valid[i])
      {
        double value;
        Eigen::Vector3d wide;
        if (normalFitScale > 1 && (*normalEvaluator)(p, value, wide) && wide.squaredNorm() > 0.0)
        {
          gradient = wide;
        }
        const Eigen::Vector3d n = -gradient.normalized();
        for (int d = 0; d < 3; ++d)
        {
          points[3 * i + d] = p[d];
          normals[3 * i + d] = n[d];
        }
      }
    }
  };
  return ParallelForInBlocks(listed.size(), refine, aborted, IsopointBlock);
}

namespace
{
// Rough isopoints: one per neighbour pair (i, j) with phi_i > 0 >= phi_j whose segment passes
// the angle criterion, placed where the linear interpolation of phi vanishes.
void RoughIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  double minimumCosine, std::vector<double>& points, const Communicator& ranks)
{
  const std::size_t n = geometry.NumberOfSamples;
  const std::size_t stride = static_cast<std::size_t>(geometry.Stride);
  const std::vector<std::size_t> front = FrontNearOwned(geometry, ranks,
    IndicesWhere<std::size_t>(
      n, [&](std::size_t i) { return phi[i] > 0.0 && phi[i] < 3.0 * geometry.RadiusOf(i); }),
    NearOwnedSteps);
  {
    // The angle criterion needs gradients on the front and at its negative neighbours.
    std::vector<char> needed(n, 0);
    std::vector<std::size_t> list;
    for (std::size_t i : front)
    {
      const std::uint32_t* ids = geometry.NeighborsOf(i);
      for (std::size_t m = 0; m < stride; ++m)
      {
        if ((m == 0 || phi[ids[m]] <= 0.0) && !needed[ids[m]])
        {
          needed[ids[m]] = 1;
          list.push_back(ids[m]);
        }
      }
    }
    geometry.EnsureStencils(list);
  }
  auto gradientAt = [&](std::size_t i) {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    return geometry.GradientAt(i, [&](std::size_t m) { return phi[ids[m]]; });
  };
  // Two passes (count, then fill) keep the output order independent of the threads.
  auto forEachAcceptedPair = [&](std::size_t i, auto&& emit) {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    const Eigen::Vector3d xi(geometry.Position(i));
    const Eigen::Vector3d gi = gradientAt(i);
    for (std::size_t m = 1; m < stride; ++m)
    {
      const std::uint32_t j = ids[m];
      if (phi[j] > 0.0)
      {
        continue;
      }
      const Eigen::Vector3d xj(geometry.Position(j));
      if (AlignedWithGradient(xj - xi, gi + gradientAt(j), minimumCosine))
      {
        emit(ZeroCrossing(xi, phi[i], xj, phi[j]));
      }
    }
  };
  std::vector<std::size_t> offsets(front.size() + 1, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(front.size()), BalancedGrain(front.size(), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        std::size_t count = 0;
        forEachAcceptedPair(front[k], [&](const Eigen::Vector3d&) { ++count; });
        offsets[k + 1] = count;
      }
    });
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  points.assign(3 * offsets.back(), 0.0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(front.size()), BalancedGrain(front.size(), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        std::size_t slot = offsets[k];
        forEachAcceptedPair(front[k], [&](const Eigen::Vector3d& p) {
          for (int d = 0; d < 3; ++d)
          {
            points[3 * slot + d] = p[d];
          }
          ++slot;
        });
      }
    });
}

} // namespace

std::vector<std::size_t> FrontNearOwned(const Neighborhoods& geometry, const Communicator& ranks,
  const std::vector<std::size_t>& front, int steps)
{
  if (!ranks.Distributed())
  {
    return front;
  }
  geometry.EnsureNeighbors(front);
  std::vector<char> near(geometry.NumberOfSamples, 0);
  std::vector<std::size_t> ghosts; // of the front, not reached yet
  for (const std::size_t i : front)
  {
    if (ranks.Owns(i))
    {
      near[i] = 1;
    }
    else
    {
      ghosts.push_back(i);
    }
  }
  // Step by step (a ghost reached in this step does not pass it on before the next).
  for (int step = 0; step < steps && !ghosts.empty(); ++step)
  {
    std::vector<std::size_t> still, added;
    for (const std::size_t i : ghosts)
    {
      const std::uint32_t* ids = geometry.NeighborsOf(i);
      bool next = false;
      for (int m = 1; m < geometry.Stride && !next; ++m)
      {
        next = near[ids[m]] || ranks.Owns(ids[m]);
      }
      (next ? added : still).push_back(i);
    }
    for (const std::size_t i : added)
    {
      near[i] = 1;
    }
    ghosts.swap(still);
  }
  std::vector<std::size_t> kept;
  kept.reserve(front.size());
  for (const std::size_t i : front)
  {
    if (near[i])
    {
      kept.push_back(i);
    }
  }
  return kept;
}

// Every sample of a pocket disagrees with the data, so only the (few) disagreeing samples are
// searched: found in parallel, then taken in ascending order (as a serial scan meets them).
FlippedSamples FlipSpuriousPockets(
  const Neighborhoods& geometry, const std::vector<double>& dataOffsets, std::vector<double>& phi)
{
  const std::size_t n = geometry.NumberOfSamples;
  auto positive = [&](std::size_t i) { return phi[i] > 0.0; };
  auto disagrees = [&](std::size_t i) { return positive(i) != (dataOffsets[i] > 0.0); };
  FlippedSamples flipped;
  const std::vector<std::uint32_t> starts = IndicesWhere<std::uint32_t>(n, disagrees);
  if (starts.empty())
  {
    return flipped;
  }
  std::vector<char> state(n, 0); // 1: in the region being searched, 2: done
  std::vector<std::uint32_t> region;
  for (const std::uint32_t start : starts)
  {
    // (A flip below only makes samples agree: a later start still disagrees, or was flipped
    // with its region and is done.)
    if (state[start] || !disagrees(start))
    {
      continue;
    }
    // The same-sign region of `start`, as long as it only contains disagreeing samples.
    region.assign(1, static_cast<std::uint32_t>(start));
    state[start] = 1;
    bool pocket = !geometry.IsTruncated(start); // a cut list cannot prove a pocket closed
    BreadthFirst(geometry, region, [&](std::uint32_t j) {
      if (positive(j) != positive(start) || state[j] == 1)
      {
        return Visit::Skip;
      }
      if (!disagrees(j) || state[j] == 2)
      {
        // The region reaches a sample the data support (or, through a one-way neighbour
        // link, a region already decided): leave it as it is.
        pocket = false;
        return Visit::Skip;
      }
      state[j] = 1;
      pocket = pocket && !geometry.IsTruncated(j);
      return Visit::Enqueue;
    });
    for (std::uint32_t i : region)
    {
      state[i] = 2;
      if (pocket)
      {
        flipped.Before.emplace_back(i, phi[i]);
        // A sample at phi = 0 gets a tiny positive value, relative to the spacing (no unit).
        phi[i] = phi[i] > 0.0 ? -phi[i] : std::max(-phi[i], 1e-12 * geometry.MeanRadius);
      }
    }
  }
  return flipped;
}

bool ExtractIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted,
  const Communicator& ranks)
{
  // Progress in proportion to the parts' times at 2M samples: rough points a third, their
  // projection the rest.
  out = IsopointSet();
  std::vector<double> points, normals;
  RoughIsopoints(geometry, phi, settings.MinimumCosine, points, ranks);
  out.RoughCount = points.size() / 3;
  // Many crossings lie within one voxel: project one per voxel only.
  std::vector<char> valid(out.RoughCount, 0);
  for (std::size_t k : ThinByVoxels(points, settings.CellSize))
  {
    valid[k] = 1;
  }
  if (!ProjectCandidates(geometry, phi, settings.Newton, NormalFitScaleFor(settings), points,
        normals, valid, SubRange(aborted, 0.36, 1.0)))
  {
    return false;
  }
  // Thin the projected points: many crossings land on nearly the same spot.
  IsopointSet projected;
  AppendSelected(points, normals, ValidIndices(valid), projected);
  AppendSelected(
    projected.Points, projected.Normals, ThinByVoxels(projected.Points, settings.CellSize), out);
  return !Aborted(aborted, 1.0);
}

} // namespace lsi
