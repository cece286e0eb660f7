// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetKeptCandidates.h"

#include "LevelSetParallel.h"
#include "NearestNeighbors.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

namespace
{
constexpr std::uint32_t NoCell = ~std::uint32_t(0);
constexpr int CellBits = 21; // per axis of a packed cell key
} // namespace

void KeptCandidates::Start(std::size_t queries, std::size_t perQuery)
{
  this->Clear();
  this->PerQuery = perQuery;
  this->Ids.resize(perQuery * queries);
  this->Outer.assign(queries, 0.0);
}

bool KeptCandidates::Finish(const double* queries, const PointCloudIndex& index)
{
  const std::size_t queryCount = this->Outer.size(), cloud = index.Size();
  this->QueryPoints.assign(queries, queries + 3 * queryCount);
  this->Cloud.resize(3 * cloud);
  for (std::size_t j = 0; j < cloud; ++j)
  {
    const double* x = index.Point(static_cast<std::uint32_t>(j));
    std::copy(x, x + 3, &this->Cloud[3 * j]);
  }
  // The cell width: twice the median outer distance of the queries that kept candidates.
  std::vector<double> outer;
  for (double o : this->Outer)
  {
    if (o > 0.0)
    {
      outer.push_back(o);
    }
  }
  if (outer.empty())
  {
    this->Clear();
    return false;
  }
  std::nth_element(outer.begin(), outer.begin() + outer.size() / 2, outer.end());
  this->CellSize = 2.0 * outer[outer.size() / 2];
  double low[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }, largest = 0.0;
  for (const std::vector<double>* xyz : { &this->QueryPoints, &this->Cloud })
  {
    for (std::size_t i = 0; i < xyz->size(); ++i)
    {
      low[i % 3] = std::min(low[i % 3], (*xyz)[i]);
      largest = std::max(largest, std::abs((*xyz)[i]));
    }
  }
  // (Each length Reach sums is a few roundings of coordinates up to `largest`.)
  this->Slack = 64.0 * 2.220446049250313e-16 * largest;
  if (!(this->CellSize > 0.0) || !std::isfinite(largest) || !std::isfinite(this->CellSize))
  {
    this->Clear();
    return false;
  }
  // Cells numbered from 1, so that the cells around every one have numbers too.
  const double limit = static_cast<double>((1 << CellBits) - 2);
  auto keyOf = [&](const double* x, std::uint64_t& key) {
    key = 0;
    for (int a = 0; a < 3; ++a)
    {
      const double c = std::floor((x[a] - low[a]) / this->CellSize) + 1.0;
      if (!(c >= 1.0 && c <= limit))
      {
        return false;
      }
      key = (key << CellBits) | static_cast<std::uint64_t>(c);
    }
    return true;
  };
  std::vector<std::uint64_t> keys(queryCount + cloud);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    const double* x =
      i < queryCount ? &this->QueryPoints[3 * i] : &this->Cloud[3 * (i - queryCount)];
    if (!keyOf(x, keys[i]))
    {
      this->Clear();
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
  this->QueryCell.resize(queryCount);
  this->CloudCell.resize(cloud);
  for (std::size_t i = 0; i < keys.size(); ++i)
  {
    (i < queryCount ? this->QueryCell[i] : this->CloudCell[i - queryCount]) = cellOf(keys[i]);
  }
  const std::uint64_t mask = (std::uint64_t(1) << CellBits) - 1;
  this->Around.resize(27 * cells.size());
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
          const std::uint64_t key =
            (((x + dx - 1) << CellBits | (y + dy - 1)) << CellBits) | (z + dz - 1);
          this->Around[27 * c + k++] = cellOf(key);
        }
      }
    }
  }
  return true;
}

bool KeptCandidates::Fits(std::size_t queries, const PointCloudIndex& index) const
{
  return !this->Empty() && this->Outer.size() == queries && this->Cloud.size() == 3 * index.Size();
}

KeptCandidates::Moves KeptCandidates::MovesSince(const PointCloudIndex& index) const
{
  const std::size_t cellCount = this->Around.size() / 27, count = index.Size();
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
        std::array<double, 6>& box = l.Boxes[this->CloudCell[j]];
        double d2 = 0.0;
        for (int a = 0; a < 3; ++a)
        {
          const double move = now[a] - this->Cloud[3 * j + a];
          box[a] = std::min(box[a], move);
          box[3 + a] = std::max(box[3 + a], move);
          d2 += move * move;
        }
        l.Farthest = d2 <= l.Farthest ? l.Farthest : (std::isfinite(d2) ? d2 : HUGE_VAL);
      }
    });
  // (Minima and maxima: the same on any number of threads.)
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
      const std::uint32_t n = this->Around[27 * c + k];
      for (int a = 0; a < 3 && n != NoCell; ++a)
      {
        moves.Around[c][a] = std::min(moves.Around[c][a], boxes[n][a]);
        moves.Around[c][3 + a] = std::max(moves.Around[c][3 + a], boxes[n][3 + a]);
      }
    }
  }
  return moves;
}

double KeptCandidates::Reach(std::size_t q, const double* query, const Moves& moves) const
{
  // A non-candidate j lay at least `outer` from where the query lay, so lies at least
  // outer - |move_j - move_query| from it now; beyond the 27 cells around, at least a cell
  // width less both moves.
  const double outer = this->Outer[q];
  if (!(outer > 0.0))
  {
    return 0.0;
  }
  const double* then = &this->QueryPoints[3 * q];
  const std::array<double, 6>& around = moves.Around[this->QueryCell[q]];
  double ownMove2 = 0.0, apart2 = 0.0; // |move_query|^2, and the largest |move_j - move_query|^2
  for (int a = 0; a < 3; ++a)
  {
    const double move = query[a] - then[a];
    ownMove2 += move * move;
    const double apart = std::max(std::abs(move - around[a]), std::abs(around[3 + a] - move));
    apart2 += apart * apart;
  }
  const double near = around[0] <= around[3] ? outer - std::sqrt(apart2) : HUGE_VAL;
  const double far = std::max(outer, this->CellSize) - moves.Farthest - std::sqrt(ownMove2);
  if (std::isnan(near) || std::isnan(far))
  {
    return 0.0; // (a position not finite)
  }
  return std::min(near, far) - this->Slack;
}

} // namespace lsi
