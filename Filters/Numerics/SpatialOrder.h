// Morton (Z-order) keys: sorting samples by them puts samples that are close in space close in
// memory, so that neighbour queries and the per-sample loops over neighbours hit the cache.
// Plain C++; the sort itself is done by the caller (in parallel).
#ifndef SpatialOrder_h
#define SpatialOrder_h

#include <algorithm>
#include <cstdint>

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

} // namespace lsi

#endif
