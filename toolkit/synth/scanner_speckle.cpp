// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "synth/scanner_speckle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "synth/pixel_random.h"

namespace floodplane::synth {
namespace {

// The speckle's generators: pixel indices shifted far beyond any image (2^30 pixels at most),
// so that they never coincide with a pixel's measuring generator.
constexpr std::uint64_t kSpeckleStream = std::uint64_t{1} << 40;

bool meetAtAnEdge(double depth_a, ProjectorLight light_a, double depth_b, ProjectorLight light_b, double depth_jump) {
  const bool hit_a = std::isfinite(depth_a);
  const bool hit_b = std::isfinite(depth_b);
  if (hit_a != hit_b) return true;
  if (!hit_a) return false;
  if (std::abs(depth_a - depth_b) > depth_jump * std::min(depth_a, depth_b)) return true;
  return (light_a == ProjectorLight::lit && light_b == ProjectorLight::shadowed) ||
         (light_a == ProjectorLight::shadowed && light_b == ProjectorLight::lit);
}

// Widens the marked pixels by `radius` in every direction (a square): a running maximum along
// the rows, then along the columns.
std::vector<std::uint8_t> dilate(const std::vector<std::uint8_t>& marked, int width, int height, int radius) {
  const auto at = [width](int u, int v) { return static_cast<std::size_t>(v) * static_cast<std::size_t>(width) + u; };
  std::vector<std::uint8_t> rows(marked.size(), 0);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      if (!marked[at(u, v)]) continue;
      for (int x = std::max(0, u - radius); x <= std::min(width - 1, u + radius); ++x) rows[at(x, v)] = 1;
    }
  }
  std::vector<std::uint8_t> square(marked.size(), 0);
  for (int v = 0; v < height; ++v) {
    for (int u = 0; u < width; ++u) {
      if (!rows[at(u, v)]) continue;
      for (int y = std::max(0, v - radius); y <= std::min(height - 1, v + radius); ++y) square[at(u, y)] = 1;
    }
  }
  return square;
}

}  // namespace

std::vector<std::uint8_t> scannerSpeckleBand(const std::vector<double>& exact_depth,
                                             const std::vector<ProjectorLight>& light, const ScannerParams& params,
                                             int width, int height) {
  std::vector<std::uint8_t> at_edge(exact_depth.size(), 0);
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t i = 0; i < exact_depth.size(); ++i) {
    const std::size_t right = i + 1;
    if (i % w + 1 < w &&
        meetAtAnEdge(exact_depth[i], light[i], exact_depth[right], light[right], params.speckle_depth_jump)) {
      at_edge[i] = at_edge[right] = 1;
    }
    const std::size_t below = i + w;
    if (below < exact_depth.size() &&
        meetAtAnEdge(exact_depth[i], light[i], exact_depth[below], light[below], params.speckle_depth_jump)) {
      at_edge[i] = at_edge[below] = 1;
    }
  }
  return dilate(at_edge, width, height, std::max(0, params.speckle_band));
}

void addScannerSpeckle(const std::vector<double>& exact_depth, const std::vector<ProjectorLight>& light,
                       const ScannerParams& params, std::uint64_t seed, RenderedFrame& frame) {
  if (!params.speckle) return;
  const int width = frame.intrinsics.width;
  const int height = frame.intrinsics.height;
  const std::vector<std::uint8_t> band = scannerSpeckleBand(exact_depth, light, params, width, height);
  const auto w = static_cast<std::size_t>(width);
  // Decided on the frame as measured: which pixels had a return.
  std::vector<std::uint8_t> returned(frame.points.size(), 0);
  for (std::size_t i = 0; i < frame.points.size(); ++i) returned[i] = std::isnan(frame.points[i].z()) ? 0 : 1;

  const Eigen::Vector3f no_point = Eigen::Vector3f::Constant(std::numeric_limits<float>::quiet_NaN());
  const int shortest = std::max(1, params.speckle_stripe_min_length);
  const int longest = std::max(shortest, params.speckle_stripe_max_length);
  for (std::size_t i = 0; i < frame.points.size(); ++i) {
    if (!band[i]) continue;
    PixelRandom random(seed, kSpeckleStream + i);
    const bool starts_stripe = random.uniform() < params.speckle_stripe_probability;
    const int length = shortest + static_cast<int>(random.uniform() * (longest - shortest + 1));
    const bool spurious = random.uniform() < params.speckle_spurious_probability;
    const double error_draw = 2.0 * random.uniform() - 1.0;
    if (returned[i]) {
      if (!starts_stripe) continue;
      // Down the column while inside the band; the stripe's start is the pixel itself.
      std::size_t j = i;
      for (int k = 0; k < length && j < band.size() && band[j]; ++k, j += w) {
        if (!returned[j] || std::isnan(frame.points[j].z())) continue;  // no return, or lost already
        frame.points[j] = no_point;
        if (frame.labels[j] > 0) --frame.planes[frame.labels[j] - 1].pixel_count;
        frame.labels[j] = 0;
      }
      continue;
    }
    const double z = exact_depth[i];
    if (!spurious || !std::isfinite(z)) continue;
    const std::optional<double> reported =
        reportScannerDepth(z + error_draw * params.speckle_spurious_error_at_1m * z * z, params);
    if (!reported) continue;
    const int u = static_cast<int>(i % w);
    const int v = static_cast<int>(i / w);
    frame.points[i] = (*reported * frame.intrinsics.rayThroughPixel(u, v)).cast<float>();
    frame.labels[i] = 0;
  }
}

}  // namespace floodplane::synth
