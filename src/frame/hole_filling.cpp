// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "frame/hole_filling.h"

#include <algorithm>
#include <cmath>

#include "util/vec3.h"

namespace floodplane {

namespace {

// Neighbouring pixels on a surface seen at up to 75 degrees from its normal are up to
// 1 / cos(75 deg) = 3.9 footprints apart.
constexpr double kMaxObliquity = 4.0;
// Frames with fewer bridgeable holes than this share of their pixels are left as they are.
constexpr double kSmallestShare = 0.02;
// Rows sampled to decide.
constexpr int kSampledRowStep = 8;

bool finitePoint(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// Whether measured points a and b, `pixels` apart in a row or column, are 3-D neighbours
// across the gap: no further apart than that many pixels of a steep surface, plus the noise.
bool bridgeable(const Vec3& a, const Vec3& b, int pixels, const Tolerances& tolerances) {
  const double range_sq = std::min(a.squaredNorm(), b.squaredNorm());
  const double reach = pixels * kMaxObliquity * tolerances.footprint(std::sqrt(range_sq)) +
                       noiseDeviations(tolerances.noise(), kDifferenceDeviations, range_sq);
  return static_cast<double>((a - b).squaredNorm()) <= reach * reach;
}

}  // namespace

double HoleFilling::bridgeableShare(const PointGrid& grid, const Tolerances& tolerances) const {
  std::size_t sampled = 0, holes = 0;
  for (int y = 0; y < grid.height; y += kSampledRowStep) {
    const std::size_t row = static_cast<std::size_t>(y) * static_cast<std::size_t>(grid.width);
    sampled += static_cast<std::size_t>(grid.width);
    int last_finite = -1;
    for (int x = 0; x < grid.width; ++x) {
      if (!grid.isFinite(row + static_cast<std::size_t>(x))) continue;
      const int gap = x - last_finite - 1;
      if (last_finite >= 0 && gap >= 1 && gap <= kMaxGap &&
          bridgeable(Vec3::load(grid.point(row + static_cast<std::size_t>(last_finite))),
                     Vec3::load(grid.point(row + static_cast<std::size_t>(x))), gap + 1, tolerances))
        holes += static_cast<std::size_t>(gap);
      last_finite = x;
    }
  }
  return sampled ? static_cast<double>(holes) / static_cast<double>(sampled) : 0.0;
}

void HoleFilling::fillLine(std::size_t first, std::ptrdiff_t step, int count, const Tolerances& tolerances) {
  const auto at = [&](int k) {
    return &points_[4 * static_cast<std::size_t>(static_cast<std::ptrdiff_t>(first) + k * step)];
  };
  int last_finite = -1;
  for (int k = 0; k < count; ++k) {
    if (!finitePoint(at(k))) continue;
    const int gap = k - last_finite - 1;
    if (last_finite >= 0 && gap >= 1 && gap <= kMaxGap) {
      const Vec3 a = Vec3::load(at(last_finite)), b = Vec3::load(at(k));
      if (bridgeable(a, b, gap + 1, tolerances)) {
        for (int m = 1; m <= gap; ++m) {
          const Vec3 p = a + (b - a) * (static_cast<float>(m) / static_cast<float>(gap + 1));
          float* out = at(last_finite + m);
          out[0] = p.x;
          out[1] = p.y;
          out[2] = p.z;
          out[3] = 1.f;
        }
      }
    }
    last_finite = k;
  }
}

const PointGrid& HoleFilling::fill(const PointGrid& grid, const Tolerances& tolerances) {
  source_ = grid;
  filled_ = bridgeableShare(grid, tolerances) >= kSmallestShare;
  if (!filled_) return source_;
  const std::size_t n = grid.size();
  points_.resize(4 * n);
  for (std::size_t i = 0; i < n; ++i) {
    Vec3::load(grid.point(i)).storePadded(&points_[4 * i]);
  }
  const std::size_t width = static_cast<std::size_t>(grid.width);
  for (int y = 0; y < grid.height; ++y) fillLine(static_cast<std::size_t>(y) * width, 1, grid.width, tolerances);
  for (int x = 0; x < grid.width; ++x)
    fillLine(static_cast<std::size_t>(x), static_cast<std::ptrdiff_t>(width), grid.height, tolerances);
  filled_grid_ = grid;
  filled_grid_.data = points_.data();
  filled_grid_.stride = 4;
  return filled_grid_;
}

}  // namespace floodplane
