// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The pieces the Enclosed table's two routes share (LevelSetEnclosed.cxx: every touching
// particle; LevelSetEnclosedDeepInside.cxx: the band around a deep inside kept from the last
// run): a component's running sums, a particle's part in them, the signed distances to the
// surface, and the table of the components' sums.
#ifndef LevelSetEnclosedSums_h
#define LevelSetEnclosedSums_h

#include "LevelSetEnclosed.h"

#include "NearestNeighbors.h"

#include "vtkDataArray.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <unordered_map>
#include <vector>

class vtkTable;

namespace lsi
{
namespace enclosed
{
constexpr double Pi = 3.14159265358979323846;

/// The smooth step over [-width, width] (1 inside, 0 outside).
inline double Step(double phi, double width)
{
  if (phi >= width)
  {
    return 1.0;
  }
  if (phi <= -width)
  {
    return 0.0;
  }
  const double t = phi / width;
  return 0.5 * (1.0 + t + std::sin(Pi * t) / Pi);
}

/// The step's derivative (the surface area's density).
inline double StepDerivative(double phi, double width)
{
  return std::abs(phi) >= width ? 0.0 : (1.0 + std::cos(Pi * phi / width)) / (2.0 * width);
}

/// Whether sample i touches the inside: inside (phi > 0), or within a shell width (its
/// neighbourhood radius) outside it and not far outside (phi above FarOutside).
inline bool Touches(const EnclosedInputs& in, std::size_t i)
{
  const double phi = (*in.Phi)[i];
  return phi > 0.0 || (phi > in.FarOutside && phi > -in.Geometry->RadiusOf(i));
}

/// Per sample (storage order), whether test(i) holds, in parallel. Under MPI each ghost takes its
/// owner's answer: a ghost at the halo's edge has a cut list, so its own radius, and with it a
/// test that reads it (Touches, the deep inside's), may differ from the serial one, and the
/// components would then join at the ghosts where a serial run's do not.
template <typename Test>
std::vector<char> FlagsAtOwners(const Communicator& ranks, std::size_t samples, Test&& test)
{
  std::vector<char> flags(samples);
  vtkSMPTools::For(0, static_cast<vtkIdType>(samples), BalancedGrain(samples, 16384),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        flags[i] = test(static_cast<std::size_t>(i)) ? 1 : 0;
      }
    });
  if (ranks.Distributed())
  {
    std::vector<double> atOwner(flags.begin(), flags.end());
    ranks.RefreshGhosts(atOwner);
    std::copy(atOwner.begin(), atOwner.end(), flags.begin());
  }
  return flags;
}

/// Union-find over 0..n-1, each set linked towards its lowest index (so a root is its set's
/// lowest member), that several threads may join at once: a root is linked under a lower one by
/// a compare-and-swap, and a search shortens the path it walks to ancestors only, so the sets
/// do not depend on the order of the joins. (From one thread the atomics cost nothing more: the
/// loads and stores are plain ones.) The links start in parallel: at 20M samples they are 80 MB.
struct Links
{
  std::unique_ptr<std::atomic<std::uint32_t>[]> Parent;
  std::size_t Size;
  explicit Links(std::size_t n);
  std::uint32_t Find(std::uint32_t i) const
  {
    for (;;)
    {
      const std::uint32_t parent = this->Parent[i].load(std::memory_order_relaxed);
      if (parent == i)
      {
        return i;
      }
      const std::uint32_t grandparent = this->Parent[parent].load(std::memory_order_relaxed);
      if (grandparent == parent)
      {
        return parent;
      }
      // (i is not a root, and never will be again: any ancestor may replace its link.)
      this->Parent[i].store(grandparent, std::memory_order_relaxed);
      i = grandparent;
    }
  }
  void Join(std::uint32_t i, std::uint32_t j) const
  {
    for (;;)
    {
      std::uint32_t a = this->Find(i), b = this->Find(j);
      if (a == b)
      {
        return;
      }
      if (a < b)
      {
        std::swap(a, b);
      }
      std::uint32_t root = a; // linked under b, unless another thread linked it first
      if (this->Parent[a].compare_exchange_strong(root, b, std::memory_order_relaxed))
      {
        return;
      }
    }
  }
};

