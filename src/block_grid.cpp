// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "block_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "simd.h"

namespace floodplane {

namespace {

bool finitePoint(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// What one block row's pass needs to know of a block: its pixel columns and rows.
struct Span {
  int u_begin, u_end, v_begin, v_end;
};

// The sum of a block's measured points and their number, pixel by pixel in raster order.
void sumPixelByPixel(const PointGrid& full, const Span& span, float sum[3], std::uint32_t& count) {
  sum[0] = sum[1] = sum[2] = 0.f;
  count = 0;
  for (int v = span.v_begin; v < span.v_end; ++v) {
    const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
    for (int u = span.u_begin; u < span.u_end; ++u) {
      const float* p = full.point(row + static_cast<std::size_t>(u));
      if (!finitePoint(p)) continue;
      sum[0] += p[0];
      sum[1] += p[1];
      sum[2] += p[2];
      ++count;
    }
  }
}

// The scatter of a block's measured points about `mean`, pixel by pixel, into `out` (xx yy zz
// - xy yz zx -).
void scatterPixelByPixel(const PointGrid& full, const Span& span, const float mean[3], float out[8]) {
  float xx = 0.f, yy = 0.f, zz = 0.f, xy = 0.f, yz = 0.f, zx = 0.f;
  for (int v = span.v_begin; v < span.v_end; ++v) {
    const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
    for (int u = span.u_begin; u < span.u_end; ++u) {
      const float* p = full.point(row + static_cast<std::size_t>(u));
      if (!finitePoint(p)) continue;
      const float dx = p[0] - mean[0], dy = p[1] - mean[1], dz = p[2] - mean[2];
      xx += dx * dx;
      yy += dy * dy;
      zz += dz * dz;
      xy += dx * dy;
      yz += dy * dz;
      zx += dz * dx;
    }
  }
  out[0] = xx, out[1] = yy, out[2] = zz, out[3] = 0.f;
  out[4] = xy, out[5] = yz, out[6] = zx, out[7] = 0.f;
}

}  // namespace

std::uint32_t BlockGrid::area(std::size_t i) const {
  const int bx = static_cast<int>(i % static_cast<std::size_t>(means_.width));
  const int by = static_cast<int>(i / static_cast<std::size_t>(means_.width));
  const int w = std::min(factor_, frame_width_ - bx * factor_);
  const int h = std::min(factor_, frame_height_ - by * factor_);
  return static_cast<std::uint32_t>(w * h);
}

void BlockGrid::read(const PointGrid& full, int factor) {
  factor_ = std::max(1, factor);
  frame_width_ = full.width;
  frame_height_ = full.height;
  means_ = PointGrid();
  means_.stride = 4;
  means_.width = (full.width + factor_ - 1) / factor_;
  means_.height = (full.height + factor_ - 1) / factor_;
  const std::size_t blocks = means_.size();
  mean_points_.resize(4 * blocks);
  moments_.resize(8 * blocks);
  counts_.resize(blocks);
  for (int by = 0; by < means_.height; ++by) readRow(full, by);
  means_.data = mean_points_.data();
}

void BlockGrid::readRow(const PointGrid& full, int by) {
  const int s = factor_;
  const int width = means_.width;
  const std::size_t first = static_cast<std::size_t>(by) * static_cast<std::size_t>(width);
  const int v_begin = by * s, v_end = std::min(v_begin + s, full.height);
  const auto span = [&](int bx) {
    return Span{bx * s, std::min(bx * s + s, full.width), v_begin, v_end};
  };
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  // A block's mean from its sum and count (NaN without a measured point).
  const auto setMean = [&](std::size_t i, const float sum[3], std::uint32_t count) {
    counts_[i] = static_cast<std::uint16_t>(count);
    float* mean = &mean_points_[4 * i];
    const float n = static_cast<float>(count);
    mean[0] = count ? sum[0] / n : kNaN;
    mean[1] = count ? sum[1] / n : kNaN;
    mean[2] = count ? sum[2] / n : kNaN;
    mean[3] = 0.f;
  };
#if FLOODPLANE_SIMD
  if (fourPixelsAtATime(full)) {
    // Every block's points added four floats at a time, row by row; a block whose sum is not
    // finite has a hole, and is summed again pixel by pixel. The order of the additions is
    // the pixel-by-pixel one, so both give the same bits.
    has_hole_.assign(static_cast<std::size_t>(width), 0);
    float* sums = &moments_[8 * first];  // the sums go where the scatters will: 8 floats a block
    for (int bx = 0; bx < width; ++bx) Float4::broadcast(0.f).store(sums + 8 * bx);
    for (int v = v_begin; v < v_end; ++v) {
      const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
      for (int bx = 0; bx < width; ++bx) {
        const Span b = span(bx);
        Float4 sum = Float4::load(sums + 8 * bx);
        for (int u = b.u_begin; u < b.u_end; ++u) sum = sum + Float4::load(full.point(row + static_cast<std::size_t>(u)));
        sum.store(sums + 8 * bx);
      }
    }
    for (int bx = 0; bx < width; ++bx) {
      const std::size_t i = first + static_cast<std::size_t>(bx);
      const Float4 sum = Float4::load(sums + 8 * bx);
      float total[3] = {sum.lane(0), sum.lane(1), sum.lane(2)};
      std::uint32_t count = 0;
      if (sum.firstThreeFinite()) {
        const Span b = span(bx);
        count = static_cast<std::uint32_t>((b.u_end - b.u_begin) * (b.v_end - b.v_begin));
      } else {
        has_hole_[static_cast<std::size_t>(bx)] = 1;
        sumPixelByPixel(full, span(bx), total, count);
      }
      setMean(i, total, count);
    }
    // The scatters about the means, from the rows just read.
    for (int bx = 0; bx < width; ++bx) Float4::broadcast(0.f).store(sums + 8 * bx), Float4::broadcast(0.f).store(sums + 8 * bx + 4);
    for (int v = v_begin; v < v_end; ++v) {
      const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
      for (int bx = 0; bx < width; ++bx) {
        if (has_hole_[static_cast<std::size_t>(bx)]) continue;
        const Span b = span(bx);
        const Float4 mean = Float4::load(&mean_points_[4 * (first + static_cast<std::size_t>(bx))]);
        Float4 squares = Float4::load(sums + 8 * bx), products = Float4::load(sums + 8 * bx + 4);
        for (int u = b.u_begin; u < b.u_end; ++u) {
          const Float4 d = Float4::load(full.point(row + static_cast<std::size_t>(u))) - mean;
          squares = squares + d * d;
          products = products + d * d.rotated();
        }
        squares.store(sums + 8 * bx);
        products.store(sums + 8 * bx + 4);
      }
    }
    for (int bx = 0; bx < width; ++bx) {
      float* out = sums + 8 * bx;
      if (has_hole_[static_cast<std::size_t>(bx)]) {
        scatterPixelByPixel(full, span(bx), &mean_points_[4 * (first + static_cast<std::size_t>(bx))], out);
      } else {
        out[3] = out[7] = 0.f;
      }
    }
    return;
  }
#endif
  for (int bx = 0; bx < width; ++bx) {
    const std::size_t i = first + static_cast<std::size_t>(bx);
    float total[3];
    std::uint32_t count = 0;
    sumPixelByPixel(full, span(bx), total, count);
    setMean(i, total, count);
    scatterPixelByPixel(full, span(bx), &mean_points_[4 * i], &moments_[8 * i]);
  }
}

PlaneSums BlockGrid::sums(std::size_t i) const {
  PlaneSums sums;
  addTo(i, sums);
  return sums;
}

void BlockGrid::addTo(std::size_t i, PlaneSums& sums) const {
  const double n = counts_[i];
  if (n == 0.0) return;
  const float* mean = &mean_points_[4 * i];
  const float* c = &moments_[8 * i];
  const double x = mean[0], y = mean[1], z = mean[2];
  sums.count += n;
  sums.sx += n * x;
  sums.sy += n * y;
  sums.sz += n * z;
  sums.sxx += c[0] + n * x * x;
  sums.syy += c[1] + n * y * y;
  sums.szz += c[2] + n * z * z;
  sums.sxy += c[4] + n * x * y;
  sums.syz += c[5] + n * y * z;
  sums.sxz += c[6] + n * z * x;
}

double BlockGrid::meanSquaredDistance(std::size_t i, const Vec3& normal, float offset) const {
  const double n = counts_[i];
  if (n == 0.0) return 0.0;
  const float* mean = &mean_points_[4 * i];
  const float* c = &moments_[8 * i];
  const double nx = normal.x, ny = normal.y, nz = normal.z;
  const double scatter = nx * nx * c[0] + ny * ny * c[1] + nz * nz * c[2] +
                         2.0 * (nx * ny * c[4] + ny * nz * c[5] + nz * nx * c[6]);
  const double distance = nx * mean[0] + ny * mean[1] + nz * mean[2] + offset;
  return std::max(0.0, scatter / n) + distance * distance;
}

}  // namespace floodplane
