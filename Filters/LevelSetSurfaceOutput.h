// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 8, the surface output: the isopoints as a point set with their normals, a splat radius
// from the local isopoint spacing (for disks and for ParaView's Point Gaussian representation),
// and the input's point arrays interpolated by the same MLS linear fit that refines the
// isopoints on the data. LevelSetSplatOutput.h turns it into polygons.
#ifndef LevelSetSurfaceOutput_h
#define LevelSetSurfaceOutput_h

#include "LevelSetIsopoints.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"

#include <cstdint>
#include <vector>

class vtkDataArray;
class vtkPointData;
class vtkPolyData;

namespace lsi
{
class SPHField;
class KeptCandidates;

/// Fills `surface` with the isopoints (no cells), "Normals", "SplatRadius" (`splatScale` times
/// the distance to the 6th nearest isopoint) and, if `interpolateArrays`, every numeric array
/// of `inputData` (input point order): floating-point ones interpolated over 2 (n + 1) samples,
/// integer ones the nearest sample's (CopyNearestSampleValues); `activeScalars` (the
/// isosurface's own scalar) becomes the active scalars, as Contour does. Returns false only when
/// aborted.
/// With an SPH field (`field` not null) the arrays are its interpolants instead
/// (InterpolatePointArraysSPH).
/// `pointIndex`, if given, is a search index over the isopoints (else one is built).
/// `sampledAt`, if given (3 doubles per point), is where the arrays are interpolated instead of
/// the points themselves: a periodic box's points moved by whole boxes are sampled where the
/// particles are (their fits' samples, if kept, are those nearest to `sampledAt`).
/// `scalarsInStorageOrder`, if given, holds the values of the array named `activeScalars` (one
/// component) per sample in storage order, exactly: read from there instead (the same numbers;
/// in input order the samples near a point are scattered over memory).
/// `keptSplats`, if given, keeps or reuses the splat radii's candidates (SplatRadii).
/// `splatRadii`, if given, receives the radii unrounded (the array holds floats).
bool MakeSurfacePoints(vtkPointData* inputData, const Neighborhoods& geometry,
  const IsopointSet& isopoints, double splatScale, bool interpolateArrays,
  const char* activeScalars, const SPHField* field, vtkPolyData* surface, const AbortCheck& aborted,
  const PointCloudIndex* pointIndex = nullptr, const std::vector<double>* sampledAt = nullptr,
  const std::vector<double>* scalarsInStorageOrder = nullptr, KeptCandidates* keptSplats = nullptr,
  std::vector<double>* splatRadii = nullptr);

/// For each point of `points`, fits every component of each array of `sources` (input point
/// order) linearly over the `fitCount` samples nearest to it, with the paper's MLS weights, and
/// writes the fit's value at the point into the matching array of `targets` (same components,
/// one tuple per point, already sized). A linear field is reproduced exactly. Where the fit is
/// singular the nearest sample's value is copied. `nearest`, if not null, holds each point's
/// fitCount nearest samples (IsopointSet::FitSamples), which spares their search.
/// `inStorageOrder`, if given, holds per source null or, for a one-component source, its values
/// per sample in storage order (read instead: the same numbers, near each other in memory).
/// Returns false only when aborted.
bool InterpolatePointArrays(const Neighborhoods& geometry, const std::vector<double>& points,
  std::size_t fitCount, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted,
  const std::uint32_t* nearest = nullptr,
  const std::vector<const double*>* inStorageOrder = nullptr);

/// For each point of `points`, each array of `sources` (input point order) at the sample nearest
/// to it, copied into the matching array of `targets` (the same type and components, one tuple
/// per point, already sized). For integer arrays (particle ids, halo-finder groups, flags), whose
/// interpolants mean nothing. Returns false only when aborted.
bool CopyNearestSampleValues(const Neighborhoods& geometry, const std::vector<double>& points,
  const std::vector<vtkDataArray*>& sources, const std::vector<vtkDataArray*>& targets,
  const AbortCheck& aborted);

/// Whether `values` (per sample, storage order) are exactly `array`'s (one component, a value
/// per sample, input order): MakeSurfacePoints may then read them instead of it. Checked for
/// double and float arrays (others: false).
bool SameValuesInStorageOrder(
  vtkDataArray* array, const Neighborhoods& geometry, const std::vector<double>& values);

/// Like InterpolatePointArrays, with the SPH field's interpolant: A(x) = sum_j (m_j / rho_j)
/// A_j W(|x - x_j|, H_j) (LevelSetSPHField.h). Returns false only when aborted.
bool InterpolatePointArraysSPH(const Neighborhoods& geometry, const SPHField& field,
  const std::vector<double>& points, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted);

} // namespace lsi

#endif
