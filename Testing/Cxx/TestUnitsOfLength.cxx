// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// No unit of length: the paper's one-component case at 200,000 samples with every length (the
// positions, the seed) multiplied by 0.001, 1 and 1000 gives the same surface in units of the
// spacing: the isopoint count within 5% and the mean distance to the exact surface within 20%
// (before the curvature weight was made relative to the spacing, x0.001 gave 511,888 isopoints
// against 9,402 at x1).
#include "CaseRuns.h"
#include "SyntheticParticles.h"
#include "TestCheck.h"

#include "vtkPoints.h"

#include <cstdlib>
#include <iostream>

int main()
{
  using namespace lsi::cases;
  using lsi::test::Check;
  const std::unique_ptr<Case> c = MakeCase("one-component");
  const std::size_t count = 200000;
  const std::vector<Eigen::Vector3d> samples = c->Samples(count, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  const double spacing = c->SurfaceSpacing(count);
  double referenceCount = 0.0, referenceDistance = 0.0;
  for (double scale : { 1.0, 0.001, 1000.0 })
  {
    vtkNew<vtkPolyData> scaled;
    scaled->ShallowCopy(particles);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(particles->GetNumberOfPoints());
    for (vtkIdType i = 0; i < particles->GetNumberOfPoints(); ++i)
    {
      double x[3];
      particles->GetPoint(i, x);
      points->SetPoint(i, scale * x[0], scale * x[1], scale * x[2]);
    }
    scaled->SetPoints(points);
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(scaled);
    SetCaseInputs(filter, *c);
    const Eigen::Vector3d centre = scale * c->Seeds[0].Center;
    filter->SetSeedCenter(centre.data());
    filter->SetSeedRadius(scale * c->Seeds[0].Radius);
    filter->SetOutputTypeToIsopoints();
    filter->Update();
    std::vector<double> isopoints, normals;
    IsopointArrays(filter->GetOutput(0), isopoints, normals);
    for (double& v : isopoints)
    {
      v /= scale; // back to the case's own units, where its exact surface is known
    }
    const SurfaceMetrics m = MeasureSurface(*c, isopoints, normals, samples, spacing);
    std::cout << "lengths x" << scale << ": " << m.Isopoints << " isopoints, mean distance "
              << m.MeanDistance / spacing << " spacings, normal error " << m.MeanNormalAngleDegrees
              << " deg\n";
    if (scale == 1.0)
    {
      referenceCount = static_cast<double>(m.Isopoints);
      referenceDistance = m.MeanDistance;
      continue;
    }
    Check(std::abs(m.Isopoints / referenceCount - 1.0) <= 0.05,
      "lengths x" + std::to_string(scale) + ": isopoint count within 5% of x1");
    Check(std::abs(m.MeanDistance / referenceDistance - 1.0) <= 0.2,
      "lengths x" + std::to_string(scale) + ": mean distance within 20% of x1");
  }
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
