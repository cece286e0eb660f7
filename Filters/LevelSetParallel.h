// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Parallel loops in blocks, so that the calling (main) thread can check for abort between
// blocks: vtkSMPTools workers never call UpdateProgress or CheckAbort themselves.
#ifndef LevelSetParallel_h
#define LevelSetParallel_h

#include "UninitializedVector.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <functional>
#include <iterator>
#include <memory>
#include <vector>

namespace lsi
{

/// Called between blocks of work with the fraction of the current loop done (negative when
/// unknown), so that the caller can report progress; returns true when the caller asked to stop.
using AbortCheck = std::function<bool(double done)>;

inline bool Aborted(const AbortCheck& aborted, double done = -1.0)
{
  return aborted && aborted(done);
}

/// The part [from, to] of a stage whose progress `aborted` reports over [0, 1].
inline AbortCheck SubRange(const AbortCheck& aborted, double from, double to)
{
  return [aborted, from, to](double done) {
    return Aborted(aborted, done >= 0.0 ? from + (to - from) * done : -1.0);
  };
}

/// For serial loops: Stop() asks `aborted` once every `period` calls, and stays true once it
/// said yes.
class SerialAbortCheck
{
public:
  explicit SerialAbortCheck(const AbortCheck& aborted, std::size_t period = 65536)
    : Check(aborted)
    , Period(period)
  {
  }
  bool Stop()
  {
    if (!this->Stopped && ++this->Calls % this->Period == 0)
    {
      this->Stopped = Aborted(this->Check);
    }
    return this->Stopped;
  }
  bool WasStopped() const { return this->Stopped; }

private:
  const AbortCheck& Check;
  std::size_t Period;
  std::size_t Calls = 0;
  bool Stopped = false;
};

/// A grain for vtkSMPTools::For over `count` items: 32 pieces per thread, so that a thread left
/// without work at the end waits for at most a thirty-second of its share (vtkSMPTools' own
/// grain makes 4 pieces per thread: on two threads here, loops of 1-30 ms then left 10-20% of
/// their cores idle at their ends, about 0.1 s per run at 2M samples); but at least `minimum`
/// items per piece, as many as cost about what handing out a piece does (a few microseconds):
/// fewer items than that run on the calling thread, without starting the pool. Every loop over
/// samples takes one: 16384 for cheap bodies, 1024 for those that read neighbours.
inline vtkIdType BalancedGrain(std::size_t count, std::size_t minimum)
{
  const std::size_t pieces =
    32 * static_cast<std::size_t>(vtkSMPTools::GetEstimatedNumberOfThreads());
  return static_cast<vtkIdType>(
    std::max<std::size_t>(std::max<std::size_t>(1, minimum), count / pieces));
}

/// Runs body(begin, end) over [0, count) with vtkSMPTools::For, in blocks of `block` items.
/// Returns false if `aborted()` said so between two blocks.
template <typename Body>
bool ParallelForInBlocks(
  std::size_t count, Body&& body, const AbortCheck& aborted, std::size_t block = 65536)
{
  for (std::size_t start = 0; start < count; start += block)
  {
    if (Aborted(aborted, static_cast<double>(start) / static_cast<double>(count)))
    {
      return false;
    }
    const std::size_t stop = std::min(count, start + block);
    vtkSMPTools::For(static_cast<vtkIdType>(start), static_cast<vtkIdType>(stop),
      BalancedGrain(stop - start, 8), [&](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
  }
  return true;
}

/// `count` atomics set to `value` in parallel: marks that several threads may set at once.
template <typename T>
std::unique_ptr<std::atomic<T>[]> FilledAtomics(std::size_t count, T value) {
  std::unique_ptr<std::atomic<T>[]> marks(new std::atomic<T>[count]);
  AdviseHugePages(marks.get(), sizeof(std::atomic<T>) * count);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        marks[i].store(value, std::memory_order_relaxed);
      }
    });
  return marks;
}

/// `count` copies of `value`, written in parallel: the first write to fresh memory faults its
/// pages in, which then happens on every thread at once (UninitializedVector.h).
template <typename T>
UninitializedVector<T> FilledInParallel(std::size_t count, T value)
{
  UninitializedVector<T> values(count);
  AdviseHugePages(values);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 16384),
    [&](vtkIdType begin, vtkIdType end) {
      std::fill(values.begin() + begin, values.begin() + end, value);
    });
  return values;
}

