// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// How the per-sample numerics run independent pieces of work without knowing about threads:
// they hand a list of tasks to a runner, which the VTK classes give them (one that uses threads)
// and the unit tests run in turn.
#ifndef TaskRunner_h
#define TaskRunner_h

#include <functional>
#include <vector>

namespace lsi
{

/// Runs every task of the list, possibly at the same time; returns when all are done.
using TaskRunner = std::function<void(std::vector<std::function<void()>>& tasks)>;

/// The runner that runs the tasks one after another, in order.
inline void RunInTurn(std::vector<std::function<void()>>& tasks)
{
  for (std::function<void()>& task : tasks)
  {
    task();
  }
}

} // namespace lsi

#endif
