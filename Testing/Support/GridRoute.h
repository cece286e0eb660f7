// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What a ParaView user does today to get an isosurface from particles: SPH interpolation onto a
// regular grid (vtkSPHInterpolator, quintic kernel), contouring (vtkFlyingEdges3D), and keeping
// the connected piece nearest each seed (vtkPolyDataConnectivityFilter). The benchmark runs it
// on the same particles as the level-set filter, in the same process.
#ifndef GridRoute_h
#define GridRoute_h

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataConnectivityFilter.h"
#include "vtkSMPTools.h"
#include "vtkSPHInterpolator.h"
#include "vtkSPHQuinticKernel.h"
#include "vtkSmartPointer.h"
#include "vtkStaticPointLocator.h"

#include <Eigen/Dense>

#include <chrono>
#include <cmath>
#include <string>
#include <vector>

namespace lsi
{

struct GridRouteResult
{
  std::vector<double> Points, Normals; // 3 per mesh vertex; normals point out of f > f_iso
  long long GridPoints = 0;
  double InterpolationSeconds = 0.0, ContourSeconds = 0.0, ConnectivitySeconds = 0.0;
  double TotalSeconds() const
  {
    return this->InterpolationSeconds + this->ContourSeconds + this->ConnectivitySeconds;
  }
};

/// The connected pieces of a contour nearest each seed (vtkPolyDataConnectivityFilter), appended.
inline vtkSmartPointer<vtkPolyData> PiecesNearSeeds(
  vtkAlgorithmOutput* contour, const std::vector<Eigen::Vector3d>& seeds)
{
  vtkNew<vtkAppendPolyData> pieces;
  for (const Eigen::Vector3d& seed : seeds)
  {
    vtkNew<vtkPolyDataConnectivityFilter> connectivity;
    connectivity->SetInputConnection(contour);
    connectivity->SetExtractionModeToClosestPointRegion();
    connectivity->SetClosestPoint(seed.x(), seed.y(), seed.z());
    connectivity->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(connectivity->GetOutput());
    pieces->AddInputData(piece);
  }
  pieces->Update();
  return pieces->GetOutput();
}

/// The vertices of a mesh's polygons and their normals (zero without normals): the connectivity
/// filter may keep unused points.
inline void TriangleVertices(
  vtkPolyData* mesh, std::vector<double>& points, std::vector<double>& normals)
{
  vtkDataArray* meshNormals = mesh->GetPointData()->GetNormals();
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
    double x[3], n[3] = { 0, 0, 0 };
    mesh->GetPoint(i, x);
    if (meshNormals)
    {
      meshNormals->GetTuple(i, n);
    }
    points.insert(points.end(), x, x + 3);
    normals.insert(normals.end(), n, n + 3);
  }
}

/// Grid over the particles' bounds with spacing `spacing`, which is also the kernel's spatial
/// step. Shepard normalisation is on: without mass and density arrays it is what makes the
/// interpolant a weighted average (off, values scale with the local particle count).
inline GridRouteResult RunGridRoute(vtkPolyData* particles, const std::string& arrayName,
  double isoValue, const std::vector<Eigen::Vector3d>& seeds, double spacing, int threads)
{
  GridRouteResult result;
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    auto start = Clock::now();
    double bounds[6];
    particles->GetBounds(bounds);
    vtkNew<vtkImageData> grid;
    int dims[3];
    for (int k = 0; k < 3; ++k)
    {
      dims[k] = static_cast<int>(std::ceil((bounds[2 * k + 1] - bounds[2 * k]) / spacing)) + 1;
    }
    grid->SetDimensions(dims);
    grid->SetOrigin(bounds[0], bounds[2], bounds[4]);
    grid->SetSpacing(spacing, spacing, spacing);
    result.GridPoints = static_cast<long long>(dims[0]) * dims[1] * dims[2];

    vtkNew<vtkSPHQuinticKernel> kernel;
    kernel->SetSpatialStep(spacing);
    vtkNew<vtkStaticPointLocator> locator;
    vtkNew<vtkSPHInterpolator> interpolator;
    interpolator->SetInputData(grid);
    interpolator->SetSourceData(particles);
    interpolator->SetKernel(kernel);
    interpolator->SetLocator(locator);
    interpolator->SetShepardNormalization(true);
    interpolator->SetNullPointsStrategyToNullValue();
    interpolator->Update();
    result.InterpolationSeconds = seconds(start);

    start = Clock::now();
    vtkNew<vtkFlyingEdges3D> contour;
    contour->SetInputConnection(interpolator->GetOutputPort());
    contour->SetInputArrayToProcess(
      0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, arrayName.c_str());
    contour->SetValue(0, isoValue);
    contour->ComputeNormalsOn();
    contour->ComputeScalarsOff();
    contour->Update();
    result.ContourSeconds = seconds(start);

    start = Clock::now();
    vtkSmartPointer<vtkPolyData> mesh = PiecesNearSeeds(contour->GetOutputPort(), seeds);
    result.ConnectivitySeconds = seconds(start);
    TriangleVertices(mesh, result.Points, result.Normals);
  });
  return result;
}

} // namespace lsi

#endif
