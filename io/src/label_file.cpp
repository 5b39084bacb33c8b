// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/label_file.h"

#include <stdexcept>
#include <utility>

#include "floodplane/io/grey_png.h"
#include "floodplane/io/input_frame.h"
#include "floodplane/io/pcd_input.h"

namespace floodplane::io {

LabelGrid readLabelFile(const std::string& path) {
  LabelGrid grid;
  // A label image has the depth image's extension; isDepthImagePath compares it in any case.
  if (isDepthImagePath(path)) {
    GreyImage image = readGreyPng(path, "label image", true);
    grid.width = static_cast<std::uint32_t>(image.width);
    grid.height = static_cast<std::uint32_t>(image.height);
    grid.labels.assign(image.values.begin(), image.values.end());
    return grid;
  }
  InputFrame frame = readPcdFrame(path);
  if (!frame.labels) throw std::runtime_error("the cloud has no label field (a 32-bit unsigned `label`)");
  grid.width = frame.xyz.width;
  grid.height = frame.xyz.height;
  grid.labels = std::move(*frame.labels);
  return grid;
}

}  // namespace floodplane::io
