#include "bench_frames.h"

#include <pcl/common/io.h>
#include <pcl/io/pcd_io.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "synth/point_cloud.h"
#include "synth/renderer.h"
#include "synth/scene_file.h"

namespace floodplane::bench {

namespace fs = std::filesystem;

const std::vector<Frame>& realFrames() {
  static const std::vector<Frame> frames = [] {
    std::vector<Frame> loaded;
    const fs::path folder(FLOODPLANE_REAL_DATA_DIR);
    if (!fs::is_directory(folder)) return loaded;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".pcd") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
      Frame frame{file.stem().string(), pcl::PointCloud<pcl::PointXYZ>::Ptr(new pcl::PointCloud<pcl::PointXYZ>)};
      if (pcl::io::loadPCDFile(file.string(), *frame.cloud) != 0) throw std::runtime_error("cannot read " + file.string());
      loaded.push_back(std::move(frame));
    }
    return loaded;
  }();
  return frames;
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

const Frame& renderedFrame(const std::string& scene_name, int width, int height) {
  static std::map<std::string, Frame> cache;
  const std::string key = scene_name + "@" + std::to_string(width) + "x" + std::to_string(height);
  auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  synth::Scene scene = synth::loadScene(std::string(FLOODPLANE_SCENE_DIR) + "/" + scene_name + ".json");
  scene.intrinsics = scene.intrinsics.scaledTo(width, height);
  synth::RenderSettings settings;
  settings.sensor = synth::SensorModel::kinect;
  settings.seed = 1;
  const pcl::PointCloud<pcl::PointXYZL> labelled = synth::toPointCloud(synth::renderScene(scene, settings));
  Frame frame{key, pcl::PointCloud<pcl::PointXYZ>::Ptr(new pcl::PointCloud<pcl::PointXYZ>)};
  pcl::copyPointCloud(labelled, *frame.cloud);
  return cache.emplace(key, std::move(frame)).first->second;
}

}  // namespace floodplane::bench
