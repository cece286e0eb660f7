// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// How far the level {f = f_iso} moves when f_iso changes a little, for the quick re-run after
// an isovalue change (LevelSetIsoValueSlide.h). Plain C++: unit-tested in TestNumerics.
#ifndef IsoValueShift_h
#define IsoValueShift_h

#include <algorithm>
#include <cmath>

namespace lsi
{

/// phi (a signed distance, positive where f > f_iso) after f_iso grew by `valueChange`, at a
/// sample where the data's gradient has norm `gradientNorm`: to first order the level moves by
/// valueChange / |grad f| towards larger f, so phi drops by that much. Where the gradient is
/// small the data hardly say where the level went: the drop is capped at `largestMove` either
/// way (the largest move of any point of the surface that slid there).
inline double LevelSetAfterIsoValueChange(
  double phi, double valueChange, double gradientNorm, double largestMove)
{
  if (!(gradientNorm > 0.0))
  {
    return phi - std::copysign(largestMove, valueChange);
  }
  const double move = valueChange / gradientNorm;
  return phi - std::max(-largestMove, std::min(largestMove, move));
}

} // namespace lsi

#endif
