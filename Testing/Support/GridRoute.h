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

/// The grid route in its three steps, each re-runnable on its own as ParaView re-runs a
/// pipeline: an isovalue change re-contours the kept grid (and re-connects), a seed move only
/// re-connects. Each step returns its seconds.
class GridRouteSession
{
public:
  /// Grid over the particles' bounds with spacing `spacing`, which is also the kernel's spatial
  /// step. Shepard normalisation is on: without mass and density arrays it is what makes the
  /// interpolant a weighted average (off, values scale with the local particle count).
  GridRouteSession(
    vtkPolyData* particles, const std::string& arrayName, double spacing, int threads)
    : Particles(particles)
    , ArrayName(arrayName)
    , Spacing(spacing)
    , Threads(threads)
  {
  }

  double Interpolate()
  {
    return this->Timed([&]() {
      double bounds[6];
      this->Particles->GetBounds(bounds);
      vtkNew<vtkImageData> grid;
      int dims[3];
      for (int k = 0; k < 3; ++k)
      {
        dims[k] =
          static_cast<int>(std::ceil((bounds[2 * k + 1] - bounds[2 * k]) / this->Spacing)) + 1;
      }
      grid->SetDimensions(dims);
      grid->SetOrigin(bounds[0], bounds[2], bounds[4]);
      grid->SetSpacing(this->Spacing, this->Spacing, this->Spacing);
      this->GridPoints = static_cast<long long>(dims[0]) * dims[1] * dims[2];

      vtkNew<vtkSPHQuinticKernel> kernel;
      kernel->SetSpatialStep(this->Spacing);
      vtkNew<vtkStaticPointLocator> locator;
      vtkNew<vtkSPHInterpolator> interpolator;
      interpolator->SetInputData(grid);
      interpolator->SetSourceData(this->Particles);
      interpolator->SetKernel(kernel);
      interpolator->SetLocator(locator);
      interpolator->SetShepardNormalization(true);
      interpolator->SetNullPointsStrategyToNullValue();
      interpolator->Update();
      this->Grid = vtkSmartPointer<vtkImageData>::New();
      this->Grid->ShallowCopy(interpolator->GetOutput());
    });
  }

  double Contour(double isoValue)
  {
    return this->Timed([&]() {
      this->Contourer->SetInputData(this->Grid);
      this->Contourer->SetInputArrayToProcess(
        0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, this->ArrayName.c_str());
      this->Contourer->SetValue(0, isoValue);
      this->Contourer->ComputeNormalsOn();
      this->Contourer->ComputeScalarsOff();
      this->Contourer->Update();
    });
  }

  double Connect(const std::vector<Eigen::Vector3d>& seeds)
  {
    return this->Timed(
      [&]() { this->Mesh = PiecesNearSeeds(this->Contourer->GetOutputPort(), seeds); });
  }

  vtkPolyData* GetMesh() const { return this->Mesh; }
  long long GetGridPoints() const { return this->GridPoints; }

private:
  template <typename Step>
  double Timed(Step&& step)
  {
    const auto start = std::chrono::steady_clock::now();
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ this->Threads, "STDThread", false }, step);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  vtkPolyData* Particles;
  std::string ArrayName;
  double Spacing;
  int Threads;
  long long GridPoints = 0;
  vtkSmartPointer<vtkImageData> Grid;
  vtkNew<vtkFlyingEdges3D> Contourer;
  vtkSmartPointer<vtkPolyData> Mesh;
};

/// The whole grid route once: interpolation, contour, the pieces nearest the seeds.
inline GridRouteResult RunGridRoute(vtkPolyData* particles, const std::string& arrayName,
  double isoValue, const std::vector<Eigen::Vector3d>& seeds, double spacing, int threads)
{
  GridRouteResult result;
  GridRouteSession session(particles, arrayName, spacing, threads);
  result.InterpolationSeconds = session.Interpolate();
  result.ContourSeconds = session.Contour(isoValue);
  result.ConnectivitySeconds = session.Connect(seeds);
  result.GridPoints = session.GetGridPoints();
  TriangleVertices(session.GetMesh(), result.Points, result.Normals);
  return result;
}

} // namespace lsi

#endif
