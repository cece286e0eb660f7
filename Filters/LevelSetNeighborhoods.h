// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The geometry of the sample cloud that the evolution reuses at every iteration and across
// re-executions: each sample's n nearest neighbours, its neighbourhood radius h_i, and the MLS
// gradient stencil (which depends only on positions). Built once per input geometry.
#ifndef LevelSetNeighborhoods_h
#define LevelSetNeighborhoods_h

#include "LevelSetParallel.h"
#include "NearestNeighbors.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

class vtkPoints;

namespace lsi
{

/// A std::vector allocator that leaves new elements uninitialised: resizing a multi-gigabyte
/// array then costs nothing up front, and its pages are zeroed by the kernel on first touch,
/// inside the parallel loop that fills them, instead of by one thread in resize().
template <typename T>
struct UninitializedAllocator : std::allocator<T>
{
  template <typename U>
  struct rebind
  {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&)
  {
  }
  template <typename U>
  void construct(U* p)
  {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args)
  {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

struct Neighborhoods
{
  std::size_t NumberOfSamples = 0;
  int Stride = 0; // entries per sample: the sample itself (slot 0) and its n neighbours

  // Samples are stored in the kd-tree's leaf order (after a Morton sort, SpatialOrder.h), so
  // that neighbours are near in memory.
  // Every index below is an index in that order; Order maps it back to the input point id.
  std::vector<std::uint32_t> Order;
  std::vector<double> Positions;                                         // 3 per sample
  std::vector<std::uint32_t, UninitializedAllocator<std::uint32_t>> Ids; // Stride per sample
  std::vector<double> Radius; // h_i: distance to the farthest neighbour
  std::unique_ptr<PointCloudIndex> Index;

  // MLS gradient stencils, 3 * Stride floats per sample, computed on demand (EnsureStencils):
  // the evolution only ever visits a band around the front, so most samples never need one.
  // The storage is allocated but not initialised, so untouched pages cost no memory.
  mutable std::unique_ptr<float[]> GradientStencil;
  mutable std::vector<unsigned char> StencilState; // 0: not computed, 1: ready, 2: singular
  mutable std::size_t ComputedStencils = 0;

  double MeanRadius = 0.0; // mean h_i

  // Seconds spent on each part of the build.
  double SortSeconds = 0.0, SearchSeconds = 0.0; // SearchSeconds includes TreeSeconds
  double TreeSeconds = 0.0;
  mutable double StencilSeconds = 0.0; // accumulated over EnsureStencils calls

  // Problems found while building (sample ids are input point ids); the filter turns them into
  // error messages.
  std::size_t DuplicateSamples = 0;
  long long FirstDuplicate = -1;
  bool Flat = false;                       // all samples on one plane or line: no 3D fit anywhere
  mutable std::size_t SingularSamples = 0; // among the stencils computed so far
  // Among them, neighbourhoods so thin in one direction (spread below ThinRatio of the widest)
  // that the fit's gradient across them is ill-conditioned (a thin layer of particles).
  mutable std::size_t ThinSamples = 0;
  static constexpr double ThinRatio = 0.01;

  // Under MPI (LevelSetDistribution.h): ghost samples whose neighbour list the edge of the
  // rank's halo cuts short. Their lists name nearer stand-ins for the missing neighbours, so
  // searches over the neighbour graph do not go on from them. Empty in a serial run.
  mutable std::vector<char> Truncated;

  const std::uint32_t* NeighborsOf(std::size_t i) const { return &this->Ids[i * this->Stride]; }
  bool IsTruncated(std::size_t i) const { return !this->Truncated.empty() && this->Truncated[i]; }
  /// Computes the stencils that `samples` (count indices, no repeats) still lack, in parallel.
  /// Call from the main thread between parallel loops.
  void EnsureStencils(const std::size_t* samples, std::size_t count) const;
  void EnsureStencils(const std::vector<std::size_t>& samples) const
  {
    this->EnsureStencils(samples.data(), samples.size());
  }

  const float* StencilOf(std::size_t i) const
  {
    return &this->GradientStencil[3 * i * this->Stride];
  }
  const double* Position(std::size_t i) const { return &this->Positions[3 * i]; }
};

/// What a breadth-first search over the neighbour graph does with a neighbour it meets.
enum class Visit
{
  Skip,    // leave it
  Enqueue, // append it to the queue (the decision marks it, so it is not met again)
  Stop     // end the search
};

/// Breadth-first search over the neighbour graph: for each sample of `queue` in turn (the
/// starting samples first, then those appended), `decide(j)` for each of its neighbours j.
/// Returns false when `decide` stopped it or `stop` said to abort.
template <typename Decide>
bool BreadthFirst(const Neighborhoods& geometry, std::vector<std::uint32_t>& queue, Decide&& decide,
  SerialAbortCheck* stop = nullptr)
{
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    if (stop && stop->Stop())
    {
      return false;
    }
    if (geometry.IsTruncated(queue[head]))
    {
      continue;
    }
    const std::uint32_t* ids = geometry.NeighborsOf(queue[head]);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      const Visit visit = decide(ids[m]);
      if (visit == Visit::Stop)
      {
        return false;
      }
      if (visit == Visit::Enqueue)
      {
        queue.push_back(ids[m]);
      }
    }
  }
  return true;
}

/// Builds everything from the points. Returns false only when aborted.
bool BuildNeighborhoods(
  vtkPoints* points, int numberOfNeighbors, Neighborhoods& out, const AbortCheck& aborted);

} // namespace lsi

#endif
