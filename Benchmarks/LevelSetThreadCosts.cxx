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
#include "ScatteredReads.h"

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace
{
constexpr vtkIdType Pieces = 64;
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

  // Random reads over 128 MB (ScatteredReads.h, which LevelSetInteractive runs too).
  lsi::ScatteredReads reads;
  const double overhead1 = lsi::FastestOnThreads(1, repeats, overhead) / Calls;
  const double overhead2 = lsi::FastestOnThreads(2, repeats, overhead) / Calls;
  const double arithmetic1 = lsi::FastestOnThreads(1, repeats, arithmetic);
  const double arithmetic2 = lsi::FastestOnThreads(2, repeats, arithmetic);
  const double reads1 = reads.Seconds(1, repeats);
  const double reads2 = reads.Seconds(2, repeats);
  double checksum = reads.Checksum();
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
