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
#include <limits>
#include <memory>
#include <numeric>

namespace lsi
{

namespace
{
// Why a point refused to slide (the first reason met is reported).
enum Refusal : int
{
  None = 0,
  NoCrossing = 1, // the data's gradient does not point across the surface
  TooFar = 2,     // the level lies beyond the steps, or the point would leave the band
  OneSide = 3     // its nearest samples all lie inside the new flood, or all outside
};

const char* RefusalText(int refusal)
{
  switch (refusal)
  {
    case NoCrossing:
      return "the data's gradient at a point no longer crosses the surface";
    case TooFar:
      return "a point would move further than the refinement's steps or the band reach";
    case OneSide:
      return "a point's nearest samples lie all inside or all outside the new flood";
    default:
      return "";
  }
}
// A slid point against the band the last full run resolved: the samples beyond it (phi clamped)
// lie two neighbourhoods or more from the point (Inside), or may lie nearer (NearEdge: looked
// for after the slide, ClampedSamplesClear), or the point left the band (Outside: refused).
enum class BandPlace
{
  Inside,
  NearEdge,
  Outside
};

// A fit's value, gradient and Hessian where it was made: its quadratic model near there.
struct FitModel
{
  bool Made;
  Eigen::Vector3d Centre;
  double Value;
  Eigen::Vector3d Gradient;
  Eigen::Matrix3d Hessian;
  bool Serves(const Eigen::Vector3d& x, double reach) const
  {
    return this->Made && (x - this->Centre).norm() <= reach;
  }
  void At(const Eigen::Vector3d& x, double& value, Eigen::Vector3d& gradient,
    Eigen::Matrix3d& hessian) const
  {
    const Eigen::Vector3d d = x - this->Centre;
    value = this->Value + this->Gradient.dot(d) + 0.5 * d.dot(this->Hessian * d);
    gradient = this->Gradient + this->Hessian * d;
    hessian = this->Hessian;
  }
};

// What each thread of a slide keeps: a nearest-sample search's results.
struct SlideScratch
{
  std::vector<std::uint32_t> Ids;
  std::vector<double> D2;
};

// Runs `slide` over the points in parallel blocks: refused with the first reason a point met,
// or aborted, or accepted.
template <typename Body>
SlideResult RunSlides(
  std::size_t count, Body&& slide, const std::atomic<int>& refusal, const AbortCheck& aborted)
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
  result.Accepted = true;
  return result;
}

// The order the points slide in: first the hundredth whose kept models predict the longest
// moves (or no crossing), then the others in storage order. A slide that one of those makes
// refuse (a level beyond the band, say) then stops after a few points instead of after most of
// the surface; an accepted one is the same (each point slides on its own).
std::vector<std::uint32_t> FarthestFirst(const IsopointSet& isopoints, double valueChange)
{
  const std::size_t count = isopoints.Points.size() / 3;
  if (count == 0)
  {
    return std::vector<std::uint32_t>();
  }
  std::vector<double> predicted(count);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        Eigen::Vector3d g;
        Eigen::Matrix3d h;
        LoadModel(&isopoints.FitModels[ModelSize * i], g, h);
        const Eigen::Vector3d n(&isopoints.Normals[3 * i]);
        const double slope = -g.dot(n);
        predicted[i] =
          slope > 0.0 ? std::abs(StepToQuadraticZero(-valueChange, slope, n.dot(h * n))) : HUGE_VAL;
      }
    });
  // (A strict order: the longest first, ties by index. The first points are those not after
  // the one in place first - 1; both groups then keep storage order.)
  auto before = [&](std::uint32_t a, std::uint32_t b) {
    return predicted[a] > predicted[b] || (predicted[a] == predicted[b] && a < b);
  };
  std::vector<std::uint32_t> order(count);
  std::iota(order.begin(), order.end(), 0u);
  const std::size_t first = std::min(count, count / 100 + 1);
  std::nth_element(order.begin(), order.begin() + (first - 1), order.end(), before);
  const std::uint32_t last = order[first - 1];
  std::iota(order.begin(), order.end(), 0u);
  std::stable_partition(
    order.begin(), order.end(), [&](std::uint32_t i) { return !before(last, i); });
  return order;
}

