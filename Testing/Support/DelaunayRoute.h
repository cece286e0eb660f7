// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A grid-free route a ParaView user can take on points without smoothing lengths: tetrahedra
// through the samples (vtkDelaunay3D), the isosurface of the linear interpolation on them
// (vtkContourFilter), the connected piece nearest each seed (vtkPolyDataConnectivityFilter),
// and vertex normals from the triangles (vtkPolyDataNormals: their sign is the triangles'
// order, so they are scored unsigned). Slow (minutes at 200,000 samples): the benchmark runs it
// only where asked (LevelSetCompare --methods ...,delaunay).
#ifndef DelaunayRoute_h
#define DelaunayRoute_h

#include "SurfaceMetrics.h"
#include "SyntheticCases.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkContourFilter.h"
#include "vtkDataArray.h"
#include "vtkDelaunay3D.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkPolyDataNormals.h"

#include <Eigen/Dense>

#include <chrono>
#include <vector>

namespace lsi
{
namespace cases
{

struct DelaunayRouteResult
{
  std::vector<double> Points, Normals; // 3 per mesh vertex
  double TetrahedraSeconds = 0.0, ContourSeconds = 0.0, ConnectivitySeconds = 0.0;
  double TotalSeconds() const
  {
    return this->TetrahedraSeconds + this->ContourSeconds + this->ConnectivitySeconds;
  }
};

/// The route on the case's particles ("f"), scored like the filter with each normal's sign
/// taken towards the exact one (unsigned normal error).
inline SurfaceMetrics RunAndMeasureDelaunayRoute(vtkPolyData* particles, const Case& c,
  const std::vector<Eigen::Vector3d>& samples, double surfaceSpacing, DelaunayRouteResult& result)
{
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  auto start = Clock::now();
  vtkNew<vtkDelaunay3D> delaunay;
  delaunay->SetInputData(particles);
  delaunay->Update();
  result.TetrahedraSeconds = seconds(start);

  start = Clock::now();
  vtkNew<vtkContourFilter> contour;
  contour->SetInputConnection(delaunay->GetOutputPort());
  contour->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  contour->SetValue(0, c.IsoValue);
  contour->ComputeScalarsOff();
  contour->Update();
  result.ContourSeconds = seconds(start);

  start = Clock::now();
  vtkNew<vtkAppendPolyData> pieces;
  for (const Sphere3& seed : c.Seeds)
  {
    vtkNew<vtkPolyDataConnectivityFilter> connectivity;
    connectivity->SetInputConnection(contour->GetOutputPort());
    connectivity->SetExtractionModeToClosestPointRegion();
    connectivity->SetClosestPoint(seed.Center.x(), seed.Center.y(), seed.Center.z());
    connectivity->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(connectivity->GetOutput());
    pieces->AddInputData(piece);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(pieces->GetOutputPort());
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->Update();
  result.ConnectivitySeconds = seconds(start);

  vtkPolyData* mesh = normals->GetOutput();
  vtkDataArray* n = mesh->GetPointData()->GetNormals();
  std::vector<char> used(mesh->GetNumberOfPoints(), 0);
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    for (vtkIdType k = 0; k < count; ++k)
    {
      used[ids[k]] = 1;
    }
  }
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    if (!used[i])
    {
      continue;
    }
    double x[3], v[3] = { 0, 0, 0 };
    mesh->GetPoint(i, x);
    if (n)
    {
      n->GetTuple(i, v);
    }
    // Unsigned: the sign that agrees with the exact outward normal (-grad f).
    const Eigen::Vector3d outward = -c.Gradient(Eigen::Vector3d(x));
    const double sign = Eigen::Vector3d(v).dot(outward) < 0.0 ? -1.0 : 1.0;
    result.Points.insert(result.Points.end(), x, x + 3);
    result.Normals.insert(result.Normals.end(), { sign * v[0], sign * v[1], sign * v[2] });
  }
  return MeasureSurface(c, result.Points, result.Normals, samples, surfaceSpacing);
}

} // namespace cases
} // namespace lsi

#endif
