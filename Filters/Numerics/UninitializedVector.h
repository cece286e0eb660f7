// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Per-sample arrays and page faults. The first write to fresh memory faults its pages in, and on
// a virtual machine here that costs far more than the writes (Benchmarks/LevelSetPageFaults:
// 16 MB zeroed by resize() in 0.045-0.051 s, the same writes into mapped pages in 0.0006 s);
// done by one thread, it leaves the other cores idle. Two ways around it:
// - UninitializedVector: a std::vector whose resize(n) leaves new elements uninitialised, for
//   arrays that a parallel loop fills (or that are written only near the surface): their pages
//   fault in inside that loop, and pages never written cost neither time nor memory. (A
//   std::vector zeroes new elements in resize(), on one thread.)
// - ResizeMapped: for arrays that stay std::vector<double>, maps the new storage's pages in one
//   call before resize() writes them, at half the cost of faulting them in one by one.
// And where the kernel grants transparent huge pages on request (Debian's default, `madvise`),
// AdviseHugePages asks for 2 MB pages over an array that will be written in full: one fault
// instead of 512 (build/bin/LevelSetPageFaults on a machine here: a fresh 16 MB array took
// 0.046-0.060 s by resize(), 0.006-0.029 s by ResizeMapped, which asks for them, as
// FilledInParallel does).
#ifndef UninitializedVector_h
#define UninitializedVector_h

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lsi
{

/// A std::vector allocator that default-initialises new elements: for numbers, leaves them
/// uninitialised. Copies and explicit values (resize(n, value), assign) are as usual.
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

/// A vector whose resize(n) leaves the new elements uninitialised: every element must be written
/// before it is read.
template <typename T>
using UninitializedVector = std::vector<T, UninitializedAllocator<T>>;

/// Asks the kernel to map the pages inside [begin, begin + bytes) now, in one call (Linux 5.14's
/// MADV_POPULATE_WRITE; elsewhere, or when refused, nothing happens and the writes fault them in
/// as usual). For fresh memory that one thread is about to write: on a virtual machine here
/// (build/bin/LevelSetPageFaults), 16 MB took 0.027 s this way against 0.051 s when resize()
/// faulted each page in; two threads writing a half each took 0.028 s, so an UninitializedVector
/// filled by a parallel loop gains nothing from it.
inline void MapPagesNow(void* begin, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr std::uintptr_t Page = 4096; // whole pages inside the range only
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + Page - 1) & ~(Page - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) & ~(Page - 1);
  if (bytes >= (std::size_t(1) << 20) && last > first)
  {
    madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
  }
#else
  (void)begin;
  (void)bytes;
#endif
}

/// Asks the kernel to back the whole 2 MB blocks inside [begin, begin + bytes) with 2 MB pages
/// (transparent huge pages, madvise mode, Debian's default) before they are first written. Only
/// for arrays written in full, or from the start on (the neighbour lists and stencils fill a
/// dense prefix of their storage, LevelSetNeighborhoods.h): never for arrays written at
/// scattered places, where each 2 MB page touched would become resident whole.
inline void AdviseHugePages(void* begin, std::size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t Huge = std::uintptr_t(1) << 21;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(begin) + Huge - 1) & ~(Huge - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(begin) + bytes) & ~(Huge - 1);
  if (last > first)
  {
    madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#else
  (void)begin;
  (void)bytes;
#endif
}
/// The same over a vector's whole capacity.
template <typename Vector>
void AdviseHugePages(Vector& values)
{
  AdviseHugePages(values.data(), values.capacity() * sizeof(typename Vector::value_type));
}

/// values.resize(count, value), with the pages of new storage mapped first (MapPagesNow): for the
/// per-sample arrays that a std::vector fills on one thread.
template <typename Vector>
void ResizeMapped(Vector& values, std::size_t count, const typename Vector::value_type& value = {})
{
  if (count > values.capacity())
  {
    values.reserve(count);
  }
  if (count > values.size())
  {
    AdviseHugePages(
      values.data() + values.size(), (count - values.size()) * sizeof(typename Vector::value_type));
    MapPagesNow(
      values.data() + values.size(), (count - values.size()) * sizeof(typename Vector::value_type));
  }
  values.resize(count, value);
}

} // namespace lsi

#endif
