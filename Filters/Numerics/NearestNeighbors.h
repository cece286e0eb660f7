// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// k-nearest-neighbour queries on a static point cloud, over nanoflann's kd-tree (header-only;
// Debian: libnanoflann-dev), walked by nanoflann's search or, for the k nearest, a faster copy
// of it with the same answers. Queries are const and thread-safe once built.
#ifndef NearestNeighbors_h
#define NearestNeighbors_h

#include "TaskRunner.h"
#include "UninitializedVector.h"

#include <nanoflann.hpp>

#include <algorithm>
#include <atomic>
#include <cfloat>
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

  /// The same kind of tree over points already in Morton order, built in linear time:
  /// `mortonWords[i]` is point i's word from PackedMortonKey (same box for all points), sorted.
  /// Each node splits its points where the next Morton bit changes (a binary search, as they
  /// are sorted), so the cuts need neither sorting nor moving points; a node with more than a
  /// leaf of points in one Morton cell (clustered data) is cut at coordinate medians instead.
  /// The points in `xyz` are moved into the tree's leaf order (which differs from the Morton
  /// order only inside such cells); `oldIndex[i]` receives the position in `xyz` of what is now
  /// point i. `xyz` must outlive the index and keep its buffer.
  PointCloudIndex(UninitializedVector<double>& xyz,
    const UninitializedVector<std::uint64_t>& mortonWords,
    UninitializedVector<std::uint32_t>& oldIndex, const TaskRunner& run);

  /// The k points nearest to `query`, closest first: indices and squared distances.
  /// Returns how many were found (fewer than k only when the cloud is smaller).
  std::size_t Nearest(
    const double query[3], std::size_t k, std::uint32_t* indices, double* squaredDistances) const
  {
    return this->SearchNearest(query, k, DBL_MAX, indices, squaredDistances);
  }

  /// Like Nearest, but only among points closer than sqrt(squaredBound): a good bound (from a
  /// query nearby) prunes most of the tree walk. Returns how many were found, possibly < k.
  std::size_t NearestWithin(const double query[3], std::size_t k, double squaredBound,
    std::uint32_t* indices, double* squaredDistances) const
  {
    return this->SearchNearest(query, k, squaredBound, indices, squaredDistances);
  }

  /// nanoflann's own search of this tree (its walk and KNNResultSet; squaredBound DBL_MAX: no
  /// bound), which Nearest and NearestWithin reproduce: for the tests.
  std::size_t NanoflannNearest(const double query[3], std::size_t k, double squaredBound,
    std::uint32_t* indices, double* squaredDistances) const
  {
    nanoflann::KNNResultSet<double, std::uint32_t> result(k);
    result.init(indices, squaredDistances);
    squaredDistances[k - 1] = squaredBound; // the initial worst distance
    this->Tree.findNeighbors(result, query, nanoflann::SearchParams());
    return result.size();
  }

  /// The k nearest (as Nearest), searched first within a little more than `nearbyRadius`, the
  /// k-th neighbour's distance of a query nearby (0: none): a search within it finds the same
  /// neighbours (ties included: both walks visit the same leaves in the same order) when it
  /// finds enough, else the search is repeated without a bound.
  std::size_t NearestNear(const double query[3], std::size_t k, double nearbyRadius,
    std::uint32_t* indices, double* squaredDistances) const
  {
    const double bound = 1.44 * nearbyRadius * nearbyRadius;
    if (bound > 0.0 && this->NearestWithin(query, k, bound, indices, squaredDistances) == k)
    {
      return k;
    }
    return this->Nearest(query, k, indices, squaredDistances);
  }

  /// Whether a point closer than sqrt(squaredRadius) to `query` satisfies `accept(index,
  /// squaredDistance)`; the walk stops at the first that does.
  template <typename Accept>
  bool AnyWithin(const double query[3], double squaredRadius, Accept&& accept) const
  {
    FirstAccepted<Accept> result(squaredRadius, accept);
    this->Tree.findNeighbors(result, query, nanoflann::SearchParams());
    return result.Found;
  }

  std::size_t Size() const { return this->Cloud.Count; }
  /// Point j of the cloud, as the searches' indices number them.
  const double* Point(std::uint32_t j) const { return this->Cloud.Points + 3 * std::size_t(j); }
  /// The squared distance between two points as the searches sum it (as nanoflann's
  /// L2_Simple_Adaptor does): to compare with theirs, to the bit.
  static double SquaredDistance(const double* query, const double* x)
  {
    const double dx = query[0] - x[0], dy = query[1] - x[1], dz = query[2] - x[2];
    return dx * dx + dy * dy + dz * dz;
  }

