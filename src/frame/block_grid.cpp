// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "frame/block_grid.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/depth_noise.h"
#include "util/simd.h"
#include "util/vec3.h"

namespace floodplane {

namespace {

// Neighbouring points of one surface are at most this many pixel footprints apart in depth (a
// surface seen at 75 degrees from its normal: tan 75 = 3.7), as HoleFilling bridges.
constexpr double kNeighbourFootprints = 4.0;

bool finitePoint(const float* p) { return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]); }

// What one block row's pass needs to know of a block: its pixel columns and rows.
struct Span {
  int u_begin, u_end, v_begin, v_end;
};

// The sum of a block's measured points, their number and the spread of their depths, pixel by
// pixel in raster order.
void sumPixelByPixel(const PointGrid& full, const Span& span, float sum[3], std::uint32_t& count, float& spread) {
  sum[0] = sum[1] = sum[2] = 0.f;
  count = 0;
  float smallest = std::numeric_limits<float>::infinity(), largest = -smallest;
  for (int v = span.v_begin; v < span.v_end; ++v) {
    const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
    for (int u = span.u_begin; u < span.u_end; ++u) {
      const float* p = full.point(row + static_cast<std::size_t>(u));
      if (!finitePoint(p)) continue;
      sum[0] += p[0];
      sum[1] += p[1];
      sum[2] += p[2];
      smallest = std::min(smallest, p[2]);
      largest = std::max(largest, p[2]);
      ++count;
    }
  }
  spread = count ? largest - smallest : 0.f;
}

// Whether, in a block without a hole, every two horizontal neighbours and every two vertical
// neighbours of its first column differ in depth by at most `step`: a tree of such steps then
// joins every pixel to the first, which is what separateSurfaces' flood would find, at a
// fraction of its cost (most blocks of a steep or noise-free surface spread more than one step).
bool connectedAlongRowsAndFirstColumn(const PointGrid& full, const Span& span, float step) {
  const std::size_t width = static_cast<std::size_t>(full.width);
  float above = 0.f;
  for (int v = span.v_begin; v < span.v_end; ++v) {
    const std::size_t row = static_cast<std::size_t>(v) * width;
    float left = full.point(row + static_cast<std::size_t>(span.u_begin))[2];
    if (v > span.v_begin && !(std::abs(left - above) <= step)) return false;
    above = left;
    for (int u = span.u_begin + 1; u < span.u_end; ++u) {
      const float depth = full.point(row + static_cast<std::size_t>(u))[2];
      if (!(std::abs(depth - left) <= step)) return false;
      left = depth;
    }
  }
  return true;
}

// The scatter of a block's points about their mean: the sums of the offsets' products, added
// in the order the points come, stored in the moments' layout (xx yy zz 0 xy yz zx 0).
struct ScatterSums {
  float xx = 0.f, yy = 0.f, zz = 0.f, xy = 0.f, yz = 0.f, zx = 0.f;

  void add(const float* p, const float* mean) {
    const float dx = p[0] - mean[0], dy = p[1] - mean[1], dz = p[2] - mean[2];
    xx += dx * dx;
    yy += dy * dy;
    zz += dz * dz;
    xy += dx * dy;
    yz += dy * dz;
    zx += dz * dx;
  }
  void store(float* out) const {
    out[0] = xx, out[1] = yy, out[2] = zz, out[3] = 0.f;
    out[4] = xy, out[5] = yz, out[6] = zx, out[7] = 0.f;
  }
};

// The scatter of a block's measured points about `mean`, pixel by pixel, into `out`.
void scatterPixelByPixel(const PointGrid& full, const Span& span, const float mean[3], float out[8]) {
  ScatterSums scatter;
  for (int v = span.v_begin; v < span.v_end; ++v) {
    const std::size_t row = static_cast<std::size_t>(v) * static_cast<std::size_t>(full.width);
    for (int u = span.u_begin; u < span.u_end; ++u) {
      const float* p = full.point(row + static_cast<std::size_t>(u));
      if (finitePoint(p)) scatter.add(p, mean);
    }
  }
  scatter.store(out);
}

