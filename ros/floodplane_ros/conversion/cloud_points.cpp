// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "cloud_points.h"

#include <cmath>
#include <cstring>
#include <stdexcept>

#include "byte_order.h"

namespace floodplane::conversion {
namespace {

// A message's sizes are untrusted: every product is taken in 64 bits, where 32-bit factors
// cannot overflow.
std::uint64_t product(std::uint64_t a, std::uint64_t b) { return a * b; }

std::string bytes(std::uint64_t n) { return std::to_string(n) + " bytes"; }

std::size_t fieldSize(std::uint8_t datatype) {
  switch (static_cast<FieldType>(datatype)) {
    case FieldType::int8:
    case FieldType::uint8:
      return 1;
    case FieldType::int16:
    case FieldType::uint16:
      return 2;
    case FieldType::int32:
    case FieldType::uint32:
    case FieldType::float32:
      return 4;
    case FieldType::float64:
      return 8;
  }
  return 0;
}

// The field a coordinate is read from, checked against the point record.
const PointField& coordinateField(const CloudView& cloud, const char* name) {
  const PointField* found = nullptr;
  for (const PointField& field : cloud.fields) {
    if (field.name == name) found = &field;
  }
  if (found == nullptr) throw std::invalid_argument(std::string("the cloud has no ") + name + " field");
  const auto type = static_cast<FieldType>(found->datatype);
  if (type != FieldType::float32 && type != FieldType::float64) {
    throw std::invalid_argument(std::string("field ") + name + " has datatype " + std::to_string(found->datatype) +
                                "; floodplane reads float32 (7) or float64 (8)");
  }
  if (found->count < 1) throw std::invalid_argument(std::string("field ") + name + " has count 0");
  if (std::uint64_t{found->offset} + fieldSize(found->datatype) > cloud.point_step) {
    throw std::invalid_argument(std::string("field ") + name + " at offset " + std::to_string(found->offset) +
                                " does not fit in point_step " + std::to_string(cloud.point_step));
  }
  return *found;
}

float readCoordinate(const std::uint8_t* point, const PointField& field) {
  if (static_cast<FieldType>(field.datatype) == FieldType::float32) {
    float value;
    std::memcpy(&value, point + field.offset, sizeof value);
    return value;
  }
  double value;
  std::memcpy(&value, point + field.offset, sizeof value);
  return static_cast<float>(value);
}

}  // namespace

CloudPoints readCloudPoints(const CloudView& cloud) {
  // A cloud without points is a frame without points (no planes), whatever its height says;
  // one row of points is how ROS marks an unorganized cloud.
  const bool no_points = cloud.width == 0 || cloud.height == 0;
  if (cloud.height == 1 && !no_points) {
    throw std::invalid_argument("the cloud is not organized (height 1, width " + std::to_string(cloud.width) +
                                "): floodplane needs the points on the sensor's image grid");
  }
  if (cloud.is_bigendian != hostIsBigEndian()) {
    throw std::invalid_argument(std::string("the cloud is ") + (cloud.is_bigendian ? "big" : "little") +
                                "-endian, this machine is not");
  }
  if (cloud.point_step == 0) throw std::invalid_argument("the cloud's point_step is 0");
  const std::uint64_t row_bytes = product(cloud.width, cloud.point_step);
  if (cloud.row_step < row_bytes) {
    throw std::invalid_argument("row_step " + std::to_string(cloud.row_step) + " is less than width x point_step (" +
                                bytes(row_bytes) + ")");
  }
  const std::uint64_t needed = product(cloud.row_step, cloud.height);
  if ((cloud.data == nullptr ? 0 : cloud.data_size) < needed) {
    throw std::invalid_argument("the cloud's data holds " + bytes(cloud.data == nullptr ? 0 : cloud.data_size) +
                                ", row_step x height is " + bytes(needed));
  }
  const PointField& x = coordinateField(cloud, "x");
  const PointField& y = coordinateField(cloud, "y");
  const PointField& z = coordinateField(cloud, "z");

  CloudPoints points;
  points.grid_.width = static_cast<int>(cloud.width);
  points.grid_.height = static_cast<int>(cloud.height);
  if (no_points) return points;
  const auto f32 = static_cast<std::uint8_t>(FieldType::float32);
  const bool in_place = x.datatype == f32 && y.datatype == f32 && z.datatype == f32 && y.offset == x.offset + 4 &&
                        z.offset == x.offset + 8 && x.offset % 4 == 0 && cloud.point_step % 4 == 0 &&
                        cloud.row_step == row_bytes && reinterpret_cast<std::uintptr_t>(cloud.data) % 4 == 0;
  if (in_place) {
    // The layout the library reads without a copy (PointGrid: x y z every `stride` floats).
    points.grid_.data = reinterpret_cast<const float*>(cloud.data + x.offset);
    points.grid_.stride = cloud.point_step / 4;
    return points;
  }
  points.buffer_.resize(3 * points.grid_.size());
  float* out = points.buffer_.data();
  for (std::uint32_t row = 0; row < cloud.height; ++row) {
    const std::uint8_t* point = cloud.data + product(row, cloud.row_step);
    for (std::uint32_t column = 0; column < cloud.width; ++column, point += cloud.point_step, out += 3) {
      out[0] = readCoordinate(point, x);
      out[1] = readCoordinate(point, y);
      out[2] = readCoordinate(point, z);
    }
  }
  points.grid_.data = points.buffer_.data();
  points.grid_.stride = 3;
  return points;
}

bool hasFinitePoint(const PointGrid& grid) {
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (grid.isFinite(i)) return true;
  }
  return false;
}

}  // namespace floodplane::conversion
