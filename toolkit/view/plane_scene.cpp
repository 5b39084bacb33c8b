// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "view/plane_scene.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "floodplane/io/label_palette.h"

namespace floodplane::view {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kObliqueRightDeg = 20.0;
constexpr double kObliqueUpDeg = 15.0;
constexpr double kFramedShare = 0.9;      // of the image's height or width that the scene fills
constexpr double kFramedQuantile = 0.02;  // the outermost points left out of the frame, per side
constexpr std::size_t kFramingSamples = 20000;
constexpr int kFramingRounds = 4;
constexpr float kLongestArrowShare = 0.2f;

// Running sums of one label's points, in double: a wall has 10^5 points.
struct PointSums {
  std::size_t count = 0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d sum_outer = Eigen::Matrix3d::Zero();
  std::map<std::uint32_t, std::size_t> colour_votes;
};

bool isFinite(const pcl::PointXYZ& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

PlaneMarker markerOf(std::uint32_t label, const PointSums& sums, const Eigen::Vector3d& origin) {
  const double n = static_cast<double>(sums.count);
  const Eigen::Vector3d centroid = sums.sum / n;
  const Eigen::Matrix3d covariance = sums.sum_outer / n - centroid * centroid.transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  Eigen::Vector3d normal = solver.eigenvectors().col(0);  // smallest eigenvalue first
  if (normal.dot(origin - centroid) < 0.0) normal = -normal;
  PlaneMarker marker;
  marker.id = label;
  marker.colour_label = std::max_element(sums.colour_votes.begin(), sums.colour_votes.end(), [](auto& a, auto& b) {
                          return a.second < b.second;
                        })->first;
  marker.centroid = centroid.cast<float>();
  marker.normal = normal.cast<float>();
  marker.size = static_cast<float>(std::sqrt(std::max(0.0, covariance.trace())));
  marker.inliers = sums.count;
  return marker;
}

// The vertical field of view of the grid's rows: for a pinhole camera y / z = (row - c) / f,
// so a least-squares line through (row, y / z) of every finite point gives 1 / f as its slope.
// Returns the view angle [degrees] and the sign of the slope (+1: rows go down, along +y).
std::pair<double, double> rowFieldOfView(const pcl::PointCloud<pcl::PointXYZ>& cloud, const Eigen::Vector3f& origin) {
  double n = 0, sum_row = 0, sum_slope = 0, sum_row_row = 0, sum_row_slope = 0;
  for (std::size_t row = 0; row < cloud.height; ++row) {
    for (std::size_t column = 0; column < cloud.width; ++column) {
      const pcl::PointXYZ& p = cloud.at(static_cast<int>(column), static_cast<int>(row));
      const double depth = static_cast<double>(p.z - origin.z());
      if (!isFinite(p) || depth <= 0.0) continue;
      const double v = static_cast<double>(row);
      const double slope = static_cast<double>(p.y - origin.y()) / depth;
      n += 1.0;
      sum_row += v;
      sum_slope += slope;
      sum_row_row += v * v;
      sum_row_slope += v * slope;
    }
  }
  const double row_variance = n * sum_row_row - sum_row * sum_row;
  if (n < 2.0 || row_variance <= 0.0) {
    throw std::invalid_argument("the cloud has no two rows of finite points in front of the sensor to set a camera");
  }
  const double inverse_focal = (n * sum_row_slope - sum_row * sum_slope) / row_variance;
  if (!(std::abs(inverse_focal) > 0.0) || !std::isfinite(inverse_focal)) {
    throw std::invalid_argument("the cloud's rows do not look like a camera's: y / z does not change with the row");
  }
  const double half_height = 0.5 * static_cast<double>(cloud.height) * std::abs(inverse_focal);
  return {2.0 * std::atan(half_height) * 180.0 / kPi, inverse_focal > 0.0 ? 1.0 : -1.0};
}

// The coordinate-wise median of the finite points: the centre of what the sensor sees, which
// a few far points (a window, a corridor) do not drag away as they would the mean.
Eigen::Vector3d medianPoint(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  std::vector<float> coordinates[3];
  for (std::vector<float>& values : coordinates) values.reserve(cloud.size());
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!isFinite(p)) continue;
    coordinates[0].push_back(p.x);
    coordinates[1].push_back(p.y);
    coordinates[2].push_back(p.z);
  }
  if (coordinates[0].empty()) return cloud.sensor_origin_.head<3>().cast<double>();
  Eigen::Vector3d median;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<float>& values = coordinates[axis];
    const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    median[axis] = static_cast<double>(*middle);
  }
  return median;
}

