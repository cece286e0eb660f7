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

class vtkDataArray;
class vtkPointSet;
class vtkPolyData;

namespace lsi
{

/// The input with each group of coincident points merged into its first point: `values` (the
/// scalar in input order, replaced) and every floating-point point array averaged over the
/// group, except `mass` (the SPH field's masses, if not null), which is summed, so that the SPH
/// field sum_j m_j W keeps the group's mass (particles that share a global id, the input's
/// GlobalIds, are one particle written more than once: counted once); integer arrays (ids,
/// groups, flags) take the group's smallest tuple (an average would mean nothing; the smallest
/// does not depend on the input's order). mergedId[i] is the merged point that input point i
/// became. Field data are passed on. `merged` receives how many points were merged away.
vtkSmartPointer<vtkPolyData> MergeDuplicatePoints(vtkPointSet* input, std::vector<double>& values,
  std::vector<vtkIdType>& mergedId, vtkIdType& merged, vtkDataArray* mass = nullptr);

} // namespace lsi

#endif
