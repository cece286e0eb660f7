// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The Enclosed table around a deep inside (EnclosedDeepInside): the deep inside's groups and
// sums found once, then the band's samples summed and joined to them. The components and sums
// are those of LevelSetEnclosed.cxx's route over every touching sample (to rounding: the sums
// are added in another order).
#include "LevelSetEnclosedDeepInside.h"

#include "LevelSetEnclosedSums.h"
#include "LevelSetParallel.h"
#include "UninitializedVector.h"

#include "vtkSMPTools.h"
#include "vtkTable.h"

#include <algorithm>
#include <map>
#include <unordered_map>

namespace lsi
{
namespace
{
using namespace enclosed;

// Whether sample i is one of this rank's particles (under MPI the others are ghosts: they join
// components but are summed by their owners).
bool OwnParticle(const EnclosedInputs& in, std::size_t i)
{
  return in.Ranks->Owns(i) && static_cast<vtkIdType>(in.Geometry->Order[i]) < in.ParticleCount;
}

// The places k of a list of samples that are summed here: all in one process; under MPI this
// rank's particles only (the ghosts' owners sum them).
struct SummedPlaces
{
  bool All = true;
  std::vector<std::uint32_t> Places; // under MPI
  SummedPlaces(const EnclosedInputs& in, const std::vector<std::uint32_t>& samples)
    : All(!in.Ranks->Distributed())
  {
    if (!this->All)
    {
      this->Places = IndicesWhere<std::uint32_t>(
        samples.size(), [&](std::size_t k) { return OwnParticle(in, samples[k]); });
    }
  }
  /// The place in the list of the k-th summed sample.
  std::size_t operator()(std::size_t k) const { return this->All ? k : this->Places[k]; }
  /// The summed samples themselves.
  std::vector<std::uint32_t> Of(const std::vector<std::uint32_t>& samples) const
  {
    if (this->All)
    {
      return samples;
    }
    std::vector<std::uint32_t> out(this->Places.size());
    for (std::size_t k = 0; k < out.size(); ++k)
    {
      out[k] = samples[this->Places[k]];
    }
    return out;
  }
};

// Deep inside: phi at the band's half width (where the slides leave it) and beyond two shell
// widths (so that its signed distance is phi, and its step 1).
bool DeepInside(const EnclosedInputs& in, std::size_t i)
{
  const double phi = (*in.Phi)[i];
  return phi >= -in.FarOutside && phi > 2.0 * in.Geometry->RadiusOf(i);
}

// The sums of `samples` by group (groupOf(k) for the k-th sample, below `groups`), in fixed
// chunks summed in parallel and added in chunk order: the same on any number of threads.
// recordOf(k, scratch) gives the k-th sample's particle record (ReadParticle's), read into
// `scratch` (RecordSize doubles) or kept elsewhere.
template <typename GroupOf, typename DistanceOf, typename RecordOf>
std::vector<Sums> SumsByGroup(const EnclosedInputs& in, int components,
  const std::vector<std::uint32_t>& samples, std::size_t groups, GroupOf&& groupOf,
  DistanceOf&& distanceOf, RecordOf&& recordOf)
{
  constexpr std::size_t ChunkSize = 16384;
  const std::size_t chunks = (samples.size() + ChunkSize - 1) / ChunkSize;
  std::vector<PartsByGroup<std::uint32_t>> parts(chunks);
  vtkSMPTools::For(0, static_cast<vtkIdType>(chunks), 1, [&](vtkIdType first, vtkIdType last) {
    std::vector<double> scratch(RecordSize(components));
    for (vtkIdType chunk = first; chunk < last; ++chunk)
    {
      PartsByGroup<std::uint32_t>& out = parts[static_cast<std::size_t>(chunk)];
      const std::size_t begin = static_cast<std::size_t>(chunk) * ChunkSize;
      const std::size_t end = std::min(samples.size(), begin + ChunkSize);
      for (std::size_t k = begin; k < end; ++k)
      {
        const std::size_t i = samples[k];
        AddRecord(
          in, recordOf(k, scratch.data()), components, i, distanceOf(i), out.Of(groupOf(k)));
      }
    }
  });
  std::vector<Sums> sums(groups);
  for (const PartsByGroup<std::uint32_t>& chunk : parts)
  {
    for (std::size_t k = 0; k < chunk.Parts.size(); ++k)
    {
      sums[chunk.Groups[k]].Add(chunk.Parts[k]);
    }
  }
  return sums;
}

} // namespace

bool CanUseDeepInside(const EnclosedInputs& in)
{
  if (in.Box.Enabled || !(in.FarOutside > -HUGE_VAL))
  {
    return false;
  }
  if (!in.Ranks->Distributed())
  {
    return static_cast<vtkIdType>(in.Geometry->NumberOfSamples) == in.ParticleCount;
  }
  // Under MPI: every particle of this rank is a sample of its own (none merged), and so on every
  // rank.
  const std::vector<std::uint32_t> owned = IndicesWhere<std::uint32_t>(
    in.Geometry->NumberOfSamples, [&](std::size_t i) { return OwnParticle(in, i); });
  return in.Ranks->All(static_cast<vtkIdType>(owned.size()) == in.ParticleCount);
}

void FindDeepInside(const EnclosedInputs& in, EnclosedDeepInside& deep)
{
  const Neighborhoods& geometry = *in.Geometry;
  const std::size_t n = geometry.NumberOfSamples;
  // (Under MPI a ghost is deep where its owner is: FlagsAtOwners.)
  const std::vector<char> atOwners = in.Ranks->Distributed()
    ? FlagsAtOwners(*in.Ranks, n, [&](std::size_t i) { return DeepInside(in, i); })
    : std::vector<char>();
  const std::vector<std::uint32_t> inside = IndicesWhere<std::uint32_t>(
    n, [&](std::size_t i) { return atOwners.empty() ? DeepInside(in, i) : atOwners[i] != 0; });
  // The groups: the deep samples joined through their neighbour lists (as the touching ones
  // are in the full route: from the samples whose lists are whole), numbered in storage order.
  deep.Group = FilledInParallel<std::uint32_t>(n, EnclosedDeepInside::None);
  vtkSMPTools::For(0, static_cast<vtkIdType>(inside.size()), BalancedGrain(inside.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        deep.Group[inside[k]] = static_cast<std::uint32_t>(k);
      }
    });
  // (Joined in parallel: the sets do not depend on the order.)
  const Links links(inside.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(inside.size()), BalancedGrain(inside.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const std::size_t i = inside[static_cast<std::size_t>(k)];
        if (geometry.IsTruncated(i))
        {
          continue;
        }
        const std::uint32_t* ids = geometry.NeighborsOf(i);
        for (int m = 1; m < geometry.Stride; ++m)
        {
          const std::uint32_t other = deep.Group[ids[m]];
          if (other != EnclosedDeepInside::None)
          {
            links.Join(static_cast<std::uint32_t>(k), other);
          }
        }
      }
    });
  // Each deep sample's root, in parallel (the links are complete: the roots no longer change);
  // then the groups numbered in storage order, on one thread (a light pass).
  UninitializedVector<std::uint32_t> rootOf(inside.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(inside.size()), BalancedGrain(inside.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        rootOf[k] = links.Find(static_cast<std::uint32_t>(k));
      }
    });
  UninitializedVector<std::uint32_t> groupOfRoot =
    FilledInParallel<std::uint32_t>(inside.size(), EnclosedDeepInside::None);
  std::vector<double> lowest; // per group: its lowest particle id, the key of its component
  std::uint32_t groups = 0;
  for (std::size_t k = 0; k < inside.size(); ++k)
  {
    std::uint32_t& group = groupOfRoot[rootOf[k]];
    if (group == EnclosedDeepInside::None)
    {
      group = groups++;
      lowest.push_back(HUGE_VAL);
    }
    if (OwnParticle(in, inside[k])) // (a group of ghosts alone keeps HUGE_VAL: nothing to sum)
    {
      lowest[group] = std::min(lowest[group], static_cast<double>(geometry.Order[inside[k]]));
    }
  }
  vtkSMPTools::For(0, static_cast<vtkIdType>(inside.size()), BalancedGrain(inside.size(), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        deep.Group[inside[k]] = groupOfRoot[rootOf[k]];
      }
    });
  // The rim: the deep samples whose lists reach out of the deep inside (the band's samples
  // join the groups through these, besides through their own lists).
  deep.Rim = IndicesWhere<std::uint32_t>(inside.size(), [&](std::size_t k) {
    const std::size_t i = inside[k];
    if (geometry.IsTruncated(i))
    {
      return false;
    }
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      if (deep.Group[ids[m]] == EnclosedDeepInside::None)
      {
        return true;
      }
    }
    return false;
  });
  for (std::uint32_t& k : deep.Rim)
  {
    k = inside[k];
  }
  // The near samples, numbered after the groups (so that a re-run finds the band among them
  // without a pass over every sample).
  deep.Near = IndicesWhere<std::uint32_t>(n, [&](std::size_t i) {
    return deep.Group[i] == EnclosedDeepInside::None && (*in.Phi)[i] > in.FarOutside;
  });
  vtkSMPTools::For(0, static_cast<vtkIdType>(deep.Near.size()),
    BalancedGrain(deep.Near.size(), 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        deep.Group[deep.Near[p]] = groups + static_cast<std::uint32_t>(p);
      }
    });
  int components = 0;
  const std::vector<vtkDataArray*> arrays = ArraysToAverage(in, components);
  // The near samples' particle records, in Near's order: a re-run reads them there, not
  // scattered over the input's arrays (in input order).
  const std::size_t record = RecordSize(components);
  deep.NearRecords.resize(record * deep.Near.size()); // (every record written below)
  vtkSMPTools::For(0, static_cast<vtkIdType>(deep.Near.size()),
    BalancedGrain(deep.Near.size(), 1024), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType p = begin; p < end; ++p)
      {
        if (OwnParticle(in, deep.Near[p]))
        {
          ReadParticle(in, arrays, geometry.Order[deep.Near[p]], &deep.NearRecords[record * p]);
        }
        else // (a ghost's record is never read)
        {
          std::fill_n(&deep.NearRecords[record * p], record, 0.0);
        }
      }
    });
  const std::vector<double>& phi = *in.Phi;
  const SummedPlaces summed(in, inside);
  const std::vector<Sums> sums = SumsByGroup(
    in, components, summed.Of(inside), groups,
    [&](std::size_t k) { return deep.Group[inside[summed(k)]]; },
    [&](std::size_t i) { return phi[i]; },
    [&](std::size_t k, double* scratch) {
      ReadParticle(in, arrays, geometry.Order[inside[summed(k)]], scratch);
      return scratch;
    });
  deep.Sums.clear();
  Sums nothing; // (under MPI, a group of ghosts alone: packed as wide as the others)
  nothing.Means.assign(static_cast<std::size_t>(components), 0.0);
  for (std::size_t g = 0; g < sums.size(); ++g)
  {
    Pack(lowest[g], sums[g].Means.size() == nothing.Means.size() ? sums[g] : nothing, deep.Sums);
  }
  deep.Components = components;
}

