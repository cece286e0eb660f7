// What the isopoints carry besides position and normal: a splat radius from the local isopoint
// spacing (for disks and for ParaView's Point Gaussian representation), and the input's point
// arrays interpolated by the same MLS linear fit that refines the isopoints on the data.
#ifndef LevelSetSurfaceAttributes_h
#define LevelSetSurfaceAttributes_h

#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include <vector>

class vtkDataArray;

namespace lsi
{

/// Splat radius of each point (3 doubles per point): `factor` times the distance to its
/// `neighbors`-th nearest other point. Returns false only when aborted.
bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted);

/// For each point of `points`, fits every component of each array of `sources` (input point
/// order) linearly over the `fitCount` samples nearest to it, with the paper's MLS weights, and
/// writes the fit's value at the point into the matching array of `targets` (same components,
/// one tuple per point, already sized). A linear field is reproduced exactly. Where the fit is
/// singular the nearest sample's value is copied. Returns false only when aborted.
bool InterpolatePointArrays(const Neighborhoods& geometry, const std::vector<double>& points,
  std::size_t fitCount, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted);

} // namespace lsi

#endif
