// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Messages say their byte order (is_bigendian); the conversions read them only in this
// machine's.

#include <cstdint>
#include <cstring>

namespace floodplane::conversion {

inline bool hostIsBigEndian() {
  const std::uint16_t one = 1;
  std::uint8_t first;
  std::memcpy(&first, &one, 1);
  return first == 0;
}

}  // namespace floodplane::conversion
