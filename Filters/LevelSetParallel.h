// Parallel loops in blocks, so that the calling (main) thread can check for abort between
// blocks: vtkSMPTools workers never call UpdateProgress or CheckAbort themselves.
#ifndef LevelSetParallel_h
#define LevelSetParallel_h

#include "vtkSMPTools.h"

#include <algorithm>
#include <cstddef>
#include <functional>

namespace lsi
{

/// Returns true when the caller asked to stop.
using AbortCheck = std::function<bool()>;

/// Runs body(begin, end) over [0, count) with vtkSMPTools::For, in blocks of `block` items.
/// Returns false if `aborted()` said so between two blocks.
template <typename Body>
bool ParallelForInBlocks(
  std::size_t count, Body&& body, const AbortCheck& aborted, std::size_t block = 65536)
{
  for (std::size_t start = 0; start < count; start += block)
  {
    if (aborted && aborted())
    {
      return false;
    }
    const std::size_t stop = std::min(count, start + block);
    vtkSMPTools::For(static_cast<vtkIdType>(start), static_cast<vtkIdType>(stop),
      [&](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::size_t>(begin), static_cast<std::size_t>(end));
      });
  }
  return true;
}

} // namespace lsi

#endif
