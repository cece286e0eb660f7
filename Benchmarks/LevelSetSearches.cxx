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
//     refinement's and the slide's MLSStencil::Gather, without a bound).
// For the next step on the neighbour search (the largest single cost of every run): a faster
// search shows here first. Reports numbers and asserts nothing; the checksums show that two
// builds find the same neighbours.
//   LevelSetSearches [SAMPLES [QUERIES]]
#include "MortonTree.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <random>
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
  std::printf(
    "%zu samples, %zu queries each, one thread (microseconds per query):\n", samples, queries);
  std::printf("  neighbour lists, 28 nearest, storage order, bounded: %8.3f  (checksum %.9g)\n",
    listMicroseconds, lists.Checksum);
  std::printf("  fixed radius sample, 28 nearest, every 30th sample:  %8.3f  (checksum %.9g)\n",
    scatteredMicroseconds, scattered.Checksum);
  std::printf("  gathers, 68 nearest, between samples:                %8.3f  (checksum %.9g)\n",
    gatherMicroseconds, gatherChecksum);
  return EXIT_SUCCESS;
}
