// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetIsopoints.h"

#include "NearestNeighbors.h"
#include "TangentPlaneCompletion.h"
#include "UninitializedVector.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>

namespace lsi
{

namespace
{
// Completion candidates: centres of the empty tangent-plane cells around each isopoint.
void CompletionCandidates(const IsopointSet& current, const IsopointSettings& settings,
  std::vector<double>& candidates, std::vector<char>& valid)
{
  const std::size_t count = current.Points.size() / 3;
  const int side = 2 * settings.CompletionHalfCells + 1;
  const std::size_t perPoint = static_cast<std::size_t>(side * side - 1);
  const std::size_t neighbors = std::min<std::size_t>(count, 2 * perPoint);
  PointCloudIndex index(current.Points.data(), count);
  candidates.clear();
  ResizeMapped(candidates, 3 * perPoint * count, 0.0);
  valid.assign(perPoint * count, 0);
  struct Scratch
  {
    std::vector<std::uint32_t> Ids;
    std::vector<double> D2;
    std::vector<Eigen::Vector3d> Cells;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
    Scratch& s = scratch.Local();
    s.Ids.resize(neighbors);
    s.D2.resize(neighbors);
    for (vtkIdType i = begin; i < end; ++i)
    {
      const Eigen::Vector3d p(&current.Points[3 * i]);
      const Eigen::Vector3d n(&current.Normals[3 * i]);
      const std::size_t found = index.Nearest(p.data(), neighbors, s.Ids.data(), s.D2.data());
      s.Cells.clear();
      EmptyTangentCells(
        p, n, settings.CellSize, settings.CompletionHalfCells, settings.CellSize, found,
        [&](std::size_t j) { return Eigen::Vector3d(&current.Points[3 * s.Ids[j]]); }, s.Cells);
      for (std::size_t c = 0; c < s.Cells.size() && c < perPoint; ++c)
      {
        const std::size_t slot = perPoint * i + c;
        for (int d = 0; d < 3; ++d)
        {
          candidates[3 * slot + d] = s.Cells[c][d];
        }
        valid[slot] = 1;
      }
    }
  });
}
// Neighbouring isopoints propose the same empty cells: before the costly refinement, keep one
// proposal per voxel, and none in a voxel that an isopoint already occupies.
void DropProposalsInOccupiedVoxels(const IsopointSet& current, double cell,
  const std::vector<double>& candidates, std::vector<char>& valid)
{
  const std::size_t existing = current.Points.size() / 3;
  std::vector<double> all(current.Points);
  std::vector<std::size_t> candidateOf;
  for (std::size_t c = 0; c < valid.size(); ++c)
  {
    if (valid[c])
    {
      all.insert(all.end(), &candidates[3 * c], &candidates[3 * c + 3]);
      candidateOf.push_back(c);
    }
  }
  std::fill(valid.begin(), valid.end(), 0);
  for (std::size_t k : ThinByVoxels(all, cell, existing)) // existing points win
  {
    if (k >= existing)
    {
      valid[candidateOf[k - existing]] = 1;
    }
  }
}

} // namespace

bool CompleteIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  std::vector<double> candidates, candidateNormals;
  std::vector<char> candidateValid;
  CompletionCandidates(out, settings, candidates, candidateValid);
  DropProposalsInOccupiedVoxels(out, settings.CellSize, candidates, candidateValid);
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
