#include "input_cloud.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <utility>

#include "io/input_frame.h"

namespace pcd_compare {

namespace {

std::string withoutPcdExtension(const std::string& path) {
  std::string name = std::filesystem::path(path).filename().string();
  if (name.size() > 4 && name.compare(name.size() - 4, 4, ".pcd") == 0) name.resize(name.size() - 4);
  return name;
}

}  // namespace

std::string sensorModel(const std::string& path) {
  const std::string name = withoutPcdExtension(path);
  const std::size_t dot = name.rfind('.');
  if (dot == std::string::npos) return "";
  const std::string sensor = name.substr(dot + 1);
  // Recorded frames are often named by time ("frame_20121214T142255.814212"): digits after
  // the dot are a fraction of a second, not a sensor model.
  const bool number = std::all_of(sensor.begin(), sensor.end(), [](char c) { return c >= '0' && c <= '9'; });
  return number ? "" : sensor;
}

InputCloud loadInputCloud(const std::string& path) {
  floodplane::io::InputFrame frame = floodplane::io::loadInputFrame(path);
  if (frame.xyz.width <= 1) {
    throw std::runtime_error("not an organized cloud (" + std::to_string(frame.xyz.width) + "x" +
                             std::to_string(frame.xyz.height) + "): PCL's methods need an image grid");
  }
  InputCloud input;
  input.path = path;
  input.name = withoutPcdExtension(path);
  input.sensor = sensorModel(path);
  input.cloud = std::make_shared<Cloud>(std::move(frame.xyz));
  input.valid.reserve(input.cloud->size());
  for (const pcl::PointXYZ& point : *input.cloud) input.valid.push_back(pcl::isFinite(point) ? 1 : 0);
  input.ground_truth = std::move(frame.labels);
  return input;
}

}  // namespace pcd_compare
