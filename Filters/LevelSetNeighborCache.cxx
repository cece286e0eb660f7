// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetNeighborCache.h"

#include "vtkDataArray.h"
#include "vtkPoints.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <type_traits>
#include <vector>

namespace lsi
{

namespace
{
std::uint64_t Mix(std::uint64_t h, std::uint64_t v)
{
  // splitmix64 finaliser on the running state: order-dependent and well spread.
  h ^= v + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
  h ^= h >> 30;
  h *= 0xbf58476d1ce4e5b9ull;
  h ^= h >> 27;
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

// One item's bits into a lane of BlockHash: a multiplication and a shift, each step a bijection
// of the lane's state and of the item's bits, so that one item changed always changes its lane
// (Mix's chain of two multiplications per item was most of the pass's time).
std::uint64_t Step(std::uint64_t h, std::uint64_t v)
{
  h = (h ^ v) * 0x9e3779b97f4a7c15ull;
  return h ^ (h >> 32);
}

// Items 0..count-1 hashed in fixed blocks in parallel (mixIn(i, h) steps item i's bit patterns
// into h), the blocks then combined in order after `seed`: the same on any thread count.
template <typename MixIn>
std::uint64_t BlockHash(vtkIdType count, std::uint64_t seed, MixIn&& mixIn)
{
  constexpr vtkIdType Block = 65536;
  std::vector<std::uint64_t> blocks(static_cast<std::size_t>((count + Block - 1) / Block));
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(blocks.size()), 1, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType b = first; b < last; ++b)
      {
        // Eight interleaved lanes (item i in lane i % 8): independent chains of the steps'
        // multiplications, which one chain would run one after another.
        constexpr vtkIdType Lanes = 8;
        std::uint64_t lanes[Lanes] = { 0, 1, 2, 3, 4, 5, 6, 7 };
        const vtkIdType first = b * Block, last = std::min(count, (b + 1) * Block);
        vtkIdType i = first;
        for (; i + Lanes <= last; i += Lanes)
        {
          for (vtkIdType l = 0; l < Lanes; ++l)
          {
            lanes[l] = mixIn(i + l, lanes[l]);
          }
        }
        for (; i < last; ++i)
        {
          lanes[(i - first) % Lanes] = mixIn(i, lanes[(i - first) % Lanes]);
        }
        std::uint64_t h = lanes[0];
        for (vtkIdType l = 1; l < Lanes; ++l)
        {
          h = Mix(h, lanes[l]);
        }
        blocks[b] = h;
      }
    });
  std::uint64_t h = seed;
  for (std::uint64_t b : blocks)
  {
    h = Mix(h, b);
  }
  return h;
}

std::uint64_t DoubleBits(double value)
{
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  return bits;
}
} // namespace

std::uint64_t CoordinateFingerprint(vtkPoints* points)
{
  const vtkIdType n = points->GetNumberOfPoints();
  return BlockHash(n, Mix(0, static_cast<std::uint64_t>(n)), [&](vtkIdType i, std::uint64_t h) {
    double x[3];
    points->GetPoint(i, x);
    for (double c : x)
    {
      h = Step(h, DoubleBits(c));
    }
    return h;
  });
}

