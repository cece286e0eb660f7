// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetDuplicates.h"

#include "LevelSetArrayKinds.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <numeric>

namespace lsi
{

namespace
{
// Whether tuple i of `array` comes before tuple j (component by component).
bool TupleBefore(vtkDataArray* array, vtkIdType i, vtkIdType j)
{
  for (int c = 0; c < array->GetNumberOfComponents(); ++c)
  {
    const double a = array->GetComponent(i, c), b = array->GetComponent(j, c);
    if (a != b)
    {
      return a < b;
    }
  }
  return false;
}
} // namespace

vtkSmartPointer<vtkPolyData> MergeDuplicatePoints(vtkPointSet* input, std::vector<double>& values,
  std::vector<vtkIdType>& mergedId, vtkIdType& merged, vtkDataArray* mass)
{
  const vtkIdType n = input->GetNumberOfPoints();
  std::vector<std::array<double, 3>> x(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    input->GetPoint(i, x[i].data());
  }
  // Groups of equal coordinates: sorted by coordinates (ties by id, so the first of a group is
  // its lowest id, whatever the sort).
  std::vector<vtkIdType> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), vtkIdType(0));
  std::sort(order.begin(), order.end(),
    [&](vtkIdType a, vtkIdType b) { return x[a] != x[b] ? x[a] < x[b] : a < b; });
  std::vector<vtkIdType> representative(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < order.size(); ++k)
  {
    const bool sameAsPrevious = k > 0 && x[order[k]] == x[order[k - 1]];
    representative[order[k]] = sameAsPrevious ? representative[order[k - 1]] : order[k];
  }
  // Merged ids in input order of the representatives.
  mergedId.assign(static_cast<std::size_t>(n), -1);
  std::vector<vtkIdType> kept;
  for (vtkIdType i = 0; i < n; ++i)
  {
    if (representative[i] == i)
    {
      mergedId[i] = static_cast<vtkIdType>(kept.size());
      kept.push_back(i);
    }
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    mergedId[i] = mergedId[representative[i]];
  }
  const vtkIdType m = static_cast<vtkIdType>(kept.size());
  merged = n - m;
  std::vector<double> groupSize(static_cast<std::size_t>(m), 0.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    groupSize[mergedId[i]] += 1.0;
  }

  // Which points count towards a group's summed mass: all, but a global id met before in the
  // group (the same particle written again) counts once.
  std::vector<char> counted(static_cast<std::size_t>(n), 1);
  vtkDataArray* ids = input->GetPointData()->GetGlobalIds();
  if (ids && ids->GetNumberOfTuples() == n)
  {
    for (std::size_t k = 1; k < order.size(); ++k)
    {
      for (std::size_t j = k; j-- > 0 && representative[order[j]] == representative[order[k]];)
      {
        if (ids->GetComponent(order[j], 0) == ids->GetComponent(order[k], 0))
        {
          counted[order[k]] = 0;
          break;
        }
      }
    }
  }

  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(m);
  for (vtkIdType k = 0; k < m; ++k)
  {
    points->SetPoint(k, x[kept[k]].data());
  }
  out->SetPoints(points);
  vtkPointData* source = input->GetPointData();
  for (int a = 0; a < source->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = source->GetArray(a);
    if (!array || array->GetNumberOfTuples() != n)
    {
      continue; // malformed arrays were reported on the input already
    }
    const int components = array->GetNumberOfComponents();
    vtkSmartPointer<vtkDataArray> combined = vtk::TakeSmartPointer(array->NewInstance());
    combined->SetName(array->GetName());
    combined->SetNumberOfComponents(components);
    combined->SetNumberOfTuples(m);
    if (HoldsLabels(array))
    {
      std::vector<vtkIdType> smallest(kept);
      for (vtkIdType i = 0; i < n; ++i)
      {
        vtkIdType& best = smallest[mergedId[i]];
        best = TupleBefore(array, i, best) ? i : best;
      }
      for (vtkIdType k = 0; k < m; ++k)
      {
        combined->SetTuple(k, smallest[k], array);
      }
    }
    else
    {
      const bool summed = array == mass;
      std::vector<double> sum(static_cast<std::size_t>(m) * components, 0.0);
      for (vtkIdType i = 0; i < n; ++i)
      {
        for (int c = 0; c < components && (!summed || counted[i]); ++c)
        {
          sum[mergedId[i] * components + c] += array->GetComponent(i, c);
        }
      }
      for (vtkIdType k = 0; k < m; ++k)
      {
        for (int c = 0; c < components; ++c)
        {
          combined->SetComponent(k, c, sum[k * components + c] / (summed ? 1.0 : groupSize[k]));
        }
      }
    }
    out->GetPointData()->AddArray(combined);
    if (ids == array)
    {
      out->GetPointData()->SetGlobalIds(combined);
    }
    if (source->GetScalars() == array)
    {
      out->GetPointData()->SetActiveScalars(array->GetName());
    }
  }
  std::vector<double> averaged(static_cast<std::size_t>(m), 0.0);
  for (vtkIdType i = 0; i < n; ++i)
  {
    averaged[mergedId[i]] += values[i];
  }
  for (vtkIdType k = 0; k < m; ++k)
  {
    averaged[k] /= groupSize[k];
  }
  values.swap(averaged);
  out->GetFieldData()->PassData(input->GetFieldData());
  return out;
}

} // namespace lsi
