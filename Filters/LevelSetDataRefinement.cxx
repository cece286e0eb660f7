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
  out.FitSize = fitCount;
  // (Every row is written below, by the thread that refines its point: their pages fault in
  // there, on every thread, not here on one.)
  out.FitSamples.resize(fitCount * count);
  out.FitModels.resize(ModelSize * count);
  vtkSMPThreadLocal<std::shared_ptr<MLSEvaluator>> evaluators;
  vtkSMPThreadLocal<std::size_t> moved(0);
  auto slide = [&](std::size_t begin, std::size_t end) {
    std::shared_ptr<MLSEvaluator>& evaluator = evaluators.Local();
    if (!evaluator)
    {
      evaluator.reset(new MLSEvaluator(
        geometry, dataOffsets, fitCount, settings.DataFitOrder == 2, fitCount / DataSpareFraction));
    }
    for (std::size_t i = begin; i < end; ++i)
    {
      Eigen::Vector3d p(&out.Points[3 * i]);
      const Eigen::Vector3d n(&out.Normals[3 * i]);
      Eigen::Vector3d gradient;
      // The point moves less than a spacing: the samples nearest its start serve every step.
      evaluator->Gather(p);
      Eigen::Matrix3d lastHessian = Eigen::Matrix3d::Zero();
      Eigen::Vector3d evaluatedAt = p;
      auto evaluate = [&](const Eigen::Vector3d& x, double& value, Eigen::Vector3d& g,
                        Eigen::Matrix3d& hessian) {
        evaluatedAt = x;
        const bool ok = evaluator->FitGathered(x, value, g, hessian);
        lastHessian = hessian;
        return ok;
      };
      if (SlideOntoDataLevel(p, n, evaluate, settings.DataMaximumMove, settings.DataIterations,
            gradient, DataConvergedStep * settings.DataMaximumMove))
      {
        // The last fit's model where the point ended, for a later slide.
        StoreModel(
          gradient + lastHessian * (p - evaluatedAt), lastHessian, &out.FitModels[ModelSize * i]);
        const Eigen::Vector3d dataNormal = -gradient.normalized();
        for (int d = 0; d < 3; ++d)
        {
          out.Points[3 * i + d] = p[d];
          out.Normals[3 * i + d] = dataNormal[d];
        }
        ++moved.Local();
      }
      else
      {
        std::fill_n(&out.FitModels[ModelSize * i], ModelSize, 0.0);
      }
      // The samples nearest the final point, kept for the arrays interpolated there: usually
      // found among the gathered ones and their spares (checked, not assumed), else searched.
      evaluator->Gather(p);
      const MLSStencil& gathered = evaluator->Gathered();
      for (std::size_t j = 0; j < fitCount; ++j)
      {
        out.FitSamples[fitCount * i + j] = j < gathered.Found() ? gathered.Sample(j) : NoSample;
      }
    }
  };
  if (!ParallelForInBlocks(count, slide, aborted, IsopointBlock))
  {
    out.FitSamples.clear();
    out.FitModels.clear();
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
  std::vector<char> onLevel(count, 0);
  auto slide = [&](std::size_t begin, std::size_t end) {
    SPHPointGroup group;
    SPHCandidates candidates;
    for (std::size_t i = begin; i < end; ++i)
    {
      // The reach is local: the kernel support of the sample nearest to the point. At a free
      // boundary the field's level lies up to a support beyond the outermost particles, where
      // the level set (which lives on the particles) cannot reach. One gather serves a group
      // of consecutive points (each then takes its own candidates from it).
      group.Hold(field, out.Points.data(), i, end, [&](std::size_t k) {
        std::uint32_t nearest;
        double d2;
        geometry.Index->Nearest(&out.Points[3 * k], 1, &nearest, &d2);
        return settings.SPHMaximumMove * field.Support(nearest);
      });
      Eigen::Vector3d p(&out.Points[3 * i]);
      const Eigen::Vector3d n(&out.Normals[3 * i]);
      const double reach = group.Reach(i);
      Eigen::Vector3d normal;
      if (GatherAndSolveOntoLevel(
            field, isoValue, p, n, reach, candidates, normal, &group.Candidates))
      {
        for (int d = 0; d < 3; ++d)
        {
          out.Points[3 * i + d] = p[d];
          out.Normals[3 * i + d] = normal[d];
        }
        onLevel[i] = 1;
      }
    }
  };
  if (!ParallelForInBlocks(count, slide, aborted, IsopointBlock))
  {
    return false;
  }
  // A point with no level of the field within a support of it is not on the surface: drop it.
  const std::vector<std::size_t> kept = ValidIndices(onLevel);
  IsopointSet refined;
  AppendSelected(out.Points, out.Normals, kept, refined);
  out.Points.swap(refined.Points);
  out.Normals.swap(refined.Normals);
  out.DataRefinedCount = kept.size();
  out.DroppedCount = count - kept.size();
  return true;
}

} // namespace lsi
