// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The geometry of the sample cloud that the evolution reuses at every iteration and across
// re-executions: each sample's n nearest neighbours, its neighbourhood radius h_i, and the MLS
// gradient stencil (which depends only on positions). Built once per input geometry.
#ifndef LevelSetNeighborhoods_h
#define LevelSetNeighborhoods_h

#include "LevelSetCommunicator.h"
#include "LevelSetParallel.h"
#include "MovingLeastSquares.h"
#include "NearestNeighbors.h"
#include "UninitializedVector.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

class vtkPoints;

namespace lsi
{

/// The geometry of the sample cloud. Neighbour lists are computed when first asked for
/// (NeighborsOf, RadiusOf), from any thread: the method only ever visits the seeded
/// components and a band around their front, a few percent of a large snapshot's particles,
/// so most lists are never needed. A list does not depend on when it is computed, so neither
/// does any result. Call EnsureNeighbors on a large set before a serial loop over it: it
/// computes the missing lists in parallel.
struct Neighborhoods
{
  std::size_t NumberOfSamples = 0;
  int Stride = 0; // entries per sample: the sample itself (slot 0) and its n neighbours

  // Samples are stored in the kd-tree's leaf order (after a Morton sort, SpatialOrder.h), so
  // that neighbours are near in memory.
  // Every index below is an index in that order; Order maps it back to the input point id.
  // Both are filled in parallel (UninitializedVector.h).
  UninitializedVector<std::uint32_t> Order;
  UninitializedVector<double> Positions; // 3 per sample
  std::unique_ptr<PointCloudIndex> Index;

  // MLS gradient stencils, 3 * Stride floats each, computed on demand (EnsureStencils): the
  // evolution only ever visits a band around the front, so most samples never need one. Each
  // computed stencil takes the next free slot (StencilSlot[i]), so the written part of the
  // storage is one dense prefix, in 2 MB pages where the kernel grants them: a few dozen page
  // faults instead of one per 4 KB of the band's scattered samples (the slots' order depends
  // on the threads, the stencils do not). The storage is allocated for every sample but not
  // initialised, so its unwritten part costs no memory.
  // Each is stored times the sample's radius h_i, so its coefficients are of order one in any
  // unit of length (a stencil goes as 1 / h_i, which float would overflow or flush to zero for
  // lengths beyond about 1e+-30); GradientAt and DivergenceAt divide h_i back out in double.
  mutable std::unique_ptr<float[]> GradientStencil;
  mutable UninitializedVector<std::uint32_t> StencilSlot;    // valid where StencilState is not 0
  std::unique_ptr<std::atomic<std::size_t>> NextStencilSlot; // (a pointer: the struct moves)
  // 0: not computed, 1: ready, 2: singular; computed ahead (PrecomputeStencils) and not yet
  // asked for: 3 ready, 4 singular, 5 ready and thin (counted when first asked for).
  mutable std::vector<unsigned char> StencilState;
  mutable std::size_t ComputedStencils = 0;

  // Mean h_i over up to MeanRadiusSearches of the fixed sample of the samples (InRadiusSample):
  // a scale for the checks of the data's units, not a parameter of the method.
  double MeanRadius = 0.0;

  // Which build this is: unique per build in the process (NeighborCache), so that what was
  // computed on these samples is recognised as theirs (0: not numbered).
  std::uint64_t BuildNumber = 0;

  // Seconds spent on each part of the build.
  double SortSeconds = 0.0, SearchSeconds = 0.0; // SearchSeconds includes TreeSeconds
  double TreeSeconds = 0.0;
  mutable double StencilSeconds = 0.0; // accumulated over EnsureStencils calls

  // Problems found while building (sample ids are input point ids); the filter turns them into
  // error messages.
  std::size_t DuplicateSamples = 0; // samples at exactly the position of another one
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

