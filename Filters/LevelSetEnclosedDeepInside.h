// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Step 9 for quick re-runs: the Enclosed table around a deep inside kept from the last run
// (EnclosedDeepInside, LevelSetEnclosed.h), so that a re-run after a slide of the surface sums
// the band alone.
#ifndef LevelSetEnclosedDeepInside_h
#define LevelSetEnclosedDeepInside_h

#include "LevelSetEnclosed.h"

namespace lsi
{

/// Whether the route applies: no periodic images, no merged particles, a band. Under MPI too:
/// each rank finds the groups of its samples and ghosts and sums its own particles; the
/// components are joined across the ranks where they meet at a ghost, as the full route's are.
bool CanUseDeepInside(const EnclosedInputs& in);

/// Finds the deep inside of `in` (its groups, rim and sums) into `deep`.
void FindDeepInside(const EnclosedInputs& in, EnclosedDeepInside& deep);

/// The Enclosed table of `in` (EnclosedTable's), from the band's samples and the groups of
/// `deep` (found on a phi equal to in's at and beyond the band's half width, for the same
/// samples and arrays); null when `deep` was kept for other samples or arrays.
/// `keeping` (the run that found `deep`: the same object) keeps the surface points nearest to
/// the band's samples (EnclosedDeepInside::Surface); without it, the ones kept are used.
vtkSmartPointer<vtkTable> EnclosedTableAround(
  const EnclosedInputs& in, const EnclosedDeepInside& deep, EnclosedDeepInside* keeping = nullptr);

} // namespace lsi

#endif