// Where a point whose distance to the last full run's surface is at most `bound` (BandDrift::At;
// its nearest sample `sample`) stands against the band that run resolved (null: no band).
BandPlace PlaceInBand(
  const Neighborhoods& geometry, double bound, std::size_t sample, const BandDrift* drift)
{
  if (!drift)
  {
    return BandPlace::Inside;
  }
  if (!(bound <= drift->HalfWidth))
  {
    return BandPlace::Outside;
  }
  return bound + 2.0 * geometry.RadiusOf(sample) > drift->HalfWidth ? BandPlace::NearEdge
                                                                    : BandPlace::Inside;
}
// Point i's bound at p (way travelled this slide) where there is a band, else 0.
double BoundAt(const BandDrift* drift, std::size_t i, const Eigen::Vector3d& p, double way)
{
  return drift ? drift->At(i, p, way) : 0.0;
}

// What a slide records of each point against the last full run's band: how far it went, its
// bound where it ended, whether it ended near the band's edge. Kept only if every point slid.
struct BandRecords
{
  explicit BandRecords(std::size_t count)
    : Moves(count)
    , Bounds(count)
    , NearEdge(count)
  {
  }
  // Point i ended at p, `way` from where it was (its nearest sample `sample`): false if p left
  // the band, else recorded.
  bool Record(const Neighborhoods& geometry, const BandDrift* drift, std::size_t i,
    const Eigen::Vector3d& p, double way, std::size_t sample)
  {
    const double bound = BoundAt(drift, i, p, way);
    const BandPlace place = PlaceInBand(geometry, bound, sample, drift);
    if (place == BandPlace::Outside)
    {
      return false;
    }
    this->Moves[i] = way;
    this->Bounds[i] = bound;
    this->NearEdge[i] = place == BandPlace::NearEdge;
    return true;
  }
  void MoveInto(SlideResult& result)
  {
    result.Moves.swap(this->Moves);
    result.NearBandEdge.swap(this->NearEdge);
    result.Bounds.swap(this->Bounds);
  }
  std::vector<double> Moves, Bounds;
  std::vector<char> NearEdge;
};