private:
  static constexpr std::size_t LeafSize = 16;
  static constexpr int MortonBits = 30; // of a packed Morton word's key

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
  // A nanoflann result set that keeps nothing: it stops the walk at the first point within the
  // radius that `Accept` takes.
  template <typename Accept>
  struct FirstAccepted
  {
    double Radius2;
    Accept& Take;
    bool Found = false;
    FirstAccepted(double radius2, Accept& take)
      : Radius2(radius2)
      , Take(take)
    {
    }
    void init() {}
    std::size_t size() const { return this->Found ? 1 : 0; }
    bool full() const { return true; }
    bool addPoint(double distance2, std::uint32_t index)
    {
      if (distance2 < this->Radius2 && this->Take(index, distance2))
      {
        this->Found = true;
        return false; // stop
      }
      return true;
    }
    double worstDist() const { return this->Radius2; }
  };
  using Tree3D = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, Adaptor>,
    Adaptor, 3, std::uint32_t>;
  using Node = Tree3D::Node;
  using Box = Tree3D::BoundingBox;

  // The k nearest found so far, closest first (ties in the order found), as nanoflann's
  // KNNResultSet keeps them: the same insertions, without its capacity check at every step,
  // and each distance beside its index (one move per shift; copied out at the end).
  struct NearestEntry
  {
    double D2;
    std::uint32_t Index;
  };
  struct NearestSet
  {
    NearestEntry* Entries;
    std::size_t Capacity;
    std::size_t Count;
    double Bound; // the worst distance until the set is full
    double Worst() const
    {
      return this->Count == this->Capacity ? this->Entries[this->Count - 1].D2 : this->Bound;
    }
    void Add(double d2, std::uint32_t index)
    {
      std::size_t i = this->Count;
      if (i == this->Capacity)
      {
        if (!(this->Entries[i - 1].D2 > d2))
        {
          return; // not nearer than the worst kept (which, on a tie, was found first)
        }
        --i; // the worst drops out
      }
      else
      {
        ++this->Count;
      }
      for (; i > 0 && this->Entries[i - 1].D2 > d2; --i)
      {
        this->Entries[i] = this->Entries[i - 1];
      }
      this->Entries[i] = NearestEntry{ d2, index };
    }
  };
  std::size_t SearchNearest(const double query[3], std::size_t k, double squaredBound,
    std::uint32_t* indices, double* squaredDistances) const;
  void SearchNode(NearestSet& found, const double query[3], const Node* node, double minimum,
    double cut[3]) const;

  // Moves the points into the order of the leaves (the median cuts' order within a Morton cell).
  void MoveIntoLeafOrder(UninitializedVector<double>& xyz,
    UninitializedVector<std::uint32_t>& oldIndex, const TaskRunner& run);
  using Pool = nanoflann::PooledAllocator;
  // A crowded Morton cell left for later, to be cut at medians on some thread: its node is
  // allocated already (Stub) and receives the subtree's root.
  struct MedianJob
  {
    std::size_t Begin, End;
    Node* Stub;
  };
  // A subtree of the Morton cuts left for later, to be built on some thread into Stub.
  struct PieceJob
  {
    std::size_t Begin, End;
    int Bit;
    Node* Stub;
  };
  // A piece's bounding box, computed ahead of the top cuts.
  struct PieceBox
  {
    std::size_t Begin, End;
    Box Bounds;
  };
  Node* MortonNode(const std::uint64_t* words, std::size_t begin, std::size_t end, int bit,
    Box& box, Pool& pool, std::vector<MedianJob>& jobs, std::vector<PieceJob>* pieces,
    const std::vector<PieceBox>* pieceBoxes = nullptr);
  static int NextCut(
    const std::uint64_t* words, std::size_t begin, std::size_t end, int bit, std::size_t& split);
  static void PieceRanges(const std::uint64_t* words, std::size_t begin, std::size_t end, int bit,
    std::vector<std::pair<std::size_t, std::size_t>>& ranges);
  void RunMedianJobs(std::vector<MedianJob> jobs, const TaskRunner& run);
  static int MedianAxis(const Box& box);
  std::size_t SplitAtMedian(std::size_t begin, std::size_t end, int axis);
  Node* MedianNode(std::size_t begin, std::size_t end, Box& box, Pool& pool);
  Node* Leaf(std::size_t begin, std::size_t end, Box& box, Pool& pool);
  void BoxOf(std::size_t begin, std::size_t end, Box& box) const;
  static void MakeParent(Node* node, Node* lower, Node* upper, int axis, const Box& lowerBox,
    const Box& upperBox, Box& box);
  // Crowded cells with more points than this are cut on several threads, a level at a time.
  static constexpr std::size_t ParallelCell = 1 << 16;
  // Morton subtrees of at most this many points are built as tasks (any size gives the same
  // tree: it only decides what runs where).
  static constexpr std::size_t PieceSize = 1 << 15;

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
  std::vector<std::unique_ptr<Pool>> JobPools; // the nodes built by tasks
  std::atomic<bool> Reordered{ false };        // whether a median cut reordered points
};

