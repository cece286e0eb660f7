// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// k-nearest-neighbour queries on a static point cloud, through nanoflann's kd-tree
// (header-only; Debian: libnanoflann-dev). Queries are const and thread-safe once built.
#ifndef NearestNeighbors_h
#define NearestNeighbors_h

#include "TaskRunner.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lsi
{

class PointCloudIndex
{
public:
  /// `xyz` holds 3 * count doubles and must outlive the index.
  PointCloudIndex(const double* xyz, std::size_t count)
    : Cloud{ xyz, count }
    , Tree(3, Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(LeafSize))
  {
  }

  /// The same kind of tree, built faster: `xyz` is cut at median planes into up to
  /// 2^splitLevels pieces whose subtrees `run` builds (concurrently, given a runner that uses
  /// threads); the subtrees are then joined under the cutting planes, giving an ordinary
  /// kd-tree whose top splits are medians instead of nanoflann's midpoints.
  /// The points in `xyz` (3 per point) are moved into the tree's leaf order, so that each
  /// leaf's points lie together in memory; `oldIndex[i]` receives the original position of
  /// what is now point i. `xyz` must outlive the index and keep its buffer.
  PointCloudIndex(std::vector<double>& xyz, std::vector<std::uint32_t>& oldIndex, int splitLevels,
    const TaskRunner& run);

  /// The k points nearest to `query`, closest first: indices and squared distances.
  /// Returns how many were found (fewer than k only when the cloud is smaller).
  std::size_t Nearest(
    const double query[3], std::size_t k, std::uint32_t* indices, double* squaredDistances) const
  {
    return this->Tree.knnSearch(query, k, indices, squaredDistances);
  }

  /// Like Nearest, but only among points closer than sqrt(squaredBound): a good bound (from a
  /// query nearby) prunes most of the tree walk. Returns how many were found, possibly < k.
  std::size_t NearestWithin(const double query[3], std::size_t k, double squaredBound,
    std::uint32_t* indices, double* squaredDistances) const
  {
    nanoflann::KNNResultSet<double, std::uint32_t> result(k);
    result.init(indices, squaredDistances);
    squaredDistances[k - 1] = squaredBound; // the initial worst distance
    this->Tree.findNeighbors(result, query, nanoflann::SearchParams());
    return result.size();
  }

  std::size_t Size() const { return this->Cloud.Count; }

private:
  static constexpr std::size_t LeafSize = 16;

  struct Adaptor
  {
    const double* Points;
    std::size_t Count;
    std::size_t kdtree_get_point_count() const { return this->Count; }
    double kdtree_get_pt(std::size_t i, std::size_t d) const { return this->Points[3 * i + d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const
    {
      return false;
    }
  };
  using Tree3D = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
    Adaptor, 3, std::uint32_t>;
  using Node = Tree3D::Node;
  using Box = Tree3D::BoundingBox;

  // A cut of the points [Begin, End) at a plane normal to Axis: [Begin, Middle) lie below it.
  struct Cut
  {
    std::size_t Begin, Middle, End;
    int Axis;
  };

  static std::size_t CutAtMedian(const double* xyz, std::vector<std::uint32_t>& ids,
    std::size_t begin, std::size_t end, int& axis);
  Node* Join(std::size_t begin, std::size_t end, const std::vector<std::size_t>& pieceStart,
    const std::vector<Cut>& cuts, Box& box);
  void MoveIntoLeafOrder(
    std::vector<double>& xyz, std::vector<std::uint32_t>& oldIndex, const TaskRunner& run);

  // Runs body(begin, end) over [0, count) in `chunks` tasks given to `run`.
  template <typename Body>
  static void InChunks(std::size_t count, std::size_t chunks, const TaskRunner& run, Body&& body)
  {
    std::vector<std::function<void()>> tasks;
    for (std::size_t c = 0; c < chunks; ++c)
    {
      const std::size_t begin = count * c / chunks, end = count * (c + 1) / chunks;
      tasks.push_back([&body, begin, end]() { body(begin, end); });
    }
    run(tasks);
  }

  Adaptor Cloud;
  Tree3D Tree;
  // The joined tree's subtrees live in the piece trees (and their adaptors must stay put).
  std::vector<std::unique_ptr<Adaptor>> PieceClouds;
  std::vector<std::unique_ptr<Tree3D>> PieceTrees;
};

// ---------------------------------------------------------------------------------------------
// The joined build. It fills nanoflann's public members (vAcc, root_node, root_bbox, pool) the
// way its buildIndex does; checked against nanoflann 1.4.2, the version in Debian 12.
static_assert(
  NANOFLANN_VERSION == 0x142, "PointCloudIndex's joined build was written for nanoflann 1.4.2");

// Splits ids[begin, end) at the median of the longest axis of their box, keeping the current
// (spatial) order on each side. Returns where the upper side starts: begin or end when every
// point has the median coordinate and no plane can separate them.
inline std::size_t PointCloudIndex::CutAtMedian(
  const double* xyz, std::vector<std::uint32_t>& ids, std::size_t begin, std::size_t end, int& axis)
{
  auto at = [&](std::size_t i, int a) { return xyz[3 * ids[i] + a]; };
  double low[3] = { at(begin, 0), at(begin, 1), at(begin, 2) };
  double high[3] = { low[0], low[1], low[2] };
  for (std::size_t i = begin; i < end; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      low[a] = std::min(low[a], at(i, a));
      high[a] = std::max(high[a], at(i, a));
    }
  }
  axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    axis = (high[a] - low[a] > high[axis] - low[axis]) ? a : axis;
  }
  std::vector<double> values(end - begin);
  for (std::size_t i = begin; i < end; ++i)
  {
    values[i - begin] = at(i, axis);
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  const double median = values[values.size() / 2];
  const int a = axis;
  const auto middle = std::stable_partition(ids.begin() + begin, ids.begin() + end,
    [&](std::uint32_t id) { return xyz[3 * id + a] < median; });
  return static_cast<std::size_t>(middle - ids.begin());
}

inline PointCloudIndex::PointCloudIndex(std::vector<double>& xyz,
  std::vector<std::uint32_t>& oldIndex, int splitLevels, const TaskRunner& run)
  : Cloud{ xyz.data(), xyz.size() / 3 }
  , Tree(3, Cloud,
      nanoflann::KDTreeSingleIndexAdaptorParams(
        LeafSize, nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex))
{
  const std::size_t count = xyz.size() / 3;
  oldIndex.resize(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    oldIndex[i] = static_cast<std::uint32_t>(i);
  }
  // Cut into pieces, level by level; a piece that cannot be cut stays whole.
  std::vector<Cut> cuts;
  std::vector<std::size_t> pieceStart{ 0, count };
  for (int level = 0; level < splitLevels; ++level)
  {
    // The pieces of a level are cut at once (each on its own range of oldIndex).
    const std::size_t current = pieceStart.size() - 1;
    std::vector<std::size_t> middles(current);
    std::vector<int> axes(current, 0);
    std::vector<std::function<void()>> cutTasks;
    for (std::size_t p = 0; p < current; ++p)
    {
      cutTasks.push_back([&, p]() {
        const std::size_t begin = pieceStart[p], end = pieceStart[p + 1];
        middles[p] = end - begin > 4 * LeafSize
          ? CutAtMedian(xyz.data(), oldIndex, begin, end, axes[p])
          : begin;
      });
    }
    run(cutTasks);
    std::vector<std::size_t> next{ 0 };
    for (std::size_t p = 0; p < current; ++p)
    {
      const std::size_t begin = pieceStart[p], end = pieceStart[p + 1];
      const int axis = axes[p];
      const std::size_t middle = middles[p];
      if (middle > begin && middle < end)
      {
        cuts.push_back({ begin, middle, end, axis });
        next.push_back(middle);
      }
      next.push_back(end);
    }
    pieceStart.swap(next);
  }
  const std::size_t pieces = pieceStart.size() - 1;
  {
    std::vector<double> moved(3 * count);
    InChunks(count, pieces, run, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        std::copy(&xyz[3 * oldIndex[i]], &xyz[3 * oldIndex[i]] + 3, &moved[3 * i]);
      }
    });
    xyz.swap(moved);
    this->Cloud.Points = xyz.data();
  }

  std::vector<std::function<void()>> tasks;
  for (std::size_t p = 0; p < pieces; ++p)
  {
    this->PieceClouds.emplace_back(
      new Adaptor{ xyz.data() + 3 * pieceStart[p], pieceStart[p + 1] - pieceStart[p] });
    this->PieceTrees.emplace_back(nullptr);
  }
  for (std::size_t p = 0; p < pieces; ++p)
  {
    tasks.push_back([this, p]() {
      this->PieceTrees[p].reset(
        new Tree3D(3, *this->PieceClouds[p], nanoflann::KDTreeSingleIndexAdaptorParams(LeafSize)));
    });
  }
  run(tasks);

  // The whole tree: every piece's index, shifted to the whole array, then the joining nodes.
  this->Tree.m_size = count;
  this->Tree.m_size_at_index_build = count;
  this->Tree.vAcc.resize(count);
  for (std::size_t p = 0; p < pieces; ++p)
  {
    const std::vector<std::uint32_t>& piece = this->PieceTrees[p]->vAcc;
    for (std::size_t i = 0; i < piece.size(); ++i)
    {
      this->Tree.vAcc[pieceStart[p] + i] = static_cast<std::uint32_t>(pieceStart[p] + piece[i]);
    }
    std::vector<std::uint32_t>().swap(this->PieceTrees[p]->vAcc); // no longer needed
  }
  if (count > 0)
  {
    this->Tree.root_node = this->Join(0, count, pieceStart, cuts, this->Tree.root_bbox);
  }
  this->MoveIntoLeafOrder(xyz, oldIndex, run);
}

