// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing RGB images as PNG files (libpng), atomically: encoded in memory, written with checks.

#include <string>

#include "floodplane/io/rgb_image.h"

namespace floodplane::io {

/// Writes `image` as an 8-bit RGB PNG through writeBytesAtomically.
/// Throws std::invalid_argument if the image is empty or its pixel buffer does not hold
/// width * height * 3 bytes, std::runtime_error naming `path` if the file cannot be written
/// (with the system's reason: "No space left on device").
void writePng(const std::string& path, const RgbImage& image);

/// The bytes of the PNG file writePng writes, for writing with others through AtomicFileGroup.
/// Throws as writePng does, std::runtime_error without a path.
std::string encodePng(const RgbImage& image);

/// Writes `width` x `height` pixels of libpng's simplified-API `format` (PNG_FORMAT_RGB,
/// PNG_FORMAT_LINEAR_Y for 16-bit grey, ...) from `pixels`, rows packed, through
/// writeBytesAtomically; throws std::runtime_error naming `path` if the file cannot be written.
/// The size is the caller's to check.
void writePngPixels(const std::string& path, unsigned width, unsigned height, unsigned format, const void* pixels);

/// The bytes of the PNG file writePngPixels writes; std::runtime_error, without a path, if
/// libpng cannot encode them.
std::string encodePngPixels(unsigned width, unsigned height, unsigned format, const void* pixels);

}  // namespace floodplane::io
