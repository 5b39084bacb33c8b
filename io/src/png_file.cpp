// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/png_file.h"

#include <png.h>

#include <limits>
#include <stdexcept>

#include "floodplane/io/atomic_file.h"

namespace floodplane::io {
namespace {

void checkImage(const RgbImage& image) {
  constexpr std::size_t max_side = std::numeric_limits<png_uint_32>::max() / 3;
  if (image.width == 0 || image.height == 0 || image.width > max_side || image.height > max_side) {
    throw std::invalid_argument("writePng: image size " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + " is not writable");
  }
  if (image.pixels.size() != image.width * image.height * 3) {
    throw std::invalid_argument("writePng: pixel buffer holds " + std::to_string(image.pixels.size()) +
                                " bytes, expected " + std::to_string(image.width * image.height * 3));
  }
}

// A libpng failure (never a file system's: the file is written elsewhere) naming `path`.
template <typename Encode>
std::string encodedFor(const std::string& path, Encode encode) {
  try {
    return encode();
  } catch (const std::runtime_error& error) {
    throw std::runtime_error("cannot write PNG file '" + path + "': " + error.what());
  }
}

}  // namespace

std::string encodePng(const RgbImage& image) {
  checkImage(image);
  return encodePngPixels(static_cast<unsigned>(image.width), static_cast<unsigned>(image.height), PNG_FORMAT_RGB,
                         image.pixels.data());
}

void writePng(const std::string& path, const RgbImage& image) {
  writeBytesAtomically(path, encodedFor(path, [&] { return encodePng(image); }));
}

std::string encodePngPixels(unsigned width, unsigned height, unsigned format, const void* pixels) {
  // libpng's simplified API reports errors through png_image::message instead of longjmp,
  // which would skip C++ destructors. Row stride 0: rows packed.
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = width;
  png.height = height;
  png.format = format;
  // The largest the file can be (stored uncompressed), so that one call encodes it.
  png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(png);
  std::string bytes(size, '\0');
  if (png_image_write_to_memory(&png, bytes.data(), &size, 0, pixels, 0, nullptr) == 0) {
    const std::string reason = png.message;
    png_image_free(&png);
    throw std::runtime_error(reason);
  }
  bytes.resize(size);
  return bytes;
}

void writePngPixels(const std::string& path, unsigned width, unsigned height, unsigned format, const void* pixels) {
  writeBytesAtomically(path, encodedFor(path, [&] { return encodePngPixels(width, height, format, pixels); }));
}

}  // namespace floodplane::io
