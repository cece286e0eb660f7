// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// One vertex cell per point, for point sets shown as points (the particles, the isopoints).
#ifndef LevelSetVertexCells_h
#define LevelSetVertexCells_h

#include "vtkCellArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"

namespace lsi
{
/// Vertex cells 0..count-1, one per point.
inline vtkNew<vtkCellArray> VertexCells(vtkIdType count)
{
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      offsets->SetValue(i, i);
      connectivity->SetValue(i, i);
    }
  });
  offsets->SetValue(count, count);
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  return cells;
}
} // namespace lsi

#endif