#if FLOODPLANE_SIMD
// A full S x S block without a hole, four floats (one PCL point) at a time, its loops unrolled
// by the compiler: the sum, the depth extremes and the scatter about the mean into `mean` and
// `scatter` (as BlockGrid stores them); false, with nothing written, where the sum is not
// finite (a hole: the caller goes pixel by pixel). `first` is the block's first point,
// `row_step` the floats from one image row to the next, `step` from one point to the next.
template <int S>
bool readFullBlock(const float* first, std::size_t row_step, std::size_t step, float* mean, float* scatter,
                   float& depth_spread) {
  Float4 sum = Float4::broadcast(0.f);
  Float4 smallest = Float4::broadcast(std::numeric_limits<float>::infinity());
  Float4 largest = Float4::broadcast(0.f) - smallest;
  for (int v = 0; v < S; ++v) {
    for (int u = 0; u < S; ++u) {
      const Float4 q =
          Float4::load(first + static_cast<std::size_t>(v) * row_step + static_cast<std::size_t>(u) * step);
      sum = sum + q;
      smallest = Float4::min(smallest, q);
      largest = Float4::max(largest, q);
    }
  }
  if (!sum.firstThreeFinite()) return false;
  depth_spread = largest.lane(2) - smallest.lane(2);
  const Float4 centre = sum / Float4::broadcast(static_cast<float>(S * S));
  centre.store(mean);
  mean[3] = 0.f;
  Float4 squares = Float4::broadcast(0.f), products = squares;
  for (int v = 0; v < S; ++v) {
    for (int u = 0; u < S; ++u) {
      const Float4 d =
          Float4::load(first + static_cast<std::size_t>(v) * row_step + static_cast<std::size_t>(u) * step) - centre;
      squares = squares + d * d;
      products = products + d * d.rotated();
    }
  }
  squares.store(scatter);
  products.store(scatter + 4);
  scatter[3] = scatter[7] = 0.f;
  return true;
}
#endif

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
  depth_spread_.resize(blocks);
  split_.assign(blocks, 0);
  for (int by = 0; by < means_.height; ++by) readRow(full, by);
  means_.data = mean_points_.data();
}

void BlockGrid::readRow(const PointGrid& full, int by) {
  const int s = factor_;
  const int width = means_.width;
  const std::size_t first = static_cast<std::size_t>(by) * static_cast<std::size_t>(width);
  const int v_begin = by * s, v_end = std::min(v_begin + s, full.height);
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  for (int bx = 0; bx < width; ++bx) {
    const std::size_t i = first + static_cast<std::size_t>(bx);
    const Span span{bx * s, std::min(bx * s + s, full.width), v_begin, v_end};
    float* mean = &mean_points_[4 * i];
    float* scatter = &moments_[8 * i];
#if FLOODPLANE_SIMD
    if (fourPixelsAtATime(full) && span.u_end - span.u_begin == s && span.v_end - span.v_begin == s) {
      // Block by block, four floats (one PCL point) at a time (readFullBlock); the rows of a
      // block row stay in the cache from one block to the next. A block with a hole goes pixel
      // by pixel below; the additions come in the same order either way, so both give the
      // same bits.
      const std::size_t frame_width = static_cast<std::size_t>(full.width);
      const float* p =
          full.point(static_cast<std::size_t>(v_begin) * frame_width + static_cast<std::size_t>(span.u_begin));
      const std::size_t row_step = frame_width * full.stride;
      bool read = false;
      switch (s) {
        case 2:
          read = readFullBlock<2>(p, row_step, full.stride, mean, scatter, depth_spread_[i]);
          break;
        case 4:
          read = readFullBlock<4>(p, row_step, full.stride, mean, scatter, depth_spread_[i]);
          break;
        case 8:
          read = readFullBlock<8>(p, row_step, full.stride, mean, scatter, depth_spread_[i]);
          break;
        default:
          break;
      }
      if (read) {
        counts_[i] = static_cast<std::uint16_t>(s * s);
        continue;
      }
    }
#endif
    float total[3];
    std::uint32_t count = 0;
    sumPixelByPixel(full, span, total, count, depth_spread_[i]);
    counts_[i] = static_cast<std::uint16_t>(count);
    const float n = static_cast<float>(count);
    (count ? Vec3{total[0] / n, total[1] / n, total[2] / n} : Vec3{kNaN, kNaN, kNaN}).storePadded(mean);
    scatterPixelByPixel(full, span, mean, scatter);
  }
}

