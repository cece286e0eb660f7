// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetNeighborhoods.h"

#include "LevelSetTiming.h"
#include "MovingLeastSquares.h"
#include "SpatialOrder.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <functional>
#include <mutex>
#include <thread>
#include <tuple>

namespace lsi
{

namespace
{
// Puts the sample itself in slot 0 of its row (duplicates are found by FindDuplicates).
void ArrangeRow(std::uint32_t self, std::uint32_t* ids, double* d2, int stride)
{
  int selfSlot = -1;
  for (int k = 0; k < stride; ++k)
  {
    if (ids[k] == self)
    {
      selfSlot = k;
    }
  }
  if (selfSlot < 0) // more exact duplicates than neighbours: make room for the sample itself
  {
    selfSlot = stride - 1;
    ids[selfSlot] = self;
    d2[selfSlot] = 0.0;
  }
  std::swap(ids[0], ids[selfSlot]);
  std::swap(d2[0], d2[selfSlot]);
}
} // namespace

namespace
{
// Calls f with the coordinate array as its concrete type (no virtual call per value), or as a
// plain vtkDataArray for types outside vtkArrayDispatch's reals.
template <typename F>
void WithTypedCoordinates(vtkDataArray* coordinates, F&& f)
{
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(coordinates, f))
  {
    f(coordinates);
  }
}

// Counts the samples at exactly the position of another one (out.DuplicateSamples, and the
// smallest input id among them). Coincident samples share a Morton cell, so only the runs of
// sorted words with the same cell are compared, after sorting each by position.
void FindDuplicates(const UninitializedVector<std::uint64_t>& words, Neighborhoods& out)
{
  // In pieces that each start a run of words of one cell, in parallel; the count and the
  // lowest id are the same whatever the pieces.
  const std::size_t n = words.size();
  auto cell = [&](std::size_t k) { return words[k] >> 32; };
  const std::size_t pieces = std::max<std::size_t>(1, std::min<std::size_t>(256, n / 4096));
  std::vector<std::size_t> starts(pieces + 1, n);
  for (std::size_t p = 0; p < pieces; ++p)
  {
    std::size_t k = n * p / pieces;
    while (k > 0 && k < n && cell(k) == cell(k - 1))
    {
      ++k;
    }
    starts[p] = k;
  }
  std::vector<std::size_t> duplicates(pieces, 0);
  std::vector<long long> first(pieces, -1);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(pieces), 1, [&](vtkIdType firstPiece, vtkIdType lastPiece) {
      std::vector<std::size_t> run;
      auto position = [&](std::size_t i) {
        return std::make_tuple(
          out.Positions[3 * i], out.Positions[3 * i + 1], out.Positions[3 * i + 2]);
      };
      for (vtkIdType p = firstPiece; p < lastPiece; ++p)
      {
        for (std::size_t begin = starts[p], end = begin; begin < starts[p + 1]; begin = end)
        {
          end = begin + 1;
          while (end < n && cell(end) == cell(begin))
          {
            ++end;
          }
          if (end - begin < 2)
          {
            continue;
          }
          run.resize(end - begin);
          for (std::size_t k = 0; k < run.size(); ++k)
          {
            run[k] = begin + k;
          }
          std::sort(run.begin(), run.end(),
            [&](std::size_t a, std::size_t b) { return position(a) < position(b); });
          for (std::size_t k = 0; k < run.size(); ++k)
          {
            const bool same = (k > 0 && position(run[k]) == position(run[k - 1])) ||
              (k + 1 < run.size() && position(run[k]) == position(run[k + 1]));
            if (same)
            {
              ++duplicates[p];
              const long long id = out.Order[run[k]];
              first[p] = first[p] < 0 ? id : std::min(first[p], id);
            }
          }
        }
      }
    });
  for (std::size_t p = 0; p < pieces; ++p)
  {
    out.DuplicateSamples += duplicates[p];
    if (first[p] >= 0)
    {
      out.FirstDuplicate =
        out.FirstDuplicate < 0 ? first[p] : std::min(out.FirstDuplicate, first[p]);
    }
  }
}

