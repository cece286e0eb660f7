// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// What the kernel did for this process: its system seconds and minor page faults, all threads
// together (getrusage). On a virtual machine here a 2M-sample run's kernel time came to 11-25
// microseconds per page fault (LevelSetInteractive --threads-only), and moved from one minute to
// the next: a run's system seconds show how much of its time (and of the noise between runs)
// went there.
#ifndef ProcessUsage_h
#define ProcessUsage_h

#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif

namespace lsi
{

struct ProcessUsage
{
  double SystemSeconds = 0.0;
  double MinorFaults = 0.0;

  /// This process's totals so far (zeros where getrusage is missing).
  static ProcessUsage Now()
  {
    ProcessUsage usage;
#if defined(__unix__) || defined(__APPLE__)
    rusage r{};
    if (getrusage(RUSAGE_SELF, &r) == 0)
    {
      usage.SystemSeconds =
        static_cast<double>(r.ru_stime.tv_sec) + 1e-6 * static_cast<double>(r.ru_stime.tv_usec);
      usage.MinorFaults = static_cast<double>(r.ru_minflt);
    }
#endif
    return usage;
  }
  ProcessUsage operator-(const ProcessUsage& before) const
  {
    ProcessUsage d;
    d.SystemSeconds = this->SystemSeconds - before.SystemSeconds;
    d.MinorFaults = this->MinorFaults - before.MinorFaults;
    return d;
  }
};

} // namespace lsi

#endif
