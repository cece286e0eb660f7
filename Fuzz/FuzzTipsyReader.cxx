// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a Tipsy file: the reader must give an error or particles, never read past its
// buffers, crash or hang.
#include "vtkDataArraySelection.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkTipsyParticleReader.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  vtkObject::GlobalWarningDisplayOff(); // bad files are expected: no message flood
  const std::string path = "/tmp/fuzz-tipsy-" + std::to_string(getpid()) + ".bin";
  if (FILE* out = std::fopen(path.c_str(), "wb"))
  {
    std::fwrite(data, 1, size, out);
    std::fclose(out);
  }
  vtkNew<vtkTipsyParticleReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  reader->GetParticleTypeSelection()->EnableAllArrays(); // every type: a multiblock
  reader->Update();
  std::remove(path.c_str());
  return 0;
}
