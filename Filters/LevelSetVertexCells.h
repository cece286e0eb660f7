// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// One vertex cell per point, for point sets shown as points (the particles, the isopoints).
#ifndef LevelSetVertexCells_h
#define LevelSetVertexCells_h

#include "UninitializedVector.h"

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
  AdviseHugePages(offsets->GetPointer(0), sizeof(vtkIdType) * static_cast<std::size_t>(count + 1));
  AdviseHugePages(connectivity->GetPointer(0), sizeof(vtkIdType) * static_cast<std::size_t>(count));
  vtkSMPTools::For(0, count, BalancedGrain(static_cast<std::size_t>(count), 1024),
    [&](vtkIdType begin, vtkIdType end) {
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
