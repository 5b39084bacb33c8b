// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/depth_warp.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "synth/random_source.h"

namespace floodplane::synth {
namespace {

// The warp's draws: a stream of the seed that neither the scene generators (streams 1 and 2)
// nor any pixel's noise (its row-major index) uses.
constexpr std::uint64_t kWarpStream = 0x7761727000000000ULL;  // "warp"

}  // namespace

DepthWarp::DepthWarp(const DepthWarpParams& params, const CameraIntrinsics& intrinsics) : intrinsics_(intrinsics) {
  if (!(params.amplitude >= 0.0) || !std::isfinite(params.amplitude)) {
    throw std::invalid_argument("DepthWarp: the amplitude must be a finite number >= 0, not " +
                                std::to_string(params.amplitude));
  }
  if (params.amplitude == 0.0) return;
  RandomSource random(params.seed, kWarpStream);
  bowl_ = random.uniform(0.6, 1.0);
  if (random.chance(0.5)) bowl_ = -bowl_;
  saddle_ = random.uniform(-0.3, 0.3);
  twist_ = random.uniform(-0.3, 0.3);
  tilt_x_ = random.uniform(-0.3, 0.3);
  tilt_y_ = random.uniform(-0.3, 0.3);

  // The farthest pixel centre from the principal point is one of the four corners.
  double corner_tangent = 0.0;
  for (const int u : {0, intrinsics.width - 1}) {
    for (const int v : {0, intrinsics.height - 1}) {
      const Eigen::Vector3d ray = intrinsics.rayThroughPixel(u, v);
      corner_tangent = std::max(corner_tangent, ray.head<2>().norm());
    }
  }
  inverse_corner_tangent_ = corner_tangent > 0.0 ? 1.0 / corner_tangent : 1.0;

  // m and p over the pixels themselves, so that mean 0 and peak A hold exactly.
  double sum = 0.0;
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) sum += shape(u, v);
  }
  mean_ = sum / (static_cast<double>(intrinsics.width) * static_cast<double>(intrinsics.height));
  double peak = 0.0;
  for (int v = 0; v < intrinsics.height; ++v) {
    for (int u = 0; u < intrinsics.width; ++u) peak = std::max(peak, std::abs(shape(u, v) - mean_));
  }
  // A one-pixel image has no shape to bend: it stays unwarped.
  scale_ = peak > 0.0 ? params.amplitude / peak : 0.0;
}

double DepthWarp::shape(int u, int v) const {
  const Eigen::Vector3d ray = intrinsics_.rayThroughPixel(u, v);
  const double x = ray.x() * inverse_corner_tangent_;
  const double y = ray.y() * inverse_corner_tangent_;
  return bowl_ * (x * x + y * y) + saddle_ * (x * x - y * y) + twist_ * x * y + tilt_x_ * x + tilt_y_ * y;
}

double DepthWarp::at(int u, int v) const { return scale_ == 0.0 ? 0.0 : scale_ * (shape(u, v) - mean_); }

}  // namespace floodplane::synth
