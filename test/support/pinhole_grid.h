// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The organized grid the core's stage tests build their scenes on: width x height points
// (three or four floats a point) seen through a pinhole of kPinholeFocal pixels, pixel (u, v)
// at depth(u, v) along its ray (2 cm between neighbours at 2 m); a NaN depth is a hole.

#include <cstddef>
#include <functional>
#include <vector>

#include "floodplane/point_grid.h"
#include "util/vec3.h"

namespace floodplane::test {

constexpr double kPinholeFocal = 100.0;  // pixels

struct PinholeGrid {
  int width = 0;
  int height = 0;
  std::size_t stride = 3;
  std::vector<float> data;

  PinholeGrid(int w, int h, const std::function<double(int, int)>& depth, std::size_t point_stride = 3)
      : width(w),
        height(h),
        stride(point_stride),
        data(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * point_stride, 0.f) {
    for (int v = 0; v < h; ++v) {
      for (int u = 0; u < w; ++u) {
        const double z = depth(u, v);
        float* p = &data[index(u, v) * stride];
        p[0] = static_cast<float>((u - (w - 1) / 2.0) / kPinholeFocal * z);
        p[1] = static_cast<float>((v - (h - 1) / 2.0) / kPinholeFocal * z);
        p[2] = static_cast<float>(z);
      }
    }
  }
  PointGrid grid() const {
    PointGrid g;
    g.data = data.data();
    g.stride = stride;
    g.width = width;
    g.height = height;
    return g;
  }
  std::size_t index(int u, int v) const {
    return static_cast<std::size_t>(v) * static_cast<std::size_t>(width) + static_cast<std::size_t>(u);
  }
  Vec3 point(std::size_t i) const { return Vec3::load(&data[i * stride]); }
  Vec3 point(int u, int v) const { return point(index(u, v)); }
};

}  // namespace floodplane::test
