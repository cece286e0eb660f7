// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// One vertex cell per point, for point sets shown as points (the particles, the isopoints).
#ifndef LevelSetVertexCells_h
#define LevelSetVertexCells_h

#include "LevelSetParallel.h"
#include "UninitializedVector.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkSMPTools.h"
#include "vtkTypeInt32Array.h"
#include "vtkTypeInt64Array.h"

#include <atomic>

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

/// Whether `cells` are the vertex cells 0..count-1, one per point in order (as VertexCells and
/// this project's readers make them). Checked in parallel: a read of them costs less than new
/// ones' fresh pages.
inline bool AreVertexCells(vtkCellArray* cells, vtkIdType count)
{
  if (!cells || cells->GetNumberOfCells() != count || cells->GetNumberOfConnectivityIds() != count)
  {
    return false;
  }
  auto identity = [count](auto* offsets, auto* connectivity) {
    std::atomic<bool> same{ true };
    vtkSMPTools::For(0, count, BalancedGrain(static_cast<std::size_t>(count), 16384),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end && same.load(std::memory_order_relaxed); ++i)
        {
          if (offsets[i] != i || connectivity[i] != i)
          {
            same = false;
          }
        }
      });
    return same.load() && offsets[count] == count;
  };
  return cells->IsStorage64Bit() ? identity(cells->GetOffsetsArray64()->GetPointer(0),
                                     cells->GetConnectivityArray64()->GetPointer(0))
                                 : identity(cells->GetOffsetsArray32()->GetPointer(0),
                                     cells->GetConnectivityArray32()->GetPointer(0));
}
} // namespace lsi

#endif
