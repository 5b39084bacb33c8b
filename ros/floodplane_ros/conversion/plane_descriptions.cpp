// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "plane_descriptions.h"

#include <stdexcept>
#include <string>

#include <Eigen/Core>

#include "floodplane/io/label_palette.h"

namespace floodplane::conversion {

std::vector<std::uint32_t> publishedLabels(std::size_t plane_count, const std::vector<std::uint32_t>& track_ids) {
  if (!track_ids.empty()) {
    if (track_ids.size() != plane_count) {
      throw std::invalid_argument("publishedLabels: " + std::to_string(track_ids.size()) + " track ids for " +
                                  std::to_string(plane_count) + " planes");
    }
    return track_ids;
  }
  std::vector<std::uint32_t> labels(plane_count);
  for (std::size_t k = 0; k < plane_count; ++k) labels[k] = static_cast<std::uint32_t>(k + 1);
  return labels;
}

std::vector<PlaneDescription> describePlanes(const Segmentation& segmentation,
                                             const std::vector<std::uint32_t>& track_ids,
                                             const std::optional<std::array<double, 3>>& up) {
  const std::vector<std::uint32_t> labels = publishedLabels(segmentation.planes.size(), track_ids);
  // The library's descriptions (floodplane::, not this namespace's of the same name).
  std::vector<floodplane::PlaneDescription> classes;
  if (up) classes = floodplane::describePlanes(segmentation.planes, Eigen::Vector3d((*up)[0], (*up)[1], (*up)[2]));
  std::vector<PlaneDescription> planes(segmentation.planes.size());
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const SegmentedPlane& plane = segmentation.planes[k];
    PlaneDescription& description = planes[k];
    description.label = labels[k];
    description.track_id = track_ids.empty() ? 0 : track_ids[k];
    description.coefficients = {plane.fit.normal.x(), plane.fit.normal.y(), plane.fit.normal.z(), plane.fit.offset};
    description.centroid = {plane.fit.centroid.x(), plane.fit.centroid.y(), plane.fit.centroid.z()};
    description.inlier_count = plane.inlier_count;
    description.mean_squared_error = plane.fit.mean_squared_error;
    if (up) {
      description.plane_class = classes[k].plane_class;
      description.height_above_floor = classes[k].height_above_floor;
    }
  }
  return planes;
}

std::array<float, 3> planeClassColor(PlaneClass plane_class) {
  switch (plane_class) {
    case PlaneClass::kFloor:
      return {0.2f, 0.8f, 0.2f};
    case PlaneClass::kCeiling:
      return {0.7f, 0.4f, 1.0f};
    case PlaneClass::kWall:
      return {0.2f, 0.5f, 1.0f};
    case PlaneClass::kHorizontalSurface:
      return {1.0f, 0.6f, 0.0f};
    case PlaneClass::kOther:
      break;
  }
  return {0.6f, 0.6f, 0.6f};
}

std::array<float, 3> markerColor(const PlaneDescription& plane, bool classed) {
  if (classed) return planeClassColor(plane.plane_class);
  const auto rgb = io::labelColor(plane.label);
  return {rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f};
}

PlaneOutline outlinePlane(const Segmentation& segmentation, const PointGrid& grid, std::size_t plane,
                          const std::array<float, 3>& color, std::size_t max_points, double normal_length) {
  if (plane >= segmentation.planes.size()) {
    throw std::invalid_argument("outlinePlane: plane " + std::to_string(plane) + " of " +
                                std::to_string(segmentation.planes.size()));
  }
  if (max_points < 3) throw std::invalid_argument("outlinePlane: max_points must be at least 3");
  if (grid.width != segmentation.width || grid.height != segmentation.height) {
    throw std::invalid_argument("outlinePlane: the grid is not the segmentation's size");
  }
  const PlaneFit& fit = segmentation.planes[plane].fit;
  std::vector<int> contour;
  segmentation.boundary(plane, contour);

  PlaneOutline outline;
  // Every step-th boundary pixel, so that a wall's outline of thousands of pixels stays a
  // marker rviz draws at once; the closing point is added after.
  const std::size_t step = (contour.size() + max_points - 2) / (max_points - 1);
  for (std::size_t i = 0; i < contour.size(); i += step == 0 ? 1 : step) {
    const auto index = static_cast<std::size_t>(contour[i]);
    if (!grid.isFinite(index)) continue;
    const float* p = grid.point(index);
    const Eigen::Vector3d point(p[0], p[1], p[2]);
    // Onto the plane along its normal: the pixels of its edge scatter with the noise.
    const Eigen::Vector3d on_plane = point - (fit.normal.dot(point) + fit.offset) * fit.normal;
    outline.points.push_back(
        {static_cast<float>(on_plane.x()), static_cast<float>(on_plane.y()), static_cast<float>(on_plane.z())});
  }
  if (!outline.points.empty()) outline.points.push_back(outline.points.front());

  const Eigen::Vector3d end = fit.centroid + normal_length * fit.normal;
  outline.normal_start = {static_cast<float>(fit.centroid.x()), static_cast<float>(fit.centroid.y()),
                          static_cast<float>(fit.centroid.z())};
  outline.normal_end = {static_cast<float>(end.x()), static_cast<float>(end.y()), static_cast<float>(end.z())};
  outline.color = color;
  return outline;
}

}  // namespace floodplane::conversion
