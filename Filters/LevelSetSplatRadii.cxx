// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSplatRadii.h"

#include "NearestNeighbors.h"
#include "Splats.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>

namespace lsi
{

namespace
{
constexpr std::uint32_t NoCell = ~std::uint32_t(0);
constexpr int CellBits = 21; // per axis of a packed cell key

// The squared distance, summed as the tree search sums it (PointCloudIndex::SearchNode): the
// same bits.
double SquaredDistance(const double* query, const double* x)
{
  const double dx = query[0] - x[0], dy = query[1] - x[1], dz = query[2] - x[2];
  return dx * dx + dy * dy + dz * dz;
}

// The grid of `kept` (SplatCandidates): cells, each point's cell and the cells around each.
// False if the points span too many cells to number (then nothing is kept).
bool BuildGrid(SplatCandidates& kept)
{
  std::vector<double> outer(kept.Outer);
  std::nth_element(outer.begin(), outer.begin() + outer.size() / 2, outer.end());
  kept.CellSize = 2.0 * outer[outer.size() / 2];
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, largest = 0.0;
  for (const std::vector<double>* xyz : { &kept.Queries, &kept.Cloud })
  {
    for (std::size_t i = 0; i < xyz->size(); ++i)
    {
      low[i % 3] = std::min(low[i % 3], (*xyz)[i]);
      largest = std::max(largest, std::abs((*xyz)[i]));
    }
  }
  // (Each length below sums a few roundings of coordinates up to `largest`.)
  kept.Slack = 64.0 * 2.220446049250313e-16 * largest;
  if (!(kept.CellSize > 0.0) || !std::isfinite(largest) || !std::isfinite(kept.CellSize))
  {
    return false;
  }
  const double limit = static_cast<double>((1 << CellBits) - 2);
  auto keyOf = [&](const double* x, std::uint64_t& key) {
    key = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double c =
        std::floor((x[a] - low[a]) / kept.CellSize) + 1.0; // (0: for the cells around)
      if (!(c >= 1.0 && c <= limit))
      {
        return false;
      }
      key = (key << CellBits) | static_cast<std::uint64_t>(c);
    }
    return true;
  };
  const std::size_t queries = kept.Queries.size() / 3, cloud = kept.Cloud.size() / 3;
  std::vector<std::uint64_t> keys(queries + cloud);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    const double* x = i < queries ? &kept.Queries[3 * i] : &kept.Cloud[3 * (i - queries)];
    if (!keyOf(x, keys[i]))
    {
      return false;
    }
  }
  std::vector<std::uint64_t> cells(keys);
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  auto cellOf = [&](std::uint64_t key) {
    const auto at = std::lower_bound(cells.begin(), cells.end(), key);
    return at != cells.end() && *at == key ? static_cast<std::uint32_t>(at - cells.begin())
                                           : NoCell;
  };
  kept.QueryCell.resize(queries);
  kept.CloudCell.resize(cloud);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    (i < queries ? kept.QueryCell[i] : kept.CloudCell[i - queries]) = cellOf(keys[i]);
  }
  const std::uint64_t mask = (std::uint64_t(1) << CellBits) - 1;
  kept.Around.resize(27 * cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
  {
    const std::uint64_t x = cells[c] >> (2 * CellBits), y = (cells[c] >> CellBits) & mask,
                        z = cells[c] & mask;
    std::size_t k = 0;
    for (std::uint64_t dx = 0; dx < 3; ++dx)
    {
      for (std::uint64_t dy = 0; dy < 3; ++dy)
      {
        for (std::uint64_t dz = 0; dz < 3; ++dz)
        {
          kept.Around[27 * c + k++] =
            cellOf((((x + dx - 1) << CellBits | (y + dy - 1)) << CellBits) | (z + dz - 1));
        }
      }
    }
  }
  return true;
}