std::uint64_t ValueFingerprint(vtkDataArray* array)
{
  // Plain memory is read as it lies (the value's bytes), other layouts through the interface.
  const vtkIdType n = array->GetNumberOfValues();
  const int components = std::max(1, array->GetNumberOfComponents());
  const int size = array->GetDataTypeSize();
  const unsigned char* raw = array->HasStandardMemoryLayout() && size <= 8
    ? static_cast<const unsigned char*>(array->GetVoidPointer(0))
    : nullptr;
  const std::uint64_t seed =
    Mix(static_cast<std::uint64_t>(array->GetDataType()), static_cast<std::uint64_t>(n));
  // A value's bytes into the low bytes of a zeroed word, with the size known to the compiler
  // (a copy of a size known only at run time is a call per value).
  auto hashBytes = [&](auto sizeOf) {
    constexpr std::size_t Size = decltype(sizeOf)::value;
    return BlockHash(n, seed, [&](vtkIdType i, std::uint64_t h) {
      std::uint64_t bits = 0;
      std::memcpy(&bits, raw + static_cast<std::size_t>(i) * Size, Size);
      return Step(h, bits);
    });
  };
  switch (raw ? size : 0)
  {
    case 8:
      return hashBytes(std::integral_constant<std::size_t, 8>());
    case 4:
      return hashBytes(std::integral_constant<std::size_t, 4>());
    case 2:
      return hashBytes(std::integral_constant<std::size_t, 2>());
    case 1:
      return hashBytes(std::integral_constant<std::size_t, 1>());
    default:
      break;
  }
  return BlockHash(n, seed, [&](vtkIdType i, std::uint64_t h) {
    std::uint64_t bits = 0;
    if (raw)
    {
      std::memcpy(&bits, raw + static_cast<std::size_t>(i) * size, size);
    }
    else
    {
      bits = DoubleBits(array->GetComponent(i / components, static_cast<int>(i % components)));
    }
    return Step(h, bits);
  });
}

std::uint64_t ValueFingerprint(const std::vector<double>& values)
{
  const vtkIdType n = static_cast<vtkIdType>(values.size());
  return BlockHash(n, Mix(static_cast<std::uint64_t>(VTK_DOUBLE), static_cast<std::uint64_t>(n)),
    [&](vtkIdType i, std::uint64_t h) { return Step(h, DoubleBits(values[i])); });
}

const Neighborhoods* NeighborCache::Find(vtkPoints* points, int neighbors)
{
  const vtkIdType n = points->GetNumberOfPoints();
  // Hashing the coordinates takes a pass over them: at most once per call, and only when an
  // entry of the same size is not the very same unmodified points object.
  std::uint64_t fingerprint = 0;
  bool fingerprinted = false;
  auto fingerprintOnce = [&]() {
    if (!fingerprinted)
    {
      fingerprint = CoordinateFingerprint(points);
      fingerprinted = true;
    }
    return fingerprint;
  };
  for (auto it = this->Entries.begin(); it != this->Entries.end(); ++it)
  {
    Entry& e = **it;
    if (e.NumberOfPoints != n || e.NumberOfNeighbors != neighbors)
    {
      continue;
    }
    if ((e.Points == points && e.PointsTime == points->GetMTime()) ||
      e.Fingerprint == fingerprintOnce())
    {
      e.Points = points;
      e.PointsTime = points->GetMTime();
      this->Entries.splice(this->Entries.begin(), this->Entries, it);
      return &e.Geometry;
    }
  }
  return nullptr;
}

const Neighborhoods* NeighborCache::Get(
  vtkPoints* points, int neighbors, std::size_t capacity, const AbortCheck& aborted, bool& built)
{
  built = false;
  if (const Neighborhoods* cached = this->Find(points, neighbors))
  {
    return cached;
  }
  // Make room first: the old entries' memory is freed before the new one is allocated.
  while (!this->Entries.empty() && this->Entries.size() >= std::max<std::size_t>(1, capacity))
  {
    this->Entries.pop_back();
  }
  auto entry = std::make_unique<Entry>();
  if (!BuildNeighborhoods(points, neighbors, entry->Geometry, aborted))
  {
    return nullptr;
  }
  static std::atomic<std::uint64_t> builds(0);
  entry->Geometry.BuildNumber = ++builds;
  entry->Points = points;
  entry->PointsTime = points->GetMTime();
  entry->NumberOfPoints = points->GetNumberOfPoints();
  entry->NumberOfNeighbors = neighbors;
  entry->Fingerprint = CoordinateFingerprint(points); // (a pass over them, against a build)
  this->Entries.push_front(std::move(entry));
  built = true;
  return &this->Entries.front()->Geometry;
}

} // namespace lsi