/// A search index over `points` (3 doubles each; they must outlive it), or null when there are
/// none.
inline std::unique_ptr<PointCloudIndex> IndexOfPoints(const std::vector<double>& points)
{
  return points.size() < 3
    ? nullptr
    : std::unique_ptr<PointCloudIndex>(new PointCloudIndex(points.data(), points.size() / 3));
}

/// Whether the k points gathered as the nearest to a point c are still the k nearest to a point
/// `step` away from c, given that each lies within `farthest` of the new point and that every
/// point not gathered lies at least `outerRadius` from c (so at least outerRadius - step from
/// the new point). Margins cover the rounding of the distances.
inline bool StillNearest(double farthest, double step, double outerRadius)
{
  return farthest * (1.0 + 1e-9) < (outerRadius - step) * (1.0 - 1e-9);
}

// ---------------------------------------------------------------------------------------------
// The k-nearest search: nanoflann's walk (KDTreeSingleIndexAdaptor::findNeighbors and
// searchLevel, 1.4.2) with its KNNResultSet, so the same leaves in the same order and the same
// neighbours in the same order, ties included; a leaf's distances are computed first and those
// below the worst kept picked in a branch-free pass, then inserted (about a sixth faster on
// the searches of LevelSetSearches; TestNumerics checks it against nanoflann's own search).

inline std::size_t PointCloudIndex::SearchNearest(const double query[3], std::size_t k,
  double squaredBound, std::uint32_t* indices, double* squaredDistances) const
{
  if (k == 0 || this->Cloud.Count == 0 || !this->Tree.root_node)
  {
    return 0;
  }
  constexpr std::size_t OnStack = 128; // more than any fit asks for
  NearestEntry onStack[OnStack];
  std::vector<NearestEntry> onHeap(k > OnStack ? k : 0);
  NearestSet found{ k > OnStack ? onHeap.data() : onStack, k, 0, squaredBound };
  // The squared distance to the root's box, per axis and in all (nanoflann's
  // computeInitialDistances).
  double cut[3] = { 0.0, 0.0, 0.0 }, minimum = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    const auto& side = this->Tree.root_bbox[a];
    if (query[a] < side.low)
    {
      cut[a] = (query[a] - side.low) * (query[a] - side.low);
      minimum += cut[a];
    }
    if (query[a] > side.high)
    {
      cut[a] = (query[a] - side.high) * (query[a] - side.high);
      minimum += cut[a];
    }
  }
  this->SearchNode(found, query, this->Tree.root_node, minimum, cut);
  for (std::size_t j = 0; j < found.Count; ++j)
  {
    indices[j] = found.Entries[j].Index;
    squaredDistances[j] = found.Entries[j].D2;
  }
  return found.Count;
}

