// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The up direction a node classes its planes by (floodplane::describePlanes), without ROS
// types: from its ~up parameter (the direction in the sensor's frame, as text or as three
// numbers) or from ~target_frame (that frame's +z axis, turned into the sensor's frame).

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "plane_transform.h"

namespace floodplane::conversion {

/// A direction x y z against gravity, in the sensor's frame (the frame of the segmented
/// points): finite, not zero, of any length.
using UpDirection = std::array<double, 3>;

/// ~up given as text: three numbers separated by commas or blanks, within brackets or not
/// ("[0, -1, 0]", "0,-1,0", "0 -1 0"); empty or blank: no up direction (nothing). Throws
/// std::invalid_argument saying what is wrong with anything else: not three numbers, one not
/// finite, all three zero.
std::optional<UpDirection> parseUpDirection(const std::string& text);

/// ~up given as numbers (a YAML list on the parameter server). Throws std::invalid_argument
/// unless there are three, finite and not all zero.
UpDirection upDirection(const std::vector<double>& values);

/// The target frame's +z axis in the source frame, from the source frame's pose in the target
/// frame (as tf2's lookupTransform(target, source, ...) gives it, p_target = R p_source + t):
/// R^T (0 0 1), a unit vector (the rotation normalized first). A robot's base_link or a map
/// frame has z up, so that this is up in the sensor's frame. Throws std::invalid_argument
/// when the rotation is not finite or has no length.
UpDirection targetUpInSource(const RigidTransform& source_in_target);

}  // namespace floodplane::conversion
