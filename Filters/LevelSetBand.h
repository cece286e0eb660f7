// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The sets of samples the evolution and the reinitialisation work on: the band |phi| < w and
// its neighbours. Only these are visited, which is the method's locality.
#ifndef LevelSetBand_h
#define LevelSetBand_h

#include "LevelSetNeighborhoods.h"

#include "vtkSMPTools.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace lsi
{

class BandCollector
{
public:
  explicit BandCollector(const Neighborhoods& geometry);

  /// The samples with |phi| < halfWidth, in storage order (a sequential scan: O(N) cheap memory
  /// traffic, and a deterministic order).
  void Where(const std::vector<double>& phi, double halfWidth, std::vector<std::size_t>& out) const;

  /// `core` and all their neighbours, each once, in storage order (marked in parallel, then
  /// collected by a scan).
  void WithNeighbors(const std::vector<std::size_t>& core, std::vector<std::size_t>& out);

private:
  const Neighborhoods& Geometry;
  // Marks for neighbourhood collection, set by several threads at once (all the same value).
  std::unique_ptr<std::atomic<std::uint32_t>[]> Stamp;
  std::uint32_t CurrentStamp = 0;
};

/// Runs body(k, where[k]) for every k, in parallel.
template <typename Body>
void ForEachIn(const std::vector<std::size_t>& where, Body&& body)
{
  vtkSMPTools::For(0, static_cast<vtkIdType>(where.size()), BalancedGrain(where.size(), 256),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        body(static_cast<std::size_t>(k), where[static_cast<std::size_t>(k)]);
      }
    });
}

} // namespace lsi

#endif
