// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "bench_frames.h"

#include <pcl/common/io.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "floodplane/io/input_files.h"
#include "floodplane/io/input_frame.h"
#include "synth/point_cloud.h"
#include "synth/renderer.h"
#include "synth/scene_file.h"

namespace floodplane::bench {

namespace fs = std::filesystem;

const std::vector<Frame>& realFrames() {
  static const std::vector<Frame> frames = [] {
    std::vector<Frame> loaded;
    if (!fs::is_directory(FLOODPLANE_REAL_DATA_DIR)) return loaded;
    for (const io::InputFile& file : io::expandInputs({FLOODPLANE_REAL_DATA_DIR})) {
      try {
        if (!file.error.empty()) throw std::runtime_error(file.error);
        io::InputFrame frame = io::loadInputFrame(file.path);
        loaded.push_back({fs::path(file.path).stem().string(),
                          std::make_shared<pcl::PointCloud<pcl::PointXYZ>>(std::move(frame.xyz))});
      } catch (const std::runtime_error& error) {
        throw std::runtime_error("cannot read " + file.path + ": " + error.what());
      }
    }
    return loaded;
  }();
  return frames;
}

PointGrid gridOf(const Frame& frame) {
  PointGrid grid;
  grid.data = reinterpret_cast<const float*>(frame.cloud->data());
  grid.width = static_cast<int>(frame.cloud->width);
  grid.height = static_cast<int>(frame.cloud->height);
  grid.stride = sizeof(pcl::PointXYZ) / sizeof(float);
  return grid;
}

const std::vector<std::string>& sceneNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> stems;
    for (const auto& entry : fs::directory_iterator(FLOODPLANE_SCENE_DIR))
      if (entry.path().extension() == ".json") stems.push_back(entry.path().stem().string());
    std::sort(stems.begin(), stems.end());
    return stems;
  }();
  return names;
}

const Frame& renderedFrame(const std::string& scene_name, int width, int height, bool exact) {
  static std::map<std::string, Frame> cache;
  const std::string key =
      scene_name + "@" + std::to_string(width) + "x" + std::to_string(height) + (exact ? "/exact" : "");
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  synth::Scene scene = synth::loadScene(std::string(FLOODPLANE_SCENE_DIR) + "/" + scene_name + ".json");
  scene.intrinsics = scene.intrinsics.scaledTo(width, height);
  synth::RenderSettings settings;
  settings.sensor = exact ? synth::SensorModel::none : synth::SensorModel::kinect;
  settings.seed = 1;
  const pcl::PointCloud<pcl::PointXYZL> labelled = synth::toPointCloud(synth::renderScene(scene, settings));
  Frame frame{key, pcl::PointCloud<pcl::PointXYZ>::Ptr(new pcl::PointCloud<pcl::PointXYZ>)};
  pcl::copyPointCloud(labelled, *frame.cloud);
  return cache.emplace(key, std::move(frame)).first->second;
}

}  // namespace floodplane::bench
