// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetFlood.h"

#include "LevelSetParallel.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <Eigen/Dense>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <queue>
#include <thread>

namespace lsi
{

namespace
{
// Breadth-first flood through neighbours with f > f_iso from the seed samples not yet in
// `flooded`.
void Flood(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inSeed, std::vector<char>& flooded, FloodResult& result,
  SerialAbortCheck& stop, const FloodEdgeCheck& mayCross)
{
  const std::size_t n = geometry.NumberOfSamples;
  if (flooded.size() != n)
  {
    flooded.clear();
    ResizeMappedInParallel(flooded, n, char(0));
  }
  std::vector<std::uint32_t> queue = IndicesWhere<std::uint32_t>(
    n, [&](std::size_t i) { return inSeed[i] && dataOffsets[i] > 0.0 && !flooded[i]; });
  for (const std::uint32_t i : queue)
  {
    flooded[i] = 1;
  }
  result.SeedSamples = queue.size();
  BreadthFirst(
    geometry, queue,
    [&](std::uint32_t j, std::uint32_t from) {
      if (flooded[j] || !(dataOffsets[j] > 0.0) || (mayCross && !mayCross(from, j)))
      {
        return Visit::Skip; // (refused from here, j may still be reached from elsewhere)
      }
      flooded[j] = 1;
      return Visit::Enqueue;
    },
    &stop);
}

// Outside pockets next to the inside with fewer than `bubbleSize` samples become inside.
// A pocket is what a search from one of the inside's outside neighbours (a start) reaches
// through outside samples. Neighbour lists are not symmetric, so that depends on the start:
// each start is decided on its own, against the flood's reach alone (`flooded`), never against
// what an earlier search decided about other samples. The result is then the same in any order
// of the samples, so on any number of MPI ranks. (A search from s that meets a start t known to
// reach a large pocket stops: s reaches all t reaches. A start inside a filled pocket needs no
// search: all it reaches is filled already.) Each search stops as soon as its pocket proves
// large, so the cost stays near the front.
void FillBubbles(const Neighborhoods& geometry, std::size_t bubbleSize,
  const std::vector<char>& flooded, std::vector<char>& inside, SerialAbortCheck& stop)
{
  const std::size_t n = geometry.NumberOfSamples;
  const int stride = geometry.Stride;
  // (Zeroed in parallel: at 20M samples these are 20 MB each.)
  UninitializedVector<char> large = FilledInParallel<char>(n, 0); // starts that reach far
  std::vector<std::uint32_t> pocket;
  UninitializedVector<char> visited = FilledInParallel<char>(n, 0);
  // A ghost whose neighbour list is cut short (MPI, Neighborhoods::Truncated) cannot tell how far
  // its pocket goes: it counts as part of a large pocket.
  // The outside neighbours of the inside samples, in the order of the loop that visits them
  // (collected in parallel, in fixed chunks joined in order).
  constexpr std::size_t Chunk = 1 << 16;
  std::vector<std::vector<std::uint32_t>> found((n + Chunk - 1) / Chunk);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(found.size()), 1, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType c = first; c < last; ++c)
      {
        for (std::size_t i = static_cast<std::size_t>(c) * Chunk;
             i < std::min(n, (static_cast<std::size_t>(c) + 1) * Chunk); ++i)
        {
          if (!flooded[i] || geometry.IsTruncated(i))
          {
            continue;
          }
          const std::uint32_t* around = geometry.NeighborsOf(i);
          for (int a = 1; a < stride; ++a)
          {
            if (!flooded[around[a]] && !geometry.IsTruncated(around[a]))
            {
              found[static_cast<std::size_t>(c)].push_back(around[a]);
            }
          }
        }
      }
    });
  // Their lists, in parallel: the searches below start there, and the distances after the
  // flood read them anyway (InsideAndNeighbors).
  std::vector<std::uint32_t> allStarts(JoinedSize(found));
  JoinInParallel(found, allStarts.begin());
  geometry.EnsureNeighbors(allStarts);
  for (const std::vector<std::uint32_t>& starts : found)
  {
    for (const std::uint32_t start : starts)
    {
      if (stop.Stop())
      {
        return;
      }
      if (inside[start] || large[start])
      {
        continue;
      }
      pocket.assign(1, start);
      visited[start] = 1;
      const bool isLarge = !BreadthFirst(geometry, pocket, [&](std::uint32_t j) {
        if (flooded[j] || visited[j])
        {
          return Visit::Skip;
        }
        if (large[j] || pocket.size() >= bubbleSize || geometry.IsTruncated(j))
        {
          return Visit::Stop;
        }
        visited[j] = 1;
        return Visit::Enqueue;
      });
      for (const std::uint32_t j : pocket)
      {
        visited[j] = 0;
      }
      if (isLarge)
      {
        large[start] = 1;
        continue;
      }
      for (const std::uint32_t j : pocket)
      {
        inside[j] = 1;
      }
    }
  }
}

