// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Abort during a run on 2M samples (as ParaView's Abort button does) returns within a second
// at every stage, and leaves empty outputs.
#include "AbortLatency.h"

#include <cstdlib>
#include <iostream>

int main()
{
  const std::vector<double> delays = { 0.3, 1.0, 1.8, 2.6, 3.2, 3.6, 4.0, 4.4, 4.8 };
  const lsi::cases::AbortLatencies result =
    lsi::cases::MeasureAbortLatencies(2000000, delays, std::cout);
  std::cout << "\nlongest time from Abort to return: " << result.LongestSeconds << " s\n";
  int failures = 0;
  if (!result.OutputsEmpty)
  {
    std::cerr << "FAILED: an aborted run left output\n";
    ++failures;
  }
  if (result.LongestSeconds > 1.0)
  {
    std::cerr << "FAILED: Abort took " << result.LongestSeconds << " s (limit 1 s)\n";
    ++failures;
  }
  return failures ? EXIT_FAILURE : EXIT_SUCCESS;
}