/// ResizeMapped (UninitializedVector.h) with the new storage's pages mapped by every thread at
/// once, 2 MB each: the kernel zeroes each page it maps, and on a virtual machine here that is
/// most of the cost. For the per-sample arrays that stay std::vector (whose resize then writes
/// every value on one thread, into mapped pages).
template <typename Vector>
void ResizeMappedInParallel(
  Vector& values, std::size_t count, const typename Vector::value_type& value = {})
{
  // (Only new storage: a vector's own beyond its size was written when it was longer.)
  if (count > values.capacity())
  {
    values.reserve(count);
    char* begin = reinterpret_cast<char*>(values.data() + values.size());
    const std::size_t bytes = (count - values.size()) * sizeof(typename Vector::value_type);
    AdviseHugePages(begin, bytes);
    constexpr std::size_t Piece = std::size_t(1) << 21;
    const std::size_t pieces = (bytes + Piece - 1) / Piece;
    vtkSMPTools::For(0, static_cast<vtkIdType>(pieces), 1, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType p = first; p < last; ++p)
      {
        const std::size_t offset = static_cast<std::size_t>(p) * Piece;
        MapPagesNow(begin + offset, std::min(Piece, bytes - offset));
      }
    });
  }
  values.resize(count, value);
}

/// Copies `count` values from `from` to `to`, in parallel pieces.
template <typename From, typename To>
void CopyInParallel(From from, std::size_t count, To to)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 16384),
    [&](vtkIdType begin, vtkIdType end) { std::copy(from + begin, from + end, to + begin); });
}

/// A copy of `values`, written in parallel (its pages fault in on every thread at once).
template <typename T, typename Allocator>
UninitializedVector<T> CopiedInParallel(const std::vector<T, Allocator>& values)
{
  UninitializedVector<T> copy(values.size());
  AdviseHugePages(copy);
  CopyInParallel(values.begin(), values.size(), copy.begin());
  return copy;
}

/// to = from, with to's new pages mapped and the values copied by every thread at once.
template <typename T>
void AssignInParallel(std::vector<T>& to, const std::vector<T>& from)
{
  to.clear();
  ResizeMappedInParallel(to, from.size());
  CopyInParallel(from.begin(), from.size(), to.begin());
}

/// The total size of `parts`, joined in order.
template <typename T>
std::size_t JoinedSize(const std::vector<std::vector<T>>& parts)
{
  std::size_t total = 0;
  for (const std::vector<T>& part : parts)
  {
    total += part.size();
  }
  return total;
}

/// Copies `parts`, joined in order, to `out` (JoinedSize values): each part to its place by
/// whichever thread takes it; a short join on this thread (handing out the copies would cost
/// more).
template <typename T, typename Out>
void JoinInParallel(const std::vector<std::vector<T>>& parts, Out out)
{
  std::vector<std::size_t> offsets(parts.size() + 1, 0);
  for (std::size_t p = 0; p < parts.size(); ++p)
  {
    offsets[p + 1] = offsets[p] + parts[p].size();
  }
  constexpr std::size_t ParallelFrom = std::size_t(1) << 16;
  vtkSMPTools::For(0, static_cast<vtkIdType>(parts.size()),
    offsets.back() < ParallelFrom ? std::max<vtkIdType>(1, static_cast<vtkIdType>(parts.size()))
                                  : 1,
    [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType p = first; p < last; ++p)
      {
        std::copy(parts[p].begin(), parts[p].end(), out + offsets[p]);
      }
    });
}

/// The indices i < count for which keep(i) holds, in increasing order, into `out`: found in fixed
/// chunks in parallel and copied to their places in parallel (for scans over every sample,
/// several per run). `out`'s storage is reused: the band's lists, found anew each iteration,
/// then write to pages already mapped (fresh pages cost more than the copy, UninitializedVector.h).
template <typename Index, typename Keep>
void IndicesWhere(std::size_t count, Keep&& keep, std::vector<Index>& out)
{
  constexpr std::size_t Chunk = 1 << 16;
  const std::size_t chunks = (count + Chunk - 1) / Chunk;
  std::vector<std::vector<Index>> found(chunks);
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), 1, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType c = first; c < last; ++c)
    {
      const std::size_t end = std::min(count, (static_cast<std::size_t>(c) + 1) * Chunk);
      for (std::size_t i = static_cast<std::size_t>(c) * Chunk; i < end; ++i)
      {
        if (keep(i))
        {
          found[c].push_back(static_cast<Index>(i));
        }
      }
    }
  });
  ResizeMappedInParallel(out, JoinedSize(found));
  JoinInParallel(found, out.begin());
}

