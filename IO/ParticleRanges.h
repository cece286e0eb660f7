// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Ranges of particle indices [begin, end) of one type, as a reader reads them: the candidates of
// a region (all of a type, or the cells of a SWIFT snapshot that overlap it) and an MPI rank's
// contiguous share of them. Plain C++.
#ifndef ParticleRanges_h
#define ParticleRanges_h

#include <algorithm>
#include <utility>
#include <vector>

namespace lsi
{
namespace io
{
using Range = std::pair<long long, long long>; // [first, second)

/// The ranges sorted, overlapping or touching ones joined, empty ones dropped.
inline std::vector<Range> MergedRanges(std::vector<Range> ranges)
{
  ranges.erase(std::remove_if(
                 ranges.begin(), ranges.end(), [](const Range& r) { return r.second <= r.first; }),
    ranges.end());
  std::sort(ranges.begin(), ranges.end());
  std::vector<Range> merged;
  for (const Range& r : ranges)
  {
    if (!merged.empty() && r.first <= merged.back().second)
    {
      merged.back().second = std::max(merged.back().second, r.second);
    }
    else
    {
      merged.push_back(r);
    }
  }
  return merged;
}

/// How many indices the ranges hold.
inline long long CountOf(const std::vector<Range>& ranges)
{
  long long count = 0;
  for (const Range& r : ranges)
  {
    count += r.second - r.first;
  }
  return count;
}

/// Piece `piece` of `pieces` (0 <= piece < pieces) of the ranges' indices taken in order: the
/// same contiguous share of their concatenation a reader gives each rank of a whole type, so
/// that the pieces together hold every index once.
inline std::vector<Range> ShareOfRanges(const std::vector<Range>& ranges, int piece, int pieces)
{
  const long long total = CountOf(ranges);
  const long long from = total * piece / pieces, to = total * (piece + 1) / pieces;
  std::vector<Range> share;
  long long before = 0; // indices in the ranges before r
  for (const Range& r : ranges)
  {
    const long long length = r.second - r.first;
    const long long begin = std::max(from, before), end = std::min(to, before + length);
    if (begin < end)
    {
      share.emplace_back(r.first + (begin - before), r.first + (end - before));
    }
    before += length;
  }
  return share;
}
} // namespace io
} // namespace lsi

#endif
