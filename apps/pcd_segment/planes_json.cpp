// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "planes_json.h"

#include "floodplane/io/params_json.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "floodplane/version.h"

namespace pcd_segment {

PixelBox pixelBox(const std::vector<int>& indices, std::size_t width) {
  PixelBox box;
  if (indices.empty()) return box;
  box.min_column = box.min_row = std::numeric_limits<int>::max();
  box.max_column = box.max_row = std::numeric_limits<int>::min();
  for (const int index : indices) {
    const int column = static_cast<int>(static_cast<std::size_t>(index) % width);
    const int row = static_cast<int>(static_cast<std::size_t>(index) / width);
    box.min_column = std::min(box.min_column, column);
    box.max_column = std::max(box.max_column, column);
    box.min_row = std::min(box.min_row, row);
    box.max_row = std::max(box.max_row, row);
  }
  return box;
}

std::vector<PlaneRecord> planeRecords(
    const std::vector<pcl::ModelCoefficients>& coefficients,
    const std::vector<pcl::PlanarRegion<pcl::PointXYZ>, Eigen::aligned_allocator<pcl::PlanarRegion<pcl::PointXYZ>>>&
        regions,
    const std::vector<pcl::PointIndices>& inliers, const std::vector<pcl::PointIndices>& boundaries,
    std::size_t width) {
  const std::size_t count = coefficients.size();
  if (regions.size() != count || inliers.size() != count || boundaries.size() != count) {
    throw std::logic_error("planeRecords: the segmentation outputs disagree on the plane count");
  }
  std::vector<PlaneRecord> records(count);
  for (std::size_t k = 0; k < count; ++k) {
    PlaneRecord& record = records[k];
    record.id = static_cast<std::uint32_t>(k + 1);
    const std::vector<float>& values = coefficients[k].values;
    for (int i = 0; i < 3; ++i) record.normal[i] = values.at(i);
    record.d = values.at(3);
    const Eigen::Vector3f centroid = regions[k].getCentroid();
    for (int i = 0; i < 3; ++i) record.centroid[i] = centroid[i];
    record.inliers = inliers[k].indices.size();
    record.boundary_box = pixelBox(boundaries[k].indices, width);
  }
  return records;
}

void describeRecords(std::vector<PlaneRecord>& records, const std::vector<floodplane::PlaneDescription>& descriptions) {
  if (descriptions.size() != records.size()) {
    throw std::logic_error("describeRecords: " + std::to_string(descriptions.size()) + " descriptions for " +
                           std::to_string(records.size()) + " planes");
  }
  for (std::size_t k = 0; k < records.size(); ++k) records[k].description = descriptions[k];
}

nlohmann::ordered_json reportJson(const Report& report) {
  nlohmann::ordered_json planes = nlohmann::ordered_json::array();
  for (const PlaneRecord& plane : report.planes) {
    nlohmann::ordered_json record = {{"id", plane.id}};
    if (plane.track != 0) record["track"] = plane.track;  // only with --track
    if (plane.description) {                              // only with --up or --gravity
      record["class"] = floodplane::planeClassName(plane.description->plane_class);
      const double height = plane.description->height_above_floor;
      record["height_above_floor"] = std::isnan(height) ? nlohmann::ordered_json() : nlohmann::ordered_json(height);
    }
    record["normal"] = {plane.normal[0], plane.normal[1], plane.normal[2]};
    record["d"] = plane.d;
    record["centroid"] = {plane.centroid[0], plane.centroid[1], plane.centroid[2]};
    record["inliers"] = plane.inliers;
    record["boundary_box"] = {{"min_column", plane.boundary_box.min_column},
                              {"max_column", plane.boundary_box.max_column},
                              {"min_row", plane.boundary_box.min_row},
                              {"max_row", plane.boundary_box.max_row}};
    planes.push_back(std::move(record));
  }
  const floodplane::Params& p = report.params;
  nlohmann::ordered_json json = {
      {"input", report.input},
      {"width", report.width},
      {"height", report.height},
      {"floodplane_version", FLOODPLANE_VERSION_STRING},
      {"parameters", floodplane::io::paramsJson(p)},
      {"noise", floodplane::io::noiseJson(report.noise)},
      {"head_start", report.head_start},
      {"segmentation_ms", report.segmentation_ms},
  };
  if (report.up) json["up"] = {report.up->x(), report.up->y(), report.up->z()};
  json["plane_count"] = report.planes.size();
  json["planes"] = std::move(planes);
  if (report.objects) {
    nlohmann::ordered_json objects = nlohmann::ordered_json::array();
    for (const floodplane::SegmentedObject& object : *report.objects) {
      objects.push_back({{"id", object.id},
                         {"pixels", object.pixel_count},
                         {"centroid", {object.centroid.x(), object.centroid.y(), object.centroid.z()}},
                         {"min", {object.min.x(), object.min.y(), object.min.z()}},
                         {"max", {object.max.x(), object.max.y(), object.max.z()}},
                         {"support", object.support}});
    }
    json["objects_ms"] = report.objects_ms;
    json["object_count"] = report.objects->size();
    json["objects"] = std::move(objects);
  }
  return json;
}

}  // namespace pcd_segment
