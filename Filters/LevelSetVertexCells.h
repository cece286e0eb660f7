// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// One vertex cell per point, for point sets shown as points (the particles, the isopoints).
#ifndef LevelSetVertexCells_h
#define LevelSetVertexCells_h

#include "UninitializedVector.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

namespace lsi
{
/// Vertex cells 0..count-1, one per point: in 32-bit storage where the ids fit (half the fresh
/// memory of 64-bit ids: 16 MB fewer pages to fault in at 2M points, which on the virtual
/// machines here cost more than the writes), else in vtkIdType.
template <typename Array>
vtkNew<vtkCellArray> VertexCellsIn(vtkIdType count)
{
  using Value = typename Array::ValueType;
  vtkNew<Array> offsets, connectivity;
  offsets->SetNumberOfValues(count + 1);
  connectivity->SetNumberOfValues(count);
  AdviseHugePages(offsets->GetPointer(0), sizeof(Value) * static_cast<std::size_t>(count + 1));
  AdviseHugePages(connectivity->GetPointer(0), sizeof(Value) * static_cast<std::size_t>(count));
  vtkSMPTools::For(0, count, BalancedGrain(static_cast<std::size_t>(count), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        offsets->SetValue(i, static_cast<Value>(i));
        connectivity->SetValue(i, static_cast<Value>(i));
      }
    });
  offsets->SetValue(count, static_cast<Value>(count));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  return cells;
}

inline vtkNew<vtkCellArray> VertexCells(vtkIdType count)
{
  return count < VTK_INT_MAX ? VertexCellsIn<vtkTypeInt32Array>(count)
                             : VertexCellsIn<vtkTypeInt64Array>(count);
}
} // namespace lsi

#endif
