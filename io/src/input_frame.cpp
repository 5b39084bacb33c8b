// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/input_frame.h"

#include <pcl/common/point_tests.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

#include "floodplane/io/depth_png.h"
#include "floodplane/io/pcd_input.h"

namespace floodplane::io {
namespace {

InputFrame depthFrame(const DepthImage& image, const DepthCamera& camera) {
  InputFrame frame;
  frame.xyz.resize(static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height));
  for (int v = 0; v < image.height; ++v) {
    for (int u = 0; u < image.width; ++u) {
      const std::size_t i =
          static_cast<std::size_t>(v) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(u);
      backProjectPixel(u, v, image.depth[i], camera, frame.xyz[i].data);
    }
  }
  frame.xyz.is_dense = std::find(image.depth.begin(), image.depth.end(), 0) == image.depth.end();
  return frame;
}

InputFrame readDepthFrame(const std::string& path, const std::optional<DepthCamera>& camera) {
  if (!camera) throw std::runtime_error("a depth image needs the camera's intrinsics (fx, fy, cx, cy)");
  const DepthImage image = readDepthPng(path);
  // Organized means an image grid of more than one row, as for PCD input.
  if (image.height <= 1) {
    throw std::runtime_error("a depth image of " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                             " pixels is not an image grid (height > 1)");
  }
  return depthFrame(image, *camera);
}

}  // namespace

bool isDepthImagePath(const std::string& path) {
  const std::string extension = kDepthImageExtension;
  if (path.size() < extension.size()) return false;
  return std::equal(extension.begin(), extension.end(), path.end() - static_cast<std::ptrdiff_t>(extension.size()),
                    [](char a, char b) {
                      return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
                    });
}

InputFrame loadInputFrame(const std::string& path, const std::optional<DepthCamera>& camera) {
  if (camera) {
    const std::string problem = camera->problem();
    if (!problem.empty()) throw std::invalid_argument(problem);
  }
  if (isDepthImagePath(path)) return readDepthFrame(path, camera);
  // Every other file is read as PCD, whatever its extension: the PCD reader's own checks say
  // what is wrong with a file that is not one.
  return readPcdFrame(path);
}

std::vector<std::uint8_t> finitePoints(const pcl::PointCloud<pcl::PointXYZ>& points) {
  std::vector<std::uint8_t> finite;
  finite.reserve(points.size());
  for (const pcl::PointXYZ& point : points) finite.push_back(pcl::isFinite(point) ? 1 : 0);
  return finite;
}

std::optional<RgbImage> frameColours(const InputFrame& frame) {
  if (!frame.xyzrgb) return std::nullopt;
  RgbImage image;
  image.width = frame.xyzrgb->width;
  image.height = frame.xyzrgb->height;
  image.pixels.reserve(frame.xyzrgb->size() * 3);
  for (const pcl::PointXYZRGB& point : *frame.xyzrgb)
    image.pixels.insert(image.pixels.end(), {point.r, point.g, point.b});
  return image;
}

}  // namespace floodplane::io