/// One component's (or a part of one's) running sums.
struct Sums
{
  vtkIdType Particles = 0;
  double Mass = 0.0, Volume = 0.0, Area = 0.0, Weight = 0.0;
  // The weighted positions, taken relative to the first one (in a periodic box the table's
  // centres come from a second pass instead: CentresInPeriodicBox in LevelSetEnclosed.cxx).
  double Moment[3] = { 0.0, 0.0, 0.0 };
  double Reference[3] = { 0.0, 0.0, 0.0 };
  bool HasReference = false;
  // In a periodic box, per axis the weighted sums of cos and sin of the position's angle round
  // the box: sums in any order, whose direction is the component's circular mean (CircularMean).
  double Circular[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  std::vector<double> Means; // weighted sums of every array component
  bool Inside = false;       // holds a particle with phi > 0

  /// Adds another part of the same component (its moment taken about this reference).
  void Add(const Sums& other);
};

/// A chunk's running sums, one part per group (a component, or its root), in the order the
/// groups first appear: consecutive samples are mostly of one group, so the last group's part is
/// tried before a hash lookup.
template <typename Key>
class PartsByGroup
{
public:
  std::vector<Sums> Parts;
  std::vector<Key> Groups; // Parts[k]'s group

  /// The part of `group`, made if new (valid until the next call).
  Sums& Of(Key group)
  {
    if (this->Parts.empty() || group != this->LastGroup)
    {
      const auto found = this->PartOf.emplace(group, this->Parts.size());
      if (found.second)
      {
        this->Parts.emplace_back();
        this->Groups.push_back(group);
      }
      this->LastGroup = group;
      this->LastPart = found.first->second;
    }
    return this->Parts[this->LastPart];
  }

private:
  std::unordered_map<Key, std::size_t> PartOf;
  Key LastGroup{};
  std::size_t LastPart = 0;
};

constexpr int FixedFields = 19; // a packed Sums: key, then the numbers of Sums before Means

/// Appends `c` under `key` to `out` (FixedFields numbers, then the means).
void Pack(double key, const Sums& c, std::vector<double>& out);
/// The key a component of several ranks' parts goes by: the lowest key joined to `key` in
/// `parent` (a union-find over keys, each linked under a lower one; a key not met is its own).
double FindJoined(std::map<double, double>& parent, double key);
/// Under MPI: this rank's links between components (pairs of keys: a component here, one it
/// meets at a ghost on another rank), gathered from every rank into `links` and joined, for
/// FindJoined.
std::map<double, double> JoinedLinks(const Communicator& ranks, std::vector<double>& links);

/// Under MPI: the components of every rank joined where they meet at a ghost, for FindJoined.
/// keyOf(i) is sample i's component key here (the rank in its high bits), or -1 where it joins
/// none; owned(i) whether sample i is this rank's (else a ghost of another's). Each ghost with
/// a key links it to its owner's key, where the owner has one.
template <typename Owned, typename KeyOf>
std::map<double, double> JoinedAtGhosts(
  const Communicator& ranks, std::size_t samples, Owned&& owned, KeyOf&& keyOf)
{
  std::vector<double> ownerKey(samples, -1.0);
  for (std::size_t i = 0; i < samples; ++i)
  {
    ownerKey[i] = owned(i) ? keyOf(i) : -1.0;
  }
  ranks.RefreshGhosts(ownerKey);
  std::vector<double> links;
  for (std::size_t i = 0; i < samples; ++i)
  {
    if (!owned(i) && ownerKey[i] >= 0.0)
    {
      const double key = keyOf(i);
      if (key >= 0.0)
      {
        links.insert(links.end(), { key, ownerKey[i] });
      }
    }
  }
  return JoinedLinks(ranks, links);
}

/// The Sums packed at `in`, with `means` means.
Sums Unpack(const double* in, std::size_t means);

/// Every rank's parts of the components (`parts`, part k under the key keyOfPart(k); parts
/// without a particle left out), gathered on every rank and added up by key.
template <typename KeyOfPart>
std::map<double, Sums> AddedOverRanks(
  const Communicator& ranks, const std::vector<Sums>& parts, int components, KeyOfPart&& keyOfPart)
{
  std::vector<double> packed;
  for (std::size_t k = 0; k < parts.size(); ++k)
  {
    if (parts[k].HasReference)
    {
      Pack(keyOfPart(k), parts[k], packed);
    }
  }
  ranks.GatherAll(packed);
  std::map<double, Sums> byKey;
  const std::size_t record = FixedFields + static_cast<std::size_t>(components);
  for (std::size_t k = 0; k + record <= packed.size(); k += record)
  {
    byKey[packed[k]].Add(Unpack(&packed[k], static_cast<std::size_t>(components)));
  }
  return byKey;
}

/// The arrays whose means the table gives: every named numeric point array with a value per
/// particle (all their components, `components` in all).
std::vector<vtkDataArray*> ArraysToAverage(const EnclosedInputs& in, int& components);

/// The weight of particle p (sample i, at `signedDistance` from the surface) in its
/// component's centre and means: its mass (or volume) times its part inside.
double CentreWeight(const EnclosedInputs& in, vtkIdType p, std::size_t i, double signedDistance);

/// A position on each axis of the periodic box whose angle round the box is that of the
/// circular sums `circular` (Sums::Circular), in [Origin, Origin + Size): the same whatever
/// order the particles were summed in.
void CircularMean(const PeriodicBox& box, const double circular[6], double mean[3]);

/// The doubles of a particle's record: its mass and density (0 without those arrays), then the
/// values of the `components` of the arrays averaged.
inline std::size_t RecordSize(int components)
{
  return 2 + static_cast<std::size_t>(components);
}

/// Particle p's record (RecordSize doubles) from the input's arrays. (GetTuple into a buffer is
/// safe from threads.)
void ReadParticle(
  const EnclosedInputs& in, const std::vector<vtkDataArray*>& arrays, vtkIdType p, double* record);

/// Adds particle p (sample i, at signed distance `signedDistance` from the surface) to the sums
/// of its component. `tuple` is scratch space for its record.
void AddParticle(const EnclosedInputs& in, const std::vector<vtkDataArray*>& arrays, int components,
  vtkIdType p, std::size_t i, double signedDistance, std::vector<double>& tuple, Sums& c);

/// AddParticle from the particle's record, read before (ReadParticle).
void AddRecord(const EnclosedInputs& in, const double* record, int components, std::size_t i,
  double signedDistance, Sums& c);

/// How far from the surface, in shell widths (a sample's neighbourhood radius), a sample
/// measures its distance by the tangent plane of the surface point nearest to it
/// (SurfaceDistance): a sample whose |phi| is larger takes phi, a point farther is not used.
constexpr double TangentReach = 2.0;
inline bool MeasuresTangentDistance(double phi, double shellWidth)
{
  return !(std::abs(phi) > TangentReach * shellWidth); // (as before: NaN measures)
}

/// The signed distance of a sample to the surface, positive inside: near the surface its height
/// over the tangent plane of the nearest surface point, elsewhere phi. In a periodic box, the
/// surface points' images within `reach` of the box count too.
class SurfaceDistance
{
public:
  /// Surface points kept per sample (KeptCandidates): the nearest and a margin.
  static constexpr std::size_t Candidates = 16;

