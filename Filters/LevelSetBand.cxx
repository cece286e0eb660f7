// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetBand.h"

#include "LevelSetParallel.h"

#include <cmath>

namespace lsi
{

BandCollector::BandCollector(const Neighborhoods& geometry)
  : Geometry(geometry)
  , Stamp(geometry.NumberOfSamples, 0)
{
}

void BandCollector::Where(
  const std::vector<double>& phi, double halfWidth, std::vector<std::size_t>& out) const
{
  // In parallel: it runs several times per iteration over every sample.
  out = IndicesWhere<std::size_t>(
    this->Geometry.NumberOfSamples, [&](std::size_t i) { return std::abs(phi[i]) < halfWidth; });
}

void BandCollector::WithNeighbors(
  const std::vector<std::size_t>& core, std::vector<std::size_t>& out)
{
  ++this->CurrentStamp;
  out.clear();
  const int stride = this->Geometry.Stride;
  this->Geometry.EnsureNeighbors(core);
  for (std::size_t i : core)
  {
    const std::uint32_t* ids = this->Geometry.NeighborsOf(i);
    for (int k = 0; k < stride; ++k)
    {
      if (this->Stamp[ids[k]] != this->CurrentStamp)
      {
        this->Stamp[ids[k]] = this->CurrentStamp;
        out.push_back(ids[k]);
      }
    }
  }
}

} // namespace lsi
