#include "LevelSetSurfaceAttributes.h"

#include "MovingLeastSquares.h"
#include "NearestNeighbors.h"
#include "Splats.h"

#include "vtkDataArray.h"

#include <algorithm>
#include <cmath>

namespace lsi
{

bool SplatRadii(const std::vector<double>& points, int neighbors, double factor,
  std::vector<double>& radii, const AbortCheck& aborted)
{
  const std::size_t count = points.size() / 3;
  radii.assign(count, 0.0);
  if (count < 2)
  {
    return true;
  }
  const PointCloudIndex index(points.data(), count);
  // The point itself comes first in its own query.
  const std::size_t k = std::min<std::size_t>(count, static_cast<std::size_t>(neighbors) + 1);
  return ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t> ids(k);
      std::vector<double> d2(k);
      for (std::size_t i = begin; i < end; ++i)
      {
        const std::size_t found = index.Nearest(&points[3 * i], k, ids.data(), d2.data());
        radii[i] = SplatRadiusFromNeighbors(d2.data(), found, factor);
      }
    },
    aborted);
}

bool InterpolatePointArrays(const Neighborhoods& geometry, const std::vector<double>& points,
  std::size_t fitCount, const std::vector<vtkDataArray*>& sources,
  const std::vector<vtkDataArray*>& targets, const AbortCheck& aborted)
{
  const std::size_t count = points.size() / 3;
  const std::size_t k = std::min(fitCount, geometry.NumberOfSamples);
  return ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::vector<std::uint32_t> ids(k);
      std::vector<double> d2(k), gradient(3 * k), weights(k);
      for (std::size_t i = begin; i < end; ++i)
      {
        const double* p = &points[3 * i];
        const std::size_t found = geometry.Index->Nearest(p, k, ids.data(), d2.data());
        const double h = std::sqrt(*std::max_element(d2.begin(), d2.begin() + found));
        const bool fitted = BuildLinearStencil(p, found,
          [&](std::size_t j) { return geometry.Position(ids[j]); }, h,
          LinearStencilView{ gradient.data(), weights.data() });
        if (!fitted)
        {
          std::fill(weights.begin(), weights.end(), 0.0);
          weights[0] = 1.0; // the nearest sample
        }
        for (std::size_t a = 0; a < sources.size(); ++a)
        {
          const int components = sources[a]->GetNumberOfComponents();
          for (int c = 0; c < components; ++c)
          {
            double value = 0.0;
            for (std::size_t j = 0; j < found; ++j)
            {
              if (weights[j] != 0.0)
              {
                value += weights[j] * sources[a]->GetComponent(geometry.Order[ids[j]], c);
              }
            }
            targets[a]->SetComponent(static_cast<vtkIdType>(i), c, value);
          }
        }
      }
    },
    aborted, 8192);
}

} // namespace lsi
