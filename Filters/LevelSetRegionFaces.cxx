// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetRegionFaces.h"

#include "NearestNeighbors.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkPointSet.h"
#include "vtkSMPTools.h"
#include "vtkVariant.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace lsi
{

RegionFaces FindRegionFaces(vtkPointSet* input, const PeriodicBox& box)
{
  RegionFaces region;
  vtkFieldData* fields = input ? input->GetFieldData() : nullptr;
  vtkDataArray* bounds = fields ? fields->GetArray("RegionBounds") : nullptr;
  vtkDataArray* period = fields ? fields->GetArray("RegionPeriod") : nullptr;
  if (!bounds || bounds->GetNumberOfValues() != 6)
  {
    return region;
  }
  for (int k = 0; k < 6; ++k)
  {
    region.Bounds[k] = bounds->GetVariantValue(k).ToDouble(); // (values of one array, as BoxSize)
  }
  for (int a = 0; a < 3; ++a)
  {
    const double wrapped =
      period && period->GetNumberOfValues() == 3 ? period->GetVariantValue(a).ToDouble() : 0.0;
    const double p = wrapped > 0.0 ? wrapped : (box.Enabled ? box.Size[a] : 0.0);
    region.Period[a] = p > 0.0 && std::isfinite(p) ? p : 0.0;
    const double low = region.Bounds[2 * a], high = region.Bounds[2 * a + 1];
    region.HasFaces[a] = low <= high && !(region.Period[a] > 0.0 && high - low >= region.Period[a]);
  }
  region.Known = true;
  return region;
}

double DistanceToRegionFaces(const double x[3], const RegionFaces& region)
{
  double nearest = HUGE_VAL;
  for (int a = 0; a < 3 && region.Known; ++a)
  {
    if (!region.HasFaces[a])
    {
      continue;
    }
    for (int side = 0; side < 2; ++side)
    {
      double d = std::abs(x[a] - region.Bounds[2 * a + side]);
      if (region.Period[a] > 0.0)
      {
        d = std::fmod(d, region.Period[a]);
        d = std::min(d, region.Period[a] - d);
      }
      nearest = std::min(nearest, d);
    }
  }
  return nearest;
}

std::size_t PointsNearRegionFaces(const Neighborhoods& geometry, const SPHField* field,
  const std::vector<double>& points, const RegionFaces& region)
{
  const std::size_t count = points.size() / 3;
  if (!region.Known || count == 0 || geometry.NumberOfSamples == 0)
  {
    return 0;
  }
  std::atomic<std::size_t> near(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 1024),
    [&](vtkIdType begin, vtkIdType end) {
      std::size_t local = 0;
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double* x = &points[3 * i];
        const double distance = DistanceToRegionFaces(x, region);
        if (!(distance < HUGE_VAL))
        {
          continue;
        }
        std::uint32_t sample;
        double d2;
        if (geometry.Index->Nearest(x, 1, &sample, &d2) != 1)
        {
          continue;
        }
        const double reach = field ? field->Support(sample) : 2.0 * geometry.RadiusOf(sample);
        local += distance < reach ? 1 : 0;
      }
      near += local;
    });
  return near;
}

} // namespace lsi
