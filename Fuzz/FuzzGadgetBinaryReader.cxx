// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a GADGET binary snapshot: the reader must give an error or particles, never read
// past its buffers, crash or hang. (The file is named NAME.0: a header that says several files
// makes the reader look for the others.)
#include "FuzzReaderOnBytes.h"
#include "vtkGadgetBinaryReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return FuzzReaderOnBytes<vtkGadgetBinaryReader>(data, size, ".0");
}
