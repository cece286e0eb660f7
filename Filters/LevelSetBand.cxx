// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetBand.h"

#include "vtkSMPTools.h"

#include <algorithm>
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
  // In fixed chunks, in parallel, joined in order: the samples in storage order, as a serial
  // scan gives them (it runs several times per iteration over every sample).
  constexpr std::size_t Chunk = 1 << 16;
  const std::size_t n = this->Geometry.NumberOfSamples;
  const std::size_t chunks = (n + Chunk - 1) / Chunk;
  std::vector<std::vector<std::size_t>> found(chunks);
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), 1, [&](vtkIdType first, vtkIdType last) {
    for (vtkIdType c = first; c < last; ++c)
    {
      std::vector<std::size_t>& mine = found[c];
      const std::size_t end = std::min(n, (static_cast<std::size_t>(c) + 1) * Chunk);
      for (std::size_t i = static_cast<std::size_t>(c) * Chunk; i < end; ++i)
      {
        if (std::abs(phi[i]) < halfWidth)
        {
          mine.push_back(i);
        }
      }
    }
  });
  out.clear();
  for (const std::vector<std::size_t>& mine : found)
  {
    out.insert(out.end(), mine.begin(), mine.end());
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
