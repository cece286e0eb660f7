// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Which point arrays are labels rather than quantities: one rule for every step that carries
// arrays (merged duplicates, the surface's arrays).
#ifndef LevelSetArrayKinds_h
#define LevelSetArrayKinds_h

#include "vtkDataArray.h"
#include "vtkType.h"

namespace lsi
{

/// Whether `array` holds labels (particle ids, halo-finder groups, flags: any type but float
/// and double), whose averages and interpolants mean nothing: they take one particle's value.
inline bool HoldsLabels(vtkDataArray* array)
{
  return array->GetDataType() != VTK_FLOAT && array->GetDataType() != VTK_DOUBLE;
}

} // namespace lsi

#endif
