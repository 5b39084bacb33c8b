// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the input bytes as a sensor_msgs/PointCloud2 and a depth image with its
// CameraInfo, through the ROS node's conversions (ros/floodplane_ros/conversion): the layout
// comes from the first bytes, the rest is the message's data, in a buffer of exactly its size
// so that ASan sees any read beyond it. A message must be read consistently or rejected with
// std::invalid_argument.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "cloud_points.h"
#include "depth_image.h"
#include "loader_fuzzing.h"

namespace {

using floodplane::fuzz::fail;

// Takes values from the front of the input; 0 once it is used up.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  template <typename T>
  T take() {
    T value{};
    const std::size_t n = sizeof(T) < size_ ? sizeof(T) : size_;
    std::memcpy(&value, data_, n);
    data_ += n;
    size_ -= n;
    return value;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
};

void fuzzCloud(Bytes& bytes, const std::vector<std::uint8_t>& data) {
  floodplane::conversion::CloudView cloud;
  cloud.width = bytes.take<std::uint8_t>();
  cloud.height = bytes.take<std::uint8_t>() % 8;
  cloud.point_step = bytes.take<std::uint8_t>();
  cloud.row_step = cloud.width * cloud.point_step + bytes.take<std::uint8_t>() % 4 - 1;
  cloud.is_bigendian = (bytes.take<std::uint8_t>() & 0x80) != 0;
  const char* names[] = {"x", "y", "z", "rgb"};
  const int fields = bytes.take<std::uint8_t>() % 6;
  for (int i = 0; i < fields; ++i) {
    floodplane::conversion::PointField field;
    field.name = names[bytes.take<std::uint8_t>() % 4];
    field.offset = bytes.take<std::uint8_t>() % 40;
    field.datatype = bytes.take<std::uint8_t>() % 10;
    field.count = bytes.take<std::uint8_t>() % 3;
    cloud.fields.push_back(field);
  }
  cloud.data = data.data();
  cloud.data_size = data.size();
  try {
    const auto points = floodplane::conversion::readCloudPoints(cloud);
    const floodplane::PointGrid& grid = points.grid();
    if (grid.width != static_cast<int>(cloud.width) || grid.height != static_cast<int>(cloud.height)) {
      fail("the grid is not the cloud's size");
    }
    // A cloud without points is an empty frame (the one rule of Python, ROS and the CLI);
    // one row of points is an unorganized cloud, refused.
    if (grid.height == 1 && grid.width > 0) fail("an unorganized cloud was accepted");
    float sum = 0.0f;
    for (std::size_t i = 0; i < grid.size(); ++i) sum += grid.point(i)[0] + grid.point(i)[1] + grid.point(i)[2];
    (void)sum;
  } catch (const std::invalid_argument&) {
  }
}

void fuzzDepth(Bytes& bytes, const std::vector<std::uint8_t>& data) {
  floodplane::conversion::ImageView image;
  image.width = bytes.take<std::uint8_t>();
  image.height = bytes.take<std::uint8_t>();
  const char* encodings[] = {"16UC1", "mono16", "32FC1", "rgb8", ""};
  image.encoding = encodings[bytes.take<std::uint8_t>() % 5];
  image.step = bytes.take<std::uint16_t>() % 1024;
  image.is_bigendian = (bytes.take<std::uint8_t>() & 0x80) != 0;
  floodplane::conversion::CameraInfoView info;
  info.width = bytes.take<std::uint8_t>();
  info.height = bytes.take<std::uint8_t>();
  info.k = {bytes.take<float>(), 0.0, bytes.take<float>(), 0.0, bytes.take<float>(), bytes.take<float>(), 0, 0, 1};
  image.data = data.data();
  image.data_size = data.size();
  std::vector<float> xyz;
  try {
    floodplane::conversion::backProjectDepthImage(image, info, xyz);
  } catch (const std::invalid_argument&) {
    return;
  }
  if (xyz.size() != 3 * std::size_t(image.width) * image.height) fail("the points do not fill the image");
  for (std::size_t i = 2; i < xyz.size(); i += 3) {
    if (!(xyz[i] > 0.0f) && !std::isnan(xyz[i])) fail("a point's depth is neither positive nor no return");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The header's bytes come first; the message data is what follows them, copied to a buffer
  // of its own size.
  Bytes cloud_header(data, size);
  Bytes depth_header(data, size);
  constexpr std::size_t kHeader = 48;
  const std::vector<std::uint8_t> message =
      size > kHeader ? std::vector<std::uint8_t>(data + kHeader, data + size) : std::vector<std::uint8_t>();
  fuzzCloud(cloud_header, message);
  fuzzDepth(depth_header, message);
  return 0;
}
