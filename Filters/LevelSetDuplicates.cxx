// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetDuplicates.h"

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

vtkSmartPointer<vtkPolyData> MergeDuplicatePoints(vtkPointSet* input, std::vector<double>& values,
  std::vector<vtkIdType>& mergedId, vtkIdType& merged)
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
    std::vector<double> sum(static_cast<std::size_t>(m) * components, 0.0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        sum[mergedId[i] * components + c] += array->GetComponent(i, c);
      }
    }
    vtkSmartPointer<vtkDataArray> average = vtk::TakeSmartPointer(array->NewInstance());
    average->SetName(array->GetName());
    average->SetNumberOfComponents(components);
    average->SetNumberOfTuples(m);
    for (vtkIdType k = 0; k < m; ++k)
    {
      for (int c = 0; c < components; ++c)
      {
        average->SetComponent(k, c, sum[k * components + c] / groupSize[k]);
      }
    }
    out->GetPointData()->AddArray(average);
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