// The `fit` samples nearest to p into `ids`: the same samples as a search without a bound
// (within one, the tree walk visits the same leaves in the same order), found sooner. Searched
// first within 1.1 times the radius of the `found` samples `last` about where they were gathered
// (`lastCentre`: the density changes little over a stride; 0.2% of a 10% change's gathers need
// more, against 1.2 times: 5% less time in the slide), then within the farthest of them from p,
// which bounds them.
std::size_t GatherNear(const Neighborhoods& geometry, const Eigen::Vector3d& p,
  const Eigen::Vector3d& lastCentre, const std::uint32_t* last, std::size_t found, std::size_t fit,
  std::uint32_t* ids, double* d2)
{
  double radius = 0.0, bound = 0.0;
  for (std::size_t j = 0; j < found; ++j)
  {
    const Eigen::Vector3d x(geometry.Position(last[j]));
    radius = std::max(radius, (x - lastCentre).squaredNorm());
    bound = std::max(bound, (x - p).squaredNorm());
  }
  if (found == fit && radius > 0.0 && radius < bound &&
    geometry.Index->NearestWithin(p.data(), fit, 1.21 * radius, ids, d2) == fit)
  {
    return fit;
  }
  if (found == fit && bound > 0.0 &&
    geometry.Index->NearestWithin(p.data(), fit, bound * (1.0 + 1e-9), ids, d2) == fit)
  {
    return fit;
  }
  return geometry.Index->Nearest(p.data(), fit, ids, d2);
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
  const UninitializedVector<std::uint32_t>& samples = isopoints.FitSamples;
  std::vector<double> newCentres(points.size());
  BandRecords records(count);
  const bool withModels = isopoints.FitModels.size() == ModelSize * count;
  const std::vector<std::uint32_t> order =
    withModels ? FarthestFirst(isopoints, settings.ValueChange) : std::vector<std::uint32_t>();
  UninitializedVector<double> models(ModelSize * count, 0.0);
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
    for (std::size_t k = begin; k < end && refusal.load(std::memory_order_relaxed) == None; ++k)
    {
      const std::size_t i = order.empty() ? k : order[k];
      const Eigen::Vector3d start(&points[3 * i]);
      // The line of a step: the point's last normal first, then the data's gradient where the
      // last step ended (a far level lies along the field's lines, which bend away from it).
      Eigen::Vector3d n(&normals[3 * i]);
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
      double way = 0.0; // the length of the point's path so far
      for (int step = 0; step < settings.Steps && !reached && crossed; ++step)
      {
        double reach = settings.MaximumMove - (p - centre).norm();
        if (step > 0 || reach < 0.25 * settings.MaximumMove)
        {
          found = GatherNear(geometry, p, centre, nearest, found, fit, s.Ids.data(), s.D2.data());
          nearest = s.Ids.data();
          centre = p;
          reach = settings.MaximumMove;
        }
        s.Evaluator->UseGathered(centre, nearest, found);
        // The first evaluation at p: on the first step the last fit's model (kept by the last
        // run), where f - f_iso is now minus the change, so that the only fit is made near the
        // new level, as the refinement's second step is; else a fit.
        double value = 0.0;
        Eigen::Vector3d g;
        Eigen::Matrix3d h;
        bool fromModel = false;
        if (step == 0 && withModels)
        {
          LoadModel(&isopoints.FitModels[ModelSize * i], g, h);
          value = -settings.ValueChange;
          fromModel = g.squaredNorm() > 0.0; // none where the refinement left the point
        }
        if (!fromModel && !s.Evaluator->FitGathered(p, value, g, h))
        {
          crossed = false;
          break;
        }
        const double slope = -g.dot(n);
        if (!(slope > 0.0) || !std::isfinite(value))
        {
          crossed = false;
          break;
        }
        const double predicted = StepToQuadraticZero(value, slope, n.dot(h * n));
        if (std::abs(predicted) > reach && step + 1 < settings.Steps)
        {
          // A far level: a stride by this model alone, at most FarMove (within the fit's
          // samples), then on from the samples nearest to where it ended, along its gradient.
          const Eigen::Vector3d from = p;
          p -= std::max(-settings.FarMove, std::min(settings.FarMove, predicted)) * n;
          gradient = g + h * (p - from);
          if (!(gradient.squaredNorm() > 0.0))
          {
            crossed = false;
            break;
          }
          way += (p - from).norm();
          if (PlaceInBand(geometry, BoundAt(settings.Drift, i, p, way), nearest[0],
                settings.Drift) == BandPlace::Outside)
          {
            break; // leaving the band (refused below, and soon: the other points stop too)
          }
          n = -gradient.normalized();
          lastModelHessian = h;
          continue;
        }
        // A near level: the refinement's steps over the samples gathered here, the first from
        // the evaluation just made.
        Eigen::Matrix3d lastHessian = h;
        Eigen::Vector3d evaluatedAt = p;
        bool made = true;
        // The last fit made in this slide (not the kept model, fitted where the point was):
        // near it, its quadratic model answers instead of a fit anew (ModelReach).
        FitModel fitted{ !fromModel, p, value, g, h };
        auto evaluate = [&](const Eigen::Vector3d& x, double& v, Eigen::Vector3d& gx,
                          Eigen::Matrix3d& hx) {
          evaluatedAt = x;
          if (made)
          {
            made = false;
            v = value;
            gx = g;
            hx = h;
            return true;
          }
          bool ok = true;
          if (fitted.Serves(x, settings.ModelReach))
          {
            fitted.At(x, v, gx, hx);
          }
          else
          {
            ok = s.Evaluator->FitGathered(x, v, gx, hx);
            fitted = FitModel{ ok, x, v, gx, hx };
          }
          lastHessian = hx;
          return ok;
        };
        const Eigen::Vector3d from = p;
        crossed = SlideOntoDataLevel(
          p, n, evaluate, reach, settings.Iterations, gradient, settings.Tolerance);
        if (!crossed)
        {
          break;
        }
        way += (p - from).norm();
        // The fit's gradient where the point ended, by its quadratic model (the last fit was
        // made where the last iteration started).
        gradient += lastHessian * (p - evaluatedAt);
        lastModelHessian = lastHessian;
        reached = (p - from).norm() < reach * (1.0 - 1e-9); // else stopped at the reach
        if (!reached && gradient.squaredNorm() > 0.0)
        {
          n = -gradient.normalized();
        }
      }
      if (!reached)
      {
        refusal = crossed ? TooFar : NoCrossing;
        break;
      }
      if (!records.Record(geometry, settings.Drift, i, p, way, nearest[0]))
      {
        refusal = TooFar;
        break;
      }
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
  result = RunSlides(count, slide, refusal, aborted);
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
    records.MoveInto(result);
  }
  return result;
}

