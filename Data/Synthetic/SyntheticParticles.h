// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Turns samples of an analytic case into VTK particles: double points and the scalar "f".
// Shared by the data generator and the benchmark.
#ifndef SyntheticParticles_h
#define SyntheticParticles_h

#include "SyntheticCases.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <vector>

namespace lsi
{
namespace cases
{

/// Values are c.MeasuredValue (exact, or noisy for a noisy case: `seed` fixes the noise).
inline vtkSmartPointer<vtkPolyData> MakeParticles(
  const Case& c, const std::vector<Eigen::Vector3d>& samples, std::uint64_t seed = 7)
{
  std::mt19937_64 random(seed);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(samples.size()));
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  f->SetNumberOfValues(static_cast<vtkIdType>(samples.size()));
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    points->SetPoint(static_cast<vtkIdType>(i), samples[i].data());
    f->SetValue(static_cast<vtkIdType>(i), c.MeasuredValue(samples[i], random));
  }
  auto particles = vtkSmartPointer<vtkPolyData>::New();
  particles->SetPoints(points);
  particles->GetPointData()->SetScalars(f);
  return particles;
}

} // namespace cases
} // namespace lsi

#endif
