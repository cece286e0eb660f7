// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetIsopoints.h"

#include "NearestNeighbors.h"
#include "TangentPlaneCompletion.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>
#include <functional>

namespace lsi
{

namespace
{
// The voxels that the isopoints occupy, sorted.
std::vector<std::uint64_t> OccupiedVoxels(const IsopointSet& current, double cell)
{
  std::vector<std::uint64_t> keys(current.Points.size() / 3);
  vtkSMPTools::For(0, static_cast<vtkIdType>(keys.size()), BalancedGrain(keys.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        keys[i] = VoxelKey(&current.Points[3 * i], cell);
      }
    });
  ParallelSort(keys.begin(), keys.end(), std::less<std::uint64_t>());
  return keys;
}

// Completion candidates: centres of the empty tangent-plane cells around each isopoint, in the
// order of the isopoints and of their cells. A proposal in a voxel an isopoint already occupies
// is left out at once: the isopoint keeps its voxel (ThinnedVoxels' preferred points), so the
// proposal could never be kept. (At 2M samples 290,000 proposals, most of them there.)
UninitializedVector<double> CompletionCandidates(
  const IsopointSet& current, const IsopointSettings& settings)
{
  const std::size_t count = current.Points.size() / 3;
  const int side = 2 * settings.CompletionHalfCells + 1;
  const std::size_t perPoint = static_cast<std::size_t>(side * side - 1);
  const std::size_t neighbors = std::min<std::size_t>(count, 2 * perPoint);
  const std::vector<std::uint64_t> occupied = OccupiedVoxels(current, settings.CellSize);
  PointCloudIndex index(current.Points.data(), count);
  // Fixed blocks of isopoints, each with its own list, joined in block order: the same list on
  // any number of threads, without a slot for every cell of every isopoint.
  constexpr std::size_t Block = 512;
  std::vector<std::vector<double>> found((count + Block - 1) / Block);
  struct Scratch
  {
    std::vector<std::uint32_t> Ids;
    std::vector<double> D2;
    std::vector<Eigen::Vector3d> Cells;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(found.size()), 1, [&](vtkIdType first, vtkIdType last) {
      Scratch& s = scratch.Local();
      s.Ids.resize(neighbors);
      s.D2.resize(neighbors);
      for (vtkIdType b = first; b < last; ++b)
      {
        std::vector<double>& out = found[static_cast<std::size_t>(b)];
        const std::size_t end = std::min(count, (static_cast<std::size_t>(b) + 1) * Block);
        for (std::size_t i = static_cast<std::size_t>(b) * Block; i < end; ++i)
        {
          const Eigen::Vector3d p(&current.Points[3 * i]);
          const Eigen::Vector3d n(&current.Normals[3 * i]);
          const std::size_t near = index.Nearest(p.data(), neighbors, s.Ids.data(), s.D2.data());
          s.Cells.clear();
          EmptyTangentCells(
            p, n, settings.CellSize, settings.CompletionHalfCells, settings.CellSize, near,
            [&](std::size_t j) { return Eigen::Vector3d(&current.Points[3 * s.Ids[j]]); }, s.Cells);
          for (std::size_t c = 0; c < s.Cells.size() && c < perPoint; ++c)
          {
            if (!std::binary_search(
                  occupied.begin(), occupied.end(), VoxelKey(s.Cells[c].data(), settings.CellSize)))
            {
              out.insert(out.end(), s.Cells[c].data(), s.Cells[c].data() + 3);
            }
          }
        }
      }
    });
  UninitializedVector<double> candidates(JoinedSize(found)); // joined in block order
  JoinInParallel(found, candidates.begin());
  return candidates;
}
} // namespace

bool CompleteIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  // Neighbouring isopoints propose the same empty cells: before the costly projection, one
  // proposal per voxel (the same one as thinning them with the isopoints would keep).
  const UninitializedVector<double> proposals = CompletionCandidates(out, settings);
  const std::vector<std::size_t> distinct = ThinnedVoxels(
    proposals.size() / 3, [&](std::size_t k) { return &proposals[3 * k]; }, settings.CellSize);
  std::vector<double> candidates(3 * distinct.size()), candidateNormals;
  for (std::size_t k = 0; k < distinct.size(); ++k)
  {
    std::copy_n(&proposals[3 * distinct[k]], 3, &candidates[3 * k]);
  }
  std::vector<char> candidateValid(distinct.size(), 1);
  NewtonSettings newton = settings.Newton;
  newton.MaximumDistance = 2.0 * settings.CellSize; // stay near the cell it was proposed for
  if (!ProjectCandidates(geometry, phi, newton, NormalFitScaleFor(settings), candidates,
        candidateNormals, candidateValid, SubRange(aborted, 0.1, 0.9)))
  {
    return false;
  }

  // The union, thinned again; existing isopoints come first and so win their voxels.
  IsopointSet all = out;
  AppendSelected(candidates, candidateNormals, ValidIndices(candidateValid), all);
  const std::size_t before = out.Points.size() / 3;
  const std::vector<std::size_t> kept = ThinByVoxels(all.Points, settings.CellSize, before);
  IsopointSet result;
  result.RoughCount = out.RoughCount;
  AppendSelected(all.Points, all.Normals, kept, result);
  result.CompletedCount = result.Points.size() / 3 - std::min(before, result.Points.size() / 3);
  out = std::move(result);
  return true;
}

} // namespace lsi
