#include "LevelSetNeighborhoods.h"

#include "AutomaticParameters.h"
#include "MovingLeastSquares.h"

#include "vtkPoints.h"
#include "vtkSMPThreadLocal.h"

#include <atomic>
#include <cmath>

namespace lsi
{

namespace
{
// Puts the sample itself in slot 0 of its row and reports whether another sample sits at
// exactly the same position.
bool ArrangeRow(std::uint32_t self, std::uint32_t* ids, double* d2, int stride)
{
  int selfSlot = -1;
  bool duplicate = false;
  for (int k = 0; k < stride; ++k)
  {
    if (ids[k] == self)
    {
      selfSlot = k;
    }
    else if (d2[k] == 0.0)
    {
      duplicate = true;
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
  return duplicate;
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
  out.Positions.resize(3 * n);
  for (std::size_t i = 0; i < n; ++i)
  {
    points->GetPoint(static_cast<vtkIdType>(i), &out.Positions[3 * i]);
  }
  out.Index.reset(new PointCloudIndex(out.Positions.data(), n));
  out.Ids.resize(n * stride);
  out.Radius.resize(n);
  out.GradientStencil.resize(3 * n * stride);

  std::atomic<std::size_t> duplicates(0), singular(0);
  std::atomic<long long> firstDuplicate(-1), firstSingular(-1);
  auto remember = [](std::atomic<long long>& first, long long i) {
    long long expected = -1;
    while ((expected < 0 || i < expected) && !first.compare_exchange_weak(expected, i))
    {
    }
  };

  struct Scratch
  {
    std::vector<double> D2, Stencil;
  };
  vtkSMPThreadLocal<Scratch> scratch;
  const bool completed = ParallelForInBlocks(
    n,
    [&](std::size_t begin, std::size_t end) {
      Scratch& s = scratch.Local();
      s.D2.resize(stride);
      s.Stencil.resize(3 * stride);
      for (std::size_t i = begin; i < end; ++i)
      {
        std::uint32_t* ids = &out.Ids[i * stride];
        out.Index->Nearest(out.Position(i), stride, ids, s.D2.data());
        if (ArrangeRow(static_cast<std::uint32_t>(i), ids, s.D2.data(), stride))
        {
          ++duplicates;
          remember(firstDuplicate, static_cast<long long>(i));
        }
        double h2 = 0.0;
        for (int k = 0; k < stride; ++k)
        {
          h2 = std::max(h2, s.D2[k]);
        }
        out.Radius[i] = std::sqrt(h2);
        const bool ok = BuildLinearStencil(
          out.Position(i), static_cast<std::size_t>(stride),
          [&](std::size_t k) { return out.Position(ids[k]); }, out.Radius[i],
          LinearStencilView{ s.Stencil.data(), nullptr });
        if (!ok)
        {
          ++singular;
          remember(firstSingular, static_cast<long long>(i));
        }
        float* stencil = &out.GradientStencil[3 * i * stride];
        for (int k = 0; k < 3 * stride; ++k)
        {
          stencil[k] = static_cast<float>(s.Stencil[k]);
        }
      }
    },
    aborted);
  if (!completed)
  {
    return false;
  }
  out.DuplicateSamples = duplicates;
  out.FirstDuplicate = firstDuplicate;
  out.SingularSamples = singular;
  out.FirstSingular = firstSingular;
  double sumRadius = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    sumRadius += out.Radius[i];
  }
  out.MeanRadius = n ? sumRadius / n : 0.0;
  out.MeanSpacing = SpacingFromNeighborhoodRadius(out.MeanRadius, numberOfNeighbors);
  return true;
}

} // namespace lsi
