// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// --poses of pcd_segment --track: the camera pose of every input, read from a JSON file (as
// pcd_synth --sequence writes <scene>.poses.json), and the camera motions the tracker takes
// from them. No PCL here.

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pcd_segment {

/// Reads the camera poses of a sequence: a JSON object whose "poses" is an array with one entry
/// per frame, in frame order, each an object whose "world_from_camera" is the frame's camera pose
/// as a 4 x 4 matrix given row by row (a point in the camera's frame to the world frame, metres;
/// other keys are ignored). Throws std::runtime_error, with a one-line message naming the file
/// and the entry, when the file cannot be read or parsed (a number beyond a double included),
/// or a matrix is not 4 x 4 numbers or not a finite rigid transform (the tracker's rule).
std::vector<Eigen::Matrix4d> readCameraPoses(const std::string& path);

/// The motion from the camera at pose `from` to the camera at pose `to`, in `from`'s frame:
/// inverse(from) * to, with its rotation made exactly orthonormal and its last row exactly
/// 0 0 0 1, so that rounding never makes the tracker refuse it.
Eigen::Matrix4d cameraMotion(const Eigen::Matrix4d& from, const Eigen::Matrix4d& to);

/// The motions of a sequence of inputs with one pose each: for input k, the motion from the
/// last input the tracker took (which is input k - 1 unless that one failed) to input k.
class CameraMotions {
 public:
  explicit CameraMotions(std::vector<Eigen::Matrix4d> world_from_camera);
  std::size_t size() const { return poses_.size(); }
  /// The motion to input k; none before the tracker took any input. Throws std::out_of_range
  /// for k >= size().
  std::optional<Eigen::Matrix4d> motionTo(std::size_t k) const;
  /// Notes that the tracker took input k.
  void taken(std::size_t k);

 private:
  std::vector<Eigen::Matrix4d> poses_;
  std::optional<std::size_t> last_taken_;
};

}  // namespace pcd_segment