// Runs the tasks on VTK's thread pool, one task per piece. (Starting threads for each call, as
// RunOnThreads does, left a core idle for a third of the spatial sort's passes.)
void RunOnPool(std::vector<std::function<void()>>& tasks)
{
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(tasks.size()), 1, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType t = first; t < last; ++t)
      {
        tasks[static_cast<std::size_t>(t)]();
      }
    });
}

// Runs the tasks on at most `threads` threads (the calling one included), each thread taking
// the next task not yet started: for the tree build, which runs on a thread of its own (so that
// an abort need not wait for it) and so leaves VTK's pool to the caller.
void RunOnThreads(std::vector<std::function<void()>>& tasks, int threads)
{
  std::atomic<std::size_t> next(0);
  auto work = [&]() {
    for (std::size_t t = next++; t < tasks.size(); t = next++)
    {
      tasks[t]();
    }
  };
  std::vector<std::thread> helpers;
  for (int t = 1; t < threads && static_cast<std::size_t>(t) < tasks.size(); ++t)
  {
    helpers.emplace_back(work);
  }
  work();
  for (std::thread& helper : helpers)
  {
    helper.join();
  }
}

} // namespace

void PointBounds(vtkPoints* points, double bounds[6])
{
  const vtkIdType n = points->GetNumberOfPoints();
  vtkSMPThreadLocal<std::array<double, 6>> local(
    std::array<double, 6>{ HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL });
  auto scan = [&](auto* array) {
    const auto xyz = vtk::DataArrayTupleRange<3>(array);
    vtkSMPTools::For(
      0, n, BalancedGrain(static_cast<std::size_t>(n), 16384), [&](vtkIdType begin, vtkIdType end) {
        std::array<double, 6>& b = local.Local();
        for (vtkIdType i = begin; i < end; ++i)
        {
          for (int k = 0; k < 3; ++k)
          {
            const double x = static_cast<double>(xyz[i][k]);
            b[2 * k] = std::min(b[2 * k], x);
            b[2 * k + 1] = std::max(b[2 * k + 1], x);
          }
        }
      });
  };
  WithTypedCoordinates(points->GetData(), scan);
  const double empty[6] = { HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL };
  std::copy(empty, empty + 6, bounds);
  for (const std::array<double, 6>& b : local)
  {
    for (int k = 0; k < 6; k += 2)
    {
      bounds[k] = std::min(bounds[k], b[k]);
      bounds[k + 1] = std::max(bounds[k + 1], b[k + 1]);
    }
  }
}

