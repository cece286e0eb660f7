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

#include "GridRoute.h"
#include "SurfaceMetrics.h"
#include "SyntheticCases.h"

#include "vtkContourFilter.h"
#include "vtkDelaunay3D.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
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
  std::vector<Eigen::Vector3d> seeds;
  for (const Sphere3& seed : c.Seeds)
  {
    seeds.push_back(seed.Center);
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(PiecesNearSeeds(contour->GetOutputPort(), seeds));
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->Update();
  result.ConnectivitySeconds = seconds(start);
  TriangleVertices(normals->GetOutput(), result.Points, result.Normals);
  // Unsigned: each normal with the sign that agrees with the exact outward normal (-grad f).
  for (std::size_t i = 0; i < result.Points.size() / 3; ++i)
  {
    const Eigen::Vector3d outward = -c.Gradient(Eigen::Vector3d(&result.Points[3 * i]));
    if (Eigen::Vector3d(&result.Normals[3 * i]).dot(outward) < 0.0)
    {
      for (int d = 0; d < 3; ++d)
      {
        result.Normals[3 * i + d] = -result.Normals[3 * i + d];
      }
    }
  }
  return MeasureSurface(c, result.Points, result.Normals, samples, surfaceSpacing);
}

} // namespace cases
} // namespace lsi

#endif
