// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetFloodOnField.h"

#include <memory>

namespace lsi
{

FloodEdgeCheck FieldStaysAboveBetween(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<double>& dataOffsets, double isoValue)
{
  // Per sample: 0 not yet looked at, 1 near the surface, 2 not.
  auto state = std::make_shared<std::vector<char>>(geometry.NumberOfSamples, 0);
  return [&geometry, &field, &dataOffsets, isoValue, state](std::uint32_t from, std::uint32_t to) {
    char& near = (*state)[from];
    if (near == 0)
    {
      near = 2;
      const std::uint32_t* ids = geometry.NeighborsOf(from);
      for (int m = 1; m < geometry.Stride && near == 2; ++m)
      {
        near = dataOffsets[ids[m]] > 0.0 ? 2 : 1;
      }
    }
    if (near == 2)
    {
      return true;
    }
    const double* a = geometry.Position(from);
    const double* b = geometry.Position(to);
    const double middle[3] = { 0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]), 0.5 * (a[2] + b[2]) };
    return field.ValueAt(middle) - isoValue > 0.0;
  };
}

} // namespace lsi
