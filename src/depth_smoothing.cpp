#include "depth_smoothing.h"

#include <cmath>
#include <limits>

namespace floodplane {

namespace {

// The neighbours either side that take part in a point's mean.
constexpr int kHalfWidth = 1;

// The mean of each point of `in` (four floats a point from `in`, `in_stride` floats apart)
// and its neighbours along rows (step 1) or columns (step width) within the depth gate, into
// `out` (four floats a point).
void smoothLines(const float* in, std::size_t in_stride, float* out, int width, int height, bool columns,
                 const DepthNoise& noise) {
  const std::ptrdiff_t step = columns ? width : 1;
  const int length = columns ? height : width;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const float* centre = in + i * in_stride;
      float* o = out + 4 * i;
      o[3] = 0.f;
      if (!std::isfinite(centre[2])) {
        o[0] = o[1] = o[2] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const double range_sq = centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2];
      const float gate = static_cast<float>(3.0 * std::sqrt(2.0) * noise.sigma(range_sq));
      const int at = columns ? y : x;
      float sx = 0.f, sy = 0.f, sz = 0.f;
      int n = 0;
      for (int k = -kHalfWidth; k <= kHalfWidth; ++k) {
        if (at + k < 0 || at + k >= length) continue;
        const float* p = in + static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + k * step) * in_stride;
        if (!(std::abs(p[2] - centre[2]) <= gate)) continue;  // NaN and the other side of a step
        sx += p[0];
        sy += p[1];
        sz += p[2];
        ++n;
      }
      const float inverse = 1.0f / static_cast<float>(n);
      o[0] = sx * inverse;
      o[1] = sy * inverse;
      o[2] = sz * inverse;
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
