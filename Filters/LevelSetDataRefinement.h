// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 7 of the method, the refinement on the data (ours, not in the paper): the level set only
// uses the sign of f - f_iso, which places the surface to a fraction of the spacing. Each
// isopoint slides along its normal to the zero of an MLS fit of f - f_iso
// (Numerics/IsopointRefinement.h, SlideOntoDataLevel) and takes its normal from that fit.
#ifndef LevelSetDataRefinement_h
#define LevelSetDataRefinement_h

#include "LevelSetIsopoints.h"

namespace lsi
{

/// Moves the isopoints of `out` onto the zero level of the MLS fit of `dataOffsets` (f - f_iso per
/// sample) over DataFitScale (n + 1) samples, at most DataMaximumMove each, and replaces their
/// normals by the fit's. Returns false only when aborted.
bool RefineIsopointsOnData(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

} // namespace lsi

#endif
