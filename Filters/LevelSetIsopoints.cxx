#include "LevelSetIsopoints.h"

#include "LevelSetTiming.h"
#include "MovingLeastSquares.h"
#include "NearestNeighbors.h"
#include "TangentPlaneCompletion.h"

#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numeric>

namespace lsi
{

MLSStencil::MLSStencil(const Neighborhoods& geometry, std::size_t count)
  : Geometry(geometry)
  , Ids(std::min(count, geometry.NumberOfSamples))
  , D2(Ids.size())
  , GradientWeightData(3 * Ids.size())
  , ValueWeights(Ids.size())
{
}

void MLSStencil::Gather(const Eigen::Vector3d& p)
{
  this->FoundCount = this->Geometry.Index->Nearest(
    p.data(), this->Ids.size(), this->Ids.data(), this->D2.data());
  this->GatherRadius =
    std::sqrt(*std::max_element(this->D2.begin(), this->D2.begin() + this->FoundCount));
  this->GatherPoint = p;
}

bool MLSStencil::Build(const Eigen::Vector3d& p)
{
  const std::size_t k = this->FoundCount;
  // The support must still reach all gathered samples from p (the weight vanishes at h).
  double h = this->GatherRadius;
  if (p != this->GatherPoint)
  {
    double h2 = 0.0;
    for (std::size_t j = 0; j < k; ++j)
    {
      h2 = std::max(h2, (Eigen::Vector3d(this->Geometry.Position(this->Ids[j])) - p).squaredNorm());
    }
    h = std::max(h, std::sqrt(h2));
  }
  return BuildLinearStencil(p.data(), k,
    [&](std::size_t j) { return this->Geometry.Position(this->Ids[j]); }, h,
    LinearStencilView{ this->GradientWeightData.data(), this->ValueWeights.data() });
}

MLSEvaluator::MLSEvaluator(
  const Neighborhoods& geometry, const std::vector<double>& values, std::size_t count)
  : Stencil(geometry, count ? count : static_cast<std::size_t>(geometry.Stride))
  , Values(values)
{
}

bool MLSEvaluator::operator()(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient)
{
  this->Stencil.Gather(p);
  return this->FitGathered(p, value, gradient);
}

bool MLSEvaluator::FitGathered(const Eigen::Vector3d& p, double& value, Eigen::Vector3d& gradient)
{
  if (!this->Stencil.Build(p))
  {
    return false;
  }
  value = 0.0;
  gradient.setZero();
  for (std::size_t j = 0; j < this->Stencil.Found(); ++j)
  {
    const double v = this->Values[this->Stencil.Sample(j)];
    value += this->Stencil.ValueWeight(j) * v;
    gradient += v * Eigen::Vector3d(this->Stencil.GradientWeights(j));
  }
  return true;
}

namespace
{
// Isopoints per block of the parallel loops, between two abort checks: a block of Newton
// projections with MLS fits takes a few tens of milliseconds on one core.
constexpr std::size_t IsopointBlock = 8192;

// Keeps the first point (in input order) of each cubic voxel of side `cell`: removes
// near-duplicates, deterministically, and bounds the density of the output.
std::vector<std::size_t> ThinByVoxels(const std::vector<double>& points, double cell)
{
  const std::size_t count = points.size() / 3;
  std::vector<std::uint64_t> keys(count);
  for (std::size_t i = 0; i < count; ++i)
  {
    std::uint64_t key = 0;
    for (int d = 0; d < 3; ++d)
    {
      const auto v = static_cast<std::int64_t>(std::floor(points[3 * i + d] / cell)) + (1 << 20);
      key = (key << 21) | (static_cast<std::uint64_t>(v) & ((1u << 21) - 1));
    }
    keys[i] = key;
  }
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  std::vector<std::size_t> kept;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (k == 0 || keys[order[k]] != keys[order[k - 1]])
    {
      kept.push_back(order[k]);
    }
  }
  std::sort(kept.begin(), kept.end());
  return kept;
}

void AppendSelected(const std::vector<double>& points, const std::vector<double>& normals,
  const std::vector<std::size_t>& selected, IsopointSet& out)
{
  for (std::size_t i : selected)
  {
    out.Points.insert(out.Points.end(), &points[3 * i], &points[3 * i + 3]);
    out.Normals.insert(out.Normals.end(), &normals[3 * i], &normals[3 * i + 3]);
  }
}

// Refines candidate points in place; `valid` says which converged. Normals point along
// -grad phi: out of the region phi > 0, which is the region f > f_iso. Returns false if aborted.
bool RefineCandidates(const Neighborhoods& geometry, const std::vector<double>& phi,
  const NewtonSettings& newton, int normalFitScale, std::vector<double>& points,
  std::vector<double>& normals, std::vector<char>& valid, const AbortCheck& aborted)
{
  const std::size_t normalFitCount = std::min<std::size_t>(
    geometry.NumberOfSamples, static_cast<std::size_t>(normalFitScale) * geometry.Stride);
  vtkSMPThreadLocal<std::shared_ptr<MLSEvaluator>> evaluators, normalEvaluators;
  const std::size_t count = points.size() / 3;
  normals.assign(3 * count, 0.0);
  auto refine = [&](std::size_t begin, std::size_t end) {
    std::shared_ptr<MLSEvaluator>& evaluator = evaluators.Local();
    std::shared_ptr<MLSEvaluator>& normalEvaluator = normalEvaluators.Local();
    if (!evaluator)
    {
      evaluator.reset(new MLSEvaluator(geometry, phi));
      normalEvaluator.reset(new MLSEvaluator(geometry, phi, normalFitCount));
    }
    for (std::size_t i = begin; i < end; ++i)
    {
      if (!valid[i])
      {
        continue;
      }
      Eigen::Vector3d p(&points[3 * i]);
      Eigen::Vector3d gradient;
      valid[i] = ProjectOntoZeroLevel(p, gradient, *evaluator, newton);
      if (valid[i])
      {
        double value;
        Eigen::Vector3d wide;
        if (normalFitScale > 1 && (*normalEvaluator)(p, value, wide) && wide.squaredNorm() > 0.0)
        {
          gradient = wide;
        }
        const Eigen::Vector3d n = -gradient.normalized();
        for (int d = 0; d < 3; ++d)
        {
          points[3 * i + d] = p[d];
          normals[3 * i + d] = n[d];
        }
      }
    }
  };
  return ParallelForInBlocks(count, refine, aborted, IsopointBlock);
}

std::vector<std::size_t> ValidIndices(const std::vector<char>& valid)
{
  std::vector<std::size_t> indices;
  for (std::size_t i = 0; i < valid.size(); ++i)
  {
    if (valid[i])
    {
      indices.push_back(i);
    }
  }
  return indices;
}

// Rough isopoints: one per neighbour pair (i, j) with phi_i > 0 >= phi_j whose segment passes
// the angle criterion, placed where the linear interpolation of phi vanishes.
void RoughIsopoints(const Neighborhoods& geometry, const std::vector<double>& phi,
  double minimumCosine, std::vector<double>& points)
{
  const std::size_t n = geometry.NumberOfSamples;
  const std::size_t stride = static_cast<std::size_t>(geometry.Stride);
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (phi[i] > 0.0 && phi[i] < 3.0 * geometry.Radius[i])
    {
      front.push_back(i);
    }
  }
  {
    // The angle criterion needs gradients on the front and at its negative neighbours.
    std::vector<char> needed(n, 0);
    std::vector<std::size_t> list;
    for (std::size_t i : front)
    {
      const std::uint32_t* ids = geometry.NeighborsOf(i);
      for (std::size_t m = 0; m < stride; ++m)
      {
        if ((m == 0 || phi[ids[m]] <= 0.0) && !needed[ids[m]])
        {
          needed[ids[m]] = 1;
          list.push_back(ids[m]);
        }
      }
    }
    geometry.EnsureStencils(list);
  }
  auto gradientAt = [&](std::size_t i) {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    return ApplyGradientStencil(
      geometry.StencilOf(i), stride, [&](std::size_t m) { return phi[ids[m]]; });
  };
  // Two passes (count, then fill) keep the output order independent of the threads.
  auto forEachAcceptedPair = [&](std::size_t i, auto&& emit) {
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    const Eigen::Vector3d xi(geometry.Position(i));
    const Eigen::Vector3d gi = gradientAt(i);
    for (std::size_t m = 1; m < stride; ++m)
    {
      const std::uint32_t j = ids[m];
      if (phi[j] > 0.0)
      {
        continue;
      }
      const Eigen::Vector3d xj(geometry.Position(j));
      if (AlignedWithGradient(xj - xi, gi + gradientAt(j), minimumCosine))
      {
        emit(ZeroCrossing(xi, phi[i], xj, phi[j]));
      }
    }
  };
  std::vector<std::size_t> offsets(front.size() + 1, 0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(front.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      std::size_t count = 0;
      forEachAcceptedPair(front[k], [&](const Eigen::Vector3d&) { ++count; });
      offsets[k + 1] = count;
    }
  });
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  points.assign(3 * offsets.back(), 0.0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(front.size()), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType k = begin; k < end; ++k)
    {
      std::size_t slot = offsets[k];
      forEachAcceptedPair(front[k], [&](const Eigen::Vector3d& p) {
        for (int d = 0; d < 3; ++d)
        {
          points[3 * slot + d] = p[d];
        }
        ++slot;
      });
    }
  });
}

