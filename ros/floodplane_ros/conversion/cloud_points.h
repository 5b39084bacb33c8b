// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The points of an organized sensor_msgs/PointCloud2, as the library reads them, without ROS
// types: the message's layout is described by plain structs that ROS 1 and ROS 2 messages map
// onto field for field, so a node of either only copies a few numbers and a pointer.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "floodplane/point_grid.h"

namespace floodplane::conversion {

/// sensor_msgs/PointField's datatype codes (the same in ROS 1 and ROS 2).
enum class FieldType : std::uint8_t {
  int8 = 1,
  uint8 = 2,
  int16 = 3,
  uint16 = 4,
  int32 = 5,
  uint32 = 6,
  float32 = 7,
  float64 = 8
};

/// One field of a point record (sensor_msgs/PointField).
struct PointField {
  std::string name;
  std::uint32_t offset = 0;   ///< bytes from the start of the point record
  std::uint8_t datatype = 0;  ///< a FieldType code
  std::uint32_t count = 1;    ///< elements in the field
};

/// A sensor_msgs/PointCloud2 without its header, its data in place (not owned).
struct CloudView {
  std::uint32_t width = 0;
  std::uint32_t height = 0;  ///< 1 for an unorganized cloud
  std::vector<PointField> fields;
  bool is_bigendian = false;
  std::uint32_t point_step = 0;  ///< bytes from one point to the next
  std::uint32_t row_step = 0;    ///< bytes from one row to the next
  const std::uint8_t* data = nullptr;
  std::size_t data_size = 0;  ///< bytes at `data`
};

/// The x y z of an organized cloud as a PointGrid: in the message's own memory when x y z are
/// three consecutive float32 on 4-byte boundaries and the rows follow each other without
/// padding (PCL's point types, depth_image_proc's clouds), otherwise copied into a buffer of
/// its own. Valid while the message's data and this object live.
class CloudPoints {
 public:
  const PointGrid& grid() const { return grid_; }
  /// Whether the points were copied (false: the grid reads the message's data).
  bool copied() const { return !buffer_.empty(); }

 private:
  friend CloudPoints readCloudPoints(const CloudView& cloud);
  PointGrid grid_;
  std::vector<float> buffer_;
};

/// Reads the points of `cloud`. Throws std::invalid_argument with a one-line reason when the
/// cloud is not organized (height 1), lacks a float32 or float64 x, y or z field, is
/// big-endian, or when its steps, fields and data size do not fit together. Non-finite
/// coordinates are holes, as in the library. A cloud without points (width or height 0) gives
/// a grid of that size without points: a frame with no planes.
CloudPoints readCloudPoints(const CloudView& cloud);

/// Whether any point of `grid` has finite x, y and z (stops at the first).
bool hasFinitePoint(const PointGrid& grid);

}  // namespace floodplane::conversion
