// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A plain 8-bit RGB image, the exchange type of the PNG writer and the label palette.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace floodplane::io {

struct RgbImage {
  std::size_t width = 0;
  std::size_t height = 0;
  /// Row-major, three bytes (red, green, blue) per pixel: width * height * 3 bytes.
  std::vector<std::uint8_t> pixels;
};

}  // namespace floodplane::io
