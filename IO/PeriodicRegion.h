// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A reader's region (RegionBounds) in a periodic box: a particle lies inside when one of its
// periodic images x + n * period (n whole, on each axis) does, so that a region across a face of
// the box holds the halo there whole (its particles keep their positions in the box; the
// filter's periodic images join them across the face). Plain C++.
#ifndef PeriodicRegion_h
#define PeriodicRegion_h

#include <array>
#include <cmath>
#include <vector>

namespace lsi
{
namespace io
{
/// Whether an image x + n * period of x lies in [low, high] (a point on a face is inside);
/// without a period (0), whether x does. A range at least a period long holds an image of
/// every x.
inline bool InsideOnAxis(double x, double low, double high, double period)
{
  if (!(period > 0.0) || !std::isfinite(period))
  {
    return x >= low && x <= high;
  }
  if (high - low >= period)
  {
    return std::isfinite(x);
  }
  // The lowest image at or above `low` (rounding may put it a hair below: the one before it is
  // then checked too).
  const double n = std::ceil((low - x) / period);
  const double image = x + n * period;
  return (image >= low && image <= high) || (image - period >= low && image - period <= high) ||
    (image + period >= low && image + period <= high);
}

/// Whether x (3 values) lies inside `bounds` (xmin, xmax, ymin, ymax, zmin, zmax) on every axis,
/// by InsideOnAxis with that axis's period (3 values; 0: not periodic on that axis).
inline bool InsidePeriodicRegion(const double x[3], const double bounds[6], const double period[3])
{
  return InsideOnAxis(x[0], bounds[0], bounds[1], period[0]) &&
    InsideOnAxis(x[1], bounds[2], bounds[3], period[1]) &&
    InsideOnAxis(x[2], bounds[4], bounds[5], period[2]);
}

/// Boxes whose union holds every x with -period <= x < 2 period on each periodic axis (a box and
/// particles that drifted a little past its faces) that InsidePeriodicRegion accepts: the region
/// shifted by whole periods (at most 4 shifts per axis), one range over an axis whose range spans
/// a period. For the formats that find a box's particles without reading them all (SWIFT's
/// cell table): the candidates of the region are those of these boxes.
inline std::vector<std::array<double, 6>> PeriodicRegionBoxes(
  const double bounds[6], const double period[3])
{
  std::vector<std::array<double, 2>> ranges[3];
  for (int a = 0; a < 3; ++a)
  {
    const double low = bounds[2 * a], high = bounds[2 * a + 1], p = period[a];
    if (!(p > 0.0) || !std::isfinite(p))
    {
      ranges[a].push_back({ low, high });
    }
    else if (high - low >= p)
    {
      ranges[a].push_back({ -HUGE_VAL, HUGE_VAL });
    }
    else
    {
      // The region moved so that its minimum lies in [0, p): an x in [-p, 2p) has an image
      // inside only if it lies in one of the region's shifts by -2p ... +p (one more each way
      // for rounding), of which those that meet [-p, 2p] are kept.
      const double shift = std::floor(low / p) * p;
      for (int n = -3; n <= 2; ++n)
      {
        const double from = low - shift + n * p, to = high - shift + n * p;
        if (to >= -p && from <= 2.0 * p)
        {
          ranges[a].push_back({ from, to });
        }
      }
    }
  }
  std::vector<std::array<double, 6>> boxes;
  for (const auto& x : ranges[0])
  {
    for (const auto& y : ranges[1])
    {
      for (const auto& z : ranges[2])
      {
        boxes.push_back({ x[0], x[1], y[0], y[1], z[0], z[1] });
      }
    }
  }
  return boxes;
}
} // namespace io
} // namespace lsi

#endif
