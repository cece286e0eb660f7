#include "LevelSetSurfaceAttributes.h"

#include "LevelSetIsopoints.h"
#include "NearestNeighbors.h"
#include "Splats.h"

#include "vtkDataArray.h"
#include "vtkSMPThreadLocal.h"

#include <algorithm>
#include <cmath>
#include <memory>

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
  vtkSMPThreadLocal<std::shared_ptr<MLSStencil>> stencils;
  return ParallelForInBlocks(
    count,
    [&](std::size_t begin, std::size_t end) {
      std::shared_ptr<MLSStencil>& stencil = stencils.Local();
      if (!stencil)
      {
        stencil.reset(new MLSStencil(geometry, fitCount));
      }
      for (std::size_t i = begin; i < end; ++i)
      {
        const Eigen::Vector3d p(&points[3 * i]);
        stencil->Gather(p);
        // A singular fit (samples on a plane or line) takes the nearest sample's value.
        const bool fitted = stencil->Build(p);
        const std::size_t used = fitted ? stencil->Found() : 1;
        for (std::size_t a = 0; a < sources.size(); ++a)
        {
          const int components = sources[a]->GetNumberOfComponents();
          for (int c = 0; c < components; ++c)
          {
            double value = 0.0;
            for (std::size_t j = 0; j < used; ++j)
            {
              const double w = fitted ? stencil->ValueWeight(j) : 1.0;
              if (w != 0.0)
              {
                value += w * sources[a]->GetComponent(geometry.Order[stencil->Sample(j)], c);
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
