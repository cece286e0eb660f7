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

/// A grain for vtkSMPTools::For over `count` items of uneven cost: 32 pieces per thread, so that a
/// thread left without work at the end waits for at most a thirty-second of its share
/// (vtkSMPTools' own grain makes 4 pieces per thread); but at least `minimum` items per piece,
/// as many as cost about what handing out a piece does (a few microseconds): fewer items than
/// that run on the calling thread.
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
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
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
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
    std::fill(values.begin() + begin, values.begin() + end, value);
  });
  return values;
}

/// The indices i < count for which keep(i) holds, in increasing order: found in fixed chunks
/// in parallel and joined in order (for scans over every sample, several per run).
template <typename Index, typename Keep>
std::vector<Index> IndicesWhere(std::size_t count, Keep&& keep)
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
  std::vector<Index> all;
  for (const std::vector<Index>& part : found)
  {
    all.insert(all.end(), part.begin(), part.end());
  }
  return all;
}

/// Sorts [first, last) by `less`, a strict total order (so the result is the same as
/// std::sort's on any number of threads): pieces sorted in parallel, then merged pairwise
/// (vtkSMPTools::Sort is serial with the STDThread backend).
template <typename Iterator, typename Less>
void ParallelSort(Iterator first, Iterator last, Less less)
{
  const std::ptrdiff_t count = last - first;
  const std::ptrdiff_t pieces = std::max<std::ptrdiff_t>(
    1, std::min<std::ptrdiff_t>(vtkSMPTools::GetEstimatedNumberOfThreads(), count / 16384));
  if (pieces == 1)
  {
    std::sort(first, last, less);
    return;
  }
  auto bound = [&](std::ptrdiff_t piece) { return first + count * piece / pieces; };
  vtkSMPTools::For(0, static_cast<vtkIdType>(pieces), 1, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType piece = begin; piece < end; ++piece)
    {
      std::sort(bound(piece), bound(piece + 1), less);
    }
  });
  for (std::ptrdiff_t width = 1; width < pieces; width *= 2)
  {
    for (std::ptrdiff_t piece = 0; piece + width < pieces; piece += 2 * width)
    {
      std::inplace_merge(
        bound(piece), bound(piece + width), bound(std::min(piece + 2 * width, pieces)), less);
    }
  }
}

} // namespace lsi

#endif
