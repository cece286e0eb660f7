// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
#include "SwiftCells.h"

#include "HDF5Handles.h"

#include <numeric>
#include <string>

namespace lsi
{
namespace io
{
namespace
{
// Whether every link of the path "a/b/c" exists (H5Lexists needs each one before the next).
bool PathExists(hid_t file, const std::string& path)
{
  for (std::size_t slash = path.find('/');; slash = path.find('/', slash + 1))
  {
    if (!Exists(file, path.substr(0, slash)))
    {
      return false;
    }
    if (slash == std::string::npos)
    {
      return true;
    }
  }
}

// The dataset at `path` as `columns` values per row, converted to `memoryType`; false if it is
// missing or of another shape.
template <typename T>
bool ReadRows(
  hid_t file, const std::string& path, hsize_t columns, hid_t memoryType, std::vector<T>& values)
{
  if (!PathExists(file, path))
  {
    return false;
  }
  Handle dataset(H5Dopen2(file, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle space(H5Dget_space(dataset), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  hsize_t dims[2] = { 0, 1 };
  if (!dataset.Valid() || rank != (columns == 1 ? 1 : 2) ||
    H5Sget_simple_extent_dims(space, dims, nullptr) < 0 || dims[1] != columns)
  {
    return false;
  }
  values.resize(static_cast<std::size_t>(dims[0] * columns));
  return values.empty() ||
    H5Dread(dataset, memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) >= 0;
}
} // namespace

bool SwiftCellRanges(hid_t file, int number, const double bounds[6],
  const std::vector<long long>& partStarts, const std::vector<long long>& partCounts,
  std::vector<Range>& ranges)
{
  QuietHDF5 quiet;
  const std::string type = "/PartType" + std::to_string(number);
  std::vector<long long> counts, offsets, files;
  if (!ReadRows(file, "Cells/Counts" + type, 1, H5T_NATIVE_LLONG, counts))
  {
    return false;
  }
  const std::size_t cells = counts.size();
  // Offsets within each file (with the file of each cell), or older SWIFT's over the snapshot.
  const bool inFile = ReadRows(file, "Cells/OffsetsInFile" + type, 1, H5T_NATIVE_LLONG, offsets);
  if (inFile
      ? !ReadRows(file, "Cells/Files" + type, 1, H5T_NATIVE_LLONG, files) || files.size() != cells
      : !ReadRows(file, "Cells/Offsets" + type, 1, H5T_NATIVE_LLONG, offsets))
  {
    return false;
  }
  // Each cell's box: its particles' extent, or its centre plus or minus a cell size.
  std::vector<double> low, high;
  if (!ReadRows(file, "Cells/MinPositions" + type, 3, H5T_NATIVE_DOUBLE, low) ||
    !ReadRows(file, "Cells/MaxPositions" + type, 3, H5T_NATIVE_DOUBLE, high))
  {
    std::vector<double> centres;
    const std::vector<double> size = PathExists(file, "Cells/Meta-data")
      ? NumericAttribute(Handle(H5Gopen2(file, "Cells/Meta-data", H5P_DEFAULT), H5Gclose), "size")
      : std::vector<double>();
    if (!ReadRows(file, "Cells/Centres", 3, H5T_NATIVE_DOUBLE, centres) || size.size() != 3 ||
      !(size[0] > 0.0 && size[1] > 0.0 && size[2] > 0.0))
    {
      return false;
    }
    low = high = centres;
    for (std::size_t v = 0; v < centres.size(); ++v)
    {
      low[v] -= size[v % 3];
      high[v] += size[v % 3];
    }
  }
  if (offsets.size() != cells || low.size() != 3 * cells || high.size() != 3 * cells)
  {
    return false;
  }
  // Every cell's particles within its part, and all of them together every particle of the
  // type; a table that says otherwise is not trusted.
  const long long total = std::accumulate(partCounts.begin(), partCounts.end(), 0LL);
  long long counted = 0;
  std::vector<Range> found;
  for (std::size_t c = 0; c < cells; ++c)
  {
    if (counts[c] == 0)
    {
      continue;
    }
    if (counts[c] < 0 || offsets[c] < 0)
    {
      return false;
    }
    long long first = offsets[c], limit = total; // where the cell's particles may lie
    if (inFile)
    {
      const long long f = files[c];
      if (f < 0 || f >= static_cast<long long>(partStarts.size()))
      {
        return false; // (a virtual file's table points into files this reader does not read)
      }
      if (offsets[c] > partCounts[f])
      {
        return false;
      }
      first += partStarts[f];
      limit = partStarts[f] + partCounts[f];
    }
    if (counts[c] > limit - first)
    {
      return false;
    }
    counted += counts[c];
    bool overlaps = true;
    for (int axis = 0; axis < 3; ++axis)
    {
      const double lo = low[3 * c + axis], hi = high[3 * c + axis];
      if (!(lo <= hi))
      {
        return false; // a cell with particles has an extent (not NaN, not inverted)
      }
      overlaps = overlaps && hi >= bounds[2 * axis] && lo <= bounds[2 * axis + 1];
    }
    if (overlaps)
    {
      found.emplace_back(first, first + counts[c]);
    }
  }
  if (counted != total)
  {
    return false;
  }
  ranges = found;
  return true;
}
} // namespace io
} // namespace lsi
