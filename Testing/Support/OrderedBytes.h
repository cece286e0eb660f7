// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// The readers' tests write their files with this, not with the readers' own byte-order code:
// values appended to a buffer in a chosen byte order.
#ifndef OrderedBytes_h
#define OrderedBytes_h

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace lsi
{
namespace test
{
class OrderedBytes
{
public:
  explicit OrderedBytes(bool bigEndian)
    : BigEndian(bigEndian)
  {
  }
  template <typename T>
  void Put(T value)
  {
    char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    const std::uint16_t probe = 1;
    const bool hostLittle = *reinterpret_cast<const char*>(&probe) == 1;
    if (this->BigEndian == hostLittle)
    {
      std::reverse(bytes, bytes + sizeof(T));
    }
    this->Data.insert(this->Data.end(), bytes, bytes + sizeof(T));
  }
  std::vector<char> Data;
  bool BigEndian;
};
} // namespace test
} // namespace lsi

#endif
