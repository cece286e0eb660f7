// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The tests' one assertion: a failed check prints what failed and is counted, and the test
// goes on so that one run reports every failure.
#ifndef TestCheck_h
#define TestCheck_h

#include <iostream>
#include <string>

namespace lsi
{
namespace test
{
inline int& Failures()
{
  static int failures = 0;
  return failures;
}

inline void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures();
  }
}
} // namespace test
} // namespace lsi

#endif
