// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "IsopointRefinement.h"
#include "LevelSetIsopoints.h"
#include "LevelSetSPHField.h"

#include "vtkSMPThreadLocal.h"

#include <cmath>

namespace lsi
{
bool OutwardOfCloud(const Neighborhoods& geometry, std::size_t i, Eigen::Vector3d& outward)
{
  const std::uint32_t* ids = geometry.NeighborsOf(i);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (int m = 1; m < geometry.Stride; ++m)
  {
    centroid += Eigen::Vector3d(geometry.Position(ids[m]));
  }
  centroid /= geometry.Stride - 1;
  outward = Eigen::Vector3d(geometry.Position(i)) - centroid;
  const double offset = outward.norm();
  if (!(offset > 0.3 * geometry.RadiusOf(i)))
  {
    return false;
  }
  outward /= offset;
  return true;
}

bool AddFreeBoundaryPoints(const Neighborhoods& geometry, const SPHField& field, double isoValue,
  const std::vector<char>& inside, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<double> points(3 * n), normals(3 * n);
  std::vector<char> found(n, 0);
  auto shoot = [&](std::size_t begin, std::size_t end) {
    SPHCandidates candidates;
    for (std::size_t i = begin; i < end; ++i)
    {
      Eigen::Vector3d outward;
      // Inside the extracted component, above the isovalue, on the edge of the cloud.
      if (!inside[i] || !(dataOffsets[i] > 0.0) || !OutwardOfCloud(geometry, i, outward))
      {
        continue;
      }
      const double reach = field.Support(i);
      Eigen::Vector3d p(geometry.Position(i));
      field.Gather(p.data(), reach, candidates);
      // The ray starts inside (f > f_iso) and leaves the cloud: its crossing is the surface.
      Eigen::Vector3d normal;
      if (SolveOntoLevel(field, candidates, isoValue, p, outward, reach, 1e-9 * reach, normal) &&
        (p - Eigen::Vector3d(geometry.Position(i))).dot(outward) > 0.0)
      {
        for (int d = 0; d < 3; ++d)
        {
          points[3 * i + d] = p[d];
          normals[3 * i + d] = normal[d];
        }
        found[i] = 1;
      }
    }
  };
  if (!ParallelForInBlocks(n, shoot, aborted, IsopointBlock))
  {
    return false;
  }
  // The new points, thinned by voxels against the existing isopoints (all of which stay) and
  // each other.
  const std::size_t before = out.Points.size() / 3;
  IsopointSet all = out;
  AppendSelected(points, normals, ValidIndices(found), all);
  std::vector<std::size_t> added;
  for (std::size_t k : ThinByVoxels(all.Points, settings.CellSize, before))
  {
    if (k >= before)
    {
      added.push_back(k);
    }
  }
  AppendSelected(all.Points, all.Normals, added, out);
  out.FreeBoundaryCount = added.size();
  return true;
}

} // namespace lsi