// How the index's points moved since `kept` was made: per cell of the grid, the box of their
// moves (as vectors; low above high where none lay), for the 27 cells around each cell, and the
// farthest move of any (infinite if any position is not finite).
struct Moves
{
  std::vector<std::array<double, 6>> Around; // low x y z, high x y z
  double Farthest = 0.0;
};
Moves MovesSince(const SplatCandidates& kept, const PointCloudIndex& index)
{
  const std::size_t cellCount = kept.Around.size() / 27, count = index.Size();
  const std::array<double, 6> none = { HUGE_VAL, HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL,
    -HUGE_VAL };
  struct Local
  {
    std::vector<std::array<double, 6>> Boxes;
    double Farthest = 0.0;
  };
  vtkSMPThreadLocal<Local> locals;
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 8192),
    [&](vtkIdType begin, vtkIdType end) {
      Local& l = locals.Local();
      l.Boxes.resize(cellCount, none);
      for (vtkIdType j = begin; j < end; ++j)
      {
        const double* now = index.Point(static_cast<std::uint32_t>(j));
        std::array<double, 6>& box = l.Boxes[kept.CloudCell[j]];
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          const double move = now[a] - kept.Cloud[3 * j + a];
          box[a] = std::min(box[a], move);
          box[3 + a] = std::max(box[3 + a], move);
          d2 += move * move;
        }
        l.Farthest = d2 <= l.Farthest ? l.Farthest : (std::isfinite(d2) ? d2 : HUGE_VAL);
      }
    });
  std::vector<std::array<double, 6>> boxes(cellCount, none);
  Moves moves;
  for (const Local& l : locals)
  {
    for (std::size_t c = 0; c < l.Boxes.size(); ++c)
    {
      for (int a = 0; a < 3; ++a)
      {
        boxes[c][a] = std::min(boxes[c][a], l.Boxes[c][a]);
        boxes[c][3 + a] = std::max(boxes[c][3 + a], l.Boxes[c][3 + a]);
      }
    }
    moves.Farthest = std::max(moves.Farthest, l.Farthest);
  }
  moves.Farthest = std::sqrt(moves.Farthest);
  moves.Around.assign(cellCount, none);
  for (std::size_t c = 0; c < cellCount; ++c)
  {
    for (std::size_t k = 0; k < 27; ++k)
    {
      const std::uint32_t n = kept.Around[27 * c + k];
      for (int a = 0; a < 3 && n != NoCell; ++a)
      {
        moves.Around[c][a] = std::min(moves.Around[c][a], boxes[n][a]);
        moves.Around[c][3 + a] = std::max(moves.Around[c][3 + a], boxes[n][3 + a]);
      }
    }
  }
  return moves;
}

// The squared distance from point i (at `query`) to its k-th nearest index point, from its
// candidates alone, when every other point surely lies farther. A non-candidate j lay at least
// `outer` from where the query lay, so now at least outer - |move_j - move_query|; the moves of
// the points in the 27 cells around bound that, and a point beyond them lay a cell width away at
// least. False if not sure.
bool KthFromCandidates(const SplatCandidates& kept, const Moves& moves,
  const PointCloudIndex& index, std::size_t i, const double* query, std::size_t k, double& d2)
{
  const double* then = &kept.Queries[3 * i];
  const std::array<double, 6>& around = moves.Around[kept.QueryCell[i]];
  double ownMove2 = 0.0, apart2 = 0.0; // |move_query|^2, and the largest |move_j - move_query|^2
  for (int a = 0; a < 3; ++a)
  {
    const double move = query[a] - then[a];
    ownMove2 += move * move;
    const double apart = std::max(std::abs(move - around[a]), std::abs(around[3 + a] - move));
    apart2 += apart * apart; // (infinite where no point lay around: then none is near)
  }
  const double outer = kept.Outer[i];
  const double near = around[0] <= around[3] ? outer - std::sqrt(apart2) : HUGE_VAL;
  const double far = std::max(outer, kept.CellSize) - moves.Farthest - std::sqrt(ownMove2);
  const double reach = std::min(near, far) - kept.Slack;
  if (!(reach > 0.0))
  {
    return false;
  }
  double d2s[SplatCandidates::PerPoint];
  const std::uint32_t* ids = &kept.Ids[SplatCandidates::PerPoint * i];
  for (std::size_t j = 0; j < SplatCandidates::PerPoint; ++j)
  {
    d2s[j] = SquaredDistance(query, index.Point(ids[j]));
  }
  std::nth_element(d2s, d2s + (k - 1), d2s + SplatCandidates::PerPoint);
  d2 = d2s[k - 1];
  // (StillNearest's margins for the rounding of the distances.)
  return std::sqrt(d2) * (1.0 + 1e-9) < reach * (1.0 - 1e-9);
}
} // namespace

bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted, const PointCloudIndex* given,
  SplatCandidates* kept)
{
  const std::size_t count = points.size() / 3;
  radii.assign(count, 0.0);
  if (count < 2)
  {
    if (kept)
    {
      kept->Clear();
    }
    return true;
  }
  std::unique_ptr<PointCloudIndex> built;
  if (!given)
  {
    built.reset(new PointCloudIndex(points.data(), count));
  }
  const PointCloudIndex& index = given ? *given : *built;
  // The point itself comes first in its own query.
  const std::size_t k = std::min<std::size_t>(count, static_cast<std::size_t>(neighbors) + 1);
  const std::size_t perPoint = SplatCandidates::PerPoint;
  // (A cloud of no more than the candidates, or a fit wider than them: searched each time.)
  const bool keeps = kept && index.Size() > perPoint && k <= perPoint;
  const bool reuses =
    keeps && kept->Outer.size() == count && kept->Cloud.size() == 3 * index.Size();
  if (kept && !reuses)
  {
    kept->Clear();
  }
  const Moves moves = reuses ? MovesSince(*kept, index) : Moves();
  std::atomic<std::size_t> reused(0);
  // Kept anew: the candidates, and the first one left out.
  const std::size_t wanted = keeps && !reuses ? perPoint + 1 : k;
  if (keeps && !reuses)
  {
    kept->Ids.resize(perPoint * count);
    kept->Outer.resize(count);
  }
  const bool done = ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t> ids(wanted);
      std::vector<double> d2(wanted);
      // The points are spread about evenly over the surface: the last point's farthest distance
      // bounds the search (the same neighbours, found sooner; NearestNear).
      double lastRadius = 0.0;
      std::size_t fromCandidates = 0;
      for (std::size_t i = begin; i < end; ++i)
      {
        const double* query = &points[3 * i];
        double kth = 0.0;
        if (reuses && KthFromCandidates(*kept, moves, index, i, query, k, kth))
        {
          radii[i] = factor * std::sqrt(kth);
          lastRadius = std::sqrt(kth);
          ++fromCandidates;
          continue;
        }
        const std::size_t found =
          index.NearestNear(query, wanted, lastRadius, ids.data(), d2.data());
        radii[i] = SplatRadiusFromNeighbors(d2.data(), std::min(found, k), factor);
        lastRadius = found == wanted ? std::sqrt(d2[wanted - 1]) : 0.0;
        if (wanted > perPoint)
        {
          std::copy(ids.begin(), ids.begin() + perPoint, &kept->Ids[perPoint * i]);
          kept->Outer[i] = std::sqrt(d2[perPoint]);
        }
      }
      reused += fromCandidates;
    },
    aborted);
  if (keeps && !reuses)
  {
    kept->Queries = points;
    kept->Cloud.resize(3 * index.Size());
    for (std::size_t j = 0; j < index.Size(); ++j)
    {
      const double* x = index.Point(static_cast<std::uint32_t>(j));
      std::copy(x, x + 3, &kept->Cloud[3 * j]);
    }
    if (!done || !BuildGrid(*kept))
    {
      kept->Clear();
    }
  }
  if (reuses)
  {
    kept->Reused = reused;
  }
  return done;
}

} // namespace lsi
