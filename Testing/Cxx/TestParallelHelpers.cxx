// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The parallel building blocks of Filters/LevelSetParallel.h against their serial definitions,
// on 1, 2, 3 and 4 threads:
//   - ParallelSort: the same order as std::sort, for a strict total order and for keys with
//     many repeats (equal keys are indistinguishable), for sizes around its piece thresholds;
//   - MergeSplit: every cut of a merge splits it as std::merge does (ties to the first range);
//   - IndicesWhere: the same indices as a serial scan, into a fresh vector and into a reused
//     one (longer and shorter than before);
//   - ThinnedVoxels: one point per voxel, the lowest-coordinate one (or a preferred one).
#include "LevelSetIsopoints.h"
#include "LevelSetParallel.h"
#include "TestCheck.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <map>
#include <random>
#include <vector>

namespace
{
using lsi::test::Check;

struct Entry
{
  std::uint64_t Key;
  std::size_t Index;
  bool operator==(const Entry& o) const { return Key == o.Key && Index == o.Index; }
};

bool ByKeyThenIndex(const Entry& a, const Entry& b)
{
  return a.Key < b.Key || (a.Key == b.Key && a.Index < b.Index);
}

void CheckSorts(int threads)
{
  std::mt19937_64 random(11 + threads);
  for (const std::size_t count :
    { std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(16384 * 2 - 1),
      std::size_t(16384 * 2), std::size_t(100001), std::size_t(16384 * 5 + 3) })
  {
    for (const std::uint64_t keys : { std::uint64_t(7), std::uint64_t(1) << 40 })
    {
      std::vector<Entry> entries(count);
      std::vector<std::uint64_t> plain(count);
      for (std::size_t i = 0; i < count; ++i)
      {
        entries[i] = { random() % keys, i };
        plain[i] = random() % keys;
      }
      std::vector<Entry> expected = entries;
      std::sort(expected.begin(), expected.end(), ByKeyThenIndex);
      lsi::ParallelSort(entries.begin(), entries.end(), ByKeyThenIndex);
      Check(entries == expected, "ParallelSort (strict total order) == std::sort");
      std::vector<std::uint64_t> plainExpected = plain;
      std::sort(plainExpected.begin(), plainExpected.end());
      lsi::ParallelSort(plain.begin(), plain.end(), std::less<std::uint64_t>());
      Check(plain == plainExpected, "ParallelSort (repeated keys) == std::sort");
    }
  }
}

void CheckMergeSplit()
{
  bool ok = true;
  std::mt19937 random(5);
  for (int trial = 0; trial < 200; ++trial)
  {
    std::vector<int> a(random() % 40), b(random() % 40);
    for (int& v : a)
    {
      v = static_cast<int>(random() % 10);
    }
    for (int& v : b)
    {
      v = static_cast<int>(random() % 10);
    }
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    // Which range each element of the merge comes from, as std::merge takes them.
    std::vector<std::pair<int, int>> taggedA, taggedB, merged; // (value, 0 for a / 1 for b)
    for (int v : a)
    {
      taggedA.emplace_back(v, 0);
    }
    for (int v : b)
    {
      taggedB.emplace_back(v, 1);
    }
    auto byValue = [](const std::pair<int, int>& x, const std::pair<int, int>& y) {
      return x.first < y.first;
    };
    std::merge(taggedA.begin(), taggedA.end(), taggedB.begin(), taggedB.end(),
      std::back_inserter(merged), byValue);
    std::less<int> less;
    std::ptrdiff_t fromA = 0;
    for (std::size_t d = 0; d <= merged.size(); ++d)
    {
      const std::ptrdiff_t split = lsi::MergeSplit(a.begin(), static_cast<std::ptrdiff_t>(a.size()),
        b.begin(), static_cast<std::ptrdiff_t>(b.size()), static_cast<std::ptrdiff_t>(d), less);
      if (split != fromA)
      {
        ok = false;
        break;
      }
      if (d < merged.size() && merged[d].second == 0)
      {
        ++fromA;
      }
    }
  }
  Check(ok, "MergeSplit agrees with std::merge on 200 random pairs (with ties)");
}

void CheckIndices(int threads)
{
  std::mt19937 random(3 + threads);
  std::vector<std::size_t> reused;
  for (const std::size_t count : { std::size_t(0), std::size_t(5), std::size_t(65536),
         std::size_t(65537), std::size_t(300000), std::size_t(70000) })
  {
    for (const double fraction : { 0.0, 0.01, 0.5, 1.0 })
    {
      std::vector<char> keep(count);
      for (char& k : keep)
      {
        k = (random() % 1000) < fraction * 1000.0;
      }
      std::vector<std::size_t> expected;
      for (std::size_t i = 0; i < count; ++i)
      {
        if (keep[i])
        {
          expected.push_back(i);
        }
      }
      auto kept = [&](std::size_t i) { return keep[i] != 0; };
      Check(lsi::IndicesWhere<std::size_t>(count, kept) == expected,
        "IndicesWhere into a new vector == a serial scan");
      lsi::IndicesWhere(count, kept, reused);
      Check(reused == expected, "IndicesWhere into a reused vector == a serial scan");
    }
  }
}

void CheckThinning(int threads)
{
  std::mt19937 random(17 + threads);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const double cell = 0.1;
  std::vector<double> points(3 * 50000);
  for (double& x : points)
  {
    x = unit(random);
  }
  // Repeated points: the lowest index among equals wins.
  std::copy(points.begin(), points.begin() + 3000, points.begin() + 6000);
  const std::size_t preferred = 200;
  std::map<std::uint64_t, std::size_t> winner;
  for (std::size_t i = 0; i < points.size() / 3; ++i)
  {
    const std::uint64_t key = lsi::VoxelKey(&points[3 * i], cell);
    auto found = winner.find(key);
    if (found == winner.end())
    {
      winner[key] = i;
    }
    else if (found->second >= preferred &&
      std::lexicographical_compare(&points[3 * i], &points[3 * i] + 3, &points[3 * found->second],
        &points[3 * found->second] + 3))
    {
      found->second = i;
    }
  }
  std::vector<std::size_t> expected;
  for (const auto& w : winner)
  {
    expected.push_back(w.second);
  }
  std::sort(expected.begin(), expected.end());
  Check(lsi::ThinByVoxels(points, cell, preferred) == expected,
    "ThinByVoxels: one point per voxel, preferred first, else the lowest coordinates");
}
} // namespace

int main()
{
  CheckMergeSplit();
  for (const int threads : { 1, 2, 3, 4 })
  {
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
      std::cout << "-- " << threads << " thread(s)\n";
      CheckSorts(threads);
      CheckIndices(threads);
      CheckThinning(threads);
    });
  }
  return lsi::test::Failures() == 0 ? 0 : 1;
}
