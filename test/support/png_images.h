// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// PNG files read and written with libpng's simplified API: independent of floodplane's own PNG
// code, which the tests check with them.

#include <gtest/gtest.h>
#include <png.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "floodplane/io/rgb_image.h"

namespace floodplane::test {

// Reads a PNG of any kind as 8-bit RGB. Throws std::runtime_error with libpng's message.
inline floodplane::io::RgbImage readPng(const std::filesystem::path& path) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  if (png_image_begin_read_from_file(&png, path.c_str()) == 0) throw std::runtime_error(png.message);
  png.format = PNG_FORMAT_RGB;
  floodplane::io::RgbImage image;
  image.width = png.width;
  image.height = png.height;
  image.pixels.resize(PNG_IMAGE_SIZE(png));
  if (png_image_finish_read(&png, nullptr, image.pixels.data(), 0, nullptr) == 0) {
    throw std::runtime_error(png.message);
  }
  return image;
}

// Writes a 4 x 2 PNG of libpng's simplified `format` (8-bit grey, colour, a palette...) with
// arbitrary samples: a PNG that is not a 16-bit depth image.
inline void writeOtherPng(const std::filesystem::path& path, png_uint_32 format) {
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = 4;
  png.height = 2;
  png.format = format;
  if (format & PNG_FORMAT_FLAG_COLORMAP) png.colormap_entries = 256;
  std::vector<std::uint8_t> pixels(PNG_IMAGE_SIZE(png), 7);
  std::vector<std::uint8_t> colormap(256 * 3, 9);
  ASSERT_NE(png_image_write_to_file(&png, path.c_str(), 0, pixels.data(), 0,
                                    (format & PNG_FORMAT_FLAG_COLORMAP) ? colormap.data() : nullptr),
            0)
      << png.message;
}

}  // namespace floodplane::test
