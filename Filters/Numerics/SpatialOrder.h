// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Morton (Z-order) keys: sorting samples by them puts samples that are close in space close in
// memory, so that neighbour queries and the per-sample loops over neighbours hit the cache.
// Plain C++.
#ifndef SpatialOrder_h
#define SpatialOrder_h

#include "TaskRunner.h"
#include "UninitializedVector.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace lsi
{

/// Spreads the low 21 bits of v so that there are two zero bits between consecutive bits.
inline std::uint64_t SpreadBits21(std::uint64_t v)
{
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffffULL;
  v = (v | v << 16) & 0x1f0000ff0000ffULL;
  v = (v | v << 8) & 0x100f00f00f00f00fULL;
  v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
  v = (v | v << 2) & 0x1249249249249249ULL;
  return v;
}

/// The 63-bit Morton key of x in the box [lower, lower + size] (size > 0 on every axis;
/// points outside are clamped to the box).
inline std::uint64_t MortonKey(const double x[3], const double lower[3], const double size[3])
{
  std::uint64_t key = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double t = std::min(1.0, std::max(0.0, (x[k] - lower[k]) / size[k]));
    const std::uint64_t cell = static_cast<std::uint64_t>(t * 2097151.0); // 2^21 - 1
    key |= SpreadBits21(cell) << k;
  }
  return key;
}

/// A sample's place in Morton order and its id in one word: the top 30 bits of its Morton key
/// (1024 cells per axis) above the 32-bit id. Sorting the words sorts samples into Morton order
/// at that resolution, which is all the later kd-tree build needs from it.
inline std::uint64_t PackedMortonKey(
  const double x[3], const double lower[3], const double size[3], std::uint32_t id)
{
  return (MortonKey(x, lower, size) >> 33) << 32 | id;
}

/// Sorts words made by PackedMortonKey: a least-significant-digit radix sort over the key bits
/// (three passes of 10-bit digits; 1024 buckets keep each pass's writes in cache). Stable, so
/// ids given in increasing order stay so within a cell and the words end fully sorted.
/// `scratch` is resized to the same length (Words: a std::vector of std::uint64_t, with any
/// allocator). Each pass counts, then scatters, `chunks` contiguous
/// pieces of the words as tasks given to `run` (which may run them at once). Each piece's words
/// go after the previous pieces' words of the same digit, so the result is the same for any
/// number of pieces.
template <typename Words>
void RadixSortPacked(
  Words& words, Words& scratch, std::size_t chunks = 1, const TaskRunner& run = RunInTurn)
{
  constexpr std::size_t Buckets = 1 << 10;
  const std::size_t n = words.size();
  scratch.reserve(n);
  AdviseHugePages(scratch);
  scratch.resize(n);
  chunks = std::max<std::size_t>(1, std::min(chunks, n / 4096 + 1)); // >= 4096 words each
  auto bound = [&](std::size_t c) { return n * c / chunks; };
  std::vector<std::size_t> offsets(chunks * Buckets); // [chunk][digit]
  auto forEachChunk = [&](const std::function<void(std::size_t)>& body) {
    std::vector<std::function<void()>> tasks;
    for (std::size_t c = 0; c < chunks; ++c)
    {
      tasks.push_back([&body, c]() { body(c); });
    }
    run(tasks);
  };
  for (int shift = 32; shift < 62; shift += 10)
  {
    forEachChunk([&](std::size_t c) {
      std::size_t* count = &offsets[c * Buckets];
      std::fill(count, count + Buckets, 0);
      for (std::size_t i = bound(c); i < bound(c + 1); ++i)
      {
        ++count[(words[i] >> shift) & 0x3ff];
      }
    });
    std::size_t total = 0; // digit by digit, and within a digit piece by piece
    for (std::size_t digit = 0; digit < Buckets; ++digit)
    {
      for (std::size_t c = 0; c < chunks; ++c)
      {
        std::size_t& offset = offsets[c * Buckets + digit];
        const std::size_t count = offset;
        offset = total;
        total += count;
      }
    }
    forEachChunk([&](std::size_t c) {
      std::size_t* offset = &offsets[c * Buckets];
      for (std::size_t i = bound(c); i < bound(c + 1); ++i)
      {
        scratch[offset[(words[i] >> shift) & 0x3ff]++] = words[i];
      }
    });
    words.swap(scratch);
  }
}

} // namespace lsi

#endif
