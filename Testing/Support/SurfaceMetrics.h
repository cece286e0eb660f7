// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Accuracy of isopoints against an analytic case: the paper's L (mean first-order distance
// |f(p) - f_iso| / |grad f(p)|), its 99th percentile, normal errors, coverage of the exact
// surface of the seeded components, and isopoints lying on unseeded components.
#ifndef SurfaceMetrics_h
#define SurfaceMetrics_h

#include "SyntheticCases.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lsi
{
namespace cases
{

struct SurfaceMetrics
{
  std::size_t Isopoints = 0;
  double MeanDistance = 0.0; // the paper's L
  double Percentile99Distance = 0.0;
  double MeanNormalAngleDegrees = 0.0;
  double MaxNormalLengthError = 0.0; // max | |n| - 1 |
  std::size_t UnseededIsopoints = 0; // isopoints on components that the seeds do not meet
  std::size_t SurfaceProbes = 0;     // exact surface points of seeded components checked
  double MaxGapToIsopoint = 0.0;     // the farthest any of them is from an isopoint
  double CoveredFraction = 0.0;      // fraction within `coverageRadius`
  // The mean distance to the surface of the isopoint nearest to each probe: MeanDistance
  // weighed by the surface's area instead of by where the isopoints crowd.
  double MeanDistanceOverSurface = 0.0;
};

/// `points`, `normals`: 3 per isopoint. `samples`: the sample positions (exact surface probes
/// are the samples within `coverageRadius` of the surface, projected onto it).
inline SurfaceMetrics MeasureSurface(const Case& c, const std::vector<double>& points,
  const std::vector<double>& normals, const std::vector<Eigen::Vector3d>& samples,
  double coverageRadius)
{
  SurfaceMetrics m;
  const std::size_t count = points.size() / 3;
  m.Isopoints = count;
  std::vector<double> distances(count);
  double angleSum = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const Eigen::Vector3d p(&points[3 * i]);
    const Eigen::Vector3d g = c.Gradient(p);
    distances[i] = std::abs(c.Value(p) - c.IsoValue) / g.norm();
    const Eigen::Vector3d n(&normals[3 * i]);
    m.MaxNormalLengthError = std::max(m.MaxNormalLengthError, std::abs(n.norm() - 1.0));
    const double cosine = std::max(-1.0, std::min(1.0, n.normalized().dot(-g.normalized())));
    angleSum += std::acos(cosine) * 180.0 / 3.14159265358979323846;
    m.UnseededIsopoints += !c.Seeded(c.Component(p));
  }
  if (count)
  {
    double sum = 0.0;
    for (double d : distances)
    {
      sum += d;
    }
    m.MeanDistance = sum / count;
    m.MeanNormalAngleDegrees = angleSum / count;
    std::vector<double> sorted = distances;
    const std::size_t k = std::min(count - 1, static_cast<std::size_t>(0.99 * count));
    std::nth_element(sorted.begin(), sorted.begin() + k, sorted.end());
    m.Percentile99Distance = sorted[k];
  }

  // The isopoints in VTK's point locator (the gaps below are measured with it).
  vtkNew<vtkPolyData> isopointSet;
  vtkNew<vtkStaticPointLocator> locator;
  if (count)
  {
    vtkNew<vtkDoubleArray> coordinates;
    coordinates->SetNumberOfComponents(3);
    coordinates->SetArray(const_cast<double*>(points.data()), static_cast<vtkIdType>(3 * count), 1);
    vtkNew<vtkPoints> isopointCoordinates;
    isopointCoordinates->SetData(coordinates);
    isopointSet->SetPoints(isopointCoordinates);
    locator->SetDataSet(isopointSet);
    locator->BuildLocator();
  }
  std::size_t covered = 0;
  double probeDistanceSum = 0.0;
  for (const Eigen::Vector3d& x : samples)
  {
    const Eigen::Vector3d g = c.Gradient(x);
    if (std::abs(c.Value(x) - c.IsoValue) >= coverageRadius * g.norm())
    {
      continue;
    }
    Eigen::Vector3d s = x;
    if (!ProjectOntoSurface(c, s) || !c.Seeded(c.Component(s)) || (s - x).norm() > coverageRadius)
    {
      continue;
    }
    ++m.SurfaceProbes;
    double gap = HUGE_VAL;
    if (count)
    {
      double nearest[3];
      const vtkIdType closest = locator->FindClosestPoint(s.data());
      isopointSet->GetPoint(closest, nearest);
      gap = (s - Eigen::Vector3d(nearest)).norm();
      probeDistanceSum += distances[static_cast<std::size_t>(closest)];
    }
    m.MaxGapToIsopoint = std::max(m.MaxGapToIsopoint, gap);
    covered += gap <= coverageRadius;
  }
  m.CoveredFraction = m.SurfaceProbes ? static_cast<double>(covered) / m.SurfaceProbes : 0.0;
  m.MeanDistanceOverSurface =
    m.SurfaceProbes && count ? probeDistanceSum / m.SurfaceProbes : HUGE_VAL;
  return m;
}

} // namespace cases
} // namespace lsi

#endif
