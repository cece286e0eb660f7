// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetParticleOutput.h"

#include "LevelSetVertexCells.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <algorithm>

namespace lsi
{

void MakeParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, const std::vector<vtkIdType>& mergedId, vtkPolyData* particles)
{
  const vtkIdType n = input->GetNumberOfPoints();
  particles->SetPoints(input->GetPoints());
  particles->SetVerts(VertexCells(n));
  particles->GetPointData()->PassData(input->GetPointData());
  // The value at each id the method ran on (images, past the distinct points, left out).
  const vtkIdType distinct =
    mergedId.empty() ? n : 1 + *std::max_element(mergedId.begin(), mergedId.end());
  std::vector<double> value(static_cast<std::size_t>(distinct), 0.0);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(geometry.NumberOfSamples), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (static_cast<vtkIdType>(geometry.Order[i]) < distinct)
        {
          value[geometry.Order[i]] = phi[i];
        }
      }
    });
  vtkNew<vtkDoubleArray> levelSet;
  levelSet->SetName("LevelSet");
  levelSet->SetNumberOfValues(n);
  vtkSMPTools::For(0, n, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType i = begin; i < end; ++i)
    {
      levelSet->SetValue(i, value[mergedId.empty() ? i : mergedId[i]]);
    }
  });
  particles->GetPointData()->AddArray(levelSet);
}

} // namespace lsi