namespace
{
// Fills out.Order and out.Positions: the points sorted by Morton key over the cube around their
// bounding box (cubic cells, whose halvings are the kd-tree's cuts). Returns the sorted words.
UninitializedVector<std::uint64_t> SortSpatially(vtkPoints* points, Neighborhoods& out)
{
  const std::size_t n = out.NumberOfSamples;
  vtkDataArray* coordinates = points->GetData();
  double bounds[6];
  PointBounds(points, bounds);
  const double lower[3] = { bounds[0], bounds[2], bounds[4] };
  const double side =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-300 });
  const double size[3] = { side, side, side };
  UninitializedVector<std::uint64_t> words(n);
  AdviseHugePages(words);
  auto makeKeys = [&](auto* array) {
    const auto xyz = vtk::DataArrayTupleRange<3>(array);
    vtkSMPTools::For(
      0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const double x[3] = { static_cast<double>(xyz[i][0]), static_cast<double>(xyz[i][1]),
            static_cast<double>(xyz[i][2]) };
          words[i] = PackedMortonKey(x, lower, size, static_cast<std::uint32_t>(i));
        }
      });
  };
  WithTypedCoordinates(coordinates, makeKeys);
  {
    UninitializedVector<std::uint64_t> scratch;
    // Two pieces per thread, counted and scattered in parallel (the same order on any count).
    const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
    RadixSortPacked(words, scratch, 2 * static_cast<std::size_t>(threads), RunOnPool);
  }
  out.Order.resize(n);
  out.Positions.resize(3 * n);
  AdviseHugePages(out.Order);
  AdviseHugePages(out.Positions);
  auto gather = [&](auto* array) {
    const auto xyz = vtk::DataArrayTupleRange<3>(array);
    vtkSMPTools::For(
      0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const std::uint32_t id = static_cast<std::uint32_t>(words[i]); // the low 32 bits
          out.Order[i] = id;
          for (int k = 0; k < 3; ++k)
          {
            out.Positions[3 * i + k] = static_cast<double>(xyz[id][k]);
          }
        }
      });
  };
  WithTypedCoordinates(coordinates, gather);
  FindDuplicates(words, out);
  return words;
}
// The mean radius of at most `most` of `sample` (every k-th, in order), each searched in full;
// summed in order: the same on any number of threads.
double MeanRadiusOver(
  const Neighborhoods& geometry, const std::vector<std::uint32_t>& sample, std::size_t most)
{
  if (sample.empty())
  {
    return 0.0;
  }
  const std::size_t step = (sample.size() + most - 1) / most;
  const std::size_t count = (sample.size() + step - 1) / step;
  std::vector<double> radii(count);
  vtkSMPTools::For(0, static_cast<vtkIdType>(count), BalancedGrain(count, 1024),
    [&](vtkIdType begin, vtkIdType end) {
      std::vector<std::uint32_t> ids(static_cast<std::size_t>(geometry.Stride));
      double nearby = 0.0; // (a bound for the search only: the lists are exact either way)
      for (vtkIdType m = begin; m < end; ++m)
      {
        radii[m] =
          geometry.SearchRow(sample[static_cast<std::size_t>(m) * step], nearby, ids.data());
        nearby = radii[m];
      }
    });
  double sum = 0.0;
  for (const double radius : radii)
  {
    sum += radius;
  }
  return sum / static_cast<double>(count);
}
// Whether all positions lie on one plane or line (up to rounding): the smallest eigenvalue of
// their covariance is negligible against the largest.
bool IsFlat(const std::vector<double>& positions)
{
  // The covariance of the bulk: points outside the 1st-99th percentile range of any axis are
  // left out, so that a few far outliers cannot make 3D data look flat (their own variance
  // would dwarf the others).
  const std::size_t n = positions.size() / 3;
  if (n == 0)
  {
    return false;
  }
  double low[3], high[3];
  std::vector<double> axis(n);
  for (int k = 0; k < 3; ++k)
  {
    for (std::size_t i = 0; i < n; ++i)
    {
      axis[i] = positions[3 * i + k];
    }
    const std::size_t a = n / 100, b = n - 1 - n / 100;
    std::nth_element(axis.begin(), axis.begin() + a, axis.end());
    low[k] = axis[a];
    std::nth_element(axis.begin(), axis.begin() + b, axis.end());
    high[k] = axis[b];
  }
  auto inBulk = [&](std::size_t i) {
    for (int k = 0; k < 3; ++k)
    {
      if (positions[3 * i + k] < low[k] || positions[3 * i + k] > high[k])
      {
        return false;
      }
    }
    return true;
  };
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (inBulk(i))
    {
      mean += Eigen::Vector3d(&positions[3 * i]);
      ++count;
    }
  }
  mean /= static_cast<double>(std::max<std::size_t>(count, 1));
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < n; ++i)
  {
    if (inBulk(i))
    {
      const Eigen::Vector3d d = Eigen::Vector3d(&positions[3 * i]) - mean;
      covariance.noalias() += d * d.transpose();
    }
  }
  const Eigen::Vector3d eigenvalues =
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance, Eigen::EigenvaluesOnly)
      .eigenvalues(); // increasing
  return !(eigenvalues[0] > 1e-12 * eigenvalues[2]);
}
} // namespace

