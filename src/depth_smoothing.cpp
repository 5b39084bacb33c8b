#include "depth_smoothing.h"

#include <cmath>
#include <limits>

namespace floodplane {

namespace {

// Neighbours within this many noise deviations in depth of a point take part in its mean (the
// difference of two noisy depths has sqrt(2) sigma).
const double kGateDeviations = 3.0 * std::sqrt(2.0);

// The mean of a point and those of its two neighbours along a line (`before`, `after`: null
// beyond the grid's edge) within the depth gate, into `out`. Sums in the order before,
// centre, after.
inline void smoothPoint(const float* before, const float* centre, const float* after, float* out,
                        const DepthNoise& noise) {
  out[3] = 0.f;
  if (!std::isfinite(centre[2])) {
    out[0] = out[1] = out[2] = std::numeric_limits<float>::quiet_NaN();
    return;
  }
  const double range_sq = centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2];
  const float gate = static_cast<float>(kGateDeviations * noise.sigma(range_sq));
  // The centre is within its own gate; a NaN neighbour or one across a depth step is not.
  const bool use_before = before != nullptr && std::abs(before[2] - centre[2]) <= gate;
  const bool use_after = after != nullptr && std::abs(after[2] - centre[2]) <= gate;
  float sx = 0.f, sy = 0.f, sz = 0.f;
  if (use_before) {
    sx += before[0];
    sy += before[1];
    sz += before[2];
  }
  sx += centre[0];
  sy += centre[1];
  sz += centre[2];
  if (use_after) {
    sx += after[0];
    sy += after[1];
    sz += after[2];
  }
  const float inverse = 1.0f / static_cast<float>(1 + int{use_before} + int{use_after});
  out[0] = sx * inverse;
  out[1] = sy * inverse;
  out[2] = sz * inverse;
}

// smoothPoint over every point of `in` (four floats a point from `in`, `in_stride` floats
// apart) with its neighbours along rows or columns, into `out` (four floats a point).
void smoothLines(const float* in, std::size_t in_stride, float* out, int width, int height, bool columns,
                 const DepthNoise& noise) {
  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t step = (columns ? w : 1) * in_stride;
  for (int y = 0; y < height; ++y) {
    const float* row = in + static_cast<std::size_t>(y) * w * in_stride;
    float* out_row = out + static_cast<std::size_t>(y) * w * 4;
    const bool has_before_row = !columns || y > 0;
    const bool has_after_row = !columns || y + 1 < height;
    for (int x = 0; x < width; ++x) {
      const float* centre = row + static_cast<std::size_t>(x) * in_stride;
      const bool has_before = columns ? has_before_row : x > 0;
      const bool has_after = columns ? has_after_row : x + 1 < width;
      smoothPoint(has_before ? centre - step : nullptr, centre, has_after ? centre + step : nullptr,
                  out_row + 4 * static_cast<std::size_t>(x), noise);
    }
  }
}

}  // namespace

const PointGrid& DepthSmoothing::smooth(const PointGrid& grid, const DepthNoise& noise) {
  rows_.resize(grid.size() * 4);
  result_points_.resize(grid.size() * 4);
  smoothLines(grid.data, grid.stride, rows_.data(), grid.width, grid.height, false, noise);
  smoothLines(rows_.data(), 4, result_points_.data(), grid.width, grid.height, true, noise);
  result_ = grid;
  result_.data = result_points_.data();
  result_.stride = 4;
  return result_;
}

}  // namespace floodplane
