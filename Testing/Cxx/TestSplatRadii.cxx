// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The splat radii from kept candidates (SplatRadii with KeptCandidates), which a quick isovalue
// change uses on the slid points, against a search on the same points, to the last bit:
//   - keeping the candidates changes no radius; the same points again take every radius from them;
//   - a sheet moved as a whole (a sphere grown by a third of its spacing, with a little noise)
//     takes most from them;
//   - one point moved next to a far point, one point moved next to a near one, every point
//     moved a few spacings at random: the radii a search gives (the bounds catch each);
//   - an index over more points than the queried (as under MPI), moved: the same;
//   - another point count: searched, the candidates left as they are (made anew once cleared).
// Far from the origin too (coordinates a million spacings large).
#include "LevelSetKeptCandidates.h"
#include "LevelSetSplatRadii.h"
#include "NearestNeighbors.h"
#include "TestCheck.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using lsi::test::Check;

constexpr double Pi = 3.14159265358979323846;

double SquaredDistance(const double* a, const double* b)
{
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
    (a[2] - b[2]) * (a[2] - b[2]);
}

// `count` points spread over a sphere of radius `radius` about `centre` (a spiral, jittered).
std::vector<double> Sphere(std::size_t count, double radius, double centre, std::mt19937& random)
{
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<double> points;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double z = 1.0 - (2.0 * (static_cast<double>(i) + 0.5 + jitter(random))) / count;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double angle = Pi * (3.0 - std::sqrt(5.0)) * i + 0.1 * jitter(random);
    points.push_back(centre + radius * r * std::cos(angle));
    points.push_back(centre + radius * r * std::sin(angle));
    points.push_back(centre + radius * z);
  }
  return points;
}

std::vector<double> Searched(const std::vector<double>& points, const std::vector<double>* cloud)
{
  std::vector<double> radii;
  const lsi::PointCloudIndex index(
    cloud ? cloud->data() : points.data(), (cloud ? cloud->size() : points.size()) / 3);
  lsi::SplatRadii(points, 6, 1.5, radii, lsi::AbortCheck(), &index);
  return radii;
}

// Radii from `kept` on `points` (searched in `cloud` if given) against a search; returns how
// many came from the candidates.
std::size_t CheckAgainstSearch(const std::string& what, const std::vector<double>& points,
  const std::vector<double>* cloud, lsi::KeptCandidates& kept)
{
  std::vector<double> radii;
  const lsi::PointCloudIndex index(
    cloud ? cloud->data() : points.data(), (cloud ? cloud->size() : points.size()) / 3);
  std::size_t reused = 0;
  lsi::SplatRadii(points, 6, 1.5, radii, lsi::AbortCheck(), &index, &kept, &reused);
  const std::vector<double> searched = Searched(points, cloud);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < radii.size(); ++i)
  {
    differ += radii[i] != searched[i];
  }
  Check(radii.size() == searched.size() && differ == 0,
    what + ": the radii a search gives (" + std::to_string(differ) + " differ; " +
      std::to_string(reused) + " from the candidates)");
  return reused;
}