SlideResult SlideIsopointsOnSPHField(const Neighborhoods& geometry, const SPHField& field,
  double isoValue, const std::vector<char>& inside, const std::vector<char>& lastInside,
  const IsopointSettings& settings, const BandDrift* drift, IsopointSet& isopoints,
  const AbortCheck& aborted)
{
  const std::size_t count = isopoints.Points.size() / 3;
  std::vector<double> points(isopoints.Points), normals(isopoints.Normals);
  BandRecords records(count);
  std::atomic<int> refusal(None);
  const std::size_t stride = static_cast<std::size_t>(geometry.Stride);
  struct Scratch
  {
    SPHPointGroup Group;      // the group of consecutive points the current one is in
    SPHCandidates Candidates; // one point's
    std::uint32_t NearestOf[SPHPointGroup::Most]; // the group's nearest samples (none: ~0u)
  };
  vtkSMPThreadLocal<Scratch> scratch;
  auto slide = [&](std::size_t begin, std::size_t end) {
    Scratch& s = scratch.Local();
    constexpr std::uint32_t NoNearest = ~std::uint32_t(0);
    s.Group.First = s.Group.Last = 0; // (none held: a block's groups start at its first point)
    for (std::size_t i = begin; i < end && refusal.load(std::memory_order_relaxed) == None; ++i)
    {
      s.Group.Hold(field, points.data(), i, end, [&](std::size_t k) {
        std::uint32_t& nearest = s.NearestOf[k - s.Group.First];
        double d2;
        if (geometry.Index->Nearest(&points[3 * k], 1, &nearest, &d2) == 0)
        {
          nearest = NoNearest;
          return 0.0;
        }
        return settings.SPHMaximumMove * field.Support(nearest);
      });
      Eigen::Vector3d p(&points[3 * i]);
      const Eigen::Vector3d start = p, n(&normals[3 * i]);
      const std::uint32_t nearest = s.NearestOf[i - s.Group.First];
      if (nearest == NoNearest)
      {
        refusal = OneSide;
        break;
      }
      // The samples around where the point starts (the nearest and its neighbours: their lists
      // are kept, a quarter of a search of as many) must lie on both sides of the new flood:
      // checked before the solve, so that a refused slide costs little. Or, where they all lay
      // inside the last flood too, all inside it: where the cloud itself ends inside the
      // component (the free boundary: a tube's wall or end), the level lies beyond its
      // outermost particles, which are all inside. (A cavity that closes leaves a point whose
      // samples straddled the last flood and lie all inside the new one: refused.)
      const std::uint32_t* around = geometry.NeighborsOf(nearest);
      bool in = false, out = false, outBefore = false;
      for (std::size_t j = 0; j < stride; ++j)
      {
        (inside[around[j]] ? in : out) = true;
        outBefore = outBefore || !lastInside[around[j]];
      }
      if (!in || (!out && outBefore))
      {
        refusal = OneSide;
        break;
      }
      const double reach = s.Group.Reach(i);
      Eigen::Vector3d normal;
      if (!GatherAndSolveOntoLevel(
            field, isoValue, p, n, reach, s.Candidates, normal, &s.Group.Candidates))
      {
        refusal = TooFar;
        break;
      }
      const double way = (p - start).norm(); // (along a straight line)
      if (!records.Record(geometry, drift, i, p, way, nearest))
      {
        refusal = TooFar;
        break;
      }
      for (int d = 0; d < 3; ++d)
      {
        points[3 * i + d] = p[d];
        normals[3 * i + d] = normal[d];
      }
    }
  };
  SlideResult result = RunSlides(count, slide, refusal, aborted);
  if (result.Accepted)
  {
    isopoints.Points.swap(points);
    isopoints.Normals.swap(normals);
    records.MoveInto(result);
  }
  return result;
}

bool FloodChangesNearPoints(const Neighborhoods& geometry, const std::vector<char>& before,
  const std::vector<char>& after, const PointCloudIndex* points, const std::vector<double>& moves,
  double margin, std::size_t& changed, vtkIdType particles)
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
  if (moves.size() != index.Size())
  {
    return false; // (every point needs its move)
  }
  const double largestMove = *std::max_element(moves.begin(), moves.end());
  // A sample between the old and the new level lies within the move there (plus the points'
  // spacing) of the points that passed it; looked for among the few points nearest to it.
  constexpr std::size_t Candidates = 8;
  const std::size_t k = std::min(Candidates, index.Size());
  std::atomic<bool> near(true);
  vtkSMPTools::For(0, static_cast<vtkIdType>(moved.size()), BalancedGrain(moved.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      std::uint32_t ids[Candidates];
      double d2[Candidates];
      for (vtkIdType m = begin; m < end && near.load(std::memory_order_relaxed); ++m)
      {
        const double reach = largestMove + margin;
        const std::size_t found =
          index.NearestWithin(geometry.Position(moved[m]), k, reach * reach, ids, d2);
        bool passed = false;
        for (std::size_t j = 0; j < found && !passed; ++j)
        {
          const double within = moves[ids[j]] + margin;
          passed = d2[j] <= within * within;
        }
        if (!passed)
        {
          near = false;
        }
      }
    });
  return near;
}