namespace
{
// Whether the neighbourhood's points spread less than ThinRatio as far in one direction as in
// the widest one (the square root of the covariance's eigenvalues).
bool IsThin(const std::uint32_t* ids, std::size_t count, const Neighborhoods& geometry)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t m = 0; m < count; ++m)
  {
    mean += Eigen::Vector3d(geometry.Position(ids[m]));
  }
  mean /= static_cast<double>(count);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (std::size_t m = 0; m < count; ++m)
  {
    const Eigen::Vector3d d = Eigen::Vector3d(geometry.Position(ids[m])) - mean;
    covariance.noalias() += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(covariance, Eigen::EigenvaluesOnly);
  const Eigen::Vector3d eigenvalues = solver.eigenvalues(); // increasing
  const double ratio = Neighborhoods::ThinRatio;
  return eigenvalues[0] < ratio * ratio * eigenvalues[2];
}
} // namespace

bool Neighborhoods::ComputeStencil(
  std::size_t i, std::size_t slot, std::vector<double>& scratch, bool& thin) const
{
  const std::size_t stride = static_cast<std::size_t>(this->Stride);
  scratch.resize(3 * stride);
  const std::uint32_t* ids = this->NeighborsOf(i);
  const double radius = this->RadiusOf(i);
  const bool ok = BuildLinearStencil(
    this->Position(i), stride, [&](std::size_t m) { return this->Position(ids[m]); }, radius,
    LinearStencilView{ scratch.data(), nullptr }); // zero when singular
  // Stored times h_i (see GradientStencil), of order one in any unit of length.
  this->StencilSlot[i] = static_cast<std::uint32_t>(slot);
  std::transform(scratch.begin(), scratch.end(), &this->GradientStencil[3 * slot * stride],
    [radius](double c) { return static_cast<float>(c * radius); });
  thin = ok && IsThin(ids, stride, *this);
  return ok;
}

void Neighborhoods::EnsureStencils(const std::size_t* samples, std::size_t count) const
{
  const auto start = Clock::now();
  std::vector<std::size_t> missing;
  for (std::size_t k = 0; k < count; ++k)
  {
    unsigned char& state = this->StencilState[samples[k]];
    if (state == 0)
    {
      missing.push_back(samples[k]);
    }
    else if (state >= 3) // computed ahead: counted now, as if computed here
    {
      ++this->ComputedStencils;
      this->SingularSamples += state == 4 ? 1 : 0;
      this->ThinSamples += state == 5 ? 1 : 0;
      state = state == 4 ? 2 : 1;
    }
  }
  vtkSMPThreadLocal<std::vector<double>> scratch;
  vtkSMPThreadLocal<std::size_t> singular(0), thin(0);
  vtkSMPTools::For(0, static_cast<vtkIdType>(missing.size()), BalancedGrain(missing.size(), 64),
    [&](vtkIdType begin, vtkIdType end) {
      std::vector<double>& stencil = scratch.Local();
      // One block of slots per piece: a thread's stencils stay together.
      const std::size_t first = this->NextStencilSlot->fetch_add(
        static_cast<std::size_t>(end - begin), std::memory_order_relaxed);
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::size_t i = missing[k];
        bool isThin = false;
        const bool ok =
          this->ComputeStencil(i, first + static_cast<std::size_t>(k - begin), stencil, isThin);
        this->StencilState[i] = ok ? 1 : 2;
        singular.Local() += !ok;
        thin.Local() += isThin;
      }
    });
  for (std::size_t s : singular)
  {
    this->SingularSamples += s;
  }
  for (std::size_t s : thin)
  {
    this->ThinSamples += s;
  }
  this->ComputedStencils += missing.size();
  this->StencilSeconds += SecondsSince(start);
}

void Neighborhoods::PrecomputeStencils(
  const std::uint32_t* samples, std::size_t count, const std::atomic<bool>& stop) const
{
  std::vector<double> scratch;
  for (std::size_t k = 0; k < count && !stop.load(std::memory_order_relaxed); ++k)
  {
    unsigned char& state = this->StencilState[samples[k]];
    if (state == 0)
    {
      bool thin = false;
      const std::size_t slot = this->NextStencilSlot->fetch_add(1, std::memory_order_relaxed);
      const bool ok = this->ComputeStencil(samples[k], slot, scratch, thin);
      state = !ok ? 4 : thin ? 5 : 3;
    }
  }
}

