// Morton (Z-order) keys: sorting samples by them puts samples that are close in space close in
// memory, so that neighbour queries and the per-sample loops over neighbours hit the cache.
// Plain C++.
#ifndef SpatialOrder_h
#define SpatialOrder_h

#include <algorithm>
#include <cstdint>
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

/// Sorts (key, id) pairs by key, stably, with a least-significant-digit radix sort on 16-bit
/// digits (four passes for 63-bit keys): linear time, several times faster than std::sort on
/// tens of millions of keys. `scratch` is resized to the same length.
template <typename Id>
void RadixSortByKey(std::vector<std::pair<std::uint64_t, Id>>& items,
  std::vector<std::pair<std::uint64_t, Id>>& scratch)
{
  scratch.resize(items.size());
  std::vector<std::size_t> offsets(1 << 16);
  for (int shift = 0; shift < 64; shift += 16)
  {
    std::fill(offsets.begin(), offsets.end(), 0);
    for (const auto& item : items)
    {
      ++offsets[(item.first >> shift) & 0xffff];
    }
    std::size_t total = 0;
    for (std::size_t& offset : offsets)
    {
      const std::size_t count = offset;
      offset = total;
      total += count;
    }
    for (const auto& item : items)
    {
      scratch[offsets[(item.first >> shift) & 0xffff]++] = item;
    }
    items.swap(scratch);
  }
}

} // namespace lsi

#endif