inline void PointCloudIndex::SearchNode(
  NearestSet& found, const double query[3], const Node* node, double minimum, double cut[3]) const
{
  if (!node->child1 && !node->child2)
  {
    const std::uint32_t* order = this->Tree.vAcc.data();
    const double* xyz = this->Cloud.Points;
    // In pieces of at most 16 points (a leaf of coincident points may hold more). Rereading
    // the worst distance between pieces changes nothing: a point not nearer than it is not
    // inserted either way.
    constexpr std::size_t Piece = 16;
    double d2[Piece];
    unsigned char nearer[Piece];
    for (std::size_t begin = node->node_type.lr.left; begin < node->node_type.lr.right;
         begin += Piece)
    {
      const std::size_t size = std::min(Piece, node->node_type.lr.right - begin);
      for (std::size_t i = 0; i < size; ++i)
      {
        d2[i] = SquaredDistance(query, xyz + 3 * order[begin + i]);
      }
      const double worst = found.Worst();
      std::size_t count = 0;
      for (std::size_t i = 0; i < size; ++i)
      {
        nearer[count] = static_cast<unsigned char>(i);
        count += d2[i] < worst;
      }
      for (std::size_t j = 0; j < count; ++j)
      {
        found.Add(d2[nearer[j]], order[begin + nearer[j]]);
      }
    }
    return;
  }
  // The child on the query's side first, then the other if its cut lies nearer than the worst.
  const int axis = node->node_type.sub.divfeat;
  const double value = query[axis];
  const double low = value - node->node_type.sub.divlow, high = value - node->node_type.sub.divhigh;
  const bool lowerFirst = low + high < 0.0;
  const Node* first = lowerFirst ? node->child1 : node->child2;
  const Node* other = lowerFirst ? node->child2 : node->child1;
  const double across = lowerFirst ? high * high : low * low;
  this->SearchNode(found, query, first, minimum, cut);
  const double before = cut[axis];
  minimum = minimum + across - before; // (in nanoflann's order of operations)
  cut[axis] = across;
  if (minimum <= found.Worst())
  {
    this->SearchNode(found, query, other, minimum, cut);
  }
  cut[axis] = before;
}

// ---------------------------------------------------------------------------------------------
// The build from Morton order. It fills nanoflann's public members (vAcc, root_node, root_bbox,
// pool) the way its buildIndex does; checked against nanoflann 1.4.2, the version in Debian 12.
static_assert(
  NANOFLANN_VERSION == 0x142, "PointCloudIndex's Morton build was written for nanoflann 1.4.2");

inline void PointCloudIndex::MoveIntoLeafOrder(UninitializedVector<double>& xyz,
  UninitializedVector<std::uint32_t>& oldIndex, const TaskRunner& run)
{
  std::vector<std::uint32_t>& leafOrder = this->Tree.vAcc;
  const std::size_t count = leafOrder.size();
  oldIndex.resize(count);
  AdviseHugePages(oldIndex);
  InChunks(count, 8, run, [&](std::size_t begin, std::size_t end) {
    std::copy(leafOrder.begin() + begin, leafOrder.begin() + end, oldIndex.begin() + begin);
  });
  if (!this->Reordered)
  {
    return; // no median cut: the leaves are in Morton order already
  }
  UninitializedVector<double> moved(3 * count);
  AdviseHugePages(moved);
  InChunks(count, 8, run, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      std::copy(&xyz[3 * leafOrder[i]], &xyz[3 * leafOrder[i]] + 3, &moved[3 * i]);
      leafOrder[i] = static_cast<std::uint32_t>(i); // leaf ranges now index xyz directly
    }
  });
  xyz.swap(moved);
  this->Cloud.Points = xyz.data();
}

