// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading depth images stored as 16-bit single-channel PNG files (Kinect, RealSense, the TUM
// RGB-D benchmark): the raw depth units of every pixel, 0 where the sensor saw nothing.

#include <cstdint>
#include <string>
#include <vector>

namespace floodplane::io {

struct DepthImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> depth;  ///< row-major, in the camera's units (see DepthCamera)
};

/// Reads `path`, a 16-bit greyscale PNG. Throws std::runtime_error with a one-line reason,
/// without the path, when the file cannot be opened, is not a PNG, is truncated or corrupt,
/// has 8 bits or fewer per pixel, colour or an alpha channel (a colour or 8-bit image is not a
/// depth image), or announces more pixels than its size can hold.
DepthImage readDepthPng(const std::string& path);

/// Writes `image` as a 16-bit greyscale PNG through writeFileAtomically (the format
/// readDepthPng reads). Throws std::invalid_argument if the image is empty, larger than a PNG
/// can be, or its depth buffer does not hold width * height values; std::runtime_error naming
/// `path` if the file cannot be written.
void writeDepthPng(const std::string& path, const DepthImage& image);

}  // namespace floodplane::io
