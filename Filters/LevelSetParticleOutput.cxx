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
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    // Back from storage order to input order; ghost images (ids past the input's) are left out.
    if (static_cast<vtkIdType>(geometry.Order[i]) < n)
    {
      levelSet->SetValue(geometry.Order[i], phi[i]);
    }
  }
  particles->GetPointData()->AddArray(levelSet);
}

} // namespace lsi
