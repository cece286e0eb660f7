// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 4b of the method, reinitialisation (paper eq. 10): after each evolution step, phi is
// brought back towards a signed distance near the front, without moving its zero level. Samples
// next to the interface are held at their first-order distance; the others take upwind
// pseudo-time steps (per-sample formulas in Numerics/LevelSetUpdate.h).
#ifndef LevelSetReinitialization_h
#define LevelSetReinitialization_h

#include "LevelSetBand.h"
#include "LevelSetCommunicator.h"
#include "LevelSetEvolutionSettings.h"
#include "UninitializedVector.h"

#include <cstddef>
#include <vector>

namespace lsi
{

/// Half width of the region |phi| < w that the reinitialisation keeps a signed distance: the
/// band plus a margin of two neighbourhood radii, so samples about to enter the band are ready.
double ReinitializationHalfWidth(const EvolutionSettings& settings);

class Reinitialization
{
public:
  Reinitialization(const Neighborhoods& geometry, BandCollector& band);

  /// settings.ReinitializationSteps pseudo-time steps on the region |phi| <
  /// ReinitializationHalfWidth plus one ring of neighbours, in place. Under MPI the ghosts
  /// take their owners' values after each step.
  void Run(const EvolutionSettings& settings, std::vector<double>& phi,
    const Communicator& ranks = SingleProcess());

  /// The samples the last Run updated.
  const std::vector<std::size_t>& Region() const { return this->Updated; }

private:
  const Neighborhoods& Geometry;
  BandCollector& Band;
  std::vector<std::size_t> Core, Updated, Interface;
  std::vector<double> NewValues;
  // Per region sample, kept between runs so that their pages are mapped once (every element is
  // written before it is read).
  UninitializedVector<double> Initial;
  UninitializedVector<char> AtInterface;
};

} // namespace lsi

#endif
