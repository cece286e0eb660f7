// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetParticleOutput.h"

#include "LevelSetParallel.h"
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

namespace
{
// The input's points as vertices, with its point data. Where the input holds the same vertex
// cells (this project's readers make them), they are shared with it, as the points are.
void PassParticles(
  vtkPointSet* input, vtkPolyData* particles, vtkSmartPointer<vtkCellArray>& vertices)
{
  const vtkIdType n = input->GetNumberOfPoints();
  particles->SetPoints(input->GetPoints());
  vtkPolyData* polyInput = vtkPolyData::SafeDownCast(input);
  if (polyInput && n > 0 && AreVertexCells(polyInput->GetVerts(), n))
  {
    particles->SetVerts(polyInput->GetVerts()); // (not kept: the input may change them)
  }
  else
  {
    if (!vertices || vertices->GetNumberOfCells() != n)
    {
      vertices = VertexCells(n);
    }
    particles->SetVerts(vertices);
  }
  particles->GetPointData()->PassData(input->GetPointData());
}

// A LevelSet array of n values for a new output: `spare` when nothing else holds it any more
// (an earlier output's array, whose pages are mapped already: at 20M particles a new one costs
// 160 MB of page faults), else a new one. Every value is written after.
vtkSmartPointer<vtkDoubleArray> NewLevelSet(vtkIdType n, vtkSmartPointer<vtkDoubleArray>& spare)
{
  vtkSmartPointer<vtkDoubleArray> levelSet;
  if (spare && spare->GetReferenceCount() == 1 && spare->GetNumberOfComponents() == 1 &&
    spare->GetNumberOfTuples() == n)
  {
    levelSet = spare;
    levelSet->Modified();
  }
  else
  {
    levelSet = vtkSmartPointer<vtkDoubleArray>::New();
    levelSet->SetNumberOfValues(n);
    AdviseHugePages(levelSet->GetPointer(0), sizeof(double) * static_cast<std::size_t>(n));
  }
  levelSet->SetName("LevelSet");
  spare = nullptr;
  return levelSet;
}
} // namespace

void MakeParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, const std::vector<vtkIdType>& mergedId, vtkPolyData* particles,
  vtkSmartPointer<vtkCellArray>& vertices, vtkSmartPointer<vtkDoubleArray>& spare)
{
  const vtkIdType n = input->GetNumberOfPoints();
  PassParticles(input, particles, vertices);
  const vtkSmartPointer<vtkDoubleArray> levelSet = NewLevelSet(n, spare);
  double* out = levelSet->GetPointer(0);
  const vtkIdType samples = static_cast<vtkIdType>(geometry.NumberOfSamples);
  if (mergedId.empty())
  {
    // Each input point is one sample (its images, past the points, are left out): written
    // straight into the array, in parallel (distinct ids), over zeros.
    vtkSMPTools::For(0, n, BalancedGrain(static_cast<std::size_t>(n), 16384),
      [&](vtkIdType begin, vtkIdType end) { std::fill(out + begin, out + end, 0.0); });
    vtkSMPTools::For(0, samples, BalancedGrain(static_cast<std::size_t>(samples), 16384),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          if (static_cast<vtkIdType>(geometry.Order[i]) < n)
          {
            out[geometry.Order[i]] = phi[i];
          }
        }
      });
  }
  else
  {
    // The value at each merged point the method ran on, then at each input point its merged
    // point's.
    const vtkIdType distinct = 1 + *std::max_element(mergedId.begin(), mergedId.end());
    std::vector<double> value(static_cast<std::size_t>(distinct), 0.0);
    vtkSMPTools::For(0, samples, BalancedGrain(static_cast<std::size_t>(samples), 1024),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          if (static_cast<vtkIdType>(geometry.Order[i]) < distinct)
          {
            value[geometry.Order[i]] = phi[i];
          }
        }
      });
    vtkSMPTools::For(
      0, n, BalancedGrain(static_cast<std::size_t>(n), 1024), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          out[i] = value[mergedId[i]];
        }
      });
  }
  particles->GetPointData()->AddArray(levelSet);
}

bool UpdateParticleOutput(vtkPointSet* input, const Neighborhoods& geometry,
  const std::vector<double>& phi, const std::vector<std::size_t>& changed,
  vtkDataArray* lastLevelSet, vtkPolyData* particles, vtkSmartPointer<vtkCellArray>& vertices,
  vtkSmartPointer<vtkDoubleArray>& spare)
{
  const vtkIdType n = input->GetNumberOfPoints();
  vtkDoubleArray* last = vtkDoubleArray::SafeDownCast(lastLevelSet);
  if (!last || last->GetNumberOfComponents() != 1 || last->GetNumberOfTuples() != n)
  {
    return false;
  }
  PassParticles(input, particles, vertices);
  const vtkSmartPointer<vtkDoubleArray> levelSet = NewLevelSet(n, spare);
  double* out = levelSet->GetPointer(0);
  const double* before = last->GetPointer(0);
  CopyInParallel(before, static_cast<std::size_t>(n), out);
  vtkSMPTools::For(0, static_cast<vtkIdType>(changed.size()), BalancedGrain(changed.size(), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::size_t i = changed[k];
        if (static_cast<vtkIdType>(geometry.Order[i]) < n)
        {
          out[geometry.Order[i]] = phi[i];
        }
      }
    });
  particles->GetPointData()->AddArray(levelSet);
  return true;
}

} // namespace lsi