double quantile(std::vector<double>& values, double fraction) {
  const auto at = values.begin() + static_cast<std::ptrdiff_t>(fraction * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), at, values.end());
  return *at;
}

// Moves `camera` sideways and along its view direction, keeping the direction, until the
// scene fills kFramedShare of an image of `aspect` (width / height) and sits in its middle.
// The outermost points (kFramedQuantile on each side) are left out of the frame, so that a
// few far points (a window, a corridor) do not shrink the rest. A perspective view has no
// closed form for this; each round corrects the last, and four agree to a pixel.
Camera framed(Camera camera, const pcl::PointCloud<pcl::PointXYZ>& cloud, double aspect) {
  const std::size_t stride = std::max<std::size_t>(1, cloud.size() / kFramingSamples);
  const double tan_half_height = std::tan(0.5 * camera.view_angle_deg * kPi / 180.0) * kFramedShare;
  const double tan_half_width = tan_half_height * aspect;
  for (int round = 0; round < kFramingRounds; ++round) {
    const Eigen::Vector3d forward = (camera.focal_point - camera.position).normalized();
    const Eigen::Vector3d up = (camera.view_up - camera.view_up.dot(forward) * forward).normalized();
    const Eigen::Vector3d right = forward.cross(up);
    std::vector<double> xs, ys, depths;
    std::size_t behind = 0;
    for (std::size_t i = 0; i < cloud.size(); i += stride) {
      if (!isFinite(cloud[i])) continue;
      const Eigen::Vector3d offset = cloud[i].getVector3fMap().cast<double>() - camera.position;
      const double depth = offset.dot(forward);
      if (depth <= 1e-6) {
        ++behind;
        continue;
      }
      xs.push_back(offset.dot(right) / depth);
      ys.push_back(offset.dot(up) / depth);
      depths.push_back(depth);
    }
    if (depths.size() < 2) return camera;
    const double x_low = quantile(xs, kFramedQuantile), x_high = quantile(xs, 1.0 - kFramedQuantile);
    const double y_low = quantile(ys, kFramedQuantile), y_high = quantile(ys, 1.0 - kFramedQuantile);
    const double near = quantile(depths, kFramedQuantile);
    const double middle = quantile(depths, 0.5);
    const Eigen::Vector3d sideways = middle * (0.5 * (x_low + x_high) * right + 0.5 * (y_low + y_high) * up);
    // Seen from `back` further away, extents shrink about as middle / (middle + back).
    const double scale =
        std::max((x_high - x_low) / (2.0 * tan_half_width), (y_high - y_low) / (2.0 * tan_half_height));
    double back = middle * (scale - 1.0);
    if (static_cast<double>(behind) > kFramedQuantile * static_cast<double>(depths.size())) {
      back = std::max(back, 0.5 * middle);
    }
    back = std::max(back, -(near - 0.2 * middle));  // never up to the nearest points
    camera.position += sideways - back * forward;
    camera.focal_point += sideways;
  }
  return camera;
}

Camera obliqueCamera(const Camera& sensor, const Eigen::Vector3d& centre) {
  const Eigen::Vector3d forward = (sensor.focal_point - sensor.position).normalized();
  const Eigen::Vector3d up = sensor.view_up.normalized();
  const Eigen::Vector3d right = forward.cross(up);
  // The camera's offset from the centre points backwards, towards the sensor: turned about
  // the up axis by +angle it swings to the right, about the right axis by -angle upwards.
  const Eigen::AngleAxisd turn_right(kObliqueRightDeg * kPi / 180.0, up);
  const Eigen::Vector3d right_after_turn = turn_right * right;
  const Eigen::AngleAxisd turn_up(-kObliqueUpDeg * kPi / 180.0, right_after_turn);
  const Eigen::Matrix3d rotation = (turn_up * turn_right).toRotationMatrix();
  Camera camera = sensor;
  camera.position = centre + rotation * (sensor.position - centre);
  camera.focal_point = centre;
  camera.view_up = rotation * up;
  return camera;
}

}  // namespace

