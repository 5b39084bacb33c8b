// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading the labels another program wrote for a frame, so that any method's output (or a
// data set's ground truth) can be scored as floodplane's is: a label PCD as pcd_segment
// writes it, or a grey PNG whose pixel values are the labels.

#include <cstdint>
#include <string>
#include <vector>

namespace floodplane::io {

/// A label per pixel of an image grid; 0 is "no plane".
struct LabelGrid {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint32_t> labels;  ///< row-major, width * height
};

/// Reads the label file `path`: a .png (any case) as a grey PNG of 8 or 16 bits whose value
/// at each pixel is its label; anything else as an organized PCD file with x y z fields and
/// a 32-bit unsigned `label` field (pcd_segment's <name>.labels.pcd). Throws
/// std::runtime_error with a one-line reason, without the path, when the file cannot be read
/// as either, or has no label field.
LabelGrid readLabelFile(const std::string& path);

}  // namespace floodplane::io
