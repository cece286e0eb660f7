// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetSplatRadii.h"

#include "LevelSetKeptCandidates.h"
#include "NearestNeighbors.h"
#include "Splats.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace lsi
{

namespace
{
// The squared distance from `query` to its k-th nearest index point among its candidates, if
// no other point can lie nearer (Reach); false if not sure.
bool KthFromCandidates(const KeptCandidates& kept, const KeptCandidates::Moves& moves,
  const PointCloudIndex& index, std::size_t i, const double* query, std::size_t k, double& d2)
{
  const double reach = kept.Reach(i, query, moves);
  if (!(reach > 0.0))
  {
    return false;
  }
  double d2s[SplatCandidates];
  const std::uint32_t* ids = kept.CandidatesOf(i);
  for (std::size_t j = 0; j < SplatCandidates; ++j)
  {
    d2s[j] = PointCloudIndex::SquaredDistance(query, index.Point(ids[j]));
  }
  std::nth_element(d2s, d2s + (k - 1), d2s + SplatCandidates);
  d2 = d2s[k - 1];
  // (StillNearest's margins for the rounding of the distances.)
  return std::sqrt(d2) * (1.0 + 1e-9) < reach * (1.0 - 1e-9);
}
} // namespace

bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted, const PointCloudIndex* given,
  KeptCandidates* kept, std::size_t* fromCandidates)
{
  const std::size_t count = points.size() / 3;
  radii.assign(count, 0.0);
  if (fromCandidates)
  {
    *fromCandidates = 0;
  }
  if (count < 2)
  {
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
  // Candidates kept anew when none are (a cloud of no more than them, or a fit wider than
  // them: none), used when kept for as many points and index points, else left as they are.
  const bool usable = kept && index.Size() > SplatCandidates && k <= SplatCandidates;
  const bool keeps = usable && kept->Empty();
  const bool reuses = usable && kept->Fits(count, index) && kept->Candidates() == SplatCandidates;
  const KeptCandidates::Moves moves = reuses ? kept->MovesSince(index) : KeptCandidates::Moves();
  // Kept anew: the candidates, and the first one left out.
  const std::size_t wanted = keeps ? SplatCandidates + 1 : k;
  if (keeps)
  {
    kept->Start(count, SplatCandidates);
  }
  std::atomic<std::size_t> reused(0);
  const bool done = ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t> ids(wanted);
      std::vector<double> d2(wanted);
      // The points are spread about evenly over the surface: the last point's farthest distance
      // bounds the search (the same neighbours, found sooner; NearestNear).
      double lastRadius = 0.0;
      std::size_t taken = 0;
      for (std::size_t i = begin; i < end; ++i)
      {
        const double* query = &points[3 * i];
        double kth = 0.0;
        if (reuses && KthFromCandidates(*kept, moves, index, i, query, k, kth))
        {
          radii[i] = factor * std::sqrt(kth);
          lastRadius = std::sqrt(kth);
          ++taken;
          continue;
        }
        const std::size_t found =
          index.NearestNear(query, wanted, lastRadius, ids.data(), d2.data());
        radii[i] = SplatRadiusFromNeighbors(d2.data(), std::min(found, k), factor);
        lastRadius = found == wanted ? std::sqrt(d2[wanted - 1]) : 0.0;
        if (wanted > SplatCandidates)
        {
          std::copy(ids.begin(), ids.begin() + SplatCandidates, kept->CandidatesOf(i));
          kept->SetOuter(i, std::sqrt(d2[SplatCandidates]));
        }
      }
      reused += taken;
    },
    aborted);
  if (keeps && (!done || !kept->Finish(points.data(), index)))
  {
    kept->Clear();
  }
  if (fromCandidates)
  {
    *fromCandidates = reused;
  }
  return done;
}

} // namespace lsi