// Completion candidates: centres of the empty tangent-plane cells around each isopoint.
void CompletionCandidates(const IsopointSet& current, const IsopointSettings& settings,
  std::vector<double>& candidates, std::vector<char>& valid)
{
  const std::size_t count = current.Points.size() / 3;
  const int side = 2 * settings.CompletionHalfCells + 1;
  const std::size_t perPoint = static_cast<std::size_t>(side * side - 1);
  const std::size_t neighbors = std::min<std::size_t>(count, 2 * perPoint);
  PointCloudIndex index(current.Points.data(), count);
  candidates.assign(3 * perPoint * count, 0.0);
  valid.assign(perPoint * count, 0);
  struct Scratch
  {
    std::vector<std::uint32_t> Ids;
    std::vector<double> D2;
    std::vector<Eigen::Vector3d> Cells;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), [&](vtkIdType begin, vtkIdType end) {
    Scratch& s = scratch.Local();
    s.Ids.resize(neighbors);
    s.D2.resize(neighbors);
    for (vtkIdType i = begin; i < end; ++i)
    {
      const Eigen::Vector3d p(&current.Points[3 * i]);
      const Eigen::Vector3d n(&current.Normals[3 * i]);
      const std::size_t found = index.Nearest(p.data(), neighbors, s.Ids.data(), s.D2.data());
      s.Cells.clear();
      EmptyTangentCells(p, n, settings.CellSize, settings.CompletionHalfCells,
        settings.CellSize, found,
        [&](std::size_t j) { return Eigen::Vector3d(&current.Points[3 * s.Ids[j]]); }, s.Cells);
      for (std::size_t c = 0; c < s.Cells.size() && c < perPoint; ++c)
      {
        const std::size_t slot = perPoint * i + c;
        for (int d = 0; d < 3; ++d)
        {
          candidates[3 * slot + d] = s.Cells[c][d];
        }
        valid[slot] = 1;
      }
    }
  });
}
} // namespace

