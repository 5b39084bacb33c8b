// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One input as pcd_compare compares it: the frame's points, the ground-truth labels when the
// file has a `label` field, and which pixels the metrics count.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "floodplane/io/depth_camera.h"
#include "method.h"

namespace pcd_compare {

struct InputCloud {
  std::string path;
  std::string name;  ///< the file name without ".pcd" or ".png", used in tables and image names
  /// The sensor model a file named <scene>.<sensor>.pcd was rendered or recorded with (none,
  /// kinect, scanner, ...): whatever follows the last dot of `name`. Empty when there is no
  /// dot, or when digits alone follow it (a time stamp's fraction of a second).
  std::string sensor;
  Cloud::Ptr cloud;
  /// The ground truth (plane id, 0 = none): the file's `label` field, or --ground-truth's file.
  std::optional<std::vector<std::uint32_t>> ground_truth;
  /// 1 where x, y and z are finite: the pixels the metrics count.
  std::vector<std::uint8_t> valid;
};

/// The name of the input at `path`: its file name without ".pcd" or a depth image's ".png".
std::string sceneName(const std::string& path);

/// Loads an organized cloud, or a depth image back-projected with `camera`, through
/// floodplane::io::loadInputFrame. Throws std::runtime_error with a one-line reason (without
/// the path) if the file cannot be read as a frame. Any organized grid is a frame, a single
/// column or one without a finite point too: every method finds its planes in it, or none.
InputCloud loadInputCloud(const std::string& path, const std::optional<floodplane::io::DepthCamera>& camera = {});

}  // namespace pcd_compare
