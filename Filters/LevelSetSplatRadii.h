// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The surface output's splat radius: a point's distance to its 6th nearest other surface point,
// scaled. A quick isovalue change slides the last surface's points a little and asks again:
// each point's nearest then lie among the candidates kept from the last search
// (LevelSetKeptCandidates.h).
#ifndef LevelSetSplatRadii_h
#define LevelSetSplatRadii_h

#include "LevelSetParallel.h"

#include <cstddef>
#include <vector>

namespace lsi
{
class KeptCandidates;
class PointCloudIndex;

/// Candidates kept per point for the splat radii: the neighbours and a margin.
constexpr std::size_t SplatCandidates = 12;

/// Splat radius of each point (3 doubles per point): `factor` times the distance to its
/// `neighbors`-th nearest other point, searched in `index` if given (over `points`, or over
/// more points near them), else in one built here. Returns false only when aborted.
/// `kept`, if given and empty, receives each point's SplatCandidates nearest (a search of a few
/// more points); if given and kept for as many points and index points, a point whose
/// neighbours surely lie among its candidates takes its radius from them (`fromCandidates`, if
/// given, counts those), the others are searched: the radii of a search either way. Kept for
/// other counts, it is left as it is.
bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted, const PointCloudIndex* index = nullptr,
  KeptCandidates* kept = nullptr, std::size_t* fromCandidates = nullptr);

} // namespace lsi

#endif
