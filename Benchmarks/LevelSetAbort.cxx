// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The abort benchmark behind the README's "Abort stops the filter within a second": for each
// delay, the stage the filter was in when aborted and the seconds until it returned.
//   LevelSetAbort [--samples N] [--delays 0.3,1,2,...]
#include "AbortLatency.h"

#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

int main(int argc, char* argv[])
{
  std::size_t samples = 2000000;
  std::vector<double> delays = { 0.3, 1.0, 1.8, 2.6, 3.2, 3.6, 4.0, 4.4, 4.8 };
  for (int a = 1; a < argc; ++a)
  {
    const std::string arg = argv[a];
    if (arg == "--samples" && a + 1 < argc)
    {
      samples = std::strtoull(argv[++a], nullptr, 10);
    }
    else if (arg == "--delays" && a + 1 < argc)
    {
      delays.clear();
      std::stringstream list(argv[++a]);
      std::string item;
      while (std::getline(list, item, ','))
      {
        delays.push_back(std::atof(item.c_str()));
      }
    }
    else
    {
      std::cerr << "usage: LevelSetAbort [--samples N] [--delays 0.3,1,...]\n";
      return EXIT_FAILURE;
    }
  }
  const lsi::cases::AbortLatencies result =
    lsi::cases::MeasureAbortLatencies(samples, delays, std::cout);
  std::cout << "\nlongest time from Abort to return: " << result.LongestSeconds << " s\n"
            << "aborted runs left empty outputs: " << (result.OutputsEmpty ? "yes" : "no") << "\n";
  return EXIT_SUCCESS;
}