namespace
{
// Neighbouring isopoints propose the same empty cells: before the costly refinement, keep one
// proposal per voxel, and none in a voxel that an isopoint already occupies.
void DropProposalsInOccupiedVoxels(const IsopointSet& current, double cell,
  const std::vector<double>& candidates, std::vector<char>& valid)
{
  const std::size_t existing = current.Points.size() / 3;
  std::vector<double> all(current.Points);
  std::vector<std::size_t> candidateOf;
  for (std::size_t c = 0; c < valid.size(); ++c)
  {
    if (valid[c])
    {
      all.insert(all.end(), &candidates[3 * c], &candidates[3 * c + 3]);
      candidateOf.push_back(c);
    }
  }
  std::fill(valid.begin(), valid.end(), 0);
  for (std::size_t k : ThinByVoxels(all, cell)) // existing points come first and win
  {
    if (k >= existing)
    {
      valid[candidateOf[k - existing]] = 1;
    }
  }
}

// A connected region of samples with one sign of phi (over the neighbour graph) in which no
// sample has that sign in the data (say phi <= 0 everywhere but f > f_iso everywhere) cannot
// hold a piece of the isosurface: it is a pocket the front left behind. Flip its sign, so
// that Newton's method is not drawn to spurious zeros around it. Every sample of a pocket
// disagrees with the data, so only the (few) disagreeing samples are searched.
std::vector<double> WithoutSpuriousPockets(const Neighborhoods& geometry,
  const std::vector<double>& dataOffsets, std::vector<double> phi)
{
  const std::size_t n = geometry.NumberOfSamples;
  const int stride = geometry.Stride;
  auto positive = [&](std::size_t i) { return phi[i] > 0.0; };
  auto disagrees = [&](std::size_t i) { return positive(i) != (dataOffsets[i] > 0.0); };
  std::vector<char> state(n, 0); // 1: in the region being searched, 2: done
  std::vector<std::uint32_t> region;
  for (std::size_t start = 0; start < n; ++start)
  {
    if (state[start] || !disagrees(start))
    {
      continue;
    }
    // The same-sign region of `start`, as long as it only contains disagreeing samples.
    region.assign(1, static_cast<std::uint32_t>(start));
    state[start] = 1;
    bool pocket = true;
    for (std::size_t head = 0; head < region.size(); ++head)
    {
      const std::uint32_t* ids = geometry.NeighborsOf(region[head]);
      for (int m = 1; m < stride; ++m)
      {
        const std::uint32_t j = ids[m];
        if (positive(j) != positive(start) || state[j] == 1)
        {
          continue;
        }
        if (!disagrees(j) || state[j] == 2)
        {
          // The region reaches a sample the data support (or, through a one-way neighbour
          // link, a region already decided): leave it as it is.
          pocket = false;
          continue;
        }
        state[j] = 1;
        region.push_back(j);
      }
    }
    for (std::uint32_t i : region)
    {
      state[i] = 2;
      if (pocket)
      {
        phi[i] = phi[i] > 0.0 ? -phi[i] : std::max(-phi[i], 1e-12);
      }
    }
  }
  return phi;
}

// The wide fit of phi only matters for the output normals; the data refinement replaces them.
int NormalFitScaleFor(const IsopointSettings& settings)
{
  return settings.RefineOnData ? 1 : settings.NormalFitScale;
}

bool Complete(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);
bool RefineOnData(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted);
} // namespace

