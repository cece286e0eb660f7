// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The nearest-neighbour searches that about a third of a run's CPU time goes through (perf, 2M
// samples), each timed alone on one thread over the filter's kd-tree (built from the Morton
// order, as Neighborhoods builds it) on uniform random samples (microseconds per query, the
// fastest of 3 rounds):
//   - neighbour lists: the 28 nearest to consecutive samples in storage order, each search
//     bounded by the radius of the one before it (Neighborhoods::SearchRow's NearestNear);
//   - the fixed radius sample: the same for every 30th sample (scattered queries);
//   - gathers: the 68 nearest to points between samples, in storage order (the data
//     refinement's and the slide's MLSStencil::Gather, without a bound);
//   - bounded gathers, the kd-tree against a uniform bucket grid (issue 16 names one as the
//     candidate for near-uniform data): the 54 nearest (the slide's) to points on a sphere in
//     the cloud, in the order of their Morton words, each bounded by 1.33 times its own 54th
//     neighbour's distance (the slide's GatherNear bounds its searches by 1.21 times the radius of
//     the last fit's samples, which differs from the new one by up to 10%): the tree's
//     NearestWithin, then the grid at cells of 1, 2 and 3 mean spacings (cells overlapping the
//     bound's cube, candidates within the bound, nth_element, sort by distance and index).
// For the next step on the neighbour search (the largest single cost of every run): a faster
// search shows here first. Reports numbers and asserts nothing; the checksums show that two
// builds find the same neighbours.
//   LevelSetSearches [SAMPLES [QUERIES]]
#include "MortonTree.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
#include <utility>
#include <vector>

