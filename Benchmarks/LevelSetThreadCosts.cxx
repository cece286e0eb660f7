// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What two threads can give on this machine, against which to read the filter's 1 / 2 thread
// ratio (LevelSetInteractive --threads-only N), all through vtkSMPTools with the STDThread
// backend as the filter runs it:
//   - loop overhead:  microseconds per vtkSMPTools::For call over 64 items of no work, on 1 and
//                     on 2 threads (this VTK's STDThread backend starts its threads anew for
//                     every call; the filter makes about 200 calls per run);
//   - arithmetic:     seconds for a fixed amount of floating-point work, in 64 pieces;
//   - random reads:   seconds for a fixed number of scattered reads over a 128 MB array (the
//                     pattern of neighbour lists and tree walks), in 64 pieces;
// and the 1 / 2 thread ratio of the last two. The fastest of REPEATS (default 5) each. Reports
// numbers and asserts nothing.
//   LevelSetThreadCosts [REPEATS]
#include "vtkSMPTools.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <vector>

namespace
{
constexpr vtkIdType Pieces = 64;

double Seconds(const std::function<void()>& work)
{
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The fastest of `repeats` runs of `work` on `threads` threads.
double Fastest(int threads, int repeats, const std::function<void()>& work)
{
  double best = HUGE_VAL;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&]() {
    for (int r = 0; r < repeats; ++r)
    {
      best = std::min(best, Seconds(work));
    }
  });
  return best;
}
} // namespace

int main(int argc, char* argv[])
{
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  std::vector<double> sink(Pieces, 0.0); // results kept, so that no work is optimised away

  // Loop overhead: 1,000 calls over 64 items that do nothing but write one number.
  constexpr int Calls = 1000;
  auto overhead = [&]() {
    for (int c = 0; c < Calls; ++c)
    {
      vtkSMPTools::For(0, Pieces, 1, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType i = begin; i < end; ++i)
        {
          sink[i] += 1.0;
        }
      });
    }
  };

  // Arithmetic: a dependent chain of multiply-adds per piece.
  constexpr long Steps = 4000000;
  auto arithmetic = [&]() {
    vtkSMPTools::For(0, Pieces, 1, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        double x = 1.0 + 1e-3 * static_cast<double>(i);
        for (long s = 0; s < Steps; ++s)
        {
          x = x * 1.0000001 + 1e-9;
          x = x > 2.0 ? x - 1.0 : x;
        }
        sink[i] += x;
      }
    });
  };

  // Random reads: 16M doubles (128 MB), read at scattered places by a fixed pseudo-random walk.
  const std::size_t size = std::size_t(1) << 24;
  std::vector<double> data(size, 1.0);
  constexpr std::size_t ReadsPerPiece = 1 << 19;
  auto reads = [&]() {
    vtkSMPTools::For(0, Pieces, 1, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType i = begin; i < end; ++i)
      {
        std::uint64_t state = 0x9E3779B97F4A7C15ull * static_cast<std::uint64_t>(i + 1);
        double sum = 0.0;
        for (std::size_t r = 0; r < ReadsPerPiece; ++r)
        {
          state = state * 6364136223846793005ull + 1442695040888963407ull;
          sum += data[(state >> 20) & (size - 1)];
        }
        sink[i] += sum;
      }
    });
  };

  const double overhead1 = Fastest(1, repeats, overhead) / Calls;
  const double overhead2 = Fastest(2, repeats, overhead) / Calls;
  const double arithmetic1 = Fastest(1, repeats, arithmetic);
  const double arithmetic2 = Fastest(2, repeats, arithmetic);
  const double reads1 = Fastest(1, repeats, reads);
  const double reads2 = Fastest(2, repeats, reads);
  double checksum = 0.0;
  for (double v : sink)
  {
    checksum += v;
  }
  std::printf("loop overhead (us per For, 64 items)   1 thread %8.1f   2 threads %8.1f\n",
    1e6 * overhead1, 1e6 * overhead2);
  std::printf("arithmetic (s)                         1 thread %8.4f   2 threads %8.4f   "
              "ratio %.3f\n",
    arithmetic1, arithmetic2, arithmetic1 / arithmetic2);
  std::printf("random reads over 128 MB (s)           1 thread %8.4f   2 threads %8.4f   "
              "ratio %.3f\n",
    reads1, reads2, reads1 / reads2);
  std::printf("(checksum %g)\n", checksum);
  return EXIT_SUCCESS;
}
