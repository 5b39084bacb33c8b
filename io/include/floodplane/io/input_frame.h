// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One organized frame read from an input file, in the point types the apps segment. Every
// input kind (organized PCD files, 16-bit depth PNG images) is read into this one type, so the
// apps do not depend on where their frames come from.

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "floodplane/io/rgb_image.h"

namespace floodplane::io {

struct InputFrame {
  /// The points on their image grid (height > 1), NaN where the sensor saw nothing, with the
  /// file's sensor pose.
  pcl::PointCloud<pcl::PointXYZ> xyz;
  /// The same grid and points with the file's colour, when the file has one.
  std::optional<pcl::PointCloud<pcl::PointXYZRGB>> xyzrgb;
  /// The file's per-pixel `label` (ground-truth plane id, 0 = no plane, as pcd_synth writes
  /// it), when the file has one, row-major.
  std::optional<std::vector<std::uint32_t>> labels;
};

/// The extension of depth images (16-bit greyscale PNG files).
inline constexpr const char* kDepthImageExtension = ".png";

/// Whether `path` names a depth image: it ends in .png (in any case).
bool isDepthImagePath(const std::string& path);

/// Reads the frame in `path`. A depth image (isDepthImagePath) is read with readDepthPng
/// (floodplane/io/depth_png.h) and back-projected with `camera` into points without colour, NaN where
/// the depth is 0; it needs `camera`. Every other input is read as an organized PCD file
/// (readPcdFrame, floodplane/io/pcd_input.h). Throws std::runtime_error with a one-line reason, without
/// the path, when the file cannot be read as a frame, or when a depth image comes without a
/// camera; std::invalid_argument when `camera` has a problem().
InputFrame loadInputFrame(const std::string& path, const std::optional<DepthCamera>& camera = std::nullopt);

/// 1 for each point of `points` whose x, y and z are finite, 0 for the others (no depth: a
/// hole), row-major: what a label image paints as a hole (floodplane/io/label_palette.h).
std::vector<std::uint8_t> finitePoints(const pcl::PointCloud<pcl::PointXYZ>& points);

/// The colour of every pixel of a frame read with colour (InputFrame::xyzrgb), holes
/// included, as an image on the frame's grid; std::nullopt when the frame has no colour.
std::optional<RgbImage> frameColours(const InputFrame& frame);

}  // namespace floodplane::io
