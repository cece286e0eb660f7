// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetBand.h"

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
  out.clear();
  const std::size_t n = this->Geometry.NumberOfSamples;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (std::abs(phi[i]) < halfWidth)
    {
      out.push_back(i);
    }
  }
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
