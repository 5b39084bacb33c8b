// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/png_file.h"
#include "support/png_images.h"
#include "temp_path.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace floodplane::test {
namespace {

namespace fs = std::filesystem;

TEST(PngFile, RoundTripsEveryPixelThroughLibpng) {
  floodplane::io::RgbImage image;
  image.width = 7;  // odd width: rows are not a multiple of four bytes
  image.height = 5;
  for (std::size_t i = 0; i < image.width * image.height * 3; ++i) {
    image.pixels.push_back(static_cast<std::uint8_t>((i * 37 + 11) % 256));
  }
  const fs::path path = uniqueTempPath(".png");
  floodplane::io::writePng(path.string(), image);
  const auto read = readPng(path.string());
  fs::remove(path);
  EXPECT_EQ(read.width, image.width);
  EXPECT_EQ(read.height, image.height);
  EXPECT_EQ(read.pixels, image.pixels);
}

TEST(PngFile, RejectsAPixelBufferOfTheWrongSize) {
  floodplane::io::RgbImage image;
  image.width = 4;
  image.height = 4;
  image.pixels.assign(4 * 4 * 3 - 1, 0);
  EXPECT_THROW(floodplane::io::writePng("/tmp/floodplane_never_written.png", image), std::invalid_argument);
  EXPECT_FALSE(fs::exists("/tmp/floodplane_never_written.png"));
}

TEST(PngFile, RejectsAnEmptyImage) {
  EXPECT_THROW(floodplane::io::writePng("/tmp/floodplane_never_written.png", {}), std::invalid_argument);
}

TEST(PngFile, ReportsAnUnwritableDirectoryAsARuntimeError) {
  floodplane::io::RgbImage image;
  image.width = 1;
  image.height = 1;
  image.pixels = {1, 2, 3};
  EXPECT_THROW(floodplane::io::writePng("/nonexistent_directory/x.png", image), std::runtime_error);
}

}  // namespace
}  // namespace floodplane::test
