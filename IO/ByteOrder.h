// SPDX-FileCopyrightText: 2026 LevelSetIsosurface contributors
// SPDX-License-Identifier: BSD-3-Clause
// Values from the bytes of a binary file written on a machine of either byte order.
#ifndef LevelSetIsosurface_ByteOrder_h
#define LevelSetIsosurface_ByteOrder_h

#include <cstdint>
#include <cstring>
#include <utility>

namespace lsi
{

inline bool HostIsBigEndian()
{
  const std::uint16_t probe = 1;
  return *reinterpret_cast<const unsigned char*>(&probe) == 0;
}

/// The value of type T whose sizeof(T) bytes start at `bytes`, written big-endian or not.
template <typename T>
T FromBytes(const char* bytes, bool bigEndian)
{
  char copy[sizeof(T)];
  std::memcpy(copy, bytes, sizeof(T));
  if (bigEndian != HostIsBigEndian())
  {
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i)
    {
      std::swap(copy[i], copy[sizeof(T) - 1 - i]);
    }
  }
  T value;
  std::memcpy(&value, copy, sizeof(T));
  return value;
}

} // namespace lsi

#endif
