// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the 3-D views of a segmentation show, and from where: the points with a colour label
// each, a marker per plane (centroid, normal, size, outline), and the cameras. Plain data and
// geometry, no VTK, so that tests can check the cameras and projections without a display
// (the drawing is plane_view.h).

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace floodplane::view {

/// The colour of points on no plane (label 0): a mid grey, visible on the black background
/// (the label PNG's near-black would not be) and darker than the arrows.
constexpr std::array<std::uint8_t, 3> kUnlabelledColour{110, 110, 110};
/// The arrows' colour: white, which no plane's colour is (the palette's saturation is at
/// least 0.6), lit so that it stays between 60 % and 100 % of white.
constexpr std::array<std::uint8_t, 3> kArrowColour{255, 255, 255};

/// The colour of a point with colour label `label`: floodplane::io::labelColor, except label 0.
std::array<std::uint8_t, 3> pointColour(std::uint32_t label);

/// One plane as the views draw it: an arrow along its normal from its centroid (see
/// arrowTip), "<id>: <inliers>" beside it, and its outline.
struct PlaneMarker {
  std::uint32_t id = 0;            ///< the number shown (the plane's label)
  std::uint32_t colour_label = 0;  ///< the label whose palette colour the plane's points have
  Eigen::Vector3f centroid = Eigen::Vector3f::Zero();
  Eigen::Vector3f normal = Eigen::Vector3f::UnitZ();  ///< unit, towards the sensor
  /// The root-mean-square distance of the inliers from the centroid [m]: 0.41 of the side of
  /// a square, 0.29 of the length of a long strip.
  float size = 0.0f;
  std::size_t inliers = 0;
  /// The plane's ordered outer boundary (closed: the last point joins the first); may be empty.
  std::vector<Eigen::Vector3f> outline;
};

/// The longest arrow drawn in a view of `cloud`: a fifth of the distance from the sensor to
/// the centre of the scene (its median point), so that a floor's or a wall's arrow does not
/// hide the room. 0 for a cloud without finite points.
float longestArrow(const pcl::PointCloud<pcl::PointXYZ>& cloud);

/// Where the arrow of `plane` ends: from its centroid along its normal, as long as the plane's
/// size, at most `longest_arrow`.
Eigen::Vector3f arrowTip(const PlaneMarker& plane, float longest_arrow);

/// A segmented organized cloud, ready to draw.
struct PlaneScene {
  /// The organized cloud (non-finite points are holes, not drawn). The points are in the
  /// frame of sensor_origin_, as the segmentation takes them; sensor_orientation_ is ignored
  /// as the segmentation ignores it: the grid's rows and columns are the view.
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr cloud;
  /// Per point: the label whose floodplane::io::labelColor the point gets; 0 for no plane,
  /// drawn grey. Same size as `cloud`.
  std::vector<std::uint32_t> colour_labels;
  std::vector<PlaneMarker> planes;
  /// Whether to write "<id>: <inliers>" beside each arrow (pcd_compare's panels, whose ids
  /// are arbitrary, leave it out).
  bool show_plane_text = true;
};

/// The markers of labelled points without plane models (pcd_compare's methods give labels
/// only): for each label > 0 with at least `min_points` finite points, its centroid, the
/// normal of its least-squares plane turned towards the sensor origin, its size, its inlier
/// count; id = the label, colour_label = the colour label most of its points have. No outline.
/// Throws std::invalid_argument if `labels` or `colour_labels` does not match the cloud's size.
std::vector<PlaneMarker> planeMarkersFromLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                const std::vector<std::uint32_t>& labels,
                                                const std::vector<std::uint32_t>& colour_labels,
                                                std::size_t min_points);

/// A perspective camera as VTK defines one: a vertical view angle and square pixels, the
/// principal point in the image's centre.
struct Camera {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Vector3d focal_point = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d view_up = -Eigen::Vector3d::UnitY();
  double view_angle_deg = 45.0;  ///< vertical field of view [degrees]
};

/// Where a view looks from.
enum class CameraView {
  sensor,  ///< from the sensor, as the label image: planes facing the sensor look flat
  oblique  ///< from above and to the right of the sensor, so that the planes' tilt shows
};

/// Parses "sensor" or "oblique"; std::nullopt for anything else.
std::optional<CameraView> parseCameraView(const std::string& name);

/// The camera of `view` for `scene`, a function of the cloud alone (deterministic):
/// - sensor: at sensor_origin_ looking along +z with -y up (the image's rows go down), with
///   the vertical field of view of the grid's rows, measured from the points (y / z against
///   the row, least squares);
/// - oblique: the sensor camera turned about the centre of the scene (the median point) by
///   20 degrees to the right and 15 degrees up, then moved back or forth and sideways until
///   the scene (but its outermost 2 % of points on each side) fills 90 % of an image of
///   `aspect` (width / height) and is centred in it.
/// Throws std::invalid_argument if the cloud has fewer than two rows with finite points.
Camera sceneCamera(const PlaneScene& scene, CameraView view, double aspect = 4.0 / 3.0);

/// The pixel (column, row; 0, 0 is the top-left pixel's centre) where `camera` sees `point`
/// in an image `width` x `height`; std::nullopt for points behind the camera.
std::optional<Eigen::Vector2d> projectToPixel(const Camera& camera, const Eigen::Vector3d& point, int width,
                                              int height);

}  // namespace floodplane::view
