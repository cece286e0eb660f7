// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the codes call their smoothing lengths, and what support each name implies
// (docs: sph-conventions.md). Shared by the readers, which mark the array they read, and the
// filter, which finds an unmarked one by these names: one list, so that the two agree.
#ifndef SmoothingLengthNames_h
#define SmoothingLengthNames_h

#include <initializer_list>
#include <string>

namespace lsi
{

/// The Tipsy auxiliary arrays of h = fBall / 2 (support 2 h), in the order a reader prefers
/// them: Gasoline's and ChaNGa's "smoothlength" (bDohOutput), Gasoline's gas-only "SPHH",
/// older ChaNGa's "SphH" and "hsmall". Never "hsmooth": Gasoline, ChaNGa and PKDGRAV write
/// the gravitational softening in that column.
constexpr std::initializer_list<const char*> TipsySmoothingLengthNames = { "smoothlength", "SPHH",
  "SphH", "hsmall" };

/// The names the filter takes for the smoothing lengths when no reader marked them: GADGET's,
/// SWIFT's and the Tipsy outputs'.
constexpr std::initializer_list<const char*> UsualSmoothingLengthNames = { "SmoothingLength",
  "SmoothingLengths", "smoothlength" };

/// The support per smoothing length that an array's name implies when nothing marks it:
/// 2 for the Tipsy names (and "hsmooth", should a user name that column), else 1 (GADGET's h
/// is the support radius).
inline double SupportPerSmoothingLengthOfName(const std::string& name)
{
  for (const char* tipsy : TipsySmoothingLengthNames)
  {
    if (name == tipsy)
    {
      return 2.0;
    }
  }
  return name == "hsmooth" ? 2.0 : 1.0;
}

} // namespace lsi

#endif