  SurfaceDistance(const EnclosedInputs& in, double reach);
  double operator()(std::size_t i) const;
  /// Whether sample i measures a tangent plane's height (else its distance is phi).
  bool MeasuresHeight(std::size_t i) const;
  /// The search index of the surface points (null: none).
  const PointCloudIndex* SurfaceIndex() const { return this->Index; }
  /// operator()(i) for a sample that MeasuresHeight, keeping its nearest surface points as
  /// query q of `keep` (Start-ed for Candidates).
  double Keeping(std::size_t i, std::size_t q, KeptCandidates& keep) const;
  /// operator()(i) for the sample of query q of `kept` (kept over this index's points, moved
  /// since as `moves` tells): from its candidates where the nearest surely lies among them,
  /// else searched.
  double FromKept(std::size_t i, std::size_t q, const KeptCandidates& kept,
    const KeptCandidates::Moves& moves) const;

private:
  // The distance of sample i (phi there `phi`) given its nearest surface point and the squared
  // distance to it, if within the tangent reach (as a search within it would find).
  double Height(std::size_t i, double phi, std::uint32_t nearest, double d2) const;

  const EnclosedInputs& In;
  std::vector<double> Points, Normals; // with images in a periodic box
  const double* PointData = nullptr;
  const double* NormalData = nullptr;
  std::unique_ptr<PointCloudIndex> Built;
  const PointCloudIndex* Index = nullptr;
};

/// The table of the components with a particle inside, the largest volume first (ties: the
/// lowest key), then "Total".
vtkSmartPointer<vtkTable> TableOfComponents(const std::map<double, Sums>& byKey,
  const std::vector<vtkDataArray*>& arrays, int components, bool withMass);

} // namespace enclosed
} // namespace lsi

#endif