/// The same, as a new vector.
template <typename Index, typename Keep>
std::vector<Index> IndicesWhere(std::size_t count, Keep&& keep)
{
  std::vector<Index> all;
  IndicesWhere(count, keep, all);
  return all;
}

/// The number of elements of sorted `a` (size na) among the first `d` of its merge with sorted
/// `b` (size nb), ties to `a` as std::merge does: where a part of a parallel merge starts.
template <typename Iterator, typename Less>
std::ptrdiff_t MergeSplit(
  Iterator a, std::ptrdiff_t na, Iterator b, std::ptrdiff_t nb, std::ptrdiff_t d, Less& less)
{
  std::ptrdiff_t low = std::max<std::ptrdiff_t>(0, d - nb), high = std::min(d, na);
  while (low < high)
  {
    const std::ptrdiff_t middle = low + (high - low) / 2;
    if (less(*(b + (d - middle - 1)), *(a + middle)))
    {
      high = middle;
    }
    else
    {
      low = middle + 1;
    }
  }
  return low;
}

/// Sorts [first, last) by `less`, a strict total order (so the result is the same as
/// std::sort's on any number of threads): pieces sorted in parallel, then merged pairwise, each
/// merge cut into parts that the threads write at once (vtkSMPTools::Sort is serial with the
/// STDThread backend; a serial merge of two halves would leave a core idle for a pass).
template <typename Iterator, typename Less>
void ParallelSort(Iterator first, Iterator last, Less less)
{
  const std::ptrdiff_t count = last - first;
  const std::ptrdiff_t threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  const std::ptrdiff_t pieces =
    std::max<std::ptrdiff_t>(1, std::min<std::ptrdiff_t>(threads, count / 16384));
  if (pieces == 1)
  {
    std::sort(first, last, less);
    return;
  }
  auto bound = [&](std::ptrdiff_t piece) { return count * piece / pieces; };
  vtkSMPTools::For(0, static_cast<vtkIdType>(pieces), 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType piece = begin; piece < end; ++piece)
    {
      std::sort(first + bound(piece), first + bound(piece + 1), less);
    }
  });
  using Value = typename std::iterator_traits<Iterator>::value_type;
  UninitializedVector<Value> merged(static_cast<std::size_t>(count));
  const std::ptrdiff_t parts = 4 * threads; // per merge
  for (std::ptrdiff_t width = 1; width < pieces; width *= 2)
  {
    // Every pair of runs at this width (a run without partner is copied), each cut into `parts`.
    const std::ptrdiff_t pairs = (pieces + 2 * width - 1) / (2 * width);
    vtkSMPTools::For(
      0, static_cast<vtkIdType>(pairs * parts), 1, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType task = begin; task < end; ++task)
        {
          const std::ptrdiff_t pair = task / parts, part = task % parts;
          const std::ptrdiff_t from = bound(2 * width * pair);
          const std::ptrdiff_t middle = bound(std::min(2 * width * pair + width, pieces));
          const std::ptrdiff_t to = bound(std::min(2 * width * (pair + 1), pieces));
          const std::ptrdiff_t na = middle - from, nb = to - middle;
          const std::ptrdiff_t d0 = (na + nb) * part / parts, d1 = (na + nb) * (part + 1) / parts;
          const std::ptrdiff_t a0 = MergeSplit(first + from, na, first + middle, nb, d0, less);
          const std::ptrdiff_t a1 = MergeSplit(first + from, na, first + middle, nb, d1, less);
          std::merge(first + from + a0, first + from + a1, first + middle + (d0 - a0),
            first + middle + (d1 - a1), merged.begin() + (from + d0), less);
        }
      });
    CopyInParallel(merged.begin(), static_cast<std::size_t>(count), first);
  }
}

} // namespace lsi

#endif
