// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The <name>.planes.json report: the planes found, the parameters used and the time taken.

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/point_types.h>
#include <pcl/segmentation/planar_region.h>

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "floodplane/object_segmentation.h"
#include "floodplane/params.h"
#include "floodplane/plane_classes.h"
#include "floodplane/segmenter.h"

namespace pcd_segment {

/// Pixel bounding box, inclusive, of an image region: columns and rows of an organized cloud.
struct PixelBox {
  int min_column = 0;
  int max_column = -1;
  int min_row = 0;
  int max_row = -1;
};

/// The box around the pixels `indices` (row-major indices into a grid `width` wide); an
/// empty box (max < min) for no indices.
PixelBox pixelBox(const std::vector<int>& indices, std::size_t width);

/// What the report says about one plane.
struct PlaneRecord {
  std::uint32_t id = 0;         ///< its size rank: 1 for the largest plane
  std::uint32_t track = 0;      ///< its track id with --track (its label then); 0: not tracked
  float normal[3] = {0, 0, 0};  ///< unit, towards the sensor
  float d = 0;                  ///< n . p + d = 0
  float centroid[3] = {0, 0, 0};
  std::size_t inliers = 0;
  PixelBox boundary_box;  ///< of the plane's outer boundary, which encloses all its inliers
  /// Its class and height above the floor, with --up or --gravity.
  std::optional<floodplane::PlaneDescription> description;
};

/// One record per plane from the outputs of FloodFillPlaneSegmentation::segmentAndRefine
/// (all vectors indexed by plane k-1 for label k).
std::vector<PlaneRecord> planeRecords(
    const std::vector<pcl::ModelCoefficients>& coefficients,
    const std::vector<pcl::PlanarRegion<pcl::PointXYZ>, Eigen::aligned_allocator<pcl::PlanarRegion<pcl::PointXYZ>>>&
        regions,
    const std::vector<pcl::PointIndices>& inliers, const std::vector<pcl::PointIndices>& boundaries, std::size_t width);

/// Gives each record its description (floodplane::describePlanes over the same planes, in the
/// same order). Throws std::logic_error when the counts differ.
void describeRecords(std::vector<PlaneRecord>& records, const std::vector<floodplane::PlaneDescription>& descriptions);

/// Everything a report holds about one segmented file.
struct Report {
  std::string input;  ///< the input file as given
  std::size_t width = 0;
  std::size_t height = 0;
  floodplane::Params params;
  floodplane::NoiseModel noise;  ///< the depth noise the segmentation assumed
  bool head_start = false;       ///< continued from the previous frame (--track without --cold-starts)
  double segmentation_ms = 0.0;  ///< segmentAndRefine alone, not reading or writing
  /// The up direction the planes were classed by, unit (--up, --gravity).
  std::optional<Eigen::Vector3d> up;
  std::vector<PlaneRecord> planes;
  /// With --objects: the objects on the planes, and the time segmentObjects took.
  std::optional<std::vector<floodplane::SegmentedObject>> objects;
  double objects_ms = 0.0;
};

/// The report, keys in reading order (input, size, parameters, noise, time, [up,] planes);
/// with an up direction, each plane's "class" (floodplane::planeClassName) and
/// "height_above_floor" [m] (null when no floor was found); with objects, "objects_ms",
/// "object_count" and "objects" (each object's id, pixels, centroid, bounding box min and max
/// [m] and "support": the label of the plane it stands on, 0 for none: its "id", or with
/// --track its "track", as the labels hold it).
nlohmann::ordered_json reportJson(const Report& report);

}  // namespace pcd_segment
