// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a node publishes about each plane, without ROS types: its coefficients, centroid,
// inlier count, ids, class and height above the floor (floodplane_ros/Plane), and what rviz
// draws of it (its outline and its normal, in its class's colour or its label's).

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "floodplane/plane_classes.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"

namespace floodplane::conversion {

struct PlaneDescription {
  std::uint32_t label = 0;     ///< its label in the label cloud: 1..K by size, or its track id
  std::uint32_t track_id = 0;  ///< the id that persists over frames; 0 without tracking
  /// a b c d of a x + b y + c z + d = 0: (a b c) the unit normal, facing the sensor [m]
  std::array<double, 4> coefficients{};
  std::array<double, 3> centroid{};  ///< of its inliers [m]
  std::uint32_t inlier_count = 0;    ///< pixels at full resolution
  double mean_squared_error = 0.0;   ///< of its inliers' distances to it [m^2]
  /// What it is (floodplane::describePlanes); kOther when the frame has no up direction.
  PlaneClass plane_class = PlaneClass::kOther;
  /// Along up from the floor's plane to its centroid [m]; NaN without an up direction or a
  /// floor. The same in every frame (a rigid transform keeps it).
  double height_above_floor = std::numeric_limits<double>::quiet_NaN();
};

/// The published label of each plane of a frame: its track id when `track_ids` has one per
/// plane (tracking), 1..K in the planes' order when it is empty. Throws std::invalid_argument
/// when it has another size.
std::vector<std::uint32_t> publishedLabels(std::size_t plane_count, const std::vector<std::uint32_t>& track_ids);

/// The planes of `segmentation`, largest first, with their published labels (publishedLabels)
/// and, when `track_ids` is not empty, their track ids. With an up direction x y z (in the
/// segmentation's frame: up_direction.h's UpDirection), each gets its class and height above
/// the floor from the library's floodplane::describePlanes with its default options; without
/// one, all are kOther with NaN heights. Throws std::invalid_argument for an up direction that
/// is zero or not finite.
std::vector<PlaneDescription> describePlanes(const Segmentation& segmentation,
                                             const std::vector<std::uint32_t>& track_ids,
                                             const std::optional<std::array<double, 3>>& up = std::nullopt);

/// The colour rviz draws a plane's markers in, each in [0, 1]: its class's
/// (planeClassColor) when its frame was classed (an up direction known), its label's
/// (io::labelColor, the label cloud's colour for it) when not.
std::array<float, 3> markerColor(const PlaneDescription& plane, bool classed);

/// One colour a class, told apart at a glance on rviz's dark background: floor green,
/// ceiling violet, wall blue, horizontal surface orange, other grey (and grey for a value
/// outside the enumeration). Each in [0, 1].
std::array<float, 3> planeClassColor(PlaneClass plane_class);

struct PlaneOutline {
  /// The plane's outer boundary, closed (the last point is the first), its pixels' points
  /// projected onto the plane, every n-th kept so that there are at most max_points.
  std::vector<std::array<float, 3>> points;
  std::array<float, 3> normal_start{};  ///< the centroid
  std::array<float, 3> normal_end{};    ///< normal_length along the normal from it
  std::array<float, 3> color{};         ///< each in [0, 1] (markerColor)
};

/// The outline of segmentation.planes[plane] in `grid`, the points it was segmented from, in
/// `color`. Throws std::invalid_argument for a plane index out of range, max_points < 3 or a
/// grid of another size than the segmentation.
PlaneOutline outlinePlane(const Segmentation& segmentation, const PointGrid& grid, std::size_t plane,
                          const std::array<float, 3>& color, std::size_t max_points, double normal_length);

}  // namespace floodplane::conversion
