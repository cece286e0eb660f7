// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Wall-clock time of the filter's stages, reported through its *Seconds getters.
#ifndef LevelSetTiming_h
#define LevelSetTiming_h

#include <chrono>

namespace lsi
{
using Clock = std::chrono::steady_clock;

inline double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
} // namespace lsi

#endif
