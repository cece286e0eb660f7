// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a Tipsy file: the reader must give an error or particles, never read past its
// buffers, crash or hang.
#include "FuzzReaderOnBytes.h"
#include "vtkTipsyParticleReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return FuzzReaderOnBytes<vtkTipsyParticleReader>(data, size, ".bin");
}
