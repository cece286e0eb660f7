// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// No unit of length: the paper's one-component case at 200,000 samples with every length (the
// positions, the seed) multiplied by 0.001, 1, 1000, 1e+-45 and 1e+-80 gives the same surface in
// units of the spacing: the isopoint count within 5%, the mean distance to the exact surface
// within 20% and the enclosed volume within 1% (before the curvature weight was made relative
// to the spacing, x0.001 gave 511,888 isopoints against 9,402 at x1; before the gradient
// stencils were stored relative to each sample's radius, lengths beyond 1e+-30 overflowed
// their floats and were refused). The field's values times 1e+-80 give the same surface too.
#include "CaseRuns.h"
#include "SyntheticParticles.h"
#include "TestCheck.h"

#include "vtkAbstractArray.h"
#include "vtkDoubleArray.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <cstdlib>
#include <iostream>
#include <sstream>

int main()
{
  using namespace lsi::cases;
  using lsi::test::Check;
  const std::unique_ptr<Case> c = MakeCase("one-component");
  const std::size_t count = 200000;
  const std::vector<Eigen::Vector3d> samples = c->Samples(count, 1);
  vtkSmartPointer<vtkPolyData> particles = MakeParticles(*c, samples);
  const double spacing = c->SurfaceSpacing(count);
  double referenceCount = 0.0, referenceDistance = 0.0, referenceVolume = 0.0;
  for (double scale : { 1.0, 0.001, 1000.0, 1e-45, 1e45, 1e-80, 1e80 })
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
    // The Enclosed table's Total row (the last), back in the case's units.
    vtkTable* enclosed = vtkTable::SafeDownCast(filter->GetOutputDataObject(3));
    const double volume = enclosed && enclosed->GetNumberOfRows() > 0
      ? enclosed->GetValueByName(enclosed->GetNumberOfRows() - 1, "Volume").ToDouble() /
        (scale * scale * scale)
      : 0.0;
    std::vector<double> isopoints, normals;
    IsopointArrays(filter->GetOutput(0), isopoints, normals);
    for (double& v : isopoints)
    {
      v /= scale; // back to the case's own units, where its exact surface is known
    }
    const SurfaceMetrics m = MeasureSurface(*c, isopoints, normals, samples, spacing);
    std::cout << "lengths x" << scale << ": " << m.Isopoints << " isopoints, mean distance "
              << m.MeanDistance / spacing << " spacings, normal error " << m.MeanNormalAngleDegrees
              << " deg, enclosed volume " << volume << "\n";
    std::ostringstream label;
    label << "lengths x" << scale;
    if (scale == 1.0)
    {
      referenceCount = static_cast<double>(m.Isopoints);
      referenceDistance = m.MeanDistance;
      referenceVolume = volume;
      Check(volume > 0.0, "lengths x1: an enclosed volume");
      continue;
    }
    Check(std::abs(m.Isopoints / referenceCount - 1.0) <= 0.05,
      label.str() + ": isopoint count within 5% of x1");
    Check(std::abs(m.MeanDistance / referenceDistance - 1.0) <= 0.2,
      label.str() + ": mean distance within 20% of x1");
    Check(std::abs(volume / referenceVolume - 1.0) <= 0.01,
      label.str() + ": enclosed volume within 1% of x1");
  }
  // No unit of value either: the field and the isovalue times 1e+-80 give the same surface.
  for (double scale : { 1e-80, 1e80 })
  {
    vtkNew<vtkPolyData> scaled;
    scaled->ShallowCopy(particles);
    vtkNew<vtkDoubleArray> f;
    f->DeepCopy(particles->GetPointData()->GetArray("f"));
    for (vtkIdType i = 0; i < f->GetNumberOfTuples(); ++i)
    {
      f->SetValue(i, scale * f->GetValue(i));
    }
    scaled->GetPointData()->AddArray(f); // replaces "f"
    vtkNew<vtkLevelSetIsosurface> filter;
    filter->SetInputData(scaled);
    SetCaseInputs(filter, *c);
    filter->SetIsoValue(scale * c->IsoValue);
    double seconds = 0.0;
    const SurfaceMetrics m = RunAndMeasure(filter, *c, samples, spacing, seconds);
    std::ostringstream label;
    label << "values x" << scale;
    std::cout << label.str() << ": " << m.Isopoints << " isopoints, mean distance "
              << m.MeanDistance / spacing << " spacings\n";
    Check(std::abs(m.Isopoints / referenceCount - 1.0) <= 0.05,
      label.str() + ": isopoint count within 5% of x1");
    Check(std::abs(m.MeanDistance / referenceDistance - 1.0) <= 0.2,
      label.str() + ": mean distance within 20% of x1");
  }
  return lsi::test::Failures() ? EXIT_FAILURE : EXIT_SUCCESS;
}