  /// The sample itself (slot 0) and its Stride - 1 nearest neighbours.
  const std::uint32_t* NeighborsOf(std::size_t i) const
  {
    this->EnsureRow(i);
    return &this->Ids[this->Rows->Slot[i] * static_cast<std::size_t>(this->Stride)];
  }
  /// Hints to the processor for a loop that knows which lists it reads next (a walk's queue):
  /// fetch where sample i's list lies, then, a few samples later, the list itself (if it has
  /// been computed). They change no result.
  void PrefetchPlace(std::size_t i) const
  {
    __builtin_prefetch(&this->Rows->State[i]);
    __builtin_prefetch(&this->Rows->Slot[i]);
  }
  void PrefetchList(std::size_t i) const
  {
    if (this->Rows->State[i].load(std::memory_order_relaxed) == 2)
    {
      const std::uint32_t* list =
        &this->Ids[this->Rows->Slot[i] * static_cast<std::size_t>(this->Stride)];
      __builtin_prefetch(list);
      __builtin_prefetch(list + this->Stride - 1);
    }
  }
  /// h_i: the distance to the farthest of the neighbours.
  double RadiusOf(std::size_t i) const
  {
    this->EnsureRow(i);
    return this->Radii[this->Rows->Slot[i]];
  }
  /// Computes the lists that `samples` (count indices) still lack, in parallel. Call from the
  /// main thread between parallel loops.
  template <typename Id>
  void EnsureNeighbors(const Id* samples, std::size_t count) const;
  template <typename Id>
  void EnsureNeighbors(const std::vector<Id>& samples) const
  {
    this->EnsureNeighbors(samples.data(), samples.size());
  }
  /// Computes every missing list, in parallel; false if `aborted` said to stop.
  bool EnsureAllNeighbors(const AbortCheck& aborted = AbortCheck()) const;
  /// How many lists have been computed so far.
  std::size_t ComputedNeighborLists() const { return this->Rows ? this->Rows->Computed.load() : 0; }

  bool IsTruncated(std::size_t i) const { return !this->Truncated.empty() && this->Truncated[i]; }
  /// Computes the stencils that `samples` (count indices, no repeats) still lack, in parallel.
  /// Call from the main thread between parallel loops.
  void EnsureStencils(const std::size_t* samples, std::size_t count) const;
  void EnsureStencils(const std::vector<std::size_t>& samples) const
  {
    this->EnsureStencils(samples.data(), samples.size());
  }
  /// Computes the missing stencils of `samples` one after another on the calling thread, until
  /// `stop` is set: for a helper thread to fill the cache while the main thread runs a serial
  /// loop that reads no stencil (the flood's distance propagation). Nothing else may compute
  /// stencils meanwhile. They count (ComputedStencils, SingularSamples, ThinSamples) only once
  /// EnsureStencils asks for them, so the counts do not depend on the number of threads.
  void PrecomputeStencils(
    const std::uint32_t* samples, std::size_t count, const std::atomic<bool>& stop) const;

  /// The MLS gradient at sample i of value(m), the values at its neighbours m = 0 .. Stride - 1
  /// (slot 0 is i itself). Its stencil must be computed (EnsureStencils).
  template <typename ValueFn>
  Eigen::Vector3d GradientAt(std::size_t i, ValueFn&& value) const
  {
    const double h = this->Radii[this->Rows->Slot[i]]; // 0 only where the stencil is singular
    if (!(h > 0.0))
    {
      return Eigen::Vector3d::Zero();
    }
    const std::size_t count = static_cast<std::size_t>(this->Stride);
    return ApplyGradientStencil(this->ScaledStencilOf(i), count, value) / h;
  }
  /// The divergence at sample i of vector(m), given at its neighbours like GradientAt's values.
  template <typename VectorFn>
  double DivergenceAt(std::size_t i, VectorFn&& vector) const
  {
    const double h = this->Radii[this->Rows->Slot[i]];
    if (!(h > 0.0))
    {
      return 0.0;
    }
    const std::size_t count = static_cast<std::size_t>(this->Stride);
    return ApplyDivergenceStencil(this->ScaledStencilOf(i), count, vector) / h;
  }
  const double* Position(std::size_t i) const { return &this->Positions[3 * i]; }