bool ClampedSamplesClear(const Neighborhoods& geometry, const std::vector<double>& phi,
  double halfWidth, const std::vector<double>& points, const std::vector<char>& nearEdge,
  const std::vector<char>* kept, double margin)
{
  const std::size_t count = std::min(points.size() / 3, nearEdge.size());
  std::atomic<bool> clear(true);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end && clear.load(std::memory_order_relaxed); ++i)
      {
        if (!nearEdge[i] || (kept && !(*kept)[i]))
        {
          continue;
        }
        const double* p = &points[3 * i];
        std::uint32_t nearest;
        double d2;
        if (geometry.Index->Nearest(p, 1, &nearest, &d2) == 0)
        {
          continue;
        }
        // (Searched within twice the nearest sample's radius: the Inside rule's bound.)
        const double search = 2.0 * geometry.RadiusOf(nearest) + margin;
        const bool found =
          geometry.Index->AnyWithin(p, search * search, [&](std::uint32_t j, double distance2) {
            if (std::abs(phi[j]) < halfWidth)
            {
              return false;
            }
            const double shell = geometry.RadiusOf(j) + margin;
            return distance2 < shell * shell;
          });
        if (found)
        {
          clear = false;
        }
      }
    });
  return clear;
}

BandGradients GradientsInBand(const Neighborhoods& geometry, const std::vector<double>& values,
  double halfWidth, const std::vector<double>& phi, const std::vector<std::uint32_t>* candidates,
  std::vector<double>* candidateGradients)
{
  auto inBand = [&](std::size_t i) { return std::abs(phi[i]) < halfWidth; };
  BandGradients band;
  std::vector<std::uint32_t> places; // the band's places among the candidates
  if (candidates)
  {
    places = IndicesWhere<std::uint32_t>(
      candidates->size(), [&](std::size_t k) { return inBand((*candidates)[k]); });
    band.Samples.resize(places.size());
    for (std::size_t k = 0; k < places.size(); ++k)
    {
      band.Samples[k] = (*candidates)[places[k]];
    }
  }
  else
  {
    band.Samples = IndicesWhere<std::size_t>(geometry.NumberOfSamples, inBand);
  }
  double* kept = nullptr; // per candidate: |grad f|, NaN until computed
  if (candidates && candidateGradients)
  {
    if (candidateGradients->size() != candidates->size())
    {
      candidateGradients->assign(candidates->size(), std::numeric_limits<double>::quiet_NaN());
    }
    kept = candidateGradients->data();
  }
  auto keptAt = [&](std::size_t k) {
    return kept ? kept[places[k]] : std::numeric_limits<double>::quiet_NaN();
  };
  // The samples without a kept gradient need their stencils (the evolution's: a lookup).
  std::vector<std::size_t> missing = IndicesWhere<std::size_t>(
    band.Samples.size(), [&](std::size_t k) { return std::isnan(keptAt(k)); });
  for (std::size_t& k : missing)
  {
    k = band.Samples[k];
  }
  geometry.EnsureStencils(missing);
  band.Norms.resize(band.Samples.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(band.Samples.size()),
    BalancedGrain(band.Samples.size(), 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        double norm = keptAt(k);
        if (std::isnan(norm))
        {
          const std::size_t i = band.Samples[k];
          const std::uint32_t* around = geometry.NeighborsOf(i);
          norm = geometry.GradientAt(i, [&](std::size_t m) { return values[around[m]]; }).norm();
          if (kept)
          {
            kept[places[k]] = norm;
          }
        }
        band.Norms[k] = norm;
      }
    });
  return band;
}

std::vector<std::size_t> ShiftLevelSet(const Neighborhoods& geometry,
  const std::vector<double>& values, double valueChange, double halfWidth, double largestMove,
  std::vector<double>& phi, const std::vector<std::uint32_t>* candidates,
  std::vector<double>* candidateGradients)
{
  const BandGradients band =
    GradientsInBand(geometry, values, halfWidth, phi, candidates, candidateGradients);
  // (Each sample's phi is read and written by its own iteration alone.)
  vtkSMPTools::For(0, static_cast<vtkIdType>(band.Samples.size()),
    BalancedGrain(band.Samples.size(), 16384), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        double& value = phi[band.Samples[k]];
        value = LevelSetAfterIsoValueChange(value, valueChange, band.Norms[k], largestMove);
      }
    });
  return band.Samples;
}

} // namespace lsi