namespace
{
// The fastest of 3 rounds of `queries` calls, in microseconds per call.
template <typename Call>
double MicrosecondsPerQuery(std::size_t queries, Call&& call)
{
  double fastest = HUGE_VAL;
  for (int round = 0; round < 3; ++round)
  {
    const auto start = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < queries; ++k)
    {
      call(k);
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    fastest = std::min(fastest, 1e6 * seconds / static_cast<double>(queries));
  }
  return fastest;
}

// Searches of `k` nearest from consecutive queries, each first bounded by the last one's radius
// (PointCloudIndex::NearestNear), as Neighborhoods::SearchRow searches.
struct BoundedSearch
{
  const lsi::PointCloudIndex& Index;
  std::size_t K;
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2;
  double Radius = 0.0;
  double Checksum = 0.0;
  BoundedSearch(const lsi::PointCloudIndex& index, std::size_t k)
    : Index(index)
    , K(k)
    , Ids(k)
    , D2(k)
  {
  }
  void operator()(const double* query)
  {
    this->Index.NearestNear(query, this->K, this->Radius, this->Ids.data(), this->D2.data());
    this->Radius = std::sqrt(*std::max_element(this->D2.begin(), this->D2.end()));
    this->Checksum += this->Ids[this->K - 1] + this->D2[this->K - 1];
  }
};
// A uniform bucket grid over the points: cells of side `cell`, the points copied into cell
// order (row-major cells), each cell's range of them. For the comparison only.
class BucketGrid
{
public:
  BucketGrid(const double* xyz, std::size_t count, double cell)
    : Cell(cell)
  {
    double high[3];
    for (int a = 0; a < 3; ++a)
    {
      this->Low[a] = high[a] = xyz[a];
    }
    for (std::size_t i = 0; i < count; ++i)
    {
      for (int a = 0; a < 3; ++a)
      {
        this->Low[a] = std::min(this->Low[a], xyz[3 * i + a]);
        high[a] = std::max(high[a], xyz[3 * i + a]);
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      this->Cells[a] = std::max(1, static_cast<int>(std::ceil((high[a] - this->Low[a]) / cell)));
    }
    const std::size_t cells =
      static_cast<std::size_t>(this->Cells[0]) * this->Cells[1] * this->Cells[2];
    this->Start.assign(cells + 1, 0);
    std::vector<std::uint32_t> cellOf(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      int c[3];
      for (int a = 0; a < 3; ++a)
      {
        c[a] = this->CellIndex(xyz[3 * i + a], a);
      }
      cellOf[i] = this->CellOf(c[0], c[1], c[2]);
      ++this->Start[cellOf[i] + 1];
    }
    for (std::size_t c = 0; c < cells; ++c)
    {
      this->Start[c + 1] += this->Start[c];
    }
    std::vector<std::uint32_t> next(this->Start.begin(), this->Start.end() - 1);
    this->Points.resize(3 * count);
    this->Ids.resize(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      const std::uint32_t k = next[cellOf[i]]++;
      this->Ids[k] = static_cast<std::uint32_t>(i);
      std::copy(&xyz[3 * i], &xyz[3 * i] + 3, &this->Points[3 * k]);
    }
  }

  // The k nearest within sqrt(bound2), closest first (ties by index).
  std::size_t NearestWithin(
    const double* q, std::size_t k, double bound2, std::uint32_t* ids, double* d2)
  {
    const double r = std::sqrt(bound2);
    int low[3], high[3];
    for (int a = 0; a < 3; ++a)
    {
      low[a] = this->CellIndex(q[a] - r, a);
      high[a] = this->CellIndex(q[a] + r, a);
    }
    this->Found.clear();
    for (int z = low[2]; z <= high[2]; ++z)
    {
      for (int y = low[1]; y <= high[1]; ++y)
      {
        // The cells of a row along x are consecutive: one range.
        const std::uint32_t end = this->Start[this->CellOf(high[0], y, z) + 1];
        for (std::uint32_t j = this->Start[this->CellOf(low[0], y, z)]; j < end; ++j)
        {
          const double* x = &this->Points[3 * j];
          const double dx = q[0] - x[0], dy = q[1] - x[1], dz = q[2] - x[2];
          const double d = dx * dx + dy * dy + dz * dz;
          if (d < bound2)
          {
            this->Found.push_back({ d, this->Ids[j] });
          }
        }
      }
    }
    const std::size_t m = std::min(k, this->Found.size());
    if (m < this->Found.size())
    {
      std::nth_element(this->Found.begin(), this->Found.begin() + (m - 1), this->Found.end());
    }
    std::sort(this->Found.begin(), this->Found.begin() + m);
    for (std::size_t j = 0; j < m; ++j)
    {
      d2[j] = this->Found[j].first;
      ids[j] = this->Found[j].second;
    }
    return m;
  }

private:
  int CellIndex(double x, int a) const
  {
    const int c = static_cast<int>(std::floor((x - this->Low[a]) / this->Cell));
    return std::max(0, std::min(this->Cells[a] - 1, c));
  }
  std::uint32_t CellOf(int x, int y, int z) const
  {
    return static_cast<std::uint32_t>((z * this->Cells[1] + y) * this->Cells[0] + x);
  }
  double Cell;
  double Low[3];
  int Cells[3];
  std::vector<std::uint32_t> Start, Ids;
  std::vector<double> Points;
  std::vector<std::pair<double, std::uint32_t>> Found;
};
} // namespace

int main(int argc, char* argv[])
{
  const std::size_t samples = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 2000000;
  const std::size_t queries = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 50000;
  if (samples < 1000 || queries < 1 || 30 * queries > samples)
  {
    std::fprintf(stderr, "usage: LevelSetSearches [SAMPLES >= 1000 [QUERIES <= SAMPLES / 30]]\n");
    return EXIT_FAILURE;
  }
  // Uniform random samples in a unit cube, into Morton order, into the tree (its leaf order).
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  lsi::UninitializedVector<double> positions(3 * samples);
  for (double& x : positions)
  {
    x = unit(random);
  }
  lsi::UninitializedVector<std::uint32_t> oldIndex;
  const std::unique_ptr<lsi::PointCloudIndex> tree = lsi::MortonTree(positions, oldIndex);
  const lsi::PointCloudIndex& index = *tree;

  BoundedSearch lists(index, 28), scattered(index, 28);
  const double listMicroseconds =
    MicrosecondsPerQuery(queries, [&](std::size_t k) { lists(&positions[3 * k]); });
  const double scatteredMicroseconds =
    MicrosecondsPerQuery(queries, [&](std::size_t k) { scattered(&positions[3 * 30 * k]); });
  std::vector<std::uint32_t> ids(68);
  std::vector<double> d2(68);
  double gatherChecksum = 0.0;
  const double gatherMicroseconds = MicrosecondsPerQuery(queries, [&](std::size_t k) {
    double between[3];
    for (int d = 0; d < 3; ++d)
    {
      between[d] = 0.5 * (positions[3 * k + d] + positions[3 * (k + 1) + d]);
    }
    index.Nearest(between, 68, ids.data(), d2.data());
    gatherChecksum += ids[67] + d2[67];
  });

  // Bounded gathers on a sphere of radius 0.3 about the cube's centre, in Morton order (as the
  // surface's points are), each bound from its own 54th neighbour.
  constexpr std::size_t Fit = 54;
  std::vector<std::pair<std::uint64_t, std::array<double, 3>>> onSphere(queries);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double cube[3] = { 0.0, 0.0, 0.0 }, side[3] = { 1.0, 1.0, 1.0 };
  for (std::size_t k = 0; k < queries; ++k)
  {
    double d[3] = { normal(random), normal(random), normal(random) };
    const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    std::array<double, 3>& x = onSphere[k].second;
    for (int a = 0; a < 3; ++a)
    {
      x[a] = 0.5 + 0.3 * d[a] / length;
    }
    onSphere[k].first = lsi::PackedMortonKey(x.data(), cube, side, 0);
  }
  std::sort(onSphere.begin(), onSphere.end(),
    [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<double> bounds(queries);
  for (std::size_t k = 0; k < queries; ++k)
  {
    index.Nearest(onSphere[k].second.data(), Fit, ids.data(), d2.data());
    bounds[k] = 1.33 * 1.33 * d2[Fit - 1];
  }
  double treeChecksum = 0.0;
  const double treeMicroseconds = MicrosecondsPerQuery(queries, [&](std::size_t k) {
    index.NearestWithin(onSphere[k].second.data(), Fit, bounds[k], ids.data(), d2.data());
    treeChecksum += ids[Fit - 1] + d2[Fit - 1];
  });
  const double spacing = std::cbrt(1.0 / static_cast<double>(samples));
  std::vector<std::array<double, 2>> gridRuns;
  for (double cells : { 1.0, 2.0, 3.0 })
  {
    BucketGrid grid(positions.data(), samples, cells * spacing);
    double checksum = 0.0;
    const double microseconds = MicrosecondsPerQuery(queries, [&](std::size_t k) {
      grid.NearestWithin(onSphere[k].second.data(), Fit, bounds[k], ids.data(), d2.data());
      checksum += ids[Fit - 1] + d2[Fit - 1];
    });
    gridRuns.push_back({ microseconds, checksum });
  }
  std::printf(
    "%zu samples, %zu queries each, one thread (microseconds per query):\n", samples, queries);
  std::printf("  neighbour lists, 28 nearest, storage order, bounded: %8.3f  (checksum %.9g)\n",
    listMicroseconds, lists.Checksum);
  std::printf("  fixed radius sample, 28 nearest, every 30th sample:  %8.3f  (checksum %.9g)\n",
    scatteredMicroseconds, scattered.Checksum);
  std::printf("  gathers, 68 nearest, between samples:                %8.3f  (checksum %.9g)\n",
    gatherMicroseconds, gatherChecksum);
  std::printf("  bounded gathers, 54 nearest, on a sphere, kd-tree:    %8.3f  (checksum %.9g)\n",
    treeMicroseconds, treeChecksum);
  for (std::size_t g = 0; g < gridRuns.size(); ++g)
  {
    std::printf("  the same, uniform grid of cells %zu spacing%s:         %8.3f  (checksum %.9g)\n",
      g + 1, g ? "s" : " ", gridRuns[g][0], gridRuns[g][1]);
  }
  return EXIT_SUCCESS;
}