namespace {

// The pixels of one block, numbered in raster order.
struct BlockPixels {
  const PointGrid& full;
  Span span;
  int w, h;
  BlockPixels(const PointGrid& grid, const Span& b)
      : full(grid), span(b), w(b.u_end - b.u_begin), h(b.v_end - b.v_begin) {}
  const float* at(int k) const {
    return full.point(static_cast<std::size_t>(span.v_begin + k / w) * static_cast<std::size_t>(full.width) +
                      static_cast<std::size_t>(span.u_begin + k % w));
  }
};

// Marks in `kept` the pixels connected to pixel `first` through depth steps of at most `step`
// (4-neighbours); returns how many.
std::uint32_t keepFirstSurface(const BlockPixels& block, int first, float step, std::vector<std::uint8_t>& kept,
                               std::vector<int>& stack) {
  const int w = block.w, h = block.h;
  kept.assign(static_cast<std::size_t>(w * h), 0);
  kept[static_cast<std::size_t>(first)] = 1;
  stack.assign(1, first);
  std::uint32_t count = 1;
  while (!stack.empty()) {
    const int k = stack.back();
    stack.pop_back();
    const float depth = block.at(k)[2];
    const int x = k % w, y = k / w;
    const int neighbours[4] = {x > 0 ? k - 1 : -1, x + 1 < w ? k + 1 : -1, y > 0 ? k - w : -1, y + 1 < h ? k + w : -1};
    for (const int j : neighbours) {
      if (j < 0 || kept[static_cast<std::size_t>(j)]) continue;
      const float* q = block.at(j);
      if (!finitePoint(q) || !(std::abs(q[2] - depth) <= step)) continue;
      kept[static_cast<std::size_t>(j)] = 1;
      stack.push_back(j);
      ++count;
    }
  }
  return count;
}

// The mean (padded to 4 floats) and scatter moments (8 floats) of the `count` kept pixels.
void sumKept(const BlockPixels& block, const std::vector<std::uint8_t>& kept, std::uint32_t count, float* mean,
             float* moments) {
  float sum[3] = {0.f, 0.f, 0.f};
  for (int k = 0; k < block.w * block.h; ++k) {
    if (!kept[static_cast<std::size_t>(k)]) continue;
    const float* p = block.at(k);
    sum[0] += p[0];
    sum[1] += p[1];
    sum[2] += p[2];
  }
  const float n = static_cast<float>(count);
  Vec3{sum[0] / n, sum[1] / n, sum[2] / n}.storePadded(mean);
  ScatterSums scatter;
  for (int k = 0; k < block.w * block.h; ++k) {
    if (kept[static_cast<std::size_t>(k)]) scatter.add(block.at(k), mean);
  }
  scatter.store(moments);
}

}  // namespace

void BlockGrid::separateSurfaces(const PointGrid& full, const NoiseModel& pixel_noise, float angular_pitch) {
  const int s = factor_;
  for (int by = 0; by < means_.height; ++by) {
    for (int bx = 0; bx < means_.width; ++bx) {
      const std::size_t i =
          static_cast<std::size_t>(by) * static_cast<std::size_t>(means_.width) + static_cast<std::size_t>(bx);
      if (counts_[i] < 2) continue;
      const BlockPixels block(
          full, Span{bx * s, std::min(bx * s + s, full.width), by * s, std::min(by * s + s, full.height)});
      // The block's first measured pixel, in raster order: the surface the block samples.
      int first = 0;
      while (!finitePoint(block.at(first))) ++first;
      const float* reference = block.at(first);
      const double range_sq = static_cast<double>(reference[0]) * reference[0] +
                              static_cast<double>(reference[1]) * reference[1] +
                              static_cast<double>(reference[2]) * reference[2];
      // Two neighbouring pixels of one surface differ in depth by at most what a surface seen
      // at up to 75 degrees from its normal spans over one footprint, plus the noise of both.
      const float step = static_cast<float>(kNeighbourFootprints * angular_pitch * std::sqrt(range_sq) +
                                            noiseDeviations(pixel_noise, kDifferenceDeviations, range_sq));
      if (!(depth_spread_[i] > step)) continue;  // one surface, up to the noise
      if (static_cast<int>(counts_[i]) == block.w * block.h && connectedAlongRowsAndFirstColumn(full, block.span, step))
        continue;  // every pixel measured and joined to the first by such steps: one surface
      const std::uint32_t count = keepFirstSurface(block, first, step, kept_, stack_);
      if (count == counts_[i]) continue;  // every measured pixel on the first one's surface
      split_[i] = 1;
      counts_[i] = static_cast<std::uint16_t>(count);
      sumKept(block, kept_, count, &mean_points_[4 * i], &moments_[8 * i]);
    }
  }
}

PlaneSums BlockGrid::sums(std::size_t i) const {
  PlaneSums sums;
  addTo(i, sums);
  return sums;
}

void BlockGrid::addTo(std::size_t i, PlaneSums& sums) const {
  if (counts_[i] == 0) return;
  const float* mean = &mean_points_[4 * i];
  sums.addGroup(counts_[i], mean[0], mean[1], mean[2], &moments_[8 * i]);
}

void BlockGrid::addMeanTo(std::size_t i, PlaneSums& sums) const {
  if (counts_[i] == 0) return;
  const float* mean = &mean_points_[4 * i];
  sums.addGroup(counts_[i], mean[0], mean[1], mean[2]);
}

double BlockGrid::meanSquaredDistance(std::size_t i, const Vec3& normal, float offset) const {
  const double n = counts_[i];
  if (n == 0.0) return 0.0;
  const float* mean = &mean_points_[4 * i];
  const float* c = &moments_[8 * i];
  const double nx = normal.x, ny = normal.y, nz = normal.z;
  const double scatter =
      nx * nx * c[0] + ny * ny * c[1] + nz * nz * c[2] + 2.0 * (nx * ny * c[4] + ny * nz * c[5] + nz * nx * c[6]);
  const double distance = nx * mean[0] + ny * mean[1] + nz * mean[2] + offset;
  return std::max(0.0, scatter / n) + distance * distance;
}

}  // namespace floodplane
