// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A plain VTK C++ pipeline using the filter without ParaView's server manager: random particles
// with f = 30 - |x - c|, the level-set isosurface of f = 0 (a sphere of radius 30), written as a
// binary .vtp. Exits non-zero if the isopoints are not on the sphere.
//   LevelSetExample [OUTPUT.vtp]
#include "vtkLevelSetIsosurface.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMinimalStandardRandomSequence.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cmath>
#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  const vtkIdType count = 50000;
  vtkNew<vtkMinimalStandardRandomSequence> random;
  random->SetSeed(7);
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> f;
  f->SetName("f");
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3];
    for (double& v : x)
    {
      v = random->GetNextRangeValue(0.0, 100.0);
    }
    points->InsertNextPoint(x);
    f->InsertNextValue(30.0 -
      std::sqrt((x[0] - 50) * (x[0] - 50) + (x[1] - 50) * (x[1] - 50) + (x[2] - 50) * (x[2] - 50)));
  }
  vtkNew<vtkPolyData> particles;
  particles->SetPoints(points);
  particles->GetPointData()->AddArray(f);

  vtkNew<vtkLevelSetIsosurface> isosurface;
  isosurface->SetInputData(particles);
  isosurface->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "f");
  isosurface->SetIsoValue(0.0);
  isosurface->SetSeedCenter(50, 50, 50);
  isosurface->SetSeedRadius(10);
  isosurface->SetOutputTypeToIsopoints(); // the points themselves, to measure them
  isosurface->Update();
  vtkPolyData* isopoints = isosurface->GetOutput(0);

  const vtkIdType m = isopoints->GetNumberOfPoints();
  double worst = 0.0;
  for (vtkIdType i = 0; i < m; ++i)
  {
    double p[3];
    isopoints->GetPoint(i, p);
    const double r =
      std::sqrt((p[0] - 50) * (p[0] - 50) + (p[1] - 50) * (p[1] - 50) + (p[2] - 50) * (p[2] - 50));
    worst = std::max(worst, std::abs(r - 30.0));
  }
  std::cout << m << " isopoints after " << isosurface->GetNumberOfIterationsPerformed()
            << " iterations; largest distance to the sphere " << worst << " (sample spacing "
            << isosurface->GetMeanSampleSpacing() << ")\n";
  if (argc > 1)
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputConnection(isosurface->GetOutputPort(0));
    writer->SetDataModeToBinary();
    writer->SetFileName(argv[1]);
    writer->Write();
  }
  const bool ok = m > 1000 && isopoints->GetPointData()->GetArray("Normals") &&
    worst < isosurface->GetMeanSampleSpacing();
  return ok ? EXIT_SUCCESS : EXIT_FAILURE;
}
