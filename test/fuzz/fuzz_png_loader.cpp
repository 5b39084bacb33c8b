// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the input bytes as a depth PNG through the frame reader (decoding and
// back-projection), and as a label image (8 or 16 bits). A broken or non-depth PNG must give
// std::runtime_error; an image that loads must be a consistent frame whose points follow the
// pinhole model, a label image a label per pixel.

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "floodplane/io/depth_png.h"
#include "floodplane/io/input_frame.h"
#include "floodplane/io/label_file.h"
#include "loader_fuzzing.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using floodplane::fuzz::fail;
  const std::string& path = floodplane::fuzz::scratchFile(data, size, ".png");
  const floodplane::io::DepthCamera camera{525.0, 525.0, 319.5, 239.5, 5000.0};
  try {
    const floodplane::io::LabelGrid grid = floodplane::io::readLabelFile(path);
    if (grid.width == 0 || grid.labels.size() != std::size_t(grid.width) * std::size_t(grid.height)) {
      fail("a label image's labels do not fill its grid");
    }
  } catch (const std::runtime_error&) {
    // the expected outcome for a broken file or one that is no label image
  }
  floodplane::io::DepthImage image;
  floodplane::io::InputFrame frame;
  try {
    image = floodplane::io::readDepthPng(path);
    frame = floodplane::io::loadInputFrame(path, camera);
  } catch (const std::runtime_error&) {
    return 0;  // the expected outcome for a broken file
  }
  if (image.width <= 0 || image.height <= 1) fail("an image without a grid was accepted");
  if (image.depth.size() != std::size_t(image.width) * std::size_t(image.height)) fail("depth does not fill the grid");
  const auto& xyz = frame.xyz;
  if (xyz.width != std::uint32_t(image.width) || xyz.height != std::uint32_t(image.height)) {
    fail("the frame's grid is not the image's");
  }
  for (std::size_t i = 0; i < xyz.size(); ++i) {
    const float z = xyz[i].z;
    if (image.depth[i] == 0 ? !std::isnan(z) : std::fabs(z - float(image.depth[i] / 5000.0)) > 1e-6f) {
      fail("a point's depth is not its pixel's");
    }
  }
  return 0;
}
