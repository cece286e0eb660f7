// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 4 of the method, the level-set evolution on the samples: explicit Euler steps of eq. 9
// (or eq. 13, or Rosenthal and Linsen's eq. 16) on the band where the smoothed delta is
// non-zero, each followed by the reinitialisation (LevelSetReinitialization.h); the paper's
// per-iteration statistics (P, MG, AG) and the stopping rule.
#ifndef LevelSetEvolution_h
#define LevelSetEvolution_h

#include "LevelSetBand.h"
#include "LevelSetCommunicator.h"
#include "LevelSetEvolutionSettings.h"
#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"
#include "LevelSetReinitialization.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace lsi
{

/// One row of the convergence table.
struct IterationRecord
{
  int Iteration = 0;
  double SignMismatch = 0.0;          // P: fraction of samples whose sign disagrees with f - f_iso
  double MaxGradientDeviation = 0.0;  // MG over the zero crossings
  double MeanGradientDeviation = 0.0; // AG over the zero crossings
  std::size_t BandSize = 0;           // samples updated
  std::size_t FirstSignChanges = 0;   // samples whose sign changed for the first time
  double Seconds = 0.0;
};

class LevelSetEvolution
{
public:
  /// `dataOffsets` holds f_i - f_iso (the forcing term reads its sign, the Rosenthal-Linsen
  /// scheme its values); `phi` the initial level set, evolved in place.
  LevelSetEvolution(const Neighborhoods& geometry, const std::vector<double>& dataOffsets,
    std::vector<double>& phi);

  /// Called on the calling thread after each iteration; returns true to stop (abort), like
  /// AbortCheck.
  using IterationObserver = std::function<bool(const IterationRecord&)>;

  /// Iterates until the stopping rule or the iteration limit. Returns false if aborted.
  bool Run(const EvolutionSettings& settings, const IterationObserver& observeIteration,
    const AbortCheck& aborted);

  bool Converged() const { return this->HasConverged; }

  /// Under MPI: the ghosts are refreshed after every write, the statistics and the stopping
  /// rule count the owned samples of every rank, so every rank stops at the same iteration.
  void SetCommunicator(const Communicator& ranks) { this->Ranks = &ranks; }

  /// The flood's component (one flag per sample: inside at the start), or none (the paper's
  /// seed spheres). With it, a sample above the isovalue outside the component is pushed outward
  /// like one below: otherwise the forcing term would pull in every other component of
  /// f > f_iso that comes within the band (2 eps, several spacings) of the front, and on noisy
  /// data each one joined brings the next within reach. The component's own samples, and every
  /// sample below the isovalue, keep the sign of f - f_iso. Must outlive Run.
  void SetComponent(const std::vector<char>& inside) { this->Component = &inside; }

private:
  void ComputeGradients(const std::vector<std::size_t>& where, const std::vector<double>& values);
  void Evolve(const EvolutionSettings& settings);
  void Measure(const EvolutionSettings& settings, IterationRecord& record);
  /// f_i - f_iso, negated above the isovalue outside the component (SetComponent).
  double TargetOffset(std::size_t i) const
  {
    const double offset = this->DataOffsets[i];
    return offset > 0.0 && this->Component && !(*this->Component)[i] ? -offset : offset;
  }

  const Neighborhoods& Geometry;
  const std::vector<double>& DataOffsets;
  std::vector<double>& Phi;
  // 3 per sample, valid where last computed (and only read there). Never filled: only the
  // pages under the band's region fault in, about a tenth of 48 MB at 2M samples.
  UninitializedVector<double> Gradient;
  BandCollector Collector;
  Reinitialization Reinitializer;
  std::vector<std::size_t> Band, Region, Scratch, Front;
  std::vector<double> NewValues;
  UninitializedVector<char> InitiallyPositive, HasChangedSign; // written in Run's first loop
  bool HasConverged = false;
  const Communicator* Ranks = &SingleProcess();
  const std::vector<char>* Component = nullptr;
};

} // namespace lsi

#endif
