// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "floodplane/io/depth_camera.h"

#include <cstdint>

namespace floodplane::io {
namespace {

std::string finite(double value, const char* name) {
  if (std::isfinite(value)) return {};
  return std::string(name) + " must be a finite number of pixels, got " + std::to_string(value);
}

std::string positive(double value, const char* name, const char* unit) {
  if (std::isfinite(value) && value > 0.0) return {};
  return std::string(name) + " must be a finite number of " + unit + " > 0, got " + std::to_string(value);
}

}  // namespace

std::string DepthCamera::problem() const {
  for (std::string problem : {positive(fx, "fx", "pixels"), positive(fy, "fy", "pixels"), finite(cx, "cx"),
                              finite(cy, "cy"), positive(depth_scale, "depth_scale", "units per metre")}) {
    if (!problem.empty()) return problem;
  }
  return {};
}

void backProjectDepth(const std::uint16_t* depth, int width, int height, const DepthCamera& camera, float* xyz) {
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u, ++depth, xyz += 3) backProjectPixel(u, v, *depth, camera, xyz);
  }
}

}  // namespace floodplane::io
