// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// A fuzz target's body for a file reader: the bytes written to a file (named with `suffix`),
// read with every particle type selected. The reader must give an error or particles, never
// read past its buffers, crash or hang.
#ifndef FuzzReaderOnBytes_h
#define FuzzReaderOnBytes_h

#include "vtkDataArraySelection.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

template <typename Reader>
int FuzzReaderOnBytes(const std::uint8_t* data, std::size_t size, const char* suffix)
{
  vtkObject::GlobalWarningDisplayOff(); // bad files are expected: no message flood
  const std::string path = "/tmp/fuzz-reader-" + std::to_string(getpid()) + suffix;
  if (FILE* out = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, out);
    std::fclose(out);
  }
  vtkNew<Reader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays(); // every type: a multiblock
  reader->Update();
  std::remove(path.c_str());
  return 0;
}

#endif
