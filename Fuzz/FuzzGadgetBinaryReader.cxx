// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a GADGET binary snapshot (a file named NAME.0, so that a header of several files
// looks for the others): the reader must give an error or particles, never read past its buffers,
// crash or hang.
#include "vtkDataArraySelection.h"
#include "vtkGadgetBinaryReader.h"
#include "vtkNew.h"
#include "vtkObject.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff(); // bad files are expected: no message flood
  const std::string path = "/tmp/fuzz-gadget-" + std::to_string(getpid()) + ".0";
  if (FILE* out = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, out);
    std::fclose(out);
  }
  vtkNew<vtkGadgetBinaryReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays(); // every type: a multiblock
  reader->Update();
  std::remove(path.c_str());
  return 0;
}