bool ExtractIsopoints(const Neighborhoods& geometry, const std::vector<double>& evolvedPhi,
  const std::vector<double>& dataOffsets, const IsopointSettings& settings, IsopointSet& out,
  const AbortCheck& aborted)
{
  // Progress over the sub-stages, in proportion to their times at 2M samples (pockets and
  // rough points 10%, their refinement 18%, completion 48%, refinement on the data 24%).
  out = IsopointSet();
  const std::vector<double> phi = WithoutSpuriousPockets(geometry, dataOffsets, evolvedPhi);
  std::vector<double> points, normals;
  RoughIsopoints(geometry, phi, settings.MinimumCosine, points);
  out.RoughCount = points.size() / 3;
  // Many crossings lie within one voxel: refine one per voxel only.
  std::vector<char> valid(out.RoughCount, 0);
  for (std::size_t k : ThinByVoxels(points, settings.CellSize))
  {
    valid[k] = 1;
  }
  if (!RefineCandidates(geometry, phi, settings.Newton, NormalFitScaleFor(settings), points,
        normals, valid, SubRange(aborted, 0.10, 0.28)))
  {
    return false;
  }
  {
    // Thin the refined points: many crossings land on nearly the same spot.
    IsopointSet tmp;
    AppendSelected(points, normals, ValidIndices(valid), tmp);
    const std::vector<std::size_t> kept = ThinByVoxels(tmp.Points, settings.CellSize);
    AppendSelected(tmp.Points, tmp.Normals, kept, out);
  }
  if (settings.Completion && !out.Points.empty() &&
    !Complete(geometry, phi, settings, out, SubRange(aborted, 0.28, 0.76)))
  {
    return false;
  }
  if (settings.RefineOnData && !out.Points.empty())
  {
    const auto start = Clock::now();
    if (!RefineOnData(geometry, dataOffsets, settings, out, SubRange(aborted, 0.76, 1.0)))
    {
      return false;
    }
    out.DataRefinementSeconds = SecondsSince(start);
  }
  return !Aborted(aborted, 1.0);
}

namespace
{
bool Complete(const Neighborhoods& geometry, const std::vector<double>& phi,
  const IsopointSettings& settings, IsopointSet& out, const AbortCheck& aborted)
{
  const auto completionStart = Clock::now();
  std::vector<double> candidates, candidateNormals;
  std::vector<char> candidateValid;
  CompletionCandidates(out, settings, candidates, candidateValid);
  DropProposalsInOccupiedVoxels(out, settings.CellSize, candidates, candidateValid);
  NewtonSettings newton = settings.Newton;
  newton.MaximumDistance = 2.0 * settings.CellSize; // stay near the cell it was proposed for
  if (!RefineCandidates(geometry, phi, newton, NormalFitScaleFor(settings), candidates,
        candidateNormals, candidateValid, SubRange(aborted, 0.1, 0.9)))
  {
    return false;
  }

  // The union, thinned again; existing isopoints come first and so win their voxels.
  IsopointSet all = out;
  AppendSelected(candidates, candidateNormals, ValidIndices(candidateValid), all);
  const std::vector<std::size_t> kept = ThinByVoxels(all.Points, settings.CellSize);
  const std::size_t before = out.Points.size() / 3;
  IsopointSet result;
  result.RoughCount = out.RoughCount;
  AppendSelected(all.Points, all.Normals, kept, result);
  result.CompletedCount = result.Points.size() / 3 - std::min(before, result.Points.size() / 3);
  result.CompletionSeconds = SecondsSince(completionStart);
  out = std::move(result);
  return true;
}

bool RefineOnData(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
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
      if (SlideOntoDataLevel(p, n, evaluate, settings.DataMaximumMove,
            settings.DataIterations, gradient))
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
} // namespace

} // namespace lsi