namespace
{
// The tree build cannot stop half way (0.04 s at 2M uniform points, more on clustered data): it
// runs on a worker thread while this one keeps checking for abort. An abandoned build finishes
// on its own and frees its memory, which it owns through the shared pointer.
struct TreeBuild
{
  UninitializedVector<double> Positions;
  UninitializedVector<std::uint64_t> MortonWords; // of Positions, in their order
  UninitializedVector<std::uint32_t> TreeOrder;   // the tree's reordering of Positions
  std::unique_ptr<PointCloudIndex> Index;
  std::atomic<bool> Done{ false };
  // Wakes the waiting thread as soon as the build is done (a sleep between abort checks would
  // add half its length to every build, on average).
  std::mutex Mutex;
  std::condition_variable Finished;
};

// The threads of abandoned builds. Each is joined when the next one is abandoned after it has
// finished, and the rest at exit, so that no build is still running when the program ends.
class AbandonedBuilds
{
public:
  static void Add(std::thread worker, std::shared_ptr<TreeBuild> build)
  {
    static AbandonedBuilds all;
    std::lock_guard<std::mutex> lock(all.Mutex);
    for (std::size_t i = 0; i < all.Builds.size();)
    {
      if (all.Builds[i].second->Done)
      {
        all.Builds[i].first.join();
        all.Builds.erase(all.Builds.begin() + static_cast<std::ptrdiff_t>(i));
      }
      else
      {
        ++i;
      }
    }
    all.Builds.emplace_back(std::move(worker), std::move(build));
  }
  ~AbandonedBuilds()
  {
    for (auto& entry : this->Builds)
    {
      entry.first.join();
    }
  }

private:
  std::mutex Mutex;
  std::vector<std::pair<std::thread, std::shared_ptr<TreeBuild>>> Builds;
};

bool BuildTree(
  Neighborhoods& out, UninitializedVector<std::uint64_t> mortonWords, const AbortCheck& aborted)
{
  auto build = std::make_shared<TreeBuild>();
  build->Positions = std::move(out.Positions); // the buffer moves, the index will point into it
  build->MortonWords = std::move(mortonWords);
  const std::size_t n = out.NumberOfSamples;
  const int threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  // The tree depends on the points only (not on the threads): it decides the samples' storage
  // order, and with it the order of every result.
  std::thread worker([build, threads]() {
    build->Index.reset(new PointCloudIndex(build->Positions, build->MortonWords, build->TreeOrder,
      [threads](std::vector<std::function<void()>>& tasks) { RunOnThreads(tasks, threads); }));
    UninitializedVector<std::uint64_t>().swap(build->MortonWords);
    {
      std::lock_guard<std::mutex> lock(build->Mutex);
      build->Done = true;
    }
    build->Finished.notify_all();
  });
  while (!build->Done)
  {
    if (Aborted(aborted, 0.25)) // after the sort
    {
      AbandonedBuilds::Add(std::move(worker), build);
      return false;
    }
    std::unique_lock<std::mutex> lock(build->Mutex);
    build->Finished.wait_for(
      lock, std::chrono::milliseconds(10), [&]() { return build->Done.load(); });
  }
  worker.join();
  out.Positions = std::move(build->Positions);
  out.Index = std::move(build->Index);
  // The build moved the samples into the tree's leaf order (a spatial order, like the Morton
  // order it refines): map each back to its input point id.
  UninitializedVector<std::uint32_t> order(n);
  AdviseHugePages(order);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        order[i] = out.Order[build->TreeOrder[i]];
      }
    });
  out.Order.swap(order);
  return true;
}
} // namespace

