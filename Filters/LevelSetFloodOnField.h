// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The flood's edges on the SPH field. The flood (LevelSetFlood.h) joins two samples above the
// isovalue when one is among the other's nearest neighbours; on point data the samples are all
// there is, but the SPH field is defined between them and may dip below the isovalue there: two
// clumps a neighbourhood apart (a dark-matter box's overdensities) are then two components of
// the field's level set, which the graph alone would join.
#ifndef LevelSetFloodOnField_h
#define LevelSetFloodOnField_h

#include "LevelSetFlood.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetSPHField.h"

#include <vector>

namespace lsi
{

/// The flood goes from `from` to its neighbour `to` (both above the isovalue) unless the field
/// lies at or below the isovalue at their midpoint. Looked at only where `from` has a neighbour
/// at or below the isovalue (near the surface): between samples whose neighbourhoods lie wholly
/// above it, a dip would be a hole smaller than the spacing, which the method does not resolve
/// (as the flood fills outside pockets smaller than a neighbourhood). The check keeps what it
/// learns of each sample (it is for one flood's serial walk, on one thread); `dataOffsets` holds
/// f - f_iso per sample, as the flood's.
FloodEdgeCheck FieldStaysAboveBetween(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<double>& dataOffsets, double isoValue);

} // namespace lsi

#endif
