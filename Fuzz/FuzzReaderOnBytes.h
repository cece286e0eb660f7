// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A fuzz target's body for a file reader: the bytes written to a file (named with `suffix`),
// read with every particle type selected, then again with some arrays unread and a region. The
// reader must give an error or particles, never read past its buffers, crash or hang.
#ifndef FuzzReaderOnBytes_h
#define FuzzReaderOnBytes_h

#include "vtkDataArraySelection.h"
#include "vtkDataSet.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

// `beside`: files written next to it first (the path's stem, "/tmp/fuzz-reader-PID", plus each
// one's name: auxiliary files, a parameter file) with their bytes, removed after.
template <typename Reader>
int FuzzReaderOnBytes(const std::uint8_t* data, std::size_t size, const char* suffix,
  const std::vector<std::pair<std::string, std::string>>& beside = {})
{
  vtkObject::GlobalWarningDisplayOff(); // bad files are expected: no message flood
  const std::string stem = "/tmp/fuzz-reader-" + std::to_string(getpid());
  const std::string path = stem + suffix;
  if (FILE* out = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, out);
    std::fclose(out);
  }
  for (const auto& file : beside)
  {
    if (FILE* out = std::fopen((stem + file.first).c_str(), "wb"))
    {
      std::fwrite(file.second.data(), 1, file.second.size(), out);
      std::fclose(out);
    }
  }
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays(); // every type: a multiblock
  reader->Update();
  // Again with every other array unread and a region (the lower half of what was read, or a
  // box around the origin), in chunks of 3 particles.
  vtkDataArraySelection* arrays = reader->GetPointArraySelection();
  for (int a = 0; a < arrays->GetNumberOfArrays(); a += 2)
  {
    arrays->DisableArray(arrays->GetArrayName(a));
  }
  double bounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  if (auto* read = vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0)))
  {
    read->GetBounds(bounds);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    bounds[2 * axis + 1] = 0.5 * (bounds[2 * axis] + bounds[2 * axis + 1]);
  }
  reader->SetReadRegion(true);
  reader->SetRegionBounds(bounds);
  reader->SetRegionChunkParticles(3);
  reader->Update();
  std::remove(path.c_str());
  for (const auto& file : beside)
  {
    std::remove((stem + file.first).c_str());
  }
  return 0;
}

#endif
