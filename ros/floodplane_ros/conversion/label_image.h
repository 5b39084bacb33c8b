// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The label image a node publishes, without ROS types: each pixel's plane label on the input's
// grid, as a sensor_msgs/Image of encoding 32SC1 (0: no plane).
//
// 32SC1 rather than 16UC1: the labels are track ids when tracking, which count up without
// bound over a stream (a 16-bit pixel would wrap after 65535 tracks; a 32-bit one after 2^31),
// and 32SC1 is OpenCV's label type (CV_32S: cv::connectedComponents, watershed markers), which
// cv_bridge hands over as it is.

#include <cstdint>
#include <vector>

namespace floodplane::conversion {

inline constexpr const char* kLabelImageEncoding = "32SC1";
inline constexpr std::uint32_t kLabelImageBytesPerPixel = 4;

/// Whether writeLabelImage writes big-endian pixels (it writes this machine's byte order): the
/// message's is_bigendian.
bool labelImageIsBigEndian();

/// Writes labels.size() pixels of kLabelImageBytesPerPixel bytes each to `out`, row-major, in
/// this machine's byte order: for labels[i] = k > 0 the published label plane_labels[k - 1],
/// for k = 0 the value 0. `labels` is a Segmentation's label image, `plane_labels` the
/// published label of each of its planes (1..K, or track ids). Throws std::invalid_argument
/// when labels names a plane plane_labels lacks, or a published label does not fit an int32.
void writeLabelImage(const std::vector<std::uint32_t>& labels, const std::vector<std::uint32_t>& plane_labels,
                     std::uint8_t* out);

}  // namespace floodplane::conversion
