// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Nearest-point searches that a re-run repeats on points moved a little. A quick isovalue
// change slides the last surface's points and asks again for each point's splat neighbours,
// and for each sample near the surface its nearest surface point: the answers then lie among
// the nearest points one search kept for each query, and bounds on how far the points moved
// since tell when they surely do (no tree search there: the answers of a search).
#ifndef LevelSetKeptCandidates_h
#define LevelSetKeptCandidates_h

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lsi
{
class PointCloudIndex;

/// For each query, the nearest PerQuery points of an index (the "cloud") that one search found,
/// and how far the first one left out lay. Later, with the queries and the cloud's points moved
/// (the same counts, the same order), every point not among a query's candidates lies at least
/// Reach() from it. A grid over where they all lay, of cells twice the median outer distance
/// wide: a query's non-candidates in the 27 cells around its own lay at least its outer
/// distance from it, the others at least a cell width; how the points of those 27 cells moved
/// (a sheet moves much like its neighbours) bounds how near a non-candidate can have come.
class KeptCandidates
{
public:
  /// Readies room for `queries` queries of `perQuery` candidates each, none kept yet.
  void Start(std::size_t queries, std::size_t perQuery);
  /// Query q's candidates (PerQuery ids, nearest first) and the distance of the first left out.
  std::uint32_t* CandidatesOf(std::size_t q) { return &this->Ids[this->PerQuery * q]; }
  const std::uint32_t* CandidatesOf(std::size_t q) const { return &this->Ids[this->PerQuery * q]; }
  void SetOuter(std::size_t q, double outer) { this->Outer[q] = outer; }
  /// Once every query's candidates are set (an outer distance of 0: none kept for it): keeps
  /// where the queries (3 doubles each, as many as Start's) and the index's points lie. False
  /// (and nothing kept) if no query kept any, a position is not finite, or they span too many
  /// cells to number.
  bool Finish(const double* queries, const PointCloudIndex& index);

  bool Empty() const { return this->Outer.empty(); }
  void Clear() { *this = KeptCandidates(); }
  std::size_t Queries() const { return this->Outer.size(); }
  std::size_t Candidates() const { return this->PerQuery; }
  /// The grid cell query q lay in, and the 27 cells around a cell (~0u: none there).
  std::uint32_t CellOf(std::size_t q) const { return this->QueryCell[q]; }
  const std::uint32_t* CellsAround(std::uint32_t cell) const { return &this->Around[27 * cell]; }

  /// How the cloud moved since Finish: per grid cell, the box of its points' moves (as vectors)
  /// over the 27 cells around it, and the farthest move of any (infinite if a position is not
  /// finite).
  struct Moves
  {
    std::vector<std::array<double, 6>> Around; // low x y z, high x y z (low above high: none)
    double Farthest = 0.0;
  };
  /// Whether `index` holds as many points as when kept, and `queries` queries are asked.
  bool Fits(std::size_t queries, const PointCloudIndex& index) const;
  Moves MovesSince(const PointCloudIndex& index) const;
  /// How far every point that is not among query q's candidates lies, at least, from the
  /// query now at `query` (with a margin for the rounding of coordinates this large).
  double Reach(std::size_t q, const double* query, const Moves& moves) const;

private:
  std::size_t PerQuery = 0;
  std::vector<double> QueryPoints, Cloud; // where the queries and the cloud's points lay
  std::vector<std::uint32_t> Ids;
  std::vector<double> Outer;
  double CellSize = 0.0;
  double Slack = 0.0;
  std::vector<std::uint32_t> CloudCell, QueryCell; // each point's cell
  std::vector<std::uint32_t> Around;               // per cell: the 27 cells around it
};

} // namespace lsi

#endif