// Sample i's nearest crossing on its links to samples of the other class (inside or not), as
// a squared distance and a point; left as they are if it has none. A crossing is where f - f_iso
// interpolates to zero along the link, the midpoint if the offsets disagree with the classes (a
// filled bubble).
void NearestCrossing(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inside, std::size_t i, double& squaredDistance, Eigen::Vector3d& closest)
{
  const Eigen::Vector3d xi(geometry.Position(i));
  const std::uint32_t* ids = geometry.NeighborsOf(i);
  for (int m = 1; m < geometry.Stride; ++m)
  {
    const std::uint32_t j = ids[m];
    if (inside[j] == inside[i])
    {
      continue;
    }
    const double vi = dataOffsets[i], vj = dataOffsets[j];
    double t = vi != vj ? vi / (vi - vj) : 0.5;
    if (!(t >= 0.0 && t <= 1.0))
    {
      t = 0.5;
    }
    const Eigen::Vector3d crossing = xi + t * (Eigen::Vector3d(geometry.Position(j)) - xi);
    const double d = (crossing - xi).squaredNorm();
    if (d < squaredDistance)
    {
      squaredDistance = d;
      closest = crossing;
    }
  }
}

// The inside samples and their neighbours, in storage order (the lists of the inside samples
// are computed by the flood).
std::vector<std::uint32_t> InsideAndNeighbors(
  const Neighborhoods& geometry, const std::vector<char>& inside)
{
  const std::size_t n = geometry.NumberOfSamples;
  // Marked by several threads at once (all the same value).
  const std::unique_ptr<std::atomic<unsigned char>[]> listed = FilledAtomics<unsigned char>(n, 0);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (!inside[i] || geometry.IsTruncated(static_cast<std::size_t>(i)))
        {
          continue;
        }
        const std::uint32_t* ids = geometry.NeighborsOf(static_cast<std::size_t>(i));
        for (int m = 0; m < geometry.Stride; ++m)
        {
          listed[ids[m]].store(1, std::memory_order_relaxed);
        }
      }
    });
  return IndicesWhere<std::uint32_t>(
    n, [&](std::size_t i) { return listed[i].load(std::memory_order_relaxed) != 0; });
}

// Computes, a wave at a time in parallel, the neighbour lists that the distance propagation
// below will read (most of them): of the samples within halfWidth of a sample that holds a
// crossing, reached through the neighbour graph. Results do not depend on it, only speed (the
// propagation is serial, and computes any list still missing as it goes).
// Each wave is spread in parallel: a sample reached by several threads at once takes the origin
// of whichever claims it first, which can only change which lists are fetched ahead.
// Returns the samples reached, wave by wave (nearest the front first).
std::vector<std::uint32_t> PrefetchBand(const Neighborhoods& geometry,
  const std::vector<std::uint32_t>& holders, double halfWidth, SerialAbortCheck& stop)
{
  constexpr std::uint32_t None = ~std::uint32_t(0);
  const std::size_t n = geometry.NumberOfSamples;
  const std::unique_ptr<std::atomic<std::uint32_t>[]> origin = FilledAtomics(n, None);
  for (const std::uint32_t i : holders)
  {
    origin[i].store(i, std::memory_order_relaxed);
  }
  std::vector<std::uint32_t> wave(holders), reachedAll;
  while (!wave.empty() && !stop.Stop())
  {
    reachedAll.insert(reachedAll.end(), wave.begin(), wave.end());
    geometry.EnsureNeighbors(wave);
    vtkSMPThreadLocal<std::vector<std::uint32_t>> reached;
    vtkSMPTools::For(0, static_cast<vtkIdType>(wave.size()), BalancedGrain(wave.size(), 512),
      [&](vtkIdType begin, vtkIdType end) {
        std::vector<std::uint32_t>& next = reached.Local();
        for (vtkIdType k = begin; k < end; ++k)
        {
          const std::uint32_t i = wave[static_cast<std::size_t>(k)];
          const std::uint32_t source = origin[i].load(std::memory_order_relaxed);
          const Eigen::Vector3d from(geometry.Position(source));
          const std::uint32_t* ids = geometry.NeighborsOf(i);
          for (int m = 1; m < geometry.Stride; ++m)
          {
            const std::uint32_t j = ids[m];
            std::uint32_t unclaimed = None;
            if (origin[j].load(std::memory_order_relaxed) == None &&
              (Eigen::Vector3d(geometry.Position(j)) - from).norm() <= halfWidth &&
              origin[j].compare_exchange_strong(unclaimed, source, std::memory_order_relaxed))
            {
              next.push_back(j);
            }
          }
        }
      });
    wave.clear();
    for (const std::vector<std::uint32_t>& part : reached)
    {
      wave.insert(wave.end(), part.begin(), part.end());
    }
  }
  return reachedAll;
}

