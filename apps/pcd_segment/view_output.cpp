// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "view_output.h"

#include <cmath>
#include <regex>
#include <stdexcept>

#include "floodplane/io/png_file.h"
#include "view/plane_view.h"

namespace pcd_segment {
namespace {

constexpr int kMinimumSide = 16;
constexpr int kMaximumSide = 8192;

floodplane::view::PlaneMarker planeMarker(std::uint32_t id, const pcl::PlanarRegion<pcl::PointXYZ>& region,
                                          const pcl::ModelCoefficients& coefficients) {
  floodplane::view::PlaneMarker marker;
  marker.id = id;
  marker.colour_label = id;
  marker.centroid = region.getCentroid();
  marker.normal = Eigen::Vector3f(coefficients.values[0], coefficients.values[1], coefficients.values[2]).normalized();
  marker.size = std::sqrt(std::max(0.0f, region.getCovariance().trace()));
  marker.inliers = region.getCount();
  for (const pcl::PointXYZ& p : region.getContour()) marker.outline.push_back(p.getVector3fMap());
  return marker;
}

}  // namespace

std::optional<std::pair<int, int>> parseImageSize(const std::string& text) {
  static const std::regex kSize("([0-9]{1,5})x([0-9]{1,5})");
  std::smatch match;
  if (!std::regex_match(text, match, kSize)) return std::nullopt;
  const int width = std::stoi(match[1]);
  const int height = std::stoi(match[2]);
  const auto fits = [](int side) { return side >= kMinimumSide && side <= kMaximumSide; };
  if (!fits(width) || !fits(height)) return std::nullopt;
  return std::make_pair(width, height);
}

floodplane::view::PlaneScene planeScene(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points,
                                        const pcl::PointCloud<pcl::Label>& labels, const Regions& regions,
                                        const std::vector<pcl::ModelCoefficients>& coefficients,
                                        const std::vector<std::uint32_t>& plane_labels) {
  if (labels.size() != points->size() || regions.size() != coefficients.size() ||
      (!plane_labels.empty() && plane_labels.size() != regions.size())) {
    throw std::invalid_argument("planeScene: labels, regions and coefficients do not match the cloud");
  }
  floodplane::view::PlaneScene scene;
  scene.cloud = points;
  scene.colour_labels.reserve(labels.size());
  for (const pcl::Label& label : labels) scene.colour_labels.push_back(label.label);
  for (std::size_t k = 0; k < regions.size(); ++k) {
    if (coefficients[k].values.size() < 3) throw std::invalid_argument("planeScene: a plane without coefficients");
    const std::uint32_t label = plane_labels.empty() ? static_cast<std::uint32_t>(k + 1) : plane_labels[k];
    scene.planes.push_back(planeMarker(label, regions[k], coefficients[k]));
  }
  return scene;
}

std::string snapshotPng(const floodplane::view::PlaneScene& scene, const SnapshotSettings& settings) {
  return floodplane::io::encodePng(
      floodplane::view::renderImage(scene, settings.camera, settings.width, settings.height));
}

}  // namespace pcd_segment