bool BuildNeighborhoods(
  vtkPoints* points, int numberOfNeighbors, Neighborhoods& out, const AbortCheck& aborted)
{
  const std::size_t n = static_cast<std::size_t>(points->GetNumberOfPoints());
  const int stride = numberOfNeighbors + 1;
  out = Neighborhoods();
  out.NumberOfSamples = n;
  out.Stride = stride;
  auto start = Clock::now();
  UninitializedVector<std::uint64_t> mortonWords = SortSpatially(points, out);
  out.SortSeconds = SecondsSince(start);
  if (Aborted(aborted, 0.25))
  {
    return false;
  }

  // Nearest neighbours, queried in storage (leaf) order: consecutive queries walk the same nodes.
  start = Clock::now();
  if (!BuildTree(out, std::move(mortonWords), aborted))
  {
    return false;
  }
  out.TreeSeconds = SecondsSince(start);
  if (Aborted(aborted, 0.75))
  {
    return false;
  }
  out.Ids.resize(n * stride); // not initialised: pages cost memory only once a list is written
  out.Radii.resize(n);
  out.Rows.reset(new Neighborhoods::RowStates(n));
  AdviseHugePages(out.Ids);
  AdviseHugePages(out.Radii);

  // The mean radius (for the checks of the data's scale) over a few thousand of a fixed sample
  // of the samples, searched here and not kept: the fixed sample's own lists are computed when
  // the method first needs them (ScaleAtSurface), and under MPI its sample is chosen over every
  // rank's particles, another sample: computing these 65,536 lists at every build cost each
  // rank of a 2M run about 0.2 s per build, twice.
  const std::uint64_t every = RadiusSampleEvery(static_cast<double>(n));
  const std::vector<std::uint32_t> sample =
    out.RadiusSampleWhere(every, [](std::size_t) { return true; });
  out.MeanRadius = MeanRadiusOver(out, sample, MeanRadiusSearches);
  out.SearchSeconds = SecondsSince(start);

  out.GradientStencil.reset(new float[3 * n * stride]);
  AdviseHugePages(out.GradientStencil.get(), sizeof(float) * 3 * n * stride);
  out.StencilSlot.resize(n);
  out.NextStencilSlot.reset(new std::atomic<std::size_t>(0));
  ResizeMappedInParallel(out.StencilState, n, static_cast<unsigned char>(0));
  std::vector<double> sampled; // flatness too is judged on the fixed sample
  sampled.reserve(3 * sample.size());
  for (const std::uint32_t i : sample)
  {
    sampled.insert(sampled.end(), out.Position(i), out.Position(i) + 3);
  }
  out.Flat = IsFlat(sampled);
  return true;
}

void Neighborhoods::ComputeRow(std::size_t i) const
{
  std::atomic<unsigned char>& state = this->Rows->State[i];
  unsigned char expected = 0;
  if (!state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel))
  {
    while (state.load(std::memory_order_acquire) != 2) // another thread is computing it
    {
      std::this_thread::yield();
    }
    return;
  }
  const std::size_t slot = this->Rows->Computed.fetch_add(1, std::memory_order_relaxed);
  this->Rows->Slot[i] = static_cast<std::uint32_t>(slot);
  this->Radii[slot] =
    this->SearchRow(i, 0.0, &this->Ids[slot * static_cast<std::size_t>(this->Stride)]);
  state.store(2, std::memory_order_release);
}

void Neighborhoods::ComputeRun(const std::size_t* samples, std::size_t count) const
{
  // The run's rows are claimed first and take one block of slots: rows written by one thread
  // stay together (rows of two threads interleaved slot by slot shared cache lines, and each
  // row's slot cost an exchange of the counter between the cores).
  std::uint32_t claimed[RowRun];
  std::size_t claims = 0;
  for (std::size_t k = 0; k < count && claims < RowRun; ++k)
  {
    unsigned char expected = 0;
    if (this->Rows->State[samples[k]].compare_exchange_strong(
          expected, 1, std::memory_order_acq_rel))
    {
      claimed[claims++] = static_cast<std::uint32_t>(samples[k]);
    }
  }
  const std::size_t first = this->Rows->Computed.fetch_add(claims, std::memory_order_relaxed);
  const std::size_t stride = static_cast<std::size_t>(this->Stride);
  double nearby = 0.0; // each search bounded first by the radius of the one before it
  for (std::size_t c = 0; c < claims; ++c)
  {
    const std::size_t slot = first + c;
    this->Rows->Slot[claimed[c]] = static_cast<std::uint32_t>(slot);
    nearby = this->Radii[slot] = this->SearchRow(claimed[c], nearby, &this->Ids[slot * stride]);
    this->Rows->State[claimed[c]].store(2, std::memory_order_release);
  }
  for (std::size_t k = 0; k < count; ++k)
  {
    this->EnsureRow(samples[k]); // those past RowRun, or another thread's: ready or waited for
  }
}

