// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Any bytes as a Tipsy file, with files beside it: the reader must give an error or particles,
// never read past its buffers, crash or hang. The input's parts after a line "#AUX" are
// auxiliary array files (SNAPSHOT.a1, SNAPSHOT.a2, ...), after a line "#PARAM" the run's
// parameter file (the only .param beside it); without such lines the input is the Tipsy file.
#include "FuzzReaderOnBytes.h"
#include "vtkTipsyParticleReader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string all(reinterpret_cast<const char*>(data), size);
  const std::string aux = "\n#AUX\n", param = "\n#PARAM\n";
  std::vector<std::pair<std::string, std::string>> beside;
  std::size_t end = std::min(all.find(aux), all.find(param));
  const std::size_t mainSize = std::min(end, all.size());
  int parts = 0;
  while (end < all.size())
  {
    const bool isAux = all.compare(end, aux.size(), aux) == 0;
    const std::size_t begin = end + (isAux ? aux.size() : param.size());
    end = std::min(all.find(aux, begin), all.find(param, begin));
    const std::string bytes = all.substr(begin, std::min(end, all.size()) - begin);
    beside.emplace_back(isAux ? ".bin.a" + std::to_string(++parts) : ".param", bytes);
  }
  return FuzzReaderOnBytes<vtkTipsyParticleReader>(data, mainSize, ".bin", beside);
}
