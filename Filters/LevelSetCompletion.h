// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 6 of the method, completion (paper §6, Fig. 3): around each isopoint, the empty cells of a
// small grid on its tangent plane (Numerics/TangentPlaneCompletion.h) propose new points, which
// are projected onto the zero level like the isopoints themselves, so that the set is dense
// enough to render without holes.
#ifndef LevelSetCompletion_h
#define LevelSetCompletion_h

#include "LevelSetIsopoints.h"

namespace lsi
{

/// Adds the completed points to `out` (thinned with it: existing isopoints keep their voxels).
/// `phi` is the level set the isopoints were extracted from. Returns false only when aborted.
bool CompleteIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);

} // namespace lsi

#endif
