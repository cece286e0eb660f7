// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// SWIFT's table of top-level cells (the Cells group of its snapshots): for each cell and particle
// type, where its particles lie in the file (Counts, OffsetsInFile with Files, or older
// snapshots' Offsets) and in space (MinPositions / MaxPositions, or Centres and the cell size).
// From it, the ranges of a type's particles that may lie in a box: a region is read without
// reading the rest of the snapshot.
#ifndef SwiftCells_h
#define SwiftCells_h

#include "ParticleRanges.h"

#include "vtk_hdf5.h"

#include <vector>

namespace lsi
{
namespace io
{
/**
 * The ranges of particles of PartType`number` (indices over the whole snapshot) in the cells
 * of `file`'s cell table that may hold particles inside `bounds` (xmin, xmax, ymin, ymax, zmin,
 * zmax). `partStarts[f]`: the index of part f's first particle of this type in the snapshot.
 * A cell's box is its particles' MinPositions / MaxPositions where SWIFT wrote them, else its
 * centre plus or minus a whole cell size (particles drift out of their cell between SWIFT's
 * tree rebuilds, by less than that). Returns false, with `ranges` untouched, where the file has
 * no usable table for this type (none, other lengths, a cell in a file not among the parts, an
 * offset or count beyond its part, a cell with particles and no extent, cells that do not add
 * up to the type's particles): every particle is then a candidate.
 */
bool SwiftCellRanges(hid_t file, int number, const double bounds[6],
  const std::vector<long long>& partStarts, const std::vector<long long>& partCounts,
  std::vector<Range>& ranges);
} // namespace io
} // namespace lsi

#endif
