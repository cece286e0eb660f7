// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The numbers that steer the evolution (LevelSetEvolution.h) and the reinitialisation
// (LevelSetReinitialization.h); LevelSetParameters.h chooses them from the sample spacing.
#ifndef LevelSetEvolutionSettings_h
#define LevelSetEvolutionSettings_h

#include "LevelSetUpdate.h"

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

} // namespace lsi

#endif
