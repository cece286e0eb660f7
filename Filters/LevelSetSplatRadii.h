// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The surface output's splat radius: a point's distance to its 6th nearest other surface point,
// scaled. A quick isovalue change slides the last surface's points a little and asks again:
// each point's nearest then lie among the candidates one search kept for it, and bounds on how
// the points moved since tell when they surely do (no tree search there: the same radii).
#ifndef LevelSetSplatRadii_h
#define LevelSetSplatRadii_h

#include "LevelSetParallel.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace lsi
{
class PointCloudIndex;

/// The candidates for each point's splat neighbours that one search found, for later calls on
/// the same points moved a little (and on the same index's points, moved a little).
struct SplatCandidates
{
  /// Kept per point: the nearest PerPoint of the index's points, nearest first.
  static constexpr std::size_t PerPoint = 12;
  std::vector<double> Queries, Cloud; // where the points and the index's points lay then
  std::vector<std::uint32_t> Ids;     // PerPoint per point
  std::vector<double> Outer;          // per point: the distance of the nearest one left out
  // A grid over where they lay, of cells twice the median outer distance wide: a point's
  // non-candidates in the 27 cells around its own lay at least its outer distance from it, the
  // others at least a cell width. How the points of those 27 cells moved (a sheet moves much
  // like its neighbours) then bounds how near a non-candidate can have come.
  double CellSize = 0.0;
  double Slack = 0.0; // of lengths, against the rounding of coordinates this large
  std::vector<std::uint32_t> CloudCell, QueryCell; // each point's cell
  std::vector<std::uint32_t> Around;               // per cell: the 27 cells around it
  std::size_t Reused = 0; // how many radii the last call took from the candidates
  bool Empty() const { return this->Outer.empty(); }
  void Clear() { *this = SplatCandidates(); }
};

/// Splat radius of each point (3 doubles per point): `factor` times the distance to its
/// `neighbors`-th nearest other point, searched in `index` if given (over `points`, or over
/// more points near them), else in one built here. Returns false only when aborted.
/// `kept`, if given and empty, receives each point's candidates (a search of a few more points);
/// if given and filled for as many points and index points, a point takes its radius from its
/// candidates where every other point surely lies farther (however the points moved since,
/// within the bounds above, with margins for rounding), else from a search: the radii are a
/// search's either way.
bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted, const PointCloudIndex* index = nullptr,
  SplatCandidates* kept = nullptr);

} // namespace lsi

#endif