void CheckAt(double centre)
{
  const std::string at = " (centre " + std::to_string(centre) + ")";
  std::mt19937 random(5);
  const std::size_t count = 6000;
  const double radius = 10.0;
  const std::vector<double> start = Sphere(count, radius, centre, random);
  const double spacing = radius * std::sqrt(4.0 * Pi / count);

  lsi::KeptCandidates kept;
  const std::size_t anew = CheckAgainstSearch("kept anew" + at, start, nullptr, kept);
  Check(kept.Queries() == count && anew == 0, "the candidates kept" + at);
  const std::size_t again = CheckAgainstSearch("the same points" + at, start, nullptr, kept);
  Check(again == count, "the same points: every radius from the candidates" + at);

  // The sphere grown by a third of a spacing, each point moved a little more at random.
  std::uniform_real_distribution<double> noise(-0.02 * spacing, 0.02 * spacing);
  std::vector<double> grown(start);
  for (std::size_t i = 0; i < count; ++i)
  {
    const double scale = 1.0 + spacing / (3.0 * radius);
    for (int a = 0; a < 3; ++a)
    {
      grown[3 * i + a] = centre + scale * (start[3 * i + a] - centre) + noise(random);
    }
  }
  const std::size_t slid = CheckAgainstSearch("a grown sheet" + at, grown, nullptr, kept);
  Check(slid > 0.9 * count, "a grown sheet: most radii from the candidates" + at);

  // Point 0 moved next to a point on the far side (the farthest move bounds it); a point just
  // beyond the candidates of point 100 moved next to it (the moves of the points around bound
  // it: near enough for the farthest move to allow the others).
  std::vector<std::pair<double, std::size_t>> byDistance;
  for (std::size_t j = 0; j < count; ++j)
  {
    byDistance.emplace_back(SquaredDistance(&start[3 * j], &start[300]), j);
  }
  std::sort(byDistance.begin(), byDistance.end());
  const std::size_t mover = byDistance[lsi::SplatCandidates + 1].second;
  // And the point nearest to point 100 outside the 27 cells around its cell moved next to it
  // (those lay a cell width away at least, and no more).
  const std::uint32_t* around = kept.CellsAround(kept.CellOf(100));
  std::size_t outside = 0;
  for (const auto& entry : byDistance)
  {
    if (std::find(around, around + 27, kept.CellOf(entry.second)) == around + 27)
    {
      outside = entry.second;
      break;
    }
  }
  for (const std::array<std::size_t, 2> move : { std::array<std::size_t, 2>{ 0, count - 1 },
         std::array<std::size_t, 2>{ mover, 100 }, std::array<std::size_t, 2>{ outside, 100 } })
  {
    std::vector<double> moved(grown);
    for (int a = 0; a < 3; ++a)
    {
      moved[3 * move[0] + a] = grown[3 * move[1] + a] + (a == 0 ? 0.1 * spacing : 0.0);
    }
    CheckAgainstSearch(
      "point " + std::to_string(move[0]) + " moved next to point " + std::to_string(move[1]) + at,
      moved, nullptr, kept);
  }

  // Every point moved up to three spacings.
  std::uniform_real_distribution<double> far(-3.0 * spacing, 3.0 * spacing);
  std::vector<double> scattered(start);
  for (double& x : scattered)
  {
    x += far(random);
  }
  CheckAgainstSearch("points moved at random" + at, scattered, nullptr, kept);

  // An index over these points and more (a ring of them just outside the sphere), then moved.
  std::vector<double> cloud(start);
  std::vector<double> more = Sphere(count / 2, radius + 0.5 * spacing, centre, random);
  cloud.insert(cloud.end(), more.begin(), more.end());
  lsi::KeptCandidates wider;
  CheckAgainstSearch("a wider index" + at, start, &cloud, wider);
  std::vector<double> cloudMoved(cloud);
  for (std::size_t j = 0; j < cloud.size(); ++j)
  {
    cloudMoved[j] = j < 3 * count ? grown[j] : cloud[j] + noise(random);
  }
  const std::size_t widerSlid = CheckAgainstSearch("a wider index, moved" + at,
    std::vector<double>(cloudMoved.begin(), cloudMoved.begin() + 3 * count), &cloudMoved, wider);
  Check(widerSlid > 0.8 * count, "a wider index, moved: most radii from the candidates" + at);
  for (int a = 0; a < 3; ++a) // one of the index's other points next to point 0
  {
    cloudMoved[3 * (count + count / 4) + a] = grown[a] + (a == 0 ? 0.1 * spacing : 0.0);
  }
  CheckAgainstSearch("a wider index, one of its points moved onto a point" + at,
    std::vector<double>(cloudMoved.begin(), cloudMoved.begin() + 3 * count), &cloudMoved, wider);

  // Fewer points: searched, the candidates left as they are; kept anew once cleared.
  const std::vector<double> fewer(start.begin(), start.end() - 3);
  const std::size_t fewerReused = CheckAgainstSearch("one point fewer" + at, fewer, nullptr, kept);
  Check(fewerReused == 0 && kept.Queries() == count, "one point fewer: searched, kept as is" + at);
  kept.Clear();
  CheckAgainstSearch("one point fewer, cleared" + at, fewer, nullptr, kept);
  Check(kept.Queries() == count - 1, "one point fewer, cleared: kept anew" + at);
}
} // namespace

int main()
{
  CheckAt(0.0);
  CheckAt(1.0e6);
  std::cout << (lsi::test::Failures() ? "splat radii tests FAILED\n"
                                      : "splat radii tests passed\n");
  return lsi::test::Failures() ? 1 : 0;
}
