// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "depth_image.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "byte_order.h"

namespace floodplane::conversion {
namespace {

bool isMillimetres(const std::string& encoding) { return encoding == "16UC1" || encoding == "mono16"; }

// Rows are read with memcpy: a message's rows need not be aligned for their element type.
template <typename Depth>
void backProjectRows(const ImageView& image, const io::DepthCamera& camera, float* xyz) {
  for (std::uint32_t v = 0; v < image.height; ++v) {
    const std::uint8_t* row = image.data + static_cast<std::uint64_t>(v) * image.step;
    for (std::uint32_t u = 0; u < image.width; ++u, xyz += 3) {
      Depth depth;
      std::memcpy(&depth, row + u * sizeof(Depth), sizeof depth);
      const double units = static_cast<double>(depth);
      if (!(units > 0.0) || !std::isfinite(units)) {
        // depth_image_proc's "no return" (0 or NaN); negative and infinite depths are no
        // measurement either.
        xyz[0] = xyz[1] = xyz[2] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      io::backProjectPixel(static_cast<int>(u), static_cast<int>(v), units, camera, xyz);
    }
  }
}

}  // namespace

double depthUnitsPerMetre(const std::string& encoding) {
  if (isMillimetres(encoding)) return 1000.0;
  if (encoding == "32FC1") return 1.0;
  throw std::invalid_argument("depth image encoding '" + encoding +
                              "': floodplane reads 16UC1 or mono16 (millimetres) and 32FC1 (metres)");
}

io::DepthCamera depthCamera(const CameraInfoView& info, const std::string& encoding) {
  io::DepthCamera camera;
  camera.fx = info.k[0];
  camera.fy = info.k[4];
  camera.cx = info.k[2];
  camera.cy = info.k[5];
  camera.depth_scale = depthUnitsPerMetre(encoding);
  const std::string problem = camera.problem();
  if (!problem.empty()) throw std::invalid_argument("camera_info K: " + problem);
  return camera;
}

void backProjectDepthImage(const ImageView& image, const CameraInfoView& info, std::vector<float>& xyz) {
  const io::DepthCamera camera = depthCamera(info, image.encoding);
  if (image.is_bigendian != hostIsBigEndian()) {
    throw std::invalid_argument(std::string("the depth image is ") + (image.is_bigendian ? "big" : "little") +
                                "-endian, this machine is not");
  }
  if ((info.width != 0 && info.width != image.width) || (info.height != 0 && info.height != image.height)) {
    throw std::invalid_argument("camera_info is " + std::to_string(info.width) + "x" + std::to_string(info.height) +
                                ", the depth image " + std::to_string(image.width) + "x" +
                                std::to_string(image.height));
  }
  // An image without pixels is a frame without points (no planes).
  if (image.width == 0 || image.height == 0) {
    xyz.clear();
    return;
  }
  const std::uint64_t pixel_bytes = isMillimetres(image.encoding) ? 2 : 4;
  const std::uint64_t row_bytes = pixel_bytes * image.width;
  if (image.step < row_bytes) {
    throw std::invalid_argument("the depth image's step " + std::to_string(image.step) + " is less than its " +
                                std::to_string(row_bytes) + " bytes a row");
  }
  const std::uint64_t needed = static_cast<std::uint64_t>(image.step) * (image.height - 1) + row_bytes;
  if (image.data == nullptr || image.data_size < needed) {
    throw std::invalid_argument("the depth image's data holds " +
                                std::to_string(image.data == nullptr ? 0 : image.data_size) + " bytes, its rows " +
                                std::to_string(needed));
  }
  xyz.resize(3 * static_cast<std::size_t>(image.width) * image.height);
  if (isMillimetres(image.encoding)) {
    backProjectRows<std::uint16_t>(image, camera, xyz.data());
  } else {
    backProjectRows<float>(image, camera, xyz.data());
  }
}

}  // namespace floodplane::conversion
