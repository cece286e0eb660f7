// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Neighbourhoods depend only on the particle positions, and searching them is the most
// expensive stage. This keeps the last few (one per time step on a time series), recognised by
// a fingerprint of the coordinates, so that changing the isovalue or the seed, or returning to a
// time step, reuses them.
#ifndef LevelSetNeighborCache_h
#define LevelSetNeighborCache_h

#include "LevelSetNeighborhoods.h"

#include "vtkType.h"

#include <cstdint>
#include <list>
#include <memory>
#include <vector>

class vtkDataArray;
class vtkPoints;

namespace lsi
{

/// A 64-bit hash of the point coordinates (bit patterns, in order).
std::uint64_t CoordinateFingerprint(vtkPoints* points);

/// The same of an array's values (all components, bit patterns, in order), with its type and
/// size.
std::uint64_t ValueFingerprint(vtkDataArray* array);

/// The same of a vector of doubles (as a one-component double array's).
std::uint64_t ValueFingerprint(const std::vector<double>& values);

class NeighborCache
{
public:
  /// The neighbourhoods of `points` with `neighbors` neighbours: the cached ones (marked most
  /// recently used), or newly built ones, stored after dropping the least recently used entries
  /// beyond `capacity`; `built` tells which. Returns null when aborted.
  const Neighborhoods* Get(
    vtkPoints* points, int neighbors, std::size_t capacity, const AbortCheck& aborted, bool& built);
  /// The cached neighbourhoods of `points` with `neighbors` neighbours (marked most recently
  /// used), or null: never builds.
  const Neighborhoods* Find(vtkPoints* points, int neighbors);

private:
  struct Entry
  {
    Neighborhoods Geometry;
    vtkPoints* Points = nullptr; // quick match: same object, unmodified since
    vtkMTimeType PointsTime = 0;
    vtkIdType NumberOfPoints = 0;
    int NumberOfNeighbors = 0;
    std::uint64_t Fingerprint = 0;
  };
  std::list<std::unique_ptr<Entry>> Entries; // most recently used first
};

} // namespace lsi

#endif
