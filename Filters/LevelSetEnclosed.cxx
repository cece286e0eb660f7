// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "LevelSetEnclosed.h"
#include "LevelSetEnclosedDeepInside.h"
#include "LevelSetEnclosedSums.h"

#include "LevelSetParallel.h"
#include "NearestNeighbors.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numeric>
#include <string>
#include <unordered_map>

namespace lsi
{
namespace
{
using namespace enclosed;

vtkIdType Root(std::vector<vtkIdType>& parent, vtkIdType i)
{
  while (parent[i] != i)
  {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// In a periodic box a component's centre of mass is the weighted mean of its particles' images
// nearest to its circular mean (CircularMean): the same whichever particle, thread or rank
// summed first, and for a component narrower than half the box its centre of mass. It is then
// moved by whole boxes into the cell the surface is shown in. A second pass over the touching
// particles, which the first pass named (`keyOfRoot` per root of `parent`).
template <typename SampleOf, typename Touches, typename Distances>
void CentresInPeriodicBox(const EnclosedInputs& in, vtkIdType n, const SampleOf& sampleOf,
  Touches&& touches, const Distances& distances, const std::vector<vtkIdType>& parent,
  const std::unordered_map<vtkIdType, double>& keyOfRoot, std::map<double, Sums>& byKey)
{
  const PeriodicBox& box = in.Box;
  std::map<double, std::array<double, 3>> anchors;
  for (auto& entry : byKey)
  {
    CircularMean(box, entry.second.Circular, anchors[entry.first].data());
  }
  // The moments about the anchors, in fixed chunks (as the first pass), added in chunk order.
  constexpr vtkIdType ChunkSize = 32768;
  const vtkIdType chunks = (n + ChunkSize - 1) / ChunkSize;
  std::vector<std::map<double, std::array<double, 3>>> chunkMoments(
    static_cast<std::size_t>(chunks));
  vtkSMPTools::For(0, chunks, 1, [&](vtkIdType firstChunk, vtkIdType lastChunk) {
    for (vtkIdType chunk = firstChunk; chunk < lastChunk; ++chunk)
    {
      auto& moments = chunkMoments[static_cast<std::size_t>(chunk)];
      vtkIdType lastRoot = -1;
      std::array<double, 3>* moment = nullptr;
      const std::array<double, 3>* anchor = nullptr;
      const vtkIdType end = std::min(n, (chunk + 1) * ChunkSize);
      for (vtkIdType p = chunk * ChunkSize; p < end; ++p)
      {
        const std::size_t i = sampleOf[p];
        if (!touches(i))
        {
          continue;
        }
        if (parent[p] != lastRoot)
        {
          lastRoot = parent[p];
          const double key = keyOfRoot.at(lastRoot);
          moment = &moments.emplace(key, std::array<double, 3>{ 0.0, 0.0, 0.0 }).first->second;
          anchor = &anchors.at(key);
        }
        const double weight = CentreWeight(in, p, i, distances[i]);
        const double* x = in.Geometry->Position(i);
        for (int d = 0; d < 3; ++d)
        {
          double offset = x[d] - (*anchor)[d];
          offset -= box.Size[d] * std::round(offset / box.Size[d]);
          (*moment)[d] += weight * offset;
        }
      }
    }
  });
  std::vector<double> packed; // key and moment, per component part
  for (const auto& moments : chunkMoments)
  {
    for (const auto& entry : moments)
    {
      packed.insert(
        packed.end(), { entry.first, entry.second[0], entry.second[1], entry.second[2] });
    }
  }
  in.Ranks->GatherAll(packed);
  std::map<double, std::array<double, 3>> total;
  for (std::size_t k = 0; k + 4 <= packed.size(); k += 4)
  {
    std::array<double, 3>& moment = total.emplace(packed[k], std::array<double, 3>{}).first->second;
    for (int d = 0; d < 3; ++d)
    {
      moment[d] += packed[k + 1 + d];
    }
  }
  for (auto& entry : byKey)
  {
    Sums& c = entry.second;
    const std::array<double, 3>& anchor = anchors.at(entry.first);
    const auto found = total.find(entry.first);
    for (int d = 0; d < 3; ++d)
    {
      c.Reference[d] = anchor[d];
      c.Moment[d] = found != total.end() ? found->second[d] : 0.0;
      if (c.Weight > 0.0) // into the shown cell: [low, low + Size)
      {
        const double low = in.CellCenter ? in.CellCenter[d] - 0.5 * box.Size[d] : box.Origin[d];
        const double centre = anchor[d] + c.Moment[d] / c.Weight;
        c.Reference[d] -= box.Size[d] * std::floor((centre - low) / box.Size[d]);
      }
    }
  }
}

// The components of the touching samples, joined through the neighbour graph (and, in a
// periodic box, through the images of one particle, which share its slot): each slot's
// component root, its lowest slot (a slot alone is its own).
std::vector<vtkIdType> SlotComponents(const EnclosedInputs& in, const std::vector<char>& touching,
  const std::vector<vtkIdType>& slot, vtkIdType slots)
{
  const Neighborhoods& geometry = *in.Geometry;
  const vtkIdType sampleCount = static_cast<vtkIdType>(geometry.NumberOfSamples);
  auto touches = [&](std::size_t i) { return touching[i] != 0; };
  // Over the samples first, linked towards lower storage indices (neighbours are near in memory
  // there, where slots are in input order); with periodic images, each sample is also linked to
  // the first touching one of its slot. Serial: joined from several
  // threads, these links measured no faster.
  Links links(geometry.NumberOfSamples);
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    if (!touches(i) || geometry.IsTruncated(i))
    {
      continue;
    }
    const std::uint32_t* ids = geometry.NeighborsOf(i);
    for (int m = 1; m < geometry.Stride; ++m)
    {
      if (touches(ids[m]))
      {
        links.Join(static_cast<std::uint32_t>(i), ids[m]);
      }
    }
  }
  if (in.Box.Enabled)
  {
    std::vector<std::int64_t> firstOfSlot(static_cast<std::size_t>(slots), -1);
    for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
    {
      if (touches(i))
      {
        std::int64_t& first = firstOfSlot[static_cast<std::size_t>(slot[i])];
        first < 0 ? void(first = static_cast<std::int64_t>(i))
                  : links.Join(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(first));
      }
    }
  }
  // Each component is named by its lowest slot, as a union-find over the slots names it: its
  // root sample (the lowest index, so met first below) takes the lowest slot of its members.
  UninitializedVector<vtkIdType> lowest(geometry.NumberOfSamples);
  for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
  {
    if (touches(i))
    {
      const std::uint32_t root = links.Find(static_cast<std::uint32_t>(i));
      links.Parent[i].store(root, std::memory_order_relaxed); // flattened: read in parallel below
      lowest[root] = root == i ? slot[i] : std::min(lowest[root], slot[i]);
    }
  }
  // Every slot's root: its own slot, or its component's lowest.
  std::vector<vtkIdType> parent(static_cast<std::size_t>(slots));
  vtkSMPTools::For(0, slots, BalancedGrain(static_cast<std::size_t>(slots), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      std::iota(parent.begin() + begin, parent.begin() + end, begin);
    });
  auto nameSlot = [&](std::size_t i) {
    if (touches(i))
    {
      parent[static_cast<std::size_t>(slot[i])] =
        lowest[links.Parent[i].load(std::memory_order_relaxed)];
    }
  };
  if (in.Box.Enabled) // images share slots: in turn (they write the same value)
  {
    for (std::size_t i = 0; i < geometry.NumberOfSamples; ++i)
    {
      nameSlot(i);
    }
  }
  else
  {
    vtkSMPTools::For(0, sampleCount, BalancedGrain(static_cast<std::size_t>(sampleCount), 1024),
      [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          nameSlot(static_cast<std::size_t>(i));
        }
      });
  }
  return parent;
}

// The touching particles' sums, one Sums per component (few) found through its root
// (`rootOfSums`). The particles are summed in fixed chunks in parallel, each chunk's parts then
// added in chunk order: the same sums on any number of threads.
void SumsByComponent(const EnclosedInputs& in, const std::vector<vtkDataArray*>& arrays,
  int components, const UninitializedVector<std::size_t>& sampleOf,
  const std::vector<char>& touching, const UninitializedVector<double>& distances,
  const std::vector<vtkIdType>& parent, std::vector<Sums>& sums, std::vector<vtkIdType>& rootOfSums)
{
  const vtkIdType n = in.ParticleCount;
  constexpr vtkIdType ChunkSize = 32768;
  const vtkIdType chunks = (n + ChunkSize - 1) / ChunkSize;
  std::vector<PartsByGroup<vtkIdType>> chunkSums(static_cast<std::size_t>(chunks));
  vtkSMPTools::For(0, chunks, 1, [&](vtkIdType firstChunk, vtkIdType lastChunk) {
    std::vector<double> tuple;
    for (vtkIdType chunk = firstChunk; chunk < lastChunk; ++chunk)
    {
      PartsByGroup<vtkIdType>& out = chunkSums[static_cast<std::size_t>(chunk)]; // by root
      const vtkIdType end = std::min(n, (chunk + 1) * ChunkSize);
      for (vtkIdType p = chunk * ChunkSize; p < end; ++p)
      {
        const std::size_t i = sampleOf[p];
        if (touching[i] != 0)
        {
          AddParticle(in, arrays, components, p, i, distances[i], tuple, out.Of(parent[p]));
        }
      }
    }
  });
  std::unordered_map<vtkIdType, std::size_t> sumsOfRoot;
  for (const PartsByGroup<vtkIdType>& chunk : chunkSums)
  {
    for (std::size_t k = 0; k < chunk.Parts.size(); ++k)
    {
      const auto found = sumsOfRoot.emplace(chunk.Groups[k], sums.size());
      if (found.second)
      {
        sums.emplace_back();
        rootOfSums.push_back(chunk.Groups[k]);
      }
      sums[found.first->second].Add(chunk.Parts[k]);
    }
  }
}
} // namespace

vtkSmartPointer<vtkTable> EnclosedTable(const EnclosedInputs& inputs)
{
  if ((inputs.KeepDeepInside || inputs.DeepInside) && CanUseDeepInside(inputs))
  {
    if (inputs.KeepDeepInside)
    {
      FindDeepInside(inputs, *inputs.KeepDeepInside);
    }
    vtkSmartPointer<vtkTable> table = EnclosedTableAround(inputs,
      inputs.KeepDeepInside ? *inputs.KeepDeepInside : *inputs.DeepInside, inputs.KeepDeepInside);
    if (table)
    {
      return table;
    }
  }
  EnclosedInputs withIds;
  if (inputs.OriginalIds.empty()) // one process, no images: each sample is its own particle
  {
    withIds = inputs;
    withIds.OriginalIds.assign(inputs.Geometry->Order.begin(), inputs.Geometry->Order.end());
  }
  const EnclosedInputs& in = inputs.OriginalIds.empty() ? withIds : inputs;
  const Neighborhoods& geometry = *in.Geometry;
  const std::vector<double>& phi = *in.Phi;
  const vtkIdType n = in.ParticleCount;

  // Each real particle's own sample (not an image's), and its shell width: one local spacing.
  // (0 for a particle merged into another.) Filled in parallel: at 20M particles these arrays
  // are 160 MB each.
  UninitializedVector<std::size_t> sampleOf =
    FilledInParallel(static_cast<std::size_t>(n), std::size_t(0));
  const vtkIdType samples = static_cast<vtkIdType>(geometry.NumberOfSamples);
  vtkSMPTools::For(0, samples, BalancedGrain(static_cast<std::size_t>(samples), 1024),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        if (static_cast<vtkIdType>(geometry.Order[i]) < n)
        {
          sampleOf[geometry.Order[i]] = static_cast<std::size_t>(i);
        }
      }
    });
  // The shell's half width: the neighbourhood radius (about two spacings), wide enough that
  // enough particles fall in it for a smooth surface integral.
  auto width = [&](std::size_t i) { return geometry.RadiusOf(i); };
  const std::vector<char> touching = FlagsAtOwners(
    *in.Ranks, geometry.NumberOfSamples, [&](std::size_t i) { return Touches(in, i); });
  vtkSMPThreadLocal<double> widestHere(0.0); // a maximum: the same on any number of threads
  vtkSMPTools::For(0, samples, BalancedGrain(static_cast<std::size_t>(samples), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      double& w = widestHere.Local();
      for (vtkIdType i = begin; i < end; ++i)
      {
        w = touching[i] ? std::max(w, 2.0 * width(static_cast<std::size_t>(i))) : w;
      }
    });
  double widest = 0.0;
  for (double w : widestHere)
  {
    widest = std::max(widest, w);
  }
  auto touches = [&](std::size_t i) { return touching[i] != 0; };

  // Components: the particles within a shell of the inside, joined through the neighbour graph
  // (through the images too, so a component cut by a periodic face is one).
  // Under MPI the other ranks' ghosts have slots of their own, after the particles.
  const Communicator& ranks = *in.Ranks;
  const vtkIdType sampleCount = static_cast<vtkIdType>(geometry.NumberOfSamples);
  vtkSMPThreadLocal<char> foreign(0); // samples that are no particle here (MPI ghosts)
  vtkSMPTools::For(0, sampleCount, BalancedGrain(static_cast<std::size_t>(sampleCount), 16384),
    [&](vtkIdType begin, vtkIdType end) {
      char& any = foreign.Local();
      for (vtkIdType i = begin; i < end && !any; ++i)
      {
        any = static_cast<char>(in.OriginalIds[i] < 0);
      }
    });
  vtkIdType slots = n;
  std::vector<vtkIdType> renumbered; // only with foreign samples: the particle ids are the slots
  if (std::any_of(foreign.begin(), foreign.end(), [](char f) { return f != 0; }))
  {
    renumbered = in.OriginalIds;
    for (vtkIdType& s : renumbered)
    {
      s = s >= 0 ? s : slots++;
    }
  }
  const std::vector<vtkIdType>& slot = renumbered.empty() ? in.OriginalIds : renumbered;
  std::vector<vtkIdType> parent = SlotComponents(in, touching, slot, slots); // (Root shortens)

  // The arrays to average: every numeric point array, all components.
  int components = 0;
  const std::vector<vtkDataArray*> arrays = ArraysToAverage(in, components);

  // The signed distances near the surface (a particle next to a periodic face finds the
  // surface across it within two shell widths).
  const SurfaceDistance distance(in, widest);

  // The distances of the touching samples, in parallel (a nearest-point query each near the
  // surface); the sums below are serial, in particle order, so they do not depend on threads.
  const std::vector<std::uint32_t> touchingSamples = IndicesWhere<std::uint32_t>(
    geometry.NumberOfSamples, [&](std::size_t i) { return touching[i] != 0; });
  UninitializedVector<double> distances(geometry.NumberOfSamples);
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(touchingSamples.size()), 256, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType k = begin; k < end; ++k)
      {
        distances[touchingSamples[k]] = distance(touchingSamples[k]);
      }
    });

  std::vector<Sums> sums;
  std::vector<vtkIdType> rootOfSums;
  SumsByComponent(in, arrays, components, sampleOf, touching, distances, parent, sums, rootOfSums);

  // Each component's key: its root here (the rank in the high bits under MPI). Under MPI the
  // components that meet at a ghost are one: each touching ghost links its root here to its
  // owner's (which touches too: FlagsAtOwners). (Serial loops: Root shortens the paths it
  // walks.)
  const double rankKey = ranks.Distributed() ? ranks.Rank * 4294967296.0 : 0.0;
  auto owned = [&](std::size_t i) { return in.OriginalIds[i] >= 0; };
  std::map<double, double> joined;
  if (ranks.Distributed())
  {
    joined = JoinedAtGhosts(ranks, geometry.NumberOfSamples, owned,
      [&](std::size_t i) { return touches(i) ? rankKey + Root(parent, slot[i]) : -1.0; });
  }
  // Every rank's part of every component, gathered and added up by component.
  std::map<double, Sums> byKey = AddedOverRanks(ranks, sums, components, [&](std::size_t k) {
    const double key = rankKey + rootOfSums[k];
    return ranks.Distributed() ? FindJoined(joined, key) : key;
  });
  if (in.Box.Enabled)
  {
    std::unordered_map<vtkIdType, double> keyOfRoot;
    for (const vtkIdType root : rootOfSums)
    {
      keyOfRoot[root] = ranks.Distributed() ? FindJoined(joined, rankKey + root) : root;
    }
    CentresInPeriodicBox(in, n, sampleOf, touches, distances, parent, keyOfRoot, byKey);
  }
  return TableOfComponents(byKey, arrays, components, in.Mass != nullptr);
}

} // namespace lsi
