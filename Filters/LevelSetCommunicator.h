// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the method's steps need from the other MPI ranks when the particles are spread over
// them. Each rank holds its own samples ("owned": its particles and their periodic images) and,
// after them, ghost copies of the other ranks' samples near its own. A step computes on them as
// a serial run would (on the owned ones alone where the ghosts' results would be overwritten
// by their owners' anyway: KeepOwned), and
// - counts and sums over its owned samples only, then adds the ranks' totals (Sum, Max);
// - after writing per-sample values, copies each owner's values onto its ghost copies
//   (RefreshGhosts), so the next step reads the serial values everywhere;
// - passes what it learned at a ghost back to the sample's owner (MaxToOwners).
// This base class is one process: every operation leaves its arguments as they are.
// LevelSetDistribution.h implements it with VTK's vtkMultiProcessController.
#ifndef LevelSetCommunicator_h
#define LevelSetCommunicator_h

#include <algorithm>
#include <cstddef>
#include <vector>

namespace lsi
{

class Communicator
{
public:
  virtual ~Communicator() = default;
  int Rank = 0; // this process among Size
  int Size = 1;
  bool Distributed() const { return this->Size > 1; }
  /// Whether the sample (in storage order) is owned here: only owned samples are counted in
  /// global sums and make output.
  bool Owns(std::size_t sample) const
  {
    return this->OwnedSamples.empty() || this->OwnedSamples[sample] != 0;
  }
  /// `samples` less the ghosts (one process: as they are). For a step whose writes at ghosts
  /// RefreshGhosts would overwrite: it need not compute them.
  void KeepOwned(std::vector<std::size_t>& samples) const
  {
    if (!this->OwnedSamples.empty())
    {
      samples.erase(std::remove_if(samples.begin(), samples.end(),
                      [&](std::size_t i) { return this->OwnedSamples[i] == 0; }),
        samples.end());
    }
  }
  /// Sums and maxima over the ranks, in place, the same on every rank.
  virtual void Sum(double*, int) const {}
  virtual void Max(double*, int) const {}
  /// Every rank's values, concatenated in rank order, on every rank.
  virtual void GatherAll(std::vector<double>&) const {}
  /// One value per sample (storage order): each ghost takes its owner's value.
  virtual void RefreshGhosts(std::vector<double>&) const {}
  /// One value per sample: each owned sample takes the largest of its value and its ghost
  /// copies' values on other ranks.
  virtual void MaxToOwners(std::vector<double>&) const {}

  double Sum(double value) const
  {
    this->Sum(&value, 1);
    return value;
  }
  double Max(double value) const
  {
    this->Max(&value, 1);
    return value;
  }
  /// True on every rank when every rank says true.
  bool All(bool ok) const { return this->Max(ok ? 0.0 : 1.0) == 0.0; }

protected:
  std::vector<char> OwnedSamples; // storage order; empty: all
};

/// One round of the flood's exchange between ranks. Where this rank's flood reached a ghost
/// (`inside(i)`), the ghost's owner is seeded; where an owner's sample is inside, its ghost
/// copies on other ranks are seeded; each only where f > f_iso (`dataOffsets`) and not yet
/// inside or seeded. Returns how many seeds all the ranks added: while it is not zero, every
/// rank floods again from `inSeed` (the ranks' neighbour graphs, joined at the ghosts, are the
/// serial graph, so the flood ends as the serial one).
template <typename Inside>
double SeedWhereRanksReached(const Communicator& ranks, const std::vector<double>& dataOffsets,
  Inside&& inside, std::vector<char>& inSeed)
{
  const std::size_t n = inSeed.size();
  std::vector<double> reachedHere(n, 0.0), insideAtOwner(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
  {
    reachedHere[i] = !ranks.Owns(i) && inside(i) ? 1.0 : 0.0;
    insideAtOwner[i] = inside(i) ? 1.0 : 0.0;
  }
  ranks.MaxToOwners(reachedHere);
  ranks.RefreshGhosts(insideAtOwner);
  double added = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const bool reached = ranks.Owns(i) ? reachedHere[i] > 0.0 : insideAtOwner[i] > 0.0;
    if (reached && !inSeed[i] && !inside(i) && dataOffsets[i] > 0.0)
    {
      inSeed[i] = 1;
      added += 1.0;
    }
  }
  return ranks.Sum(added);
}

/// The single-process communicator, for steps called without one.
inline const Communicator& SingleProcess()
{
  static const Communicator single;
  return single;
}

} // namespace lsi

#endif