// The node over the points [begin, end): a piece's root (its leaf ranges shifted by the
// piece's start), or a new node over a cut. `box` receives the tight box of the points.
inline PointCloudIndex::Node* PointCloudIndex::Join(std::size_t begin, std::size_t end,
  const std::vector<std::size_t>& pieceStart, const std::vector<Cut>& cuts, Box& box)
{
  for (const Cut& cut : cuts)
  {
    if (cut.Begin == begin && cut.End == end)
    {
      Box lower, upper;
      Node* node = this->Tree.pool.template allocate<Node>();
      node->child1 = this->Join(begin, cut.Middle, pieceStart, cuts, lower);
      node->child2 = this->Join(cut.Middle, end, pieceStart, cuts, upper);
      node->node_type.sub.divfeat = cut.Axis;
      node->node_type.sub.divlow = lower[cut.Axis].high; // as nanoflann's divideTree sets them
      node->node_type.sub.divhigh = upper[cut.Axis].low;
      for (int a = 0; a < 3; ++a)
      {
        box[a].low = std::min(lower[a].low, upper[a].low);
        box[a].high = std::max(lower[a].high, upper[a].high);
      }
      return node;
    }
  }
  const std::size_t p = static_cast<std::size_t>(
    std::lower_bound(pieceStart.begin(), pieceStart.end(), begin) - pieceStart.begin());
  Tree3D& piece = *this->PieceTrees[p];
  box = piece.root_bbox;
  std::vector<Node*> stack{ piece.root_node };
  while (!stack.empty())
  {
    Node* node = stack.back();
    stack.pop_back();
    if (!node->child1 && !node->child2)
    {
      node->node_type.lr.left += begin;
      node->node_type.lr.right += begin;
    }
    else
    {
      stack.push_back(node->child1);
      stack.push_back(node->child2);
    }
  }
  return piece.root_node;
}

inline void PointCloudIndex::MoveIntoLeafOrder(
  std::vector<double>& xyz, std::vector<std::uint32_t>& oldIndex, const TaskRunner& run)
{
  std::vector<std::uint32_t>& leafOrder = this->Tree.vAcc;
  const std::size_t count = leafOrder.size();
  std::vector<double> moved(3 * count);
  std::vector<std::uint32_t> movedIndex(count);
  InChunks(count, this->PieceTrees.size(), run, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      std::copy(&xyz[3 * leafOrder[i]], &xyz[3 * leafOrder[i]] + 3, &moved[3 * i]);
      movedIndex[i] = oldIndex[leafOrder[i]];
      leafOrder[i] = static_cast<std::uint32_t>(i); // leaf ranges now index xyz directly
    }
  });
  xyz.swap(moved);
  oldIndex.swap(movedIndex);
  this->Cloud.Points = xyz.data();
  for (auto& piece : this->PieceClouds)
  {
    piece->Points = nullptr; // their trees are built; only their nodes are still in use
  }
}

} // namespace lsi

#endif