inline PointCloudIndex::PointCloudIndex(UninitializedVector<double>& xyz,
  const UninitializedVector<std::uint64_t>& mortonWords,
  UninitializedVector<std::uint32_t>& oldIndex, const TaskRunner& run)
  : Cloud{ xyz.data(), xyz.size() / 3 }
  , Tree(3, Cloud,
      nanoflann::KDTreeSingleIndexAdaptorParams(
        LeafSize, nanoflann::KDTreeSingleIndexAdaptorFlags::SkipInitialBuildIndex))
{
  const std::size_t count = xyz.size() / 3;
  ResizeMapped(this->Tree.vAcc, count);
  InChunks(count, 8, run, [this](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      this->Tree.vAcc[i] = static_cast<std::uint32_t>(i);
    }
  });
  this->Tree.m_size = count;
  this->Tree.m_size_at_index_build = count;
  if (count > 0)
  {
    // The top cuts here; the subtrees below PieceSize points as tasks, each on a node pool of
    // its own; then the crowded cells that any of them left.
    // The pieces' bounding boxes first, in parallel (the top cuts need them, and they span
    // every point).
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    PieceRanges(mortonWords.data(), 0, count, MortonBits - 1, ranges);
    std::vector<PieceBox> pieceBoxes(ranges.size());
    InChunks(ranges.size(), std::min<std::size_t>(ranges.size(), 8), run,
      [this, &ranges, &pieceBoxes](std::size_t begin, std::size_t end) {
        for (std::size_t p = begin; p < end; ++p)
        {
          pieceBoxes[p].Begin = ranges[p].first;
          pieceBoxes[p].End = ranges[p].second;
          this->BoxOf(ranges[p].first, ranges[p].second, pieceBoxes[p].Bounds);
        }
      });
    std::vector<MedianJob> jobs;
    std::vector<PieceJob> pieces;
    this->Tree.root_node = this->MortonNode(mortonWords.data(), 0, count, MortonBits - 1,
      this->Tree.root_bbox, this->Tree.pool, jobs, &pieces, &pieceBoxes);
    std::vector<std::vector<MedianJob>> pieceJobs(pieces.size());
    std::vector<std::function<void()>> tasks;
    for (std::size_t p = 0; p < pieces.size(); ++p)
    {
      this->JobPools.emplace_back(new Pool);
      Pool& pool = *this->JobPools.back();
      tasks.push_back([this, &mortonWords, &pieces, &pieceJobs, &pool, p]() {
        const PieceJob& piece = pieces[p];
        Box box;
        *piece.Stub = *this->MortonNode(
          mortonWords.data(), piece.Begin, piece.End, piece.Bit, box, pool, pieceJobs[p], nullptr);
      });
    }
    run(tasks);
    for (const std::vector<MedianJob>& more : pieceJobs)
    {
      jobs.insert(jobs.end(), more.begin(), more.end());
    }
    this->RunMedianJobs(std::move(jobs), run);
  }
  this->MoveIntoLeafOrder(xyz, oldIndex, run);
}

