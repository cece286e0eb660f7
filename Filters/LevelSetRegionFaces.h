// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The faces of the region a reader read (its ReadRegion: the field data "RegionBounds" and
// "RegionPeriod" it passes on). Beyond them no particle was read, so the field near them misses
// its particles: a surface that comes within a fit's reach of a face is cut or moved there, and
// the filter warns (vtkLevelSetIsosurface::WarnIfRegionCut).
#ifndef LevelSetRegionFaces_h
#define LevelSetRegionFaces_h

#include "LevelSetNeighborhoods.h"
#include "LevelSetPeriodicImages.h"
#include "LevelSetSPHField.h"

#include <cstddef>
#include <vector>

class vtkPointSet;

namespace lsi
{

struct RegionFaces
{
  bool Known = false;
  double Bounds[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  // Per axis: the period with which the faces repeat (the reader's wrap, else the filter's
  // periodic box: its images end where the particles they copy end), 0 for none; and whether
  // the axis has faces at all (not where the region spans a whole period).
  double Period[3] = { 0.0, 0.0, 0.0 };
  bool HasFaces[3] = { false, false, false };
};

/// The region the input's reader read, from its field data (none: Known false). `box`: the
/// filter's periodic box.
RegionFaces FindRegionFaces(vtkPointSet* input, const PeriodicBox& box);

/// The distance from x to the nearest face of the region (its planes, repeated with the period
/// on a periodic axis); HUGE_VAL without faces.
double DistanceToRegionFaces(const double x[3], const RegionFaces& region);

/// How many of `points` (3 per point) lie nearer to a face of the region than the reach of the
/// field there: the kernel support of the sample nearest to the point on the SPH `field`, else
/// two neighbourhood radii of it (the MLS fit's samples).
std::size_t PointsNearRegionFaces(const Neighborhoods& geometry, const SPHField* field,
  const std::vector<double>& points, const RegionFaces& region);

} // namespace lsi

#endif
