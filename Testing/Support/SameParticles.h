// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The readers' tests' comparison of a read with a full read of the same file: which point
// arrays a read gave, and whether its particles are some of the full read's, value for value.
#ifndef SameParticles_h
#define SameParticles_h

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace lsi
{
namespace test
{
/// The point arrays of `data`, the global ids' array included.
inline std::set<std::string> PointArrayNames(vtkPolyData* data)
{
  std::set<std::string> names;
  vtkPointData* pointData = data->GetPointData();
  for (int a = 0; a < pointData->GetNumberOfArrays(); ++a)
  {
    names.insert(pointData->GetArrayName(a));
  }
  return names;
}

/// Whether particle k of `part` is particle `ids[first + k]` of `all`: the same position and,
/// for every array of `part`, an array of `all` with that name, shape and values, exactly.
inline bool SameParticles(
  vtkPolyData* all, const std::vector<vtkIdType>& ids, vtkIdType first, vtkPolyData* part)
{
  if (!part || first + part->GetNumberOfPoints() > static_cast<vtkIdType>(ids.size()))
  {
    return false;
  }
  for (vtkIdType k = 0; k < part->GetNumberOfPoints(); ++k)
  {
    const vtkIdType i = ids[first + k];
    double p[3], q[3];
    all->GetPoint(i, p);
    part->GetPoint(k, q);
    if (!std::equal(p, p + 3, q))
    {
      return false;
    }
    for (int a = 0; a < part->GetPointData()->GetNumberOfArrays(); ++a)
    {
      vtkDataArray* mine = part->GetPointData()->GetArray(a);
      vtkDataArray* theirs = all->GetPointData()->GetArray(mine->GetName());
      if (!theirs || theirs->GetNumberOfComponents() != mine->GetNumberOfComponents())
      {
        return false;
      }
      for (int c = 0; c < mine->GetNumberOfComponents(); ++c)
      {
        if (mine->GetComponent(k, c) != theirs->GetComponent(i, c))
        {
          return false;
        }
      }
    }
  }
  return true;
}
} // namespace test
} // namespace lsi

#endif
