// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The volume and area that a synthetic case's exact level encloses, for scoring the Enclosed
// table: its analytic field sampled on a fine grid over the case's box, contoured (Flying Edges)
// and measured (vtkMassProperties). At 360 points a side on the paper's case (a grid spacing of
// a third of a particle spacing at 2M) the volume lies 2.5e-4 and the area 1.6e-4 below their
// limits (their second-order convergence from 360 and 480 points a side), a tenth of the
// filter's own errors there. Every component the level has in the box counts.
#ifndef ExactEnclosed_h
#define ExactEnclosed_h

#include "SyntheticCases.h"

#include "vtkDoubleArray.h"
#include "vtkFlyingEdges3D.h"
#include "vtkImageData.h"
#include "vtkMassProperties.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSMPTools.h"

namespace lsi
{
namespace cases
{

struct Enclosed
{
  double Volume = 0.0, Area = 0.0;
};

inline Enclosed ExactEnclosed(const Case& c, double isoValue, int pointsPerSide = 360)
{
  const int n = pointsPerSide;
  vtkNew<vtkImageData> image;
  image->SetDimensions(n, n, n);
  image->SetOrigin(c.BoxMin.data());
  const Eigen::Vector3d spacing = (c.BoxMax - c.BoxMin) / (n - 1);
  image->SetSpacing(spacing.data());
  vtkNew<vtkDoubleArray> values;
  values->SetName("f");
  values->SetNumberOfTuples(static_cast<vtkIdType>(n) * n * n);
  vtkSMPTools::For(0, values->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      const vtkIdType i = id % n, j = (id / n) % n, k = id / (static_cast<vtkIdType>(n) * n);
      const Eigen::Vector3d x = c.BoxMin + Eigen::Vector3d(i, j, k).cwiseProduct(spacing);
      values->SetValue(id, c.Value(x));
    }
  });
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetValue(0, isoValue);
  contour->ComputeNormalsOff();
  vtkNew<vtkMassProperties> measure;
  measure->SetInputConnection(contour->GetOutputPort());
  measure->Update();
  Enclosed exact;
  exact.Volume = measure->GetVolume();
  exact.Area = measure->GetSurfaceArea();
  return exact;
}

} // namespace cases
} // namespace lsi

#endif
