// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Duplicate points (merged outputs, boundary particles written twice, restarts): the method's
// fits need distinct samples, so points at exactly the same coordinates are merged into one
// whose values are their average. The neighbour search finds them at no cost; only then is the
// merged copy made and searched again.
#ifndef LevelSetDuplicates_h
#define LevelSetDuplicates_h

#include "vtkSmartPointer.h"
#include "vtkType.h"

#include <vector>

class vtkPointSet;
class vtkPolyData;

namespace lsi
{

/// The input with each group of coincident points merged into its first point, every numeric
/// point array (and `values`, the scalar in input order, replaced) averaged over the group;
/// mergedId[i] is the merged point that input point i became. Field data are passed on.
/// `merged` receives how many points were merged away.
vtkSmartPointer<vtkPolyData> MergeDuplicatePoints(vtkPointSet* input, std::vector<double>& values,
  std::vector<vtkIdType>& mergedId, vtkIdType& merged);

} // namespace lsi

#endif
