// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The filter's kd-tree without a Neighborhoods, for the numerics tests and the search benchmark.
#ifndef MortonTree_h
#define MortonTree_h

#include "NearestNeighbors.h"
#include "SpatialOrder.h"

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

namespace lsi
{

// The filter's way to its kd-tree: Morton words over the cube around the points, sorted, the
// points put in their order, then the tree built from that order. oldIndex[i] receives the
// original position of what is now point i.
inline std::unique_ptr<PointCloudIndex> MortonTree(
  UninitializedVector<double>& xyz, UninitializedVector<std::uint32_t>& oldIndex)
{
  const std::size_t n = xyz.size() / 3;
  double lower[3] = { xyz[0], xyz[1], xyz[2] }, side = 1e-300;
  for (int a = 0; a < 3; ++a)
  {
    double high = xyz[a];
    for (std::size_t i = 0; i < n; ++i)
    {
      lower[a] = std::min(lower[a], xyz[3 * i + a]);
      high = std::max(high, xyz[3 * i + a]);
    }
    side = std::max(side, high - lower[a]);
  }
  const double size[3] = { side, side, side };
  UninitializedVector<std::uint64_t> words(n), scratch;
  for (std::size_t i = 0; i < n; ++i)
  {
    words[i] = PackedMortonKey(&xyz[3 * i], lower, size, static_cast<std::uint32_t>(i));
  }
  RadixSortPacked(words, scratch);
  UninitializedVector<double> sorted(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::uint32_t id = static_cast<std::uint32_t>(words[i]);
    std::copy(&xyz[3 * id], &xyz[3 * id] + 3, &sorted[3 * i]);
  }
  xyz.swap(sorted);
  UninitializedVector<std::uint32_t> treeOrder;
  std::unique_ptr<PointCloudIndex> index(new PointCloudIndex(xyz, words, treeOrder, RunInTurn));
  oldIndex.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    oldIndex[i] = static_cast<std::uint32_t>(words[treeOrder[i]]);
  }
  return index;
}

} // namespace lsi

#endif