  /// Whether sample i belongs to the deterministic sample of about 1 in `every` samples used for
  /// global scales: chosen by a hash of its coordinates, so the same particles are chosen
  /// whatever their order, storage, precision (float or double) or MPI rank.
  bool InRadiusSample(std::size_t i, std::uint64_t every) const;
  /// The hash of sample i's coordinates (as single precision) that InRadiusSample takes: the
  /// same for the same particle on any rank, in any order. Its high bits pick a sub-sample.
  std::uint64_t PositionHash(std::size_t i) const;
  /// The samples of that sample for which keep(i) holds, in storage order. The sample itself
  /// is chosen once per `every` (a parallel pass over all samples) and kept: a run asks for it
  /// several times (the build, the surface's scale, the SPH support ratio). Main thread only.
  template <typename Keep>
  std::vector<std::uint32_t> RadiusSampleWhere(std::uint64_t every, Keep&& keep) const
  {
    if (this->SampleEvery != every)
    {
      IndicesWhere<std::uint32_t>(
        this->NumberOfSamples, [&](std::size_t i) { return this->InRadiusSample(i, every); },
        this->Sample);
      this->SampleEvery = every;
    }
    std::vector<std::uint32_t> sample;
    for (const std::uint32_t i : this->Sample)
    {
      if (keep(static_cast<std::size_t>(i)))
      {
        sample.push_back(i);
      }
    }
    return sample;
  }
  /// The list and radius of sample i of the fixed sample that RadiusSampleWhere chose last: its
  /// main list (NeighborsOf, RadiusOf), computed with the sample's others on first use
  /// (EnsureFixedSampleRows), where the method's later stages find those they visit (the
  /// lists take dense slots, so a sample spread over all samples costs no more memory than
  /// they do). Main thread only, except once they are computed.
  struct SampleRow
  {
    const std::uint32_t* Ids;
    double Radius;
  };
  SampleRow FixedSampleRow(std::size_t i) const;
  /// Computes the fixed sample's lists, in parallel, unless they are already (main thread only).
  void EnsureFixedSampleRows() const;

  // The lists' storage, allocated for every sample but not initialised: untouched pages cost
  // no memory. Each computed list takes the next free slot (Slot, valid where State is 2), so
  // the written part is one dense prefix, in 2 MB pages where the kernel grants them (as the
  // stencils). RowState: 0 not computed, 1 being computed, 2 ready.
  struct RowStates
  {
    explicit RowStates(std::size_t n)
      : State(FilledAtomics<unsigned char>(n, 0)) // (in parallel: 20 MB at 20M samples)
      , Slot(new std::uint32_t[n])
    {
    }
    std::unique_ptr<std::atomic<unsigned char>[]> State;
    std::unique_ptr<std::uint32_t[]> Slot;
    std::atomic<std::size_t> Computed{ 0 }; // lists computed or being computed: the next slot
  };
  mutable UninitializedVector<std::uint32_t> Ids; // Stride per slot
  mutable UninitializedVector<double> Radii;      // per slot
  std::unique_ptr<RowStates> Rows;
  // The last fixed sample RadiusSampleWhere chose, and its `every` (0: none yet).
  mutable std::vector<std::uint32_t> Sample;
  mutable std::uint64_t SampleEvery = 0;
  // The `every` of the fixed sample whose lists are computed (EnsureFixedSampleRows).
  mutable std::uint64_t SampleRowsEvery = 0;

  /// Sample i's list into `ids` (Stride entries), not kept; returns its radius.
  /// `nearbyRadius`: the radius of a sample nearby (0 if none), which bounds the search first.
  double SearchRow(std::size_t i, double nearbyRadius, std::uint32_t* ids) const;

private:
  const float* ScaledStencilOf(std::size_t i) const
  {
    return &this->GradientStencil[3 * std::size_t(this->StencilSlot[i]) * this->Stride];
  }
  /// Sample i's stencil into the cache at `slot` (`scratch`: 3 * Stride doubles); whether it is
  /// regular, and whether its neighbourhood is thin.
  bool ComputeStencil(
    std::size_t i, std::size_t slot, std::vector<double>& scratch, bool& thin) const;
  void EnsureRow(std::size_t i) const
  {
    if (this->Rows->State[i].load(std::memory_order_acquire) != 2)
    {
      this->ComputeRow(i);
    }
  }
  /// Sample i's list, computed here unless another thread is computing it (then waited for).
  void ComputeRow(std::size_t i) const;
  /// Lists computed together by ComputeRun: near each other in storage order, each search
  /// bounded first by the radius of the one before it.
  static constexpr std::size_t RowRun = 64;
  /// The lists of `count` (at most RowRun) samples near each other not yet computed, in
  /// consecutive slots; returns when all of them are ready (some may be another thread's).
  void ComputeRun(const std::size_t* samples, std::size_t count) const;
};

/// About how many samples the global scales are taken over (Neighborhoods::InRadiusSample):
/// every sample up to twice as many, about this many beyond.
constexpr std::size_t RadiusSampleSize = 65536;
inline std::uint64_t RadiusSampleEvery(double samples)
{
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(samples / RadiusSampleSize));
}
/// How many of the fixed sample's samples Neighborhoods::MeanRadius is taken over.
constexpr std::size_t MeanRadiusSearches = 2048;

/// Samples per list computed in one parallel batch below which a serial loop computes them
/// as it goes (a parallel loop's start costs more than a few searches).
constexpr std::size_t SerialNeighborSearches = 256;

