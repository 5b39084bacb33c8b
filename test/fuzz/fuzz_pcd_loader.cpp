// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the input bytes as a PCD file (header and body) through the frame reader. A
// broken file must give std::runtime_error; a file that loads must be a consistent frame.

#include <pcl/console/print.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "floodplane/io/input_frame.h"
#include "loader_fuzzing.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using floodplane::fuzz::fail;
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  const std::string& path = floodplane::fuzz::scratchFile(data, size, ".pcd");
  floodplane::io::InputFrame frame;
  try {
    frame = floodplane::io::loadInputFrame(path);
  } catch (const std::runtime_error&) {
    return 0;  // the expected outcome for a broken file
  }
  const auto& xyz = frame.xyz;
  if (xyz.height <= 1) fail("an unorganized cloud was accepted");
  if (xyz.size() != std::size_t{xyz.width} * xyz.height) fail("points do not fill the grid");
  if (frame.xyzrgb && (frame.xyzrgb->width != xyz.width || frame.xyzrgb->height != xyz.height)) {
    fail("the colour cloud has another grid");
  }
  if (frame.labels && frame.labels->size() != xyz.size()) fail("the labels do not fill the grid");
  bool dense = true;
  for (const auto& p : xyz) dense = dense && std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  if (xyz.is_dense && !dense) fail("a cloud with non-finite points is marked dense");
  return 0;
}
