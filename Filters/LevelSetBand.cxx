// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetBand.h"

#include "LevelSetParallel.h"

#include <cmath>

namespace lsi
{

BandCollector::BandCollector(const Neighborhoods& geometry)
  : Geometry(geometry)
  , Stamp(FilledAtomics<std::uint32_t>(geometry.NumberOfSamples, 0))
{
}

void BandCollector::Where(
  const std::vector<double>& phi, double halfWidth, std::vector<std::size_t>& out) const
{
  // In parallel: it runs several times per iteration over every sample.
  IndicesWhere(
    this->Geometry.NumberOfSamples, [&](std::size_t i) { return std::abs(phi[i]) < halfWidth; },
    out);
}

void BandCollector::WithNeighbors(
  const std::vector<std::size_t>& core, std::vector<std::size_t>& out)
{
  const std::uint32_t stamp = ++this->CurrentStamp;
  const int stride = this->Geometry.Stride;
  this->Geometry.EnsureNeighbors(core);
  ForEachIn(core, [&](std::size_t, std::size_t i) {
    const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
    for (int k = 0; k < stride; ++k)
    {
      this->Stamp[ids[k]].store(stamp, std::memory_order_relaxed);
    }
  });
  IndicesWhere(
    this->Geometry.NumberOfSamples,
    [&](std::size_t i) { return this->Stamp[i].load(std::memory_order_relaxed) == stamp; }, out);
}

} // namespace lsi
