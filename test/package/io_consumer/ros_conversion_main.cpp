// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Back-projects a 2x1 depth image with the installed conversions (floodplane::ros_conversion,
// on floodplane::io's depth camera), as the ROS node does.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#include "depth_image.h"

int main() {
  const std::uint16_t depth[2] = {1000, 0};  // 1 m, no return
  floodplane::conversion::ImageView image;
  image.width = 2;
  image.height = 1;
  image.encoding = "16UC1";
  image.step = 4;
  image.data = reinterpret_cast<const std::uint8_t*>(depth);
  image.data_size = sizeof(depth);
  floodplane::conversion::CameraInfoView info;
  info.k = {500.0, 0.0, 0.0, 0.0, 500.0, 0.0, 0.0, 0.0, 1.0};
  std::vector<float> xyz;
  floodplane::conversion::backProjectDepthImage(image, info, xyz);
  if (xyz.size() != 6 || xyz[2] != 1.0f || !std::isnan(xyz[5])) {
    std::fprintf(stderr, "ros_conversion_consumer: the depth image did not back-project as expected\n");
    return 1;
  }
  std::printf("ros_conversion_consumer: a depth image back-projected with floodplane::ros_conversion\n");
  return 0;
}