// Packed Morton words hold a 30-bit key above the 32-bit id; key bit b splits axis b % 3.
inline PointCloudIndex::Node* PointCloudIndex::MortonNode(const std::uint64_t* words,
  std::size_t begin, std::size_t end, int bit, Box& box, Pool& pool, std::vector<MedianJob>& jobs,
  std::vector<PieceJob>* pieces, const std::vector<PieceBox>* pieceBoxes)
{
  if (end - begin <= LeafSize)
  {
    return this->Leaf(begin, end, box, pool);
  }
  if (pieces && end - begin <= PieceSize) // later, as a task
  {
    // (Its box computed ahead: PieceRanges meets the pieces in this order.)
    const std::size_t p = pieces->size();
    if (pieceBoxes && p < pieceBoxes->size() && (*pieceBoxes)[p].Begin == begin &&
      (*pieceBoxes)[p].End == end)
    {
      box = (*pieceBoxes)[p].Bounds;
    }
    else
    {
      this->BoxOf(begin, end, box);
    }
    pieces->push_back({ begin, end, bit, pool.template allocate<Node>() });
    return pieces->back().Stub;
  }
  std::size_t split = begin;
  bit = NextCut(words, begin, end, bit, split);
  if (bit < 0 && end - begin > ParallelCell) // one crowded Morton cell: later, in parallel
  {
    this->BoxOf(begin, end, box);
    jobs.push_back({ begin, end, pool.template allocate<Node>() });
    return jobs.back().Stub;
  }
  if (bit < 0)
  {
    return this->MedianNode(begin, end, box, pool); // one Morton cell
  }
  Box lower, upper;
  Node* below =
    this->MortonNode(words, begin, split, bit - 1, lower, pool, jobs, pieces, pieceBoxes);
  Node* above = this->MortonNode(words, split, end, bit - 1, upper, pool, jobs, pieces, pieceBoxes);
  Node* node = pool.template allocate<Node>();
  MakeParent(node, below, above, bit % 3, lower, upper, box);
  return node;
}

// The words of [begin, end) share their key bits above `bit`: the next bit that differs within
// the range (returned; -1 if none) splits it in two contiguous parts at `split`.
inline int PointCloudIndex::NextCut(
  const std::uint64_t* words, std::size_t begin, std::size_t end, int bit, std::size_t& split)
{
  for (; bit >= 0; --bit)
  {
    const auto set = [bit](std::uint64_t w) { return ((w >> (32 + bit)) & 1u) == 0; };
    split = static_cast<std::size_t>(std::partition_point(words + begin, words + end, set) - words);
    if (split > begin && split < end)
    {
      break;
    }
  }
  return bit;
}

// The pieces MortonNode's top cuts leave, in the order it meets them (the same cuts).
inline void PointCloudIndex::PieceRanges(const std::uint64_t* words, std::size_t begin,
  std::size_t end, int bit, std::vector<std::pair<std::size_t, std::size_t>>& ranges)
{
  if (end - begin <= LeafSize)
  {
    return;
  }
  if (end - begin <= PieceSize)
  {
    ranges.emplace_back(begin, end);
    return;
  }
  std::size_t split = begin;
  bit = NextCut(words, begin, end, bit, split);
  if (bit < 0)
  {
    return; // one Morton cell, cut at medians: no piece
  }
  PieceRanges(words, begin, split, bit - 1, ranges);
  PieceRanges(words, split, end, bit - 1, ranges);
}

// The crowded cells, a level of median cuts at a time: a job too large is cut once (its halves
// become the next level's jobs), a smaller one is built whole, each on a pool of its own. The
// cuts are those MedianNode makes, so the tree does not depend on the threads.
inline void PointCloudIndex::RunMedianJobs(std::vector<MedianJob> jobs, const TaskRunner& run)
{
  while (!jobs.empty())
  {
    std::vector<std::vector<MedianJob>> halves(jobs.size());
    std::vector<std::function<void()>> tasks;
    for (std::size_t j = 0; j < jobs.size(); ++j)
    {
      this->JobPools.emplace_back(new Pool);
      Pool& pool = *this->JobPools.back();
      tasks.push_back([this, &jobs, &halves, &pool, j]() {
        const MedianJob job = jobs[j];
        Box box;
        this->BoxOf(job.Begin, job.End, box);
        const int axis = MedianAxis(box);
        if (job.End - job.Begin <= ParallelCell || !(box[axis].high > box[axis].low))
        {
          *job.Stub = *this->MedianNode(job.Begin, job.End, box, pool);
          return;
        }
        const std::size_t middle = this->SplitAtMedian(job.Begin, job.End, axis);
        Box lower, upper;
        this->BoxOf(job.Begin, middle, lower);
        this->BoxOf(middle, job.End, upper);
        Node* below = pool.template allocate<Node>();
        Node* above = pool.template allocate<Node>();
        MakeParent(job.Stub, below, above, axis, lower, upper, box);
        halves[j] = { { job.Begin, middle, below }, { middle, job.End, above } };
      });
    }
    run(tasks);
    std::vector<MedianJob> next;
    for (const std::vector<MedianJob>& pair : halves)
    {
      next.insert(next.end(), pair.begin(), pair.end());
    }
    jobs.swap(next);
  }
}