std::array<std::uint8_t, 3> pointColour(std::uint32_t label) {
  return label == 0 ? kUnlabelledColour : floodplane::io::labelColor(label);
}

std::vector<PlaneMarker> planeMarkersFromLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                const std::vector<std::uint32_t>& labels,
                                                const std::vector<std::uint32_t>& colour_labels,
                                                std::size_t min_points) {
  if (labels.size() != cloud.size() || colour_labels.size() != cloud.size()) {
    throw std::invalid_argument("planeMarkersFromLabels: " + std::to_string(labels.size()) + " labels and " +
                                std::to_string(colour_labels.size()) + " colour labels for " +
                                std::to_string(cloud.size()) + " points");
  }
  std::map<std::uint32_t, PointSums> sums_of;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (labels[i] == 0 || !isFinite(cloud[i])) continue;
    const Eigen::Vector3d p = cloud[i].getVector3fMap().cast<double>();
    PointSums& sums = sums_of[labels[i]];
    ++sums.count;
    sums.sum += p;
    sums.sum_outer += p * p.transpose();
    ++sums.colour_votes[colour_labels[i]];
  }
  const Eigen::Vector3d origin = cloud.sensor_origin_.head<3>().cast<double>();
  std::vector<PlaneMarker> markers;
  for (const auto& [label, sums] : sums_of) {
    if (sums.count >= std::max<std::size_t>(min_points, 3)) markers.push_back(markerOf(label, sums, origin));
  }
  return markers;
}

std::optional<CameraView> parseCameraView(const std::string& name) {
  if (name == "sensor") return CameraView::sensor;
  if (name == "oblique") return CameraView::oblique;
  return std::nullopt;
}

float longestArrow(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  const Eigen::Vector3d origin = cloud.sensor_origin_.head<3>().cast<double>();
  return kLongestArrowShare * static_cast<float>((medianPoint(cloud) - origin).norm());
}

Eigen::Vector3f arrowTip(const PlaneMarker& plane, float longest_arrow) {
  return plane.centroid + std::min(plane.size, longest_arrow) * plane.normal;
}

Camera sceneCamera(const PlaneScene& scene, CameraView view, double aspect) {
  if (!scene.cloud) throw std::invalid_argument("sceneCamera: no cloud");
  const Eigen::Vector3f origin = scene.cloud->sensor_origin_.head<3>();
  const auto [view_angle_deg, rows_down] = rowFieldOfView(*scene.cloud, origin);
  Camera sensor;
  sensor.position = origin.cast<double>();
  sensor.focal_point = sensor.position + Eigen::Vector3d::UnitZ();
  sensor.view_up = -rows_down * Eigen::Vector3d::UnitY();
  sensor.view_angle_deg = view_angle_deg;
  if (view == CameraView::sensor) return sensor;
  return framed(obliqueCamera(sensor, medianPoint(*scene.cloud)), *scene.cloud, aspect);
}

std::optional<Eigen::Vector2d> projectToPixel(const Camera& camera, const Eigen::Vector3d& point, int width,
                                              int height) {
  const Eigen::Vector3d forward = (camera.focal_point - camera.position).normalized();
  const Eigen::Vector3d up = (camera.view_up - camera.view_up.dot(forward) * forward).normalized();
  const Eigen::Vector3d right = forward.cross(up);
  const Eigen::Vector3d offset = point - camera.position;
  const double depth = offset.dot(forward);
  if (depth <= 0.0) return std::nullopt;
  const double half_height = depth * std::tan(0.5 * camera.view_angle_deg * kPi / 180.0);
  const double aspect = static_cast<double>(width) / static_cast<double>(height);
  const double x = offset.dot(right) / (half_height * aspect);  // -1 .. 1 across the image
  const double y = offset.dot(up) / half_height;                // -1 .. 1 from bottom to top
  return Eigen::Vector2d(0.5 * (x + 1.0) * width - 0.5, 0.5 * (1.0 - y) * height - 0.5);
}

}  // namespace floodplane::view
