// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the method's steps need from the other MPI ranks when the particles are spread over
// them. Each rank holds its own samples ("owned": its particles and their periodic images) and,
// after them, ghost copies of the other ranks' samples near its own. A step computes on all of
// them, as a serial run would, and
// - counts and sums over its owned samples only, then adds the ranks' totals (Sum, Max);
// - after writing per-sample values, copies each owner's values onto its ghost copies
//   (RefreshGhosts), so the next step reads the serial values everywhere;
// - passes what it learned at a ghost back to the sample's owner (MaxToOwners).
// This base class is one process: every operation leaves its arguments as they are.
// LevelSetDistribution.h implements it with VTK's vtkMultiProcessController.
#ifndef LevelSetCommunicator_h
#define LevelSetCommunicator_h

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

/// The single-process communicator, for steps called without one.
inline const Communicator& SingleProcess()
{
  static const Communicator single;
  return single;
}

} // namespace lsi

#endif
