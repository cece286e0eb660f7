// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A partition of space into P parts of about equal weight: orthogonal recursive bisection of a
// weighted sample of the particles (each rank's sample weighted by the particles it stands
// for). Each cut halves the ranks (P/2 rounded down to the left) along the sample's widest
// axis, at the weighted quantile that gives each side its share, midway between the two
// samples it falls between. Built the same on every rank from the same samples; a point then
// finds its part by descending the cuts (x < cut: left). Plain C++: LevelSetDistribution sends
// each particle to its part's rank.
#ifndef SpatialPartition_h
#define SpatialPartition_h

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace lsi
{

class SpatialPartition
{
public:
  /// The partition of `xyz` (3 values per sample) with `weights` (one per sample, positive)
  /// into `parts` parts (at least 1).
  SpatialPartition(const std::vector<double>& xyz, const std::vector<double>& weights, int parts)
  {
    std::vector<std::size_t> samples(weights.size());
    std::iota(samples.begin(), samples.end(), std::size_t(0));
    this->Build(xyz, weights, samples, 0, std::max(parts, 1));
  }

  /// The part (0 to parts - 1) that holds x.
  int PartOf(const double* x) const
  {
    int node = 0;
    while (true)
    {
      const Cut& cut = this->Cuts[static_cast<std::size_t>(node)];
      if (cut.Axis < 0)
      {
        return cut.Part;
      }
      node = x[cut.Axis] < cut.Value ? cut.Left : cut.Right;
    }
  }

private:
  struct Cut
  {
    int Axis = -1; // -1: a leaf, holding Part
    double Value = 0.0;
    int Left = -1, Right = -1;
    int Part = 0;
  };
  std::vector<Cut> Cuts;

  // Adds the node for `samples` shared among parts [first, first + count); returns its index.
  int Build(const std::vector<double>& xyz, const std::vector<double>& weights,
    std::vector<std::size_t>& samples, int first, int count)
  {
    const int node = static_cast<int>(this->Cuts.size());
    this->Cuts.emplace_back();
    if (count == 1)
    {
      this->Cuts[static_cast<std::size_t>(node)].Part = first;
      return node;
    }
    // The widest axis of the samples' box (x without samples).
    int axis = 0;
    if (!samples.empty())
    {
      double widest = -1.0;
      for (int d = 0; d < 3; ++d)
      {
        double lo = xyz[3 * samples[0] + d], hi = lo;
        for (std::size_t s : samples)
        {
          lo = std::min(lo, xyz[3 * s + d]);
          hi = std::max(hi, xyz[3 * s + d]);
        }
        if (hi - lo > widest)
        {
          widest = hi - lo;
          axis = d;
        }
      }
    }
    // Along it, in order (ties by sample: the same order on every rank).
    std::sort(samples.begin(), samples.end(), [&](std::size_t a, std::size_t b) {
      const double xa = xyz[3 * a + axis], xb = xyz[3 * b + axis];
      return xa < xb || (xa == xb && a < b);
    });
    const int left = count / 2;
    double total = 0.0;
    for (std::size_t s : samples)
    {
      total += weights[s];
    }
    // The first sample on the right: where the weight before it reaches the left's share.
    const double share = total * static_cast<double>(left) / static_cast<double>(count);
    std::size_t split = 0;
    double before = 0.0;
    while (split < samples.size() && before + 0.5 * weights[samples[split]] < share)
    {
      before += weights[samples[split]];
      ++split;
    }
    double value = 0.0;
    if (!samples.empty())
    {
      const double below = xyz[3 * samples[split == 0 ? 0 : split - 1] + axis];
      const double above = xyz[3 * samples[std::min(split, samples.size() - 1)] + axis];
      value = split == 0 ? below : (split == samples.size() ? above : 0.5 * (below + above));
      // The samples below the cut go left, as points do (equal coordinates: all right).
      split = 0;
      while (split < samples.size() && xyz[3 * samples[split] + axis] < value)
      {
        ++split;
      }
    }
    std::vector<std::size_t> low(samples.begin(), samples.begin() + static_cast<long>(split));
    std::vector<std::size_t> high(samples.begin() + static_cast<long>(split), samples.end());
    const int l = this->Build(xyz, weights, low, first, left);
    const int r = this->Build(xyz, weights, high, first + left, count - left);
    Cut& cut = this->Cuts[static_cast<std::size_t>(node)];
    cut.Axis = axis;
    cut.Value = value;
    cut.Left = l;
    cut.Right = r;
    return node;
  }
};

} // namespace lsi

#endif
