// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetEnclosedSurface.h"

#include "LevelSetEnclosedSums.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

namespace
{
// What a point record holds in the exchange: the sending rank, the point, its normal.
constexpr std::size_t RecordSize = 7;

bool InBox(const double* box, const double* x)
{
  return x[0] >= box[0] && x[0] <= box[1] && x[1] >= box[2] && x[1] <= box[3] && x[2] >= box[4] &&
    x[2] <= box[5];
}

// Whether x, or in a periodic box one of its images (x shifted by -1, 0 or +1 box on each
// axis), lies in `box`: a rank's reach extends past the faces, over its particles' images.
bool ImageInBox(const double* box, const double* x, const PeriodicBox& periodic)
{
  if (!periodic.Enabled)
  {
    return InBox(box, x);
  }
  const double everywhere[3] = { HUGE_VAL, HUGE_VAL, HUGE_VAL }; // all 27 images
  bool found = false;
  ForEachPeriodicImage(
    x, periodic, everywhere, true, [&](const double* y) { found = found || InBox(box, y); });
  return found;
}
} // namespace

void KeptSurfaceWithinReach(const Communicator& ranks, const Neighborhoods& geometry,
  const std::vector<double>& phi, const IsopointSet& kept, const PeriodicBox& periodic,
  std::vector<double>& points, std::vector<double>& normals)
{
  points = kept.Points;
  normals = kept.Normals;
  if (!ranks.Distributed())
  {
    return;
  }
  // This rank's reach: the box of x +- 2 s over its owned samples that measure a distance
  // (SurfaceDistance's rule), a little wider against rounding. (In a periodic box the samples
  // include the particles' images past the faces, which the rank owns with them.)
  std::vector<double> boxes = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  for (std::size_t i = 0; i < geometry.NumberOfSamples && i < phi.size(); ++i)
  {
    const double s = geometry.RadiusOf(i);
    if (!ranks.Owns(i) || !enclosed::MeasuresTangentDistance(phi[i], s))
    {
      continue;
    }
    const double reach = enclosed::TangentReach * s * (1.0 + 1e-6);
    const double* x = geometry.Position(i);
    for (int d = 0; d < 3; ++d)
    {
      boxes[2 * d] = std::min(boxes[2 * d], x[d] - reach);
      boxes[2 * d + 1] = std::max(boxes[2 * d + 1], x[d] + reach);
    }
  }
  ranks.GatherAll(boxes); // every rank's, in rank order
  // This rank's kept points that another rank's reach holds, to every rank.
  std::vector<double> records;
  const std::size_t count = kept.Points.size() / 3;
  for (std::size_t k = 0; k < count; ++k)
  {
    const double* x = &kept.Points[3 * k];
    for (int r = 0; r < ranks.Size; ++r)
    {
      if (r != ranks.Rank && 6 * static_cast<std::size_t>(r) + 5 < boxes.size() &&
        ImageInBox(&boxes[6 * r], x, periodic))
      {
        records.push_back(ranks.Rank);
        records.insert(records.end(), x, x + 3);
        records.insert(records.end(), &kept.Normals[3 * k], &kept.Normals[3 * k] + 3);
        break;
      }
    }
  }
  ranks.GatherAll(records);
  const double* mine =
    6 * static_cast<std::size_t>(ranks.Rank) + 5 < boxes.size() ? &boxes[6 * ranks.Rank] : nullptr;
  for (std::size_t k = 0; mine && k + RecordSize <= records.size(); k += RecordSize)
  {
    const double* record = &records[k];
    if (static_cast<int>(record[0]) != ranks.Rank && ImageInBox(mine, record + 1, periodic))
    {
      points.insert(points.end(), record + 1, record + 4);
      normals.insert(normals.end(), record + 4, record + 7);
    }
  }
}

} // namespace lsi