template <typename Id>
void Neighborhoods::EnsureNeighbors(const Id* samples, std::size_t count) const
{
  if (count < SerialNeighborSearches)
  {
    return; // computed when asked for
  }
  // In storage (spatial) order: consecutive searches then walk the same part of the tree.
  std::vector<std::size_t> missing;
  for (std::size_t k = 0; k < count; ++k)
  {
    const std::size_t i = static_cast<std::size_t>(samples[k]);
    if (this->Rows->State[i].load(std::memory_order_relaxed) != 2)
    {
      missing.push_back(i);
    }
  }
  ParallelSort(missing.begin(), missing.end(), std::less<std::size_t>());
  // In runs of RowRun, each search bounded first by the radius of the one before it (its spatial
  // neighbour): the lists are exact either way, the bound only prunes the tree walk.
  constexpr std::size_t Run = RowRun;
  const std::size_t runs = (missing.size() + Run - 1) / Run;
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(runs), BalancedGrain(runs, 1), [&](vtkIdType first, vtkIdType last) {
      for (std::size_t r = static_cast<std::size_t>(first); r < static_cast<std::size_t>(last); ++r)
      {
        const std::size_t begin = r * Run;
        this->ComputeRun(&missing[begin], std::min(missing.size(), begin + Run) - begin);
      }
    });
}

/// What a breadth-first search over the neighbour graph does with a neighbour it meets.
enum class Visit
{
  Skip,    // leave it
  Enqueue, // append it to the queue (the decision marks it, so it is not met again)
  Stop     // end the search
};

/// `decide(j, from)` where it takes both, else `decide(j)` (overloads, not `if constexpr`: the
/// fuzz targets' clang builds C++14).
template <typename Decide>
auto DecideVisit(Decide& decide, std::uint32_t j, std::uint32_t from, int)
  -> decltype(decide(j, from))
{
  return decide(j, from);
}
template <typename Decide>
auto DecideVisit(Decide& decide, std::uint32_t j, std::uint32_t, long) -> decltype(decide(j))
{
  return decide(j);
}

/// Breadth-first search over the neighbour graph: for each sample of `queue` in turn (the
/// starting samples first, then those appended), `decide(j)` for each of its neighbours j (or
/// `decide(j, from)`, from the sample whose list holds j, when it takes both).
/// Returns false when `decide` stopped it or `stop` said to abort.
template <typename Decide>
bool BreadthFirst(const Neighborhoods& geometry, std::vector<std::uint32_t>& queue, Decide&& decide,
  SerialAbortCheck* stop = nullptr)
{
  std::size_t searched = 0; // the queue's lists computed up to here, a wave at a time
  for (std::size_t head = 0; head < queue.size(); ++head)
  {
    if (stop && stop->Stop())
    {
      return false;
    }
    if (head == searched)
    {
      geometry.EnsureNeighbors(&queue[head], queue.size() - head);
      searched = queue.size();
    }
    // The lists of the samples a little further in the queue, fetched meanwhile: the walk
    // jumps about the cloud (a quick change's flood: 7.1 ms before, 5.7-6.2 ms with this).
    constexpr std::size_t Ahead = 8;
    if (head + 2 * Ahead < queue.size())
    {
      geometry.PrefetchPlace(queue[head + 2 * Ahead]);
    }
    if (head + Ahead < queue.size())
    {
      geometry.PrefetchList(queue[head + Ahead]);
    }
    if (geometry.IsTruncated(queue[head]))
    {
      continue;
    }
    const std::uint32_t from = queue[head];
    const std::uint32_t* ids = geometry.NeighborsOf(from);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      const Visit visit = DecideVisit(decide, ids[m], from, 0);
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

/// The points' bounds (xmin, xmax, ymin, ...), scanned in parallel (vtkPoints::GetBounds scans
/// in one thread, about 0.03 s at 2M points).
void PointBounds(vtkPoints* points, double bounds[6]);

/// Builds everything from the points. Returns false only when aborted.
bool BuildNeighborhoods(
  vtkPoints* points, int numberOfNeighbors, Neighborhoods& out, const AbortCheck& aborted);

/// Whether this rank owns the sample nearest to `point`: of a piece of surface that several
/// ranks found, the rank that owns the nearest sample keeps it (always, in one process).
inline bool OwnsNearestSample(
  const Neighborhoods& geometry, const Communicator& ranks, const double point[3])
{
  std::uint32_t nearest = 0;
  double d2 = 0.0;
  return geometry.Index->Nearest(point, 1, &nearest, &d2) == 1 && ranks.Owns(nearest);
}

} // namespace lsi

#endif
