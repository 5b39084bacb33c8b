// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading single-channel grey PNG files sample by sample, exactly, with the checks that keep
// libpng from reading a broken file into a crash or exhausting memory: the one reader of depth
// images (16 bits, floodplane/io/depth_png.h) and label images (8 or 16 bits, floodplane/io/label_file.h).

#include <cstdint>
#include <string>
#include <vector>

namespace floodplane::io {

struct GreyImage {
  int width = 0;
  int height = 0;
  int bits = 0;                       ///< bits per sample in the file: 8 or 16
  std::vector<std::uint16_t> values;  ///< row-major, each sample as stored (no scaling)
};

/// Reads `path`, a grey PNG of 16 bits per pixel, or of 8 with `accept_8_bit`. Throws
/// std::runtime_error with a one-line reason, without the path, when the file cannot be
/// opened, is not a PNG, is truncated or corrupt, has another bit depth, colour or an alpha
/// channel (said as "not a <what>: ..."), or announces more pixels than its size can hold.
GreyImage readGreyPng(const std::string& path, const std::string& what, bool accept_8_bit);

}  // namespace floodplane::io
