// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What two threads give this machine, at the moment, on memory-bound work: a fixed number of
// scattered reads over a 128 MB array (the pattern of the neighbour searches' tree walks and of
// the loops over neighbour lists), in 64 pieces through vtkSMPTools with the STDThread backend
// as the filter runs. The filter's 1 / 2 thread ratio is read against it: on a virtual machine
// here this ratio moved between 1.67 and 2.01 within the hour (RESULTS.md), and the filter's
// stages that are neighbour searches at heart (the neighbours', the initialisation's) run at
// about that ratio or below (LevelSetInteractive --threads-only).
#ifndef ScatteredReads_h
#define ScatteredReads_h

#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <vector>

namespace lsi
{

/// The fastest of `repeats` runs of `work` with vtkSMPTools on `threads` threads (STDThread).
inline double FastestOnThreads(int threads, int repeats, const std::function<void()>& work)
{
  double best = HUGE_VAL;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    for (int r = 0; r < repeats; ++r)
    {
      const auto start = std::chrono::steady_clock::now();
      work();
      best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
  });
  return best;
}

class ScatteredReads
{
public:
  static constexpr vtkIdType Pieces = 64;

  ScatteredReads()
    : Data(Size, 1.0)
    , Sink(Pieces, 0.0)
  {
  }

  /// The fastest of `repeats` passes on `threads` threads, in seconds.
  double Seconds(int threads, int repeats)
  {
    return FastestOnThreads(threads, repeats, [this]() { this->Pass(); });
  }

  /// One thread's time over two threads', each the fastest of `repeats`.
  double TwoThreadRatio(int repeats)
  {
    return this->Seconds(1, repeats) / this->Seconds(2, repeats);
  }

  /// The sum of what the passes read (kept, so that no read is optimised away).
  double Checksum() const
  {
    double sum = 0.0;
    for (const double v : this->Sink)
    {
      sum += v;
    }
    return sum;
  }

private:
  static constexpr std::size_t Size = std::size_t(1) << 24; // 16M doubles: 128 MB
  static constexpr std::size_t ReadsPerPiece = std::size_t(1) << 19;

  // Each piece reads at places drawn by its own fixed pseudo-random walk.
  void Pass()
  {
    vtkSMPTools::For(0, Pieces, 1, [this](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::uint64_t state = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(i + 1);
        double sum = 0.0;
        for (std::size_t r = 0; r < ReadsPerPiece; ++r)
        {
          state = state * 6364136223846793005ull + 1442695040888963407ull;
          sum += this->Data[(state >> 20) & (Size - 1)];
        }
        this->Sink[static_cast<std::size_t>(i)] += sum;
      }
    });
  }

  std::vector<double> Data;
  std::vector<double> Sink;
};

} // namespace lsi

#endif
