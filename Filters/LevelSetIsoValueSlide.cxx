// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetIsoValueSlide.h"

#include "IsoValueShift.h"
#include "IsopointRefinement.h"
#include "LevelSetMLSFit.h"
#include "NearestNeighbors.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>

namespace lsi
{

namespace
{
// Why a point refused to slide (the first reason met is reported).
enum Refusal : int
{
  None = 0,
  NoCrossing = 1, // the data's gradient does not point across the surface
  TooFar = 2,     // the level is MaximumMove or more away
  OneSide = 3     // its nearest samples all lie inside the new flood, or all outside
};

const char* RefusalText(int refusal)
{
  switch (refusal)
  {
    case NoCrossing:
      return "the data's gradient at a point no longer crosses the surface";
    case TooFar:
      return "a point would move further than the refinement's reach";
    case OneSide:
      return "a point's nearest samples lie all inside or all outside the new flood";
    default:
      return "";
  }
}
// What each thread of a slide keeps: a nearest-sample search's results, and the largest move.
struct SlideScratch
{
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2;
  double LargestMove = 0.0;
};

// Runs `slide` over the points in parallel blocks: refused with the first reason a point met,
// or aborted, or accepted with the largest move over the threads' scratch.
template <typename Scratch, typename Body>
SlideResult RunSlides(std::size_t count, Body&& slide, vtkSMPThreadLocal<Scratch>& scratch,
  const std::atomic<int>& refusal, const AbortCheck& aborted)
{
  SlideResult result;
  if (!ParallelForInBlocks(count, slide, aborted, IsopointBlock))
  {
    result.Refusal = "aborted";
    return result;
  }
  if (refusal != None)
  {
    result.Refusal = RefusalText(refusal);
    return result;
  }
  for (const Scratch& s : scratch)
  {
    result.LargestMove = std::max(result.LargestMove, s.LargestMove);
  }
  result.Accepted = true;
  return result;
}
} // namespace

SlideResult SlideIsopoints(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const std::vector<char>& inside, const SlideSettings& settings, IsopointSet& isopoints,
  std::vector<double>& centres, const AbortCheck& aborted)
{
  SlideResult result;
  const std::size_t count = isopoints.Points.size() / 3;
  const std::size_t fit = isopoints.FitSize;
  if (fit == 0 || isopoints.FitSamples.size() != fit * count)
  {
    result.Refusal = "the last surface kept no nearest samples";
    return result;
  }
  // The results go to new arrays, kept only if every point slid. (The kept samples, the
  // largest, are not copied: the few points that gather anew record theirs.)
  std::vector<double> points(isopoints.Points), normals(isopoints.Normals);
  const std::vector<std::uint32_t>& samples = isopoints.FitSamples;
  std::vector<double> newCentres(points.size());
  const bool withModels = isopoints.FitModels.size() == ModelSize * count;
  std::vector<double> models(ModelSize * count);
  std::atomic<int> refusal(None);
  struct Scratch : SlideScratch
  {
    std::shared_ptr<MLSEvaluator> Evaluator;
    std::vector<std::size_t> Regathered;          // points whose fit's samples changed
    std::vector<std::uint32_t> RegatheredSamples; // theirs, `fit` each
  };
  vtkSMPThreadLocal<Scratch> scratch;
  auto slide = [&](std::size_t begin, std::size_t end) {
    Scratch& s = scratch.Local();
    if (!s.Evaluator)
    {
      s.Evaluator.reset(new MLSEvaluator(geometry, dataOffsets, fit, settings.Quadratic));
      s.Ids.resize(fit);
      s.D2.resize(fit);
    }
    for (std::size_t i = begin; i < end && refusal.load(std::memory_order_relaxed) == None; ++i)
    {
      const Eigen::Vector3d start(&points[3 * i]);
      const Eigen::Vector3d n(&normals[3 * i]);
      // The samples of the point's last fit, nearest to where they were gathered (`centre`);
      // a fit serves within MaximumMove of its centre, beyond it the samples nearest to where
      // the point got are gathered (a tree search) and the point slides on from there.
      Eigen::Vector3d centre = centres.empty() ? start : Eigen::Vector3d(&centres[3 * i]);
      const std::uint32_t* nearest = &samples[fit * i];
      std::size_t found =
        static_cast<std::size_t>(std::find(nearest, nearest + fit, NoSample) - nearest);
      Eigen::Vector3d p = start, gradient;
      Eigen::Matrix3d lastModelHessian = Eigen::Matrix3d::Zero();
      bool reached = false, crossed = true;
      for (int step = 0; step < settings.Steps && !reached && crossed; ++step)
      {
        double reach = settings.MaximumMove - (p - centre).norm();
        if (step > 0 || reach < 0.25 * settings.MaximumMove)
        {
          found = geometry.Index->Nearest(p.data(), fit, s.Ids.data(), s.D2.data());
          nearest = s.Ids.data();
          centre = p;
          reach = settings.MaximumMove;
        }
        s.Evaluator->UseGathered(centre, nearest, found);
        Eigen::Matrix3d lastHessian = Eigen::Matrix3d::Zero();
        Eigen::Vector3d evaluatedAt = p;
        // The first step from the last fit's model at the point (kept by the last run), where
        // f - f_iso is now minus the change: the only fit is then the second step's, near the
        // new level, as the refinement's second step is.
        bool useModel = step == 0 && withModels;
        auto evaluate = [&](const Eigen::Vector3d& x, double& value, Eigen::Vector3d& g,
                          Eigen::Matrix3d& hessian) {
          evaluatedAt = x;
          if (useModel)
          {
            useModel = false;
            LoadModel(&isopoints.FitModels[ModelSize * i], g, hessian);
            value = -settings.ValueChange;
            lastHessian = hessian;
            if (g.squaredNorm() > 0.0) // none where the refinement left the point
            {
              return true;
            }
          }
          const bool ok = s.Evaluator->FitGathered(x, value, g, hessian);
          lastHessian = hessian;
          return ok;
        };
        const Eigen::Vector3d from = p;
        crossed = SlideOntoDataLevel(
          p, n, evaluate, reach, settings.Iterations, gradient, settings.Tolerance);
        if (!crossed)
        {
          break;
        }
        // The fit's gradient where the point ended, by its quadratic model (the last fit was
        // made where the last iteration started).
        gradient += lastHessian * (p - evaluatedAt);
        lastModelHessian = lastHessian;
        reached = (p - from).norm() < reach * (1.0 - 1e-9); // else stopped at the reach
      }
      if (!reached)
      {
        refusal = crossed ? TooFar : NoCrossing;
        break;
      }
      s.LargestMove = std::max(s.LargestMove, (p - start).norm());
      bool in = false, out = false;
      for (std::size_t j = 0; j < found; ++j)
      {
        (inside[nearest[j]] ? in : out) = true;
      }
      if (!in || !out)
      {
        refusal = OneSide;
        break;
      }
      StoreModel(gradient, lastModelHessian, &models[ModelSize * i]);
      const Eigen::Vector3d dataNormal = -gradient.normalized();
      for (int d = 0; d < 3; ++d)
      {
        points[3 * i + d] = p[d];
        normals[3 * i + d] = dataNormal[d];
      }
      if (nearest != &samples[fit * i])
      {
        s.Regathered.push_back(i);
        for (std::size_t j = 0; j < fit; ++j)
        {
          s.RegatheredSamples.push_back(j < found ? nearest[j] : NoSample);
        }
      }
      for (int d = 0; d < 3; ++d)
      {
        newCentres[3 * i + d] = centre[d];
      }
    }
  };
  result = RunSlides(count, slide, scratch, refusal, aborted);
  if (result.Accepted)
  {
    isopoints.Points.swap(points);
    isopoints.Normals.swap(normals);
    for (const Scratch& s : scratch)
    {
      for (std::size_t k = 0; k < s.Regathered.size(); ++k)
      {
        std::copy(&s.RegatheredSamples[fit * k], &s.RegatheredSamples[fit * k] + fit,
          &isopoints.FitSamples[fit * s.Regathered[k]]);
      }
    }
    centres.swap(newCentres);
    isopoints.FitModels.swap(models);
  }
  return result;
}

SlideResult SlideIsopointsOnSPHField(const Neighborhoods& geometry, const SPHField& field,
  double isoValue, const std::vector<char>& inside, const IsopointSettings& settings,
  IsopointSet& isopoints, const AbortCheck& aborted)
{
  const std::size_t count = isopoints.Points.size() / 3;
  std::vector<double> points(isopoints.Points), normals(isopoints.Normals);
  std::atomic<int> refusal(None);
  const std::size_t stride = static_cast<std::size_t>(geometry.Stride);
  struct Scratch : SlideScratch
  {
    SPHCandidates Candidates;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  auto slide = [&](std::size_t begin, std::size_t end) {
    Scratch& s = scratch.Local();
    s.Ids.resize(stride);
    s.D2.resize(stride);
    for (std::size_t i = begin; i < end && refusal.load(std::memory_order_relaxed) == None; ++i)
    {
      Eigen::Vector3d p(&points[3 * i]);
      const Eigen::Vector3d start = p, n(&normals[3 * i]);
      const std::size_t near = geometry.Index->Nearest(p.data(), stride, s.Ids.data(), s.D2.data());
      // The samples nearest to where the point starts must lie on both sides of the new flood:
      // checked before the solve, so that a refused slide costs little.
      bool in = false, out = false;
      for (std::size_t j = 0; j < near; ++j)
      {
        (inside[s.Ids[j]] ? in : out) = true;
      }
      if (!in || !out)
      {
        refusal = OneSide;
        break;
      }
      const double reach = settings.SPHMaximumMove * field.Support(s.Ids[0]);
      Eigen::Vector3d normal;
      if (!GatherAndSolveOntoLevel(field, isoValue, p, n, reach, s.Candidates, normal))
      {
        refusal = TooFar;
        break;
      }
      s.LargestMove = std::max(s.LargestMove, (p - start).norm());
      for (int d = 0; d < 3; ++d)
      {
        points[3 * i + d] = p[d];
        normals[3 * i + d] = normal[d];
      }
    }
  };
  const SlideResult result = RunSlides(count, slide, scratch, refusal, aborted);
  if (result.Accepted)
  {
    isopoints.Points.swap(points);
    isopoints.Normals.swap(normals);
  }
  return result;
}

bool FloodChangesNearPoints(const Neighborhoods& geometry, const std::vector<char>& before,
  const std::vector<char>& after, const PointCloudIndex* points, double reach, std::size_t& changed,
  vtkIdType particles)
{
  const std::vector<std::uint32_t> moved =
    IndicesWhere<std::uint32_t>(geometry.NumberOfSamples, [&](std::size_t i) {
      return before[i] != after[i] && static_cast<vtkIdType>(geometry.Order[i]) < particles;
    });
  changed = moved.size();
  if (moved.empty())
  {
    return true;
  }
  if (!points || points->Size() == 0)
  {
    return false;
  }
  const PointCloudIndex& index = *points;
  std::atomic<bool> near(true);
  vtkSMPTools::For(0, static_cast<vtkIdType>(moved.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end && near.load(std::memory_order_relaxed); ++k)
    {
      std::uint32_t id;
      double d2;
      if (index.NearestWithin(geometry.Position(moved[k]), 1, reach * reach, &id, &d2) == 0)
      {
        near = false;
      }
    }
  });
  return near;
}

std::vector<std::size_t> ShiftLevelSet(const Neighborhoods& geometry,
  const std::vector<double>& values, double valueChange, double halfWidth, double largestMove,
  std::vector<double>& phi, const std::vector<std::uint32_t>* candidates)
{
  auto inBand = [&](std::size_t i) { return std::abs(phi[i]) < halfWidth; };
  std::vector<std::size_t> band;
  if (candidates)
  {
    const std::vector<std::uint32_t> kept = IndicesWhere<std::uint32_t>(
      candidates->size(), [&](std::size_t k) { return inBand((*candidates)[k]); });
    band.resize(kept.size());
    for (std::size_t k = 0; k < kept.size(); ++k)
    {
      band[k] = (*candidates)[kept[k]];
    }
  }
  else
  {
    band = IndicesWhere<std::size_t>(geometry.NumberOfSamples, inBand);
  }
  geometry.EnsureStencils(band); // computed by the evolution already: a lookup
  std::vector<double> shifted(band.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(band.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      const std::size_t i = band[k];
      const std::uint32_t* around = geometry.NeighborsOf(i);
      const double gradient =
        geometry.GradientAt(i, [&](std::size_t m) { return values[around[m]]; }).norm();
      shifted[k] = LevelSetAfterIsoValueChange(phi[i], valueChange, gradient, largestMove);
    }
  });
  for (std::size_t k = 0; k < band.size(); ++k)
  {
    phi[band[k]] = shifted[k];
  }
  return band;
}

} // namespace lsi
