// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetIsopoints.h"

#include "AutomaticParameters.h"
#include "LevelSetMLSFit.h"
#include "LevelSetSPHField.h"

#include "vtkSMPThreadLocal.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace lsi
{

bool RefineIsopointsOnData(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  const std::size_t count = out.Points.size() / 3;
  const std::size_t fitCount = std::min<std::size_t>(
    geometry.NumberOfSamples, static_cast<std::size_t>(settings.DataFitScale) * geometry.Stride);
  vtkSMPThreadLocal<std::shared_ptr<MLSEvaluator>> evaluators;
  vtkSMPThreadLocal<std::size_t> moved(0);
  auto slide = [&](std::size_t begin, std::size_t end) {
    std::shared_ptr<MLSEvaluator>& evaluator = evaluators.Local();
    if (!evaluator)
    {
      evaluator.reset(new MLSEvaluator(geometry, dataOffsets, fitCount));
    }
    for (std::size_t i = begin; i < end; ++i)
    {
      Eigen::Vector3d p(&out.Points[3 * i]);
      const Eigen::Vector3d n(&out.Normals[3 * i]);
      Eigen::Vector3d gradient;
      // The point moves less than a spacing: the samples nearest its start serve every step.
      evaluator->Gather(p);
      auto evaluate = [&](const Eigen::Vector3d& x, double& value, Eigen::Vector3d& g) {
        return evaluator->FitGathered(x, value, g);
      };
      if (SlideOntoDataLevel(
            p, n, evaluate, settings.DataMaximumMove, settings.DataIterations, gradient))
      {
        const Eigen::Vector3d dataNormal = -gradient.normalized();
        for (int d = 0; d < 3; ++d)
        {
          out.Points[3 * i + d] = p[d];
          out.Normals[3 * i + d] = dataNormal[d];
        }
        ++moved.Local();
      }
    }
  };
  if (!ParallelForInBlocks(count, slide, aborted, IsopointBlock))
  {
    return false;
  }
  out.DataRefinedCount = 0;
  for (std::size_t m : moved)
  {
    out.DataRefinedCount += m;
  }
  return true;
}
bool RefineIsopointsOnSPHField(const Neighborhoods& geometry, const SPHField& field,
  double isoValue, const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  const std::size_t count = out.Points.size() / 3;
  vtkSMPThreadLocal<std::size_t> moved(0);
  const int neighbors = geometry.Stride - 1;
  auto slide = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i)
    {
      Eigen::Vector3d p(&out.Points[3 * i]);
      const Eigen::Vector3d n(&out.Normals[3 * i]);
      // The reach is local: the spacing of the sample nearest to the point, so a point in a
      // sparse region (where the level set is coarse) may move as far as that region needs.
      std::uint32_t nearest;
      double d2;
      geometry.Index->Nearest(p.data(), 1, &nearest, &d2);
      const double reach = settings.SPHMaximumMove *
        SpacingFromNeighborhoodRadius(geometry.Radius[nearest], neighbors);
      auto evaluate = [&](const Eigen::Vector3d& x, double& value, Eigen::Vector3d& g) {
        field.Evaluate(x.data(), value, g.data());
        value -= isoValue;
        return std::isfinite(value);
      };
      Eigen::Vector3d gradient;
      if (SlideOntoDataLevel(p, n, evaluate, reach, settings.SPHIterations, gradient))
      {
        // The normal of the field where the point ended, not where the last step started.
        double value;
        field.Evaluate(p.data(), value, gradient.data());
        if (gradient.squaredNorm() > 0.0)
        {
          const Eigen::Vector3d normal = -gradient.normalized();
          for (int d = 0; d < 3; ++d)
          {
            out.Points[3 * i + d] = p[d];
            out.Normals[3 * i + d] = normal[d];
          }
          ++moved.Local();
        }
      }
    }
  };
  if (!ParallelForInBlocks(count, slide, aborted, IsopointBlock))
  {
    return false;
  }
  out.DataRefinedCount = 0;
  for (std::size_t m : moved)
  {
    out.DataRefinedCount += m;
  }
  return true;
}

} // namespace lsi