double Neighborhoods::SearchRow(std::size_t i, double nearbyRadius, std::uint32_t* ids) const
{
  const int stride = this->Stride;
  thread_local std::vector<double> d2; // one per thread: rows are computed millions of times
  d2.resize(static_cast<std::size_t>(stride));
  this->Index->NearestNear(
    this->Position(i), static_cast<std::size_t>(stride), nearbyRadius, ids, d2.data());
  ArrangeRow(static_cast<std::uint32_t>(i), ids, d2.data(), stride);
  return std::sqrt(*std::max_element(d2.begin(), d2.end()));
}

Neighborhoods::SampleRow Neighborhoods::FixedSampleRow(std::size_t i) const
{
  this->EnsureFixedSampleRows();
  return { this->NeighborsOf(i), this->RadiusOf(i) };
}

void Neighborhoods::EnsureFixedSampleRows() const
{
  if (this->SampleRowsEvery != this->SampleEvery)
  {
    // First use of this sample: its missing lists, in parallel (main thread only, as
    // RadiusSampleWhere).
    this->EnsureNeighbors(this->Sample.data(), this->Sample.size());
    this->SampleRowsEvery = this->SampleEvery;
  }
}

bool Neighborhoods::EnsureAllNeighbors(const AbortCheck& aborted) const
{
  return ParallelForInBlocks(
    this->NumberOfSamples,
    [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
      {
        this->EnsureRow(i);
      }
    },
    aborted);
}

namespace
{
/// A coordinate rounded to single precision, as bits: the sample's choice must survive a trip
/// through float coordinates (ParaView's Distribute Points writes float points). Beyond float's
/// range (lengths in extreme units, which only double points hold) the mantissa is rounded to
/// float's 24 bits and the exponent mixed in, so those samples still spread.
std::uint32_t SinglePrecisionBits(double x)
{
  const float rounded = static_cast<float>(x);
  std::uint32_t bits = 0;
  if (x == 0.0)
  {
    return bits;
  }
  if (std::isfinite(rounded) && std::abs(rounded) >= FLT_MIN)
  {
    std::memcpy(&bits, &rounded, sizeof bits);
    return bits;
  }
  int exponent = 0;
  const float mantissa = static_cast<float>(std::frexp(x, &exponent));
  std::memcpy(&bits, &mantissa, sizeof bits);
  return bits ^ (static_cast<std::uint32_t>(exponent) * 0x9e3779b9U);
}
} // namespace

bool Neighborhoods::InRadiusSample(std::size_t i, std::uint64_t every) const
{
  return every <= 1 || this->PositionHash(i) % every == 0;
}

std::uint64_t Neighborhoods::PositionHash(std::size_t i) const
{
  std::uint64_t hash = 0x9e3779b97f4a7c15ULL;
  for (int k = 0; k < 3; ++k)
  {
    const std::uint32_t bits = SinglePrecisionBits(this->Positions[3 * i + k]);
    hash ^= bits + 0x9e3779b97f4a7c15ULL + (hash << 6) + (hash >> 2);
    hash ^= hash >> 31; // splitmix64's finaliser
    hash *= 0xbf58476d1ce4e5b9ULL;
    hash ^= hash >> 27;
  }
  return hash;
}

} // namespace lsi
