#include "depth_smoothing.h"

#include <cmath>
#include <limits>

#include "simd.h"

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

#if FLOODPLANE_SIMD
// smoothPoint for the four points from `centre` on (`in_stride` floats apart), each with its
// neighbours `step` floats before and after it, into `out` (four floats a point). Every lane
// operation is smoothPoint's in its order, so each lane holds smoothPoint's result bit for
// bit; a neighbour left out is not added at all (adding a zero would turn a -0 sum into +0).
void smoothFour(const float* centre, std::size_t in_stride, std::ptrdiff_t step, float* out, const DepthNoise& noise) {
  const auto points = [in_stride](const float* first) {
    return PointLanes::transpose(first, first + in_stride, first + 2 * in_stride, first + 3 * in_stride);
  };
  const PointLanes c = points(centre), before = points(centre - step), after = points(centre + step);
  const Float4 gate = scaledSigma(noise, kGateDeviations, c.squaredNorm());
  const Mask4 use_before = (before.z - c.z).abs() <= gate;
  const Mask4 use_after = (after.z - c.z).abs() <= gate;
  const Float4 zero = Float4::broadcast(0.f), one = Float4::broadcast(1.f);
  const auto sum = [&](Float4 b, Float4 centre_lane, Float4 a) {
    const Float4 with_before = Float4::select(use_before, zero + b, zero) + centre_lane;
    return Float4::select(use_after, with_before + a, with_before);
  };
  const Float4 count = (one + Float4::select(use_before, one, zero)) + Float4::select(use_after, one, zero);
  const Float4 inverse = one / count;
  // smoothPoint's early return: a centre without a finite depth stays a hole.
  const Mask4 finite = c.z.abs() < Float4::broadcast(std::numeric_limits<float>::infinity());
  const Float4 nan = Float4::broadcast(std::numeric_limits<float>::quiet_NaN());
  PointLanes result;
  result.x = Float4::select(finite, sum(before.x, c.x, after.x) * inverse, nan);
  result.y = Float4::select(finite, sum(before.y, c.y, after.y) * inverse, nan);
  result.z = Float4::select(finite, sum(before.z, c.z, after.z) * inverse, nan);
  result.storePoints(out);
}
#endif

// smoothPoint over every point of `in` (four floats a point from `in`, `in_stride` floats
// apart) with its neighbours along rows or columns, into `out` (four floats a point). With
// `four_at_a_time`, the points that have both neighbours go four at a time (smoothFour).
void smoothLines(const float* in, std::size_t in_stride, float* out, int width, int height, bool columns,
                 bool four_at_a_time, const DepthNoise& noise) {
  const std::size_t w = static_cast<std::size_t>(width);
  const std::size_t step = (columns ? w : 1) * in_stride;
  for (int y = 0; y < height; ++y) {
    const float* row = in + static_cast<std::size_t>(y) * w * in_stride;
    float* out_row = out + static_cast<std::size_t>(y) * w * 4;
    const bool has_before_row = !columns || y > 0;
    const bool has_after_row = !columns || y + 1 < height;
    int x = 0;
#if FLOODPLANE_SIMD
    if (four_at_a_time && has_before_row && has_after_row && width > 4) {
      // Along rows the first and last points lack a neighbour: they go one at a time below.
      const int first = columns ? 0 : 1;
      const int end = columns ? width : width - 1;
      if (first > 0) smoothPoint(nullptr, row, row + step, out_row, noise);
      for (x = first; x + 4 <= end; x += 4) {
        smoothFour(row + static_cast<std::size_t>(x) * in_stride, in_stride, static_cast<std::ptrdiff_t>(step),
                   out_row + 4 * static_cast<std::size_t>(x), noise);
      }
    }
#else
    (void)four_at_a_time;
#endif
    for (; x < width; ++x) {
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
  // Four points at a time where the input has four floats a point (PCL's layout); a packed
  // x y z grid goes pixel by pixel through both passes, which the tests compare.
  const bool four_at_a_time = fourPixelsAtATime(grid);
  smoothLines(grid.data, grid.stride, rows_.data(), grid.width, grid.height, false, four_at_a_time, noise);
  smoothLines(rows_.data(), 4, result_points_.data(), grid.width, grid.height, true, four_at_a_time, noise);
  result_ = grid;
  result_.data = result_points_.data();
  result_.stride = 4;
  return result_;
}

}  // namespace floodplane
