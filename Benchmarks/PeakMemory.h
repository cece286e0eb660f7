// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Peak resident memory of this process, per stage: Linux lets a process reset its own
// high-water mark (VmHWM) by writing 5 to /proc/self/clear_refs.
#ifndef PeakMemory_h
#define PeakMemory_h

#include <fstream>
#include <string>

namespace lsi
{

/// Starts a new peak-memory measurement. Returns false if the kernel does not allow it.
inline bool ResetPeakMemory()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  return static_cast<bool>(clear);
}

/// Peak resident set size in bytes since the last reset (VmHWM), or -1.
inline double PeakMemoryBytes()
{
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key)
  {
    if (key == "VmHWM:")
    {
      double kilobytes = -1.0;
      status >> kilobytes;
      return kilobytes * 1024.0;
    }
    std::getline(status, key);
  }
  return -1.0;
}

} // namespace lsi

#endif
