// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetHaloReach.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <numeric>
#include <utility>

namespace lsi
{

namespace
{
// The farthest of the samples [first, first + count) from sample i (i itself excluded by the
// caller's window).
double FarthestOf(
  const Neighborhoods& geometry, std::size_t i, std::size_t first, std::size_t count)
{
  const double* x = geometry.Position(i);
  double farthest = 0.0;
  for (std::size_t j = first; j < first + count; ++j)
  {
    if (j == i)
    {
      continue;
    }
    const double* y = geometry.Position(j);
    const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
    farthest = std::max(farthest, dx * dx + dy * dy + dz * dz);
  }
  return std::sqrt(farthest);
}

// Rounding allowance: a bound computed here and a radius computed by the tree may differ in
// their last bits.
constexpr double Slack = 1e-9;
} // namespace

double RadiusBound(const Neighborhoods& geometry, std::size_t i)
{
  const std::size_t n = geometry.NumberOfSamples;
  const std::size_t k = geometry.Stride > 1 ? static_cast<std::size_t>(geometry.Stride) - 1 : 0;
  if (k == 0 || n < 2 * k + 1)
  {
    return HUGE_VAL;
  }
  // Windows of k others: before i, around it (k + 1 with i), after it; each clipped to the
  // samples there are.
  double bound = HUGE_VAL;
  if (i >= k)
  {
    bound = std::min(bound, FarthestOf(geometry, i, i - k, k));
  }
  const std::size_t around = std::min(i >= k / 2 ? i - k / 2 : 0, n - (k + 1));
  bound = std::min(bound, FarthestOf(geometry, i, around, k + 1));
  if (i + k < n)
  {
    bound = std::min(bound, FarthestOf(geometry, i, i + 1, k));
  }
  return bound;
}

double WindowRadiusBound(
  const Neighborhoods& geometry, std::size_t i, std::size_t half, std::vector<double>& squared)
{
  const std::size_t n = geometry.NumberOfSamples;
  const std::size_t k = geometry.Stride > 1 ? static_cast<std::size_t>(geometry.Stride) - 1 : 0;
  const std::size_t first = i >= half ? i - half : 0, last = std::min(n, i + half + 1);
  if (k == 0 || last - first < k + 1)
  {
    return HUGE_VAL;
  }
  squared.clear();
  const double* x = geometry.Position(i);
  for (std::size_t j = first; j < last; ++j)
  {
    if (j != i)
    {
      const double* y = geometry.Position(j);
      const double dx = x[0] - y[0], dy = x[1] - y[1], dz = x[2] - y[2];
      squared.push_back(dx * dx + dy * dy + dz * dz);
    }
  }
  std::nth_element(
    squared.begin(), squared.begin() + static_cast<std::ptrdiff_t>(k - 1), squared.end());
  return std::sqrt(squared[k - 1]);
}

std::vector<double> RadiusBounds(const Neighborhoods& geometry)
{
  const std::size_t n = geometry.NumberOfSamples;
  std::vector<double> bounds;
  if (n == 0 || !std::isfinite(RadiusBound(geometry, 0)))
  {
    return bounds;
  }
  bounds.resize(n);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), BalancedGrain(n, 16384), [&](vtkIdType begin, vtkIdType end) {
      for (std::size_t i = static_cast<std::size_t>(begin); i < static_cast<std::size_t>(end); ++i)
      {
        bounds[i] = RadiusBound(geometry, i);
      }
    });
  return bounds;
}

