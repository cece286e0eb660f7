// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The particles output: the input points as vertices with their point data and "LevelSet", the
// final level-set function (positive inside the extracted components), in input order.
#ifndef LevelSetParticleOutput_h
#define LevelSetParticleOutput_h

#include "LevelSetNeighborhoods.h"

#include "vtkCellArray.h"
#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkDataArray;
class vtkDoubleArray;
class vtkPointSet;
class vtkPolyData;

namespace lsi
{

/// `phi` is in the samples' storage order (geometry.Order maps it back to the ids the method
/// ran on). `mergedId` maps each input point to the sample it was merged into (duplicates), or
/// is empty; ghost images (ids past the input's) are left out. `vertices`: one vertex cell per
/// input point, kept from an earlier run (they depend on the count alone); made anew when null
/// or of another count. `spare`: an earlier output's LevelSet array, whose memory is reused
/// when nothing else holds it any more (then set to null either way).
void MakeParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, const std::vector<vtkIdType>& mergedId, vtkPolyData* particles,
  vtkSmartPointer<vtkCellArray>& vertices, vtkSmartPointer<vtkDoubleArray>& spare);

/// MakeParticleOutput's output after only the samples `changed` changed their phi since
/// `lastLevelSet` (the LevelSet array it gave for the same input, without merged points): a copy
/// of that array with those samples' values written, the same values as made anew, for a pass
/// over the changed samples instead of a scatter of every one. False, doing nothing, if
/// `lastLevelSet` is not such an array.
bool UpdateParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, const std::vector<std::size_t>& changed,
  vtkDataArray* lastLevelSet, vtkPolyData* particles, vtkSmartPointer<vtkCellArray>& vertices,
  vtkSmartPointer<vtkDoubleArray>& spare);

} // namespace lsi

#endif