// A thread that computes the MLS stencils of `samples` (Neighborhoods::PrecomputeStencils),
// nearest the front first, until Finish, which stops and joins it; so does the destructor, also
// when the caller throws. (The evolution's region, its band and one ring, lies inside the
// reinitialisation's band that `samples` covers; the reinitialisation itself needs stencils only
// at the interface.)
class StencilHelper
{
public:
  StencilHelper(const Neighborhoods& geometry, const std::vector<std::uint32_t>& samples, bool run)
  {
    if (run)
    {
      this->Worker = std::thread([&geometry, &samples, this]() {
        geometry.PrecomputeStencils(samples.data(), samples.size(), this->Stop);
      });
    }
  }
  ~StencilHelper() { this->Finish(); }
  void Finish()
  {
    this->Stop = true;
    if (this->Worker.joinable())
    {
      this->Worker.join();
    }
  }

private:
  std::atomic<bool> Stop{ false };
  std::thread Worker;
};
} // namespace

void FloodFurther(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inSeed, std::vector<char>& flooded, FloodResult& result,
  const AbortCheck& aborted, const FloodEdgeCheck& mayCross)
{
  SerialAbortCheck stop(aborted);
  Flood(geometry, dataOffsets, inSeed, flooded, result, stop, mayCross);
  result.Aborted = stop.WasStopped();
}

std::vector<char> FilledInside(const Neighborhoods& geometry, const std::vector<char>& flooded,
  std::size_t bubbleSize, FloodResult& result, const AbortCheck& aborted)
{
  SerialAbortCheck stop(aborted);
  std::vector<char> inside;
  AssignInParallel(inside, flooded);
  FillBubbles(geometry, bubbleSize, flooded, inside, stop);
  result.Aborted = stop.WasStopped();
  return inside;
}

bool SignedDistanceToCrossings(const Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, const std::vector<char>& inside, double halfWidth,
  std::vector<double>& phi, const AbortCheck& aborted)
{
  SerialAbortCheck stop(aborted);

  // Distances to the crossings by a closest-point Dijkstra: every sample near the front
  // carries the crossing nearest to it found so far and offers it to its neighbours. Squared
  // distances throughout (the same order, no square roots in the inner loop).
  const std::size_t n = geometry.NumberOfSamples;
  const int stride = geometry.Stride;
  // The squared distances are kept in phi itself, turned into phi at the end (no second array
  // of n values to fault in).
  std::vector<double>& distance = phi;
  distance.clear();
  ResizeMappedInParallel(distance, n, HUGE_VAL);
  std::vector<Eigen::Vector3d> closest(n);
  using Entry = std::pair<double, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> heap;
  // The crossings are looked for in the lists of the inside samples and of their neighbours
  // (not of every sample: most lists are never computed).
  const std::vector<std::uint32_t> nearFront = InsideAndNeighbors(geometry, inside);
  geometry.EnsureNeighbors(nearFront);
  // Each sample's nearest crossing, in parallel (each writes its own entries).
  vtkSMPTools::For(0, static_cast<vtkIdType>(nearFront.size()),
    BalancedGrain(nearFront.size(), 512), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::size_t i = nearFront[static_cast<std::size_t>(k)];
        if (geometry.IsTruncated(i)) // its list may pair it with a stand-in: no true crossing
        {
          continue;
        }
        NearestCrossing(geometry, dataOffsets, inside, i, distance[i], closest[i]);
      }
    });
  std::vector<std::uint32_t> holders; // the samples that hold a crossing
  for (const std::size_t i : nearFront)
  {
    if (distance[i] < HUGE_VAL)
    {
      if (distance[i] <= halfWidth * halfWidth)
      {
        heap.push({ distance[i], static_cast<std::uint32_t>(i) });
      }
      holders.push_back(static_cast<std::uint32_t>(i));
    }
  }
  const std::vector<std::uint32_t> band = PrefetchBand(geometry, holders, halfWidth, stop);
  // The propagation below is serial: meanwhile a helper thread computes the band's MLS
  // stencils, which the evolution needs next (the same stencils whoever computes them).
  StencilHelper helper(
    geometry, band, vtkSMPTools::GetEstimatedNumberOfThreads() > 1 && !stop.Stop());
  // A sample farther than halfWidth takes an offer (phi clamps it to halfWidth either way) but
  // passes nothing on: it never enters the heap.
  const double reach = halfWidth * halfWidth;
  while (!heap.empty() && !stop.Stop())
  {
    const Entry top = heap.top();
    heap.pop();
    const std::uint32_t i = top.second;
    if (top.first > distance[i] || geometry.IsTruncated(i))
    {
      continue;
    }
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    const Eigen::Vector3d from = closest[i];
    for (int m = 1; m < stride; ++m)
    {
      const std::uint32_t j = ids[m];
      const double d = (Eigen::Vector3d(geometry.Position(j)) - from).squaredNorm();
      if (d < distance[j])
      {
        distance[j] = d;
        closest[j] = from;
        if (d <= reach)
        {
          heap.push({ d, j });
        }
      }
    }
  }
  helper.Finish();
  if (stop.WasStopped())
  {
    return false;
  }
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double d = std::min(std::sqrt(distance[i]), halfWidth); // (phi[i] squared)
        phi[i] = inside[i] ? std::max(d, 1e-12 * halfWidth) : -d;
      }
    });
  return true;
}

} // namespace lsi