inline int PointCloudIndex::MedianAxis(const Box& box)
{
  int axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    axis = box[a].high - box[a].low > box[axis].high - box[axis].low ? a : axis;
  }
  return axis;
}

// Puts the lower half of [begin, end) along `axis` first (ties by index); returns the middle.
inline std::size_t PointCloudIndex::SplitAtMedian(std::size_t begin, std::size_t end, int axis)
{
  this->Reordered = true;
  std::vector<std::uint32_t>& order = this->Tree.vAcc;
  const std::size_t middle = begin + (end - begin) / 2;
  const double* xyz = this->Cloud.Points;
  std::nth_element(order.begin() + static_cast<std::ptrdiff_t>(begin),
    order.begin() + static_cast<std::ptrdiff_t>(middle),
    order.begin() + static_cast<std::ptrdiff_t>(end), [&](std::uint32_t a, std::uint32_t b) {
      return xyz[3 * a + axis] < xyz[3 * b + axis] ||
        (xyz[3 * a + axis] == xyz[3 * b + axis] && a < b);
    });
  return middle;
}

inline PointCloudIndex::Node* PointCloudIndex::MedianNode(
  std::size_t begin, std::size_t end, Box& box, Pool& pool)
{
  this->BoxOf(begin, end, box);
  const int axis = MedianAxis(box);
  if (end - begin <= LeafSize || !(box[axis].high > box[axis].low))
  {
    return this->Leaf(begin, end, box, pool); // few points, or all coincident
  }
  const std::size_t middle = this->SplitAtMedian(begin, end, axis);
  Box lower, upper;
  Node* below = this->MedianNode(begin, middle, lower, pool);
  Node* above = this->MedianNode(middle, end, upper, pool);
  Node* node = pool.template allocate<Node>();
  MakeParent(node, below, above, axis, lower, upper, box);
  return node;
}

inline PointCloudIndex::Node* PointCloudIndex::Leaf(
  std::size_t begin, std::size_t end, Box& box, Pool& pool)
{
  Node* node = pool.template allocate<Node>();
  node->child1 = node->child2 = nullptr;
  node->node_type.lr.left = begin;
  node->node_type.lr.right = end;
  this->BoxOf(begin, end, box);
  return node;
}

inline void PointCloudIndex::BoxOf(std::size_t begin, std::size_t end, Box& box) const
{
  const std::vector<std::uint32_t>& order = this->Tree.vAcc;
  const double* xyz = this->Cloud.Points;
  for (int a = 0; a < 3; ++a)
  {
    box[a].low = box[a].high = xyz[3 * order[begin] + a];
  }
  for (std::size_t i = begin + 1; i < end; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      box[a].low = std::min(box[a].low, xyz[3 * order[i] + a]);
      box[a].high = std::max(box[a].high, xyz[3 * order[i] + a]);
    }
  }
}

inline void PointCloudIndex::MakeParent(Node* node, Node* lower, Node* upper, int axis,
  const Box& lowerBox, const Box& upperBox, Box& box)
{
  node->child1 = lower;
  node->child2 = upper;
  node->node_type.sub.divfeat = axis;
  node->node_type.sub.divlow = lowerBox[axis].high; // as nanoflann's divideTree sets them
  node->node_type.sub.divhigh = upperBox[axis].low;
  for (int a = 0; a < 3; ++a)
  {
    box[a].low = std::min(lowerBox[a].low, upperBox[a].low);
    box[a].high = std::max(lowerBox[a].high, upperBox[a].high);
  }
}

} // namespace lsi

#endif
