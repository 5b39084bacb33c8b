#pragma once
// Writing RGB images as PNG files (libpng), atomically.

#include <string>

#include "io/rgb_image.h"

namespace floodplane::io {

/// Writes `image` as an 8-bit RGB PNG through writeFileAtomically.
/// Throws std::invalid_argument if the image is empty or its pixel buffer does not hold
/// width * height * 3 bytes, std::runtime_error naming `path` if the file cannot be written.
void writePng(const std::string& path, const RgbImage& image);

}  // namespace floodplane::io
