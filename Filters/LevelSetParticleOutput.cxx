// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetParticleOutput.h"

#include "LevelSetVertexCells.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"

namespace lsi
{

void MakeParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, vtkPolyData* particles)
{
  const vtkIdType n = input->GetNumberOfPoints();
  particles->SetPoints(input->GetPoints());
  particles->SetVerts(VertexCells(n));
  particles->GetPointData()->PassData(input->GetPointData());
  vtkNew<vtkDoubleArray> levelSet;
  levelSet->SetName("LevelSet");
  levelSet->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    levelSet->SetValue(geometry.Order[i], phi[i]); // back from storage order to input order
  }
  particles->GetPointData()->AddArray(levelSet);
}

} // namespace lsi
