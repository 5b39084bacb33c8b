// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "camera_poses.h"

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "floodplane/plane_tracker.h"

namespace pcd_segment {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& message) {
  throw std::runtime_error(path + ": " + message);
}

// The tracker's own rule for a motion (finite, orthonormal rotation of determinant 1, last row
// 0 0 0 1), checked the way FloodFillPlaneSegmentation::setCameraMotion checks it.
bool isFiniteRigid(const Eigen::Matrix4d& matrix) {
  try {
    floodplane::PlaneTracker().update(floodplane::Segmentation(), matrix);
  } catch (const std::invalid_argument&) {
    return false;
  }
  return true;
}

Eigen::Matrix4d poseMatrix(const Json& entry, const std::string& path, const std::string& name) {
  if (!entry.is_object() || !entry.contains("world_from_camera")) fail(path, name + " has no \"world_from_camera\"");
  const Json& rows = entry["world_from_camera"];
  const std::string where = name + ".world_from_camera";
  if (!rows.is_array() || rows.size() != 4) fail(path, where + " is not 4 rows of 4 numbers");
  Eigen::Matrix4d matrix;
  for (int row = 0; row < 4; ++row) {
    const Json& values = rows[static_cast<std::size_t>(row)];
    if (!values.is_array() || values.size() != 4) fail(path, where + " is not 4 rows of 4 numbers");
    for (int column = 0; column < 4; ++column) {
      const Json& value = values[static_cast<std::size_t>(column)];
      if (!value.is_number()) fail(path, where + " is not 4 rows of 4 numbers");
      matrix(row, column) = value.get<double>();
    }
  }
  if (!isFiniteRigid(matrix)) {
    fail(path, where +
                   " is not a finite rigid transform (orthonormal rotation with determinant 1, last row 0 0 0 1, "
                   "within 1e-6)");
  }
  return matrix;
}

}  // namespace

std::vector<Eigen::Matrix4d> readCameraPoses(const std::string& path) {
  std::error_code error_code;
  if (std::filesystem::is_directory(path, error_code)) fail(path, "is a directory, not a poses file");
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot read the file: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "cannot read the file");
  Json document;
  try {
    document = Json::parse(text.str());
  } catch (const Json::exception& error) {
    // A syntax error, or a number beyond a double. nlohmann's message starts with its own tag,
    // "[json.exception.parse_error.101] parse error at line 1, ...": left out here.
    const std::string what = error.what();
    const std::size_t start = what.find("] ");
    fail(path, "cannot be parsed as JSON: " + (start == std::string::npos ? what : what.substr(start + 2)));
  }
  if (!document.is_object() || !document.contains("poses") || !document["poses"].is_array()) {
    fail(path, "has no \"poses\" array");
  }
  std::vector<Eigen::Matrix4d> poses;
  const Json& entries = document["poses"];
  for (std::size_t k = 0; k < entries.size(); ++k) {
    poses.push_back(poseMatrix(entries[k], path, "poses[" + std::to_string(k) + "]"));
  }
  return poses;
}

Eigen::Matrix4d cameraMotion(const Eigen::Matrix4d& from, const Eigen::Matrix4d& to) {
  const Eigen::Matrix3d from_rotation = from.topLeftCorner<3, 3>();
  const Eigen::Matrix3d rotation = from_rotation.transpose() * to.topLeftCorner<3, 3>();
  Eigen::Matrix4d motion = Eigen::Matrix4d::Identity();
  motion.topLeftCorner<3, 3>() = Eigen::Quaterniond(rotation).normalized().toRotationMatrix();
  motion.topRightCorner<3, 1>() = from_rotation.transpose() * (to.topRightCorner<3, 1>() - from.topRightCorner<3, 1>());
  return motion;
}

CameraMotions::CameraMotions(std::vector<Eigen::Matrix4d> world_from_camera) : poses_(std::move(world_from_camera)) {}

std::optional<Eigen::Matrix4d> CameraMotions::motionTo(std::size_t k) const {
  const Eigen::Matrix4d& to = poses_.at(k);
  if (!last_taken_) return std::nullopt;
  return cameraMotion(poses_.at(*last_taken_), to);
}

void CameraMotions::taken(std::size_t k) { last_taken_ = k; }

}  // namespace pcd_segment