bool HaloReachBox(const Neighborhoods& geometry, double factor, double band, double box[6],
  std::size_t& computed, const AbortCheck& aborted, std::size_t firstPerSide, const bool wanted[6])
{
  const std::size_t n = geometry.NumberOfSamples;
  // Each side (0..5: -x, +x, -y, ...) as a maximum until the end: the lower bounds negated.
  std::fill(box, box + 6, -HUGE_VAL);
  computed = 0;
  int sides[6], sideCount = 0; // the sides computed
  for (int side = 0; side < 6; ++side)
  {
    if (!wanted || wanted[side])
    {
      sides[sideCount++] = side;
    }
    else
    {
      box[side] = HUGE_VAL; // unbounded
    }
  }
  if (sideCount == 0)
  {
    box[0] = box[2] = box[4] = -HUGE_VAL; // (the lower sides, unbounded)
    return !Aborted(aborted, 1.0);
  }
  // How far sample i reaches in direction `side` (0..5: -x, +x, -y, ...), as a maximum.
  // (Rounded as the box x_i -+ reach_i would be: -(x - reach) is reach - x exactly.)
  auto reachOf = [&](std::size_t i, int side, double radius) {
    const double x = geometry.Position(i)[side / 2];
    const double reach = factor * radius + band;
    return side % 2 ? x + reach : reach - x;
  };
  auto exactBox = [&](const std::vector<std::uint32_t>& samples) {
    for (const std::uint32_t i : samples)
    {
      for (int s = 0; s < sideCount; ++s)
      {
        const int side = sides[s];
        const double reach = reachOf(i, side, geometry.RadiusOf(i));
        box[side] = std::max(box[side], reach);
      }
    }
  };
  const std::vector<double> bounds = RadiusBounds(geometry);
  if (bounds.empty()) // few samples: every list
  {
    std::vector<std::uint32_t> all(n);
    std::iota(all.begin(), all.end(), 0U);
    if (!geometry.EnsureAllNeighbors(aborted))
    {
      return false;
    }
    computed = n;
    exactBox(all);
  }
  else
  {
    // 1. The samples that reach farthest by their bounds, a few per side: their exact reach is
    //    a reach the box attains.
    //    (Per side the m least keys (-reach, index), kept in a heap in one pass over the
    //    samples: most are no better than its worst and are never inserted.)
    const std::size_t m = std::max<std::size_t>(1, std::min(firstPerSide, n));
    using Keyed = std::pair<double, std::uint32_t>;
    std::vector<Keyed> heaps[6]; // max-heaps: the front is the worst key kept
    for (std::size_t i = 0; i < n; ++i)
    {
      for (int s = 0; s < sideCount; ++s)
      {
        const Keyed key{ -reachOf(i, sides[s], bounds[i]), static_cast<std::uint32_t>(i) };
        std::vector<Keyed>& heap = heaps[s];
        if (heap.size() < m)
        {
          heap.push_back(key);
          std::push_heap(heap.begin(), heap.end());
        }
        else if (key < heap.front())
        {
          std::pop_heap(heap.begin(), heap.end());
          heap.back() = key;
          std::push_heap(heap.begin(), heap.end());
        }
      }
    }
    std::vector<std::uint32_t> first;
    for (int s = 0; s < sideCount; ++s)
    {
      for (const Keyed& key : heaps[s])
      {
        first.push_back(key.second);
      }
    }
    std::sort(first.begin(), first.end());
    first.erase(std::unique(first.begin(), first.end()), first.end());
    geometry.EnsureNeighbors(first);
    exactBox(first);
    if (Aborted(aborted, 0.1))
    {
      return false;
    }
    // 2. Every other sample whose bounded reach passes that on some side: only these can move
    //    the box. Those that pass by RadiusBound are tried again by the tighter
    //    WindowRadiusBound (a twentieth of a list's cost), which leaves out most of them.
    const double attained[6] = { box[0], box[1], box[2], box[3], box[4], box[5] };
    auto passes = [&](std::size_t i, double bound) {
      for (int s = 0; s < sideCount; ++s)
      {
        const int side = sides[s];
        const double reach = reachOf(i, side, bound);
        const double allowance =
          Slack * (std::abs(geometry.Position(i)[side / 2]) + factor * bound + std::abs(band));
        if (reach + allowance >= attained[side])
        {
          return true;
        }
      }
      return false;
    };
    const std::vector<std::uint32_t> loose =
      IndicesWhere<std::uint32_t>(n, [&](std::size_t i) { return passes(i, bounds[i]); });
    // Those that still pass with a window of a neighbourhood's size on each side (most do
    // not), then with one four times as wide (the bound nearer h_i, its cost four times).
    auto stillPassing = [&](const std::vector<std::uint32_t>& samples, std::size_t half) {
      std::vector<char> pass(samples.size());
      vtkSMPTools::For(0, static_cast<vtkIdType>(samples.size()),
        BalancedGrain(samples.size(), 16384), [&](vtkIdType begin, vtkIdType end) {
          std::vector<double> scratch;
          for (vtkIdType k = begin; k < end; ++k)
          {
            const std::size_t i = samples[static_cast<std::size_t>(k)];
            const double bound = std::min(bounds[i], WindowRadiusBound(geometry, i, half, scratch));
            pass[k] = passes(i, bound) ? 1 : 0;
          }
        });
      std::vector<std::uint32_t> kept;
      for (std::size_t k = 0; k < samples.size(); ++k)
      {
        if (pass[k])
        {
          kept.push_back(samples[k]);
        }
      }
      return kept;
    };
    const std::size_t stride = static_cast<std::size_t>(geometry.Stride);
    const std::vector<std::uint32_t> rest = stillPassing(stillPassing(loose, stride), 4 * stride);
    geometry.EnsureNeighbors(rest);
    exactBox(rest);
    std::vector<std::uint32_t> both;
    std::set_union(first.begin(), first.end(), rest.begin(), rest.end(), std::back_inserter(both));
    computed = both.size();
  }
  // Stored as maxima: the lower bounds negated back.
  for (int d = 0; d < 3; ++d)
  {
    box[2 * d] = -box[2 * d];
  }
  return !Aborted(aborted, 1.0);
}

} // namespace lsi
