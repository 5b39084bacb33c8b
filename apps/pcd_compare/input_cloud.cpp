// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "input_cloud.h"

#include <algorithm>
#include <filesystem>
#include <utility>

#include "floodplane/io/input_frame.h"

namespace pcd_compare {

std::string sceneName(const std::string& path) {
  const std::string file = std::filesystem::path(path).filename().string();
  const bool pcd = file.size() > 4 && file.compare(file.size() - 4, 4, ".pcd") == 0;
  return pcd || floodplane::io::isDepthImagePath(file) ? file.substr(0, file.size() - 4) : file;
}

InputCloud loadInputCloud(const std::string& path, const std::optional<floodplane::io::DepthCamera>& camera) {
  floodplane::io::InputFrame frame = floodplane::io::loadInputFrame(path, camera);
  InputCloud input;
  input.path = path;
  input.name = sceneName(path);
  // Recorded frames are often named by time ("frame_20121214T142255.814212"): digits after
  // the dot are a fraction of a second, not a sensor model.
  const std::size_t dot = input.name.rfind('.');
  const std::string sensor = dot == std::string::npos ? "" : input.name.substr(dot + 1);
  if (!std::all_of(sensor.begin(), sensor.end(), [](char c) { return c >= '0' && c <= '9'; })) input.sensor = sensor;
  input.cloud = std::make_shared<Cloud>(std::move(frame.xyz));
  input.valid.reserve(input.cloud->size());
  for (const pcl::PointXYZ& point : *input.cloud) input.valid.push_back(pcl::isFinite(point) ? 1 : 0);
  input.ground_truth = std::move(frame.labels);
  return input;
}

}  // namespace pcd_compare
