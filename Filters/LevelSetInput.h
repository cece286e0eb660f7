// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 0: what the method needs of its input, checked before any work, and the data in the
// samples' storage order. Each check returns the problem in words for the filter's error
// message, or an empty string.
#ifndef LevelSetInput_h
#define LevelSetInput_h

#include "LevelSetNeighborhoods.h"

#include "vtkType.h"

#include <string>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkPointSet;

namespace lsi
{

/// Checks the points, the scalar array (`association` as GetInputArrayToProcess gave it), the
/// isovalue and the additional seeds' radii, and copies the scalar into `values` (input order).
std::string CheckInput(vtkPointSet* input, vtkDataArray* scalars, int association,
  int numberOfNeighbors, double isoValue, const std::vector<double>& additionalSeeds,
  std::vector<double>& values);

/// The parts of CheckInput, for an input in pieces (MPI): the count of the whole input; one
/// piece's points and scalar (an empty piece passes), with its range; the whole input's range
/// against IsoValue, and the seeds' radii.
std::string CheckCount(vtkIdType n, int numberOfNeighbors);
std::string CheckPiece(vtkPointSet* input, vtkDataArray* scalars, int association,
  std::vector<double>& values, double range[2]);
std::string CheckRangeAndSeeds(
  const double range[2], double isoValue, const std::vector<double>& additionalSeeds);
/// The additional seeds' radii (4 numbers per seed: centre, radius), each positive.
std::string CheckSeedRadii(const std::vector<double>& additionalSeeds);

/// A parameter that is NaN or infinite (a clamp macro lets NaN through): its name, or "".
/// `named` lists each parameter's name and value.
std::string NonFiniteParameter(const std::vector<std::pair<const char*, double>>& named);

/// Problems only the neighbour search reveals: all points on a plane or line; duplicate points
/// (which the filter merges before, LevelSetDuplicates.h).
std::string CheckNeighborhoods(const Neighborhoods& geometry);

/// The seed spheres (4 numbers each, the main one first) that contain no sample.
std::string CheckSeedSpheres(
  const std::vector<double>& spheres, const std::vector<std::size_t>& samplesPerSphere);

/// dataOffsets = f - f_iso per sample, in storage order.
void DataInStorageOrder(const Neighborhoods& geometry, const std::vector<double>& values,
  double isoValue, std::vector<double>& dataOffsets);

} // namespace lsi

#endif
