// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/depth_png.h"

#include <png.h>

#include <stdexcept>
#include <string>
#include <utility>

#include "floodplane/io/grey_png.h"
#include "floodplane/io/png_file.h"

namespace floodplane::io {

namespace {

// libpng's own default limit is a million pixels a side; depth cameras have a few thousand.
constexpr int kMaxSide = 1 << 16;

}  // namespace

DepthImage readDepthPng(const std::string& path) {
  GreyImage grey = readGreyPng(path, "depth image", false);
  DepthImage image;
  image.width = grey.width;
  image.height = grey.height;
  image.depth = std::move(grey.values);
  return image;
}

void writeDepthPng(const std::string& path, const DepthImage& image) {
  if (image.width <= 0 || image.height <= 0 || image.width > kMaxSide || image.height > kMaxSide) {
    throw std::invalid_argument("writeDepthPng: image size " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " is not writable");
  }
  const std::size_t pixels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  if (image.depth.size() != pixels) {
    throw std::invalid_argument("writeDepthPng: depth buffer holds " + std::to_string(image.depth.size()) +
                                " values, expected " + std::to_string(pixels));
  }
  // A linear greyscale image is written as 16-bit samples, unchanged.
  writePngPixels(path, static_cast<unsigned>(image.width), static_cast<unsigned>(image.height), PNG_FORMAT_LINEAR_Y,
                 image.depth.data());
}

}  // namespace floodplane::io
