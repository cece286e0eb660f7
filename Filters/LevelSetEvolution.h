// The level-set evolution on the samples: explicit Euler steps of eq. 9 (or eq. 13) on the band
// where the smoothed delta is non-zero, reinitialisation (eq. 10) on the band plus a margin,
// the paper's per-iteration statistics, and the stopping rule.
#ifndef LevelSetEvolution_h
#define LevelSetEvolution_h

#include "LevelSetNeighborhoods.h"
#include "LevelSetParallel.h"
#include "LevelSetUpdate.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace lsi
{

enum class Scheme
{
  WithReinitialization = 0,    // eq. 9 + eq. 10 (the paper's main method)
  WithoutReinitialization = 1, // eq. 13: distance regularisation instead of eq. 10
  RosenthalLinsen = 2,         // eq. 16 (+ eq. 10): phi relaxes towards the data's distance
};

struct EvolutionSettings
{
  EvolutionCoefficients Coefficients;
  Scheme Method = Scheme::WithReinitialization;
  int ReinitializationSteps = 2;
  double ReinitializationTimeStep = 0.5;
  // Rosenthal-Linsen: fraction of phi - g removed per step, and the largest change per step.
  double RelaxationRate = 0.5;
  double MaximumStep = 0.5;
  double Spacing = 1.0; // mean sample spacing at the surface: the smoothed sign's width in eq. 10
  double NeighborhoodRadius = 1.0; // mean h_i at the surface
  int MaximumIterations = 500;
  // Stop when, for StableIterationsToStop iterations in a row, at most this fraction of the
  // band's samples changed sign for the first time: the front no longer advances anywhere.
  // (Counting every change would also count samples that flicker at a converged front.)
  double ConvergenceTolerance = 1e-4;
  int StableIterationsToStop = 3;
};

/// Half width of the region |phi| < w that the reinitialisation keeps a signed distance: the
/// band plus a margin of two neighbourhood radii, so samples about to enter the band are ready.
double ReinitializationHalfWidth(const EvolutionSettings& settings);

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
  /// `dataSign` holds sgn(f_i - f_iso); `phi` the initial level set, evolved in place.
  /// `dataOffsets` (f_i - f_iso) is needed by the Rosenthal-Linsen scheme only.
  LevelSetEvolution(const Neighborhoods& geometry, const std::vector<double>& dataSign,
    std::vector<double>& phi, const std::vector<double>* dataOffsets = nullptr);

  /// Iterates until the stopping rule or the iteration limit. `onIteration` is called on the
  /// calling thread after each iteration; returning false aborts. Returns false if aborted.
  bool Run(const EvolutionSettings& settings,
    const std::function<bool(const IterationRecord&)>& onIteration, const AbortCheck& aborted);

  bool Converged() const { return this->HasConverged; }

private:
  void CollectWhere(double halfWidth, std::vector<std::size_t>& out) const;
  void CollectWithNeighbors(const std::vector<std::size_t>& core, std::vector<std::size_t>& out);
  void ComputeGradients(const std::vector<std::size_t>& where, const std::vector<double>& values);
  void Evolve(const EvolutionSettings& settings);
  void Reinitialize(const EvolutionSettings& settings);
  void Measure(const EvolutionSettings& settings, IterationRecord& record);

  const Neighborhoods& Geometry;
  const std::vector<double>& DataSign;
  const std::vector<double>* DataOffsets;
  std::vector<double>& Phi;
  std::vector<double> Gradient;         // 3 per sample, valid where last computed
  std::vector<std::uint32_t> Stamp;     // marks for neighbourhood collection
  std::uint32_t CurrentStamp = 0;
  std::vector<std::size_t> Band, Region, Scratch, Front;
  std::vector<double> NewValues;
  std::vector<char> InitiallyPositive, HasChangedSign;
  bool HasConverged = false;
};

} // namespace lsi

#endif