vtkSmartPointer<vtkTable> EnclosedTableAround(
  const EnclosedInputs& in, const EnclosedDeepInside& deep, EnclosedDeepInside* keeping)
{
  const Neighborhoods& geometry = *in.Geometry;
  const std::size_t n = geometry.NumberOfSamples;
  int components = 0;
  const std::vector<vtkDataArray*> arrays = ArraysToAverage(in, components);
  const std::size_t record = FixedFields + static_cast<std::size_t>(components);
  if (deep.Group.size() != n || deep.Components != components || deep.Sums.size() % record != 0 ||
    deep.NearRecords.size() != RecordSize(components) * deep.Near.size())
  {
    return nullptr; // kept for other samples or arrays
  }
  const std::size_t groups = deep.Sums.size() / record;
  // The band: the touching near samples (in storage order). Nodes: the groups, then the band's
  // samples; bandOf gives a near sample's place in the band.
  // (Under MPI a ghost touches where its owner does: FlagsAtOwners.)
  const std::vector<char> atOwners = in.Ranks->Distributed()
    ? FlagsAtOwners(*in.Ranks, n, [&](std::size_t i) { return Touches(in, i); })
    : std::vector<char>();
  auto touches = [&](std::uint32_t i) {
    return atOwners.empty() ? Touches(in, i) : atOwners[i] != 0;
  };
  const std::vector<std::uint32_t> inBand = IndicesWhere<std::uint32_t>(
    deep.Near.size(), [&](std::size_t p) { return touches(deep.Near[p]); });
  std::vector<std::uint32_t> band(inBand.size());
  std::vector<std::uint32_t> bandOf(deep.Near.size(), EnclosedDeepInside::None);
  vtkSMPTools::For(0, static_cast<vtkIdType>(band.size()), BalancedGrain(band.size(), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType b = begin; b < end; ++b)
      {
        band[b] = deep.Near[inBand[b]];
        bandOf[inBand[b]] = static_cast<std::uint32_t>(b);
      }
    });
  auto node = [&](std::size_t i) {
    const std::uint32_t g = deep.Group[i];
    if (g < groups || g == EnclosedDeepInside::None)
    {
      return g;
    }
    const std::uint32_t b = bandOf[g - groups];
    return b == EnclosedDeepInside::None ? b : static_cast<std::uint32_t>(groups + b);
  };
  // Joined through the band's lists and the rim's (the groups are joined within already), in
  // parallel: the sets do not depend on the order.
  const Links links(groups + band.size());
  auto joinListed = [&](const std::vector<std::uint32_t>& samples) {
    vtkSMPTools::For(0, static_cast<vtkIdType>(samples.size()), BalancedGrain(samples.size(), 1024),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType k = begin; k < end; ++k)
        {
          const std::uint32_t i = samples[static_cast<std::size_t>(k)];
          if (geometry.IsTruncated(i)) // (a cut list, of a ghost at the halo's edge: not joined)
          {
            continue;
          }
          const std::uint32_t self = node(i);
          const std::uint32_t* ids = geometry.NeighborsOf(i);
          for (int m = 1; m < geometry.Stride; ++m)
          {
            const std::uint32_t other = node(ids[m]);
            if (other != EnclosedDeepInside::None)
            {
              links.Join(self, other);
            }
          }
        }
      });
  };
  joinListed(band);
  joinListed(deep.Rim);
  // Each component: its root node, keyed by its lowest particle id; numbered in node order.
  std::vector<std::uint32_t> componentOfRoot(links.Size, EnclosedDeepInside::None);
  std::vector<std::uint32_t> componentOf(links.Size);
  std::vector<double> key;
  for (std::size_t x = 0; x < links.Size; ++x)
  {
    const std::uint32_t root = links.Find(static_cast<std::uint32_t>(x));
    if (componentOfRoot[root] == EnclosedDeepInside::None)
    {
      componentOfRoot[root] = static_cast<std::uint32_t>(key.size());
      key.push_back(HUGE_VAL);
    }
    const std::uint32_t c = componentOf[x] = componentOfRoot[root];
    const double lowest = x < groups
      ? deep.Sums[record * x]
      : (OwnParticle(in, band[x - groups]) ? static_cast<double>(geometry.Order[band[x - groups]])
                                           : HUGE_VAL);
    key[c] = std::min(key[c], lowest);
  }
  const SummedPlaces summed(in, band);
  const SurfaceDistance distance(in, 0.0);
  // The band's distances: keeping the surface points nearest to each sample that measures a
  // height (in the run that found `deep`), or from those kept, where they hold.
  const PointCloudIndex* surfaceIndex = distance.SurfaceIndex();
  std::vector<std::uint32_t> measured; // (keeping) the band's places of the queries
  if (keeping)
  {
    keeping->SurfaceQuery.assign(deep.Near.size(), EnclosedDeepInside::None);
    keeping->Surface.Clear();
    if (surfaceIndex)
    {
      measured = IndicesWhere<std::uint32_t>(
        band.size(), [&](std::size_t b) { return distance.MeasuresHeight(band[b]); });
      for (std::size_t q = 0; q < measured.size(); ++q)
      {
        keeping->SurfaceQuery[deep.Group[band[measured[q]]] - groups] =
          static_cast<std::uint32_t>(q);
      }
      keeping->Surface.Start(measured.size(), SurfaceDistance::Candidates);
    }
  }
  const bool fromKept = !keeping && surfaceIndex && deep.SurfaceQuery.size() == deep.Near.size() &&
    deep.Surface.Fits(deep.Surface.Queries(), *surfaceIndex);
  const KeptCandidates::Moves moves =
    fromKept ? deep.Surface.MovesSince(*surfaceIndex) : KeptCandidates::Moves();
  auto distanceOf = [&](std::size_t i) {
    const std::uint32_t q =
      keeping || fromKept ? deep.SurfaceQuery[deep.Group[i] - groups] : EnclosedDeepInside::None;
    if (q == EnclosedDeepInside::None)
    {
      return distance(i);
    }
    return keeping ? distance.Keeping(i, q, keeping->Surface)
                   : distance.FromKept(i, q, deep.Surface, moves);
  };
  std::vector<Sums> sums = SumsByGroup(
    in, components, summed.Of(band), key.size(),
    [&](std::size_t k) { return componentOf[groups + summed(k)]; }, distanceOf,
    [&](std::size_t k, double*) {
      return &deep.NearRecords[RecordSize(components) * inBand[summed(k)]];
    });
  if (keeping && !measured.empty())
  {
    std::vector<double> at(3 * measured.size());
    for (std::size_t q = 0; q < measured.size(); ++q)
    {
      const double* x = geometry.Position(band[measured[q]]);
      std::copy(x, x + 3, &at[3 * q]);
    }
    if (!keeping->Surface.Finish(at.data(), *surfaceIndex))
    {
      keeping->SurfaceQuery.clear();
    }
  }
  for (std::size_t g = 0; g < groups; ++g)
  {
    if (deep.Sums[record * g] < HUGE_VAL) // (a group of ghosts alone has nothing to add)
    {
      sums[componentOf[g]].Add(Unpack(&deep.Sums[record * g], components));
    }
  }
  std::map<double, Sums> byKey;
  if (!in.Ranks->Distributed())
  {
    for (std::size_t c = 0; c < sums.size(); ++c)
    {
      byKey[key[c]] = std::move(sums[c]);
    }
  }
  else
  {
    // Joined across the ranks where they meet at a ghost, keyed by (rank, component here).
    const Communicator& ranks = *in.Ranks;
    const double rankKey = ranks.Rank * 4294967296.0;
    std::map<double, double> joined = JoinedAtGhosts(
      ranks, n, [&](std::size_t i) { return ranks.Owns(i); },
      [&](std::size_t i) {
        const std::uint32_t x = node(i);
        return x == EnclosedDeepInside::None ? -1.0 : rankKey + componentOf[x];
      });
    byKey = AddedOverRanks(ranks, sums, components,
      [&](std::size_t c) { return FindJoined(joined, rankKey + static_cast<double>(c)); });
  }
  return TableOfComponents(byKey, arrays, components, in.Mass != nullptr);
}

} // namespace lsi
