// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "frame/depth_smoothing.h"

#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "util/simd.h"
#include "util/vec3.h"

namespace floodplane {

namespace {

// The mean of a point and those of its two neighbours along a line (`before`, `after`: null
// beyond the grid's edge) within the depth gate, into `out`. Sums in the order before,
// centre, after.
inline void smoothPoint(const float* before, const float* centre, const float* after, float* out,
                        const NoiseModel& noise) {
  if (!std::isfinite(centre[2])) {
    constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
    Vec3{kNaN, kNaN, kNaN}.storePadded(out);
    return;
  }
  const double range_sq = centre[0] * centre[0] + centre[1] * centre[1] + centre[2] * centre[2];
  // Neighbours within the noise of a depth difference take part in the mean.
  const float gate = static_cast<float>(noiseDeviations(noise, kDifferenceDeviations, range_sq));
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
  Vec3{sx * inverse, sy * inverse, sz * inverse}.storePadded(out);
}

#if FLOODPLANE_SIMD
// smoothPoint's sum of one coordinate, lane by lane: from +0, before (where used), centre,
// after (where used). A neighbour left out is not added at all (adding a zero would turn a -0
// sum into +0). Float: Float4, or Float8 in a function compiled for AVX.
template <class Float, class Mask>
FLOODPLANE_SIMD_INLINE Float gatedSum(Mask use_before, Mask use_after, Float before, Float centre, Float after) {
  const Float zero = Float::broadcast(0.f);
  const Float with_before = Float::select(use_before, zero + before, zero) + centre;
  return Float::select(use_after, with_before + after, with_before);
}

// smoothPoint for the points of one register from `centre` on (Lanes: PointLanes, four, or
// PointLanes8, eight, in a function compiled for AVX), each with the point at the same place
// from `before` and from `after` (all three `stride` floats a point), into `out` (four floats
// a point). Every lane operation is smoothPoint's in its order, so each lane holds
// smoothPoint's result bit for bit.
template <class Lanes>
FLOODPLANE_SIMD_INLINE void smoothLanes(const float* before_points, const float* centre, const float* after_points,
                                        std::size_t stride, float* out, const NoiseModel& noise) {
  using Float = std::decay_t<decltype(std::declval<Lanes>().x)>;
  const Lanes c = Lanes::load(centre, stride), before = Lanes::load(before_points, stride),
              after = Lanes::load(after_points, stride);
  const Float gate = noiseDeviations(noise, kDifferenceDeviations, c.squaredNorm());
  const auto use_before = (before.z - c.z).abs() <= gate;
  const auto use_after = (after.z - c.z).abs() <= gate;
  const Float zero = Float::broadcast(0.f), one = Float::broadcast(1.f);
  const Float count = (one + Float::select(use_before, one, zero)) + Float::select(use_after, one, zero);
  const Float inverse = one / count;
  // smoothPoint's early return: a centre without a finite depth stays a hole.
  const auto finite = c.z.abs() < Float::broadcast(std::numeric_limits<float>::infinity());
  const Float nan = Float::broadcast(std::numeric_limits<float>::quiet_NaN());
  Lanes result;
  result.x = Float::select(finite, gatedSum(use_before, use_after, before.x, c.x, after.x) * inverse, nan);
  result.y = Float::select(finite, gatedSum(use_before, use_after, before.y, c.y, after.y) * inverse, nan);
  result.z = Float::select(finite, gatedSum(use_before, use_after, before.z, c.z, after.z) * inverse, nan);
  result.storePoints(out);
}

void smoothFour(const float* before_points, const float* centre, const float* after_points, std::size_t stride,
                float* out, const NoiseModel& noise) {
  smoothLanes<PointLanes>(before_points, centre, after_points, stride, out, noise);
}
#endif

#if FLOODPLANE_AVX
// smoothFour for eight points (only where cpuHasAvx()).
FLOODPLANE_TARGET_AVX void smoothEight(const float* before_points, const float* centre, const float* after_points,
                                       std::size_t stride, float* out, const NoiseModel& noise) {
  smoothLanes<PointLanes8>(before_points, centre, after_points, stride, out, noise);
}
#endif

// The row pass over one row of `width` points (`stride` floats apart), neighbours left and
// right, into `out` (four floats a point). The points that have both neighbours go up to
// `lanes` (1, 4 or 8) at a time.
void smoothAlongRow(const float* row, std::size_t stride, int width, int lanes, float* out, const NoiseModel& noise) {
  int x = 0;
#if FLOODPLANE_SIMD
  if (lanes >= 4 && width > 4) {
    // The first and last points lack a neighbour: they go one at a time.
    smoothPoint(nullptr, row, row + stride, out, noise);
    x = 1;
#if FLOODPLANE_AVX
    for (; lanes == 8 && x + 8 <= width - 1; x += 8) {
      const float* centre = row + static_cast<std::size_t>(x) * stride;
      smoothEight(centre - stride, centre, centre + stride, stride, out + 4 * static_cast<std::size_t>(x), noise);
    }
#endif
    for (; x + 4 <= width - 1; x += 4) {
      const float* centre = row + static_cast<std::size_t>(x) * stride;
      smoothFour(centre - stride, centre, centre + stride, stride, out + 4 * static_cast<std::size_t>(x), noise);
    }
  }
#else
  (void)lanes;
#endif
  for (; x < width; ++x) {
    const float* centre = row + static_cast<std::size_t>(x) * stride;
    smoothPoint(x > 0 ? centre - stride : nullptr, centre, x + 1 < width ? centre + stride : nullptr,
                out + 4 * static_cast<std::size_t>(x), noise);
  }
}

// The column pass over one row of `width` points (four floats each), neighbours from the rows
// `above` and `below` (null beyond the grid's edge), into `out`.
void smoothAcrossRows(const float* above, const float* row, const float* below, int width, int lanes, float* out,
                      const NoiseModel& noise) {
  int x = 0;
#if FLOODPLANE_SIMD
  if (lanes >= 4 && above != nullptr && below != nullptr) {
#if FLOODPLANE_AVX
    for (; lanes == 8 && x + 8 <= width; x += 8) {
      const std::size_t at = 4 * static_cast<std::size_t>(x);
      smoothEight(above + at, row + at, below + at, 4, out + at, noise);
    }
#endif
    for (; x + 4 <= width; x += 4) {
      const std::size_t at = 4 * static_cast<std::size_t>(x);
      smoothFour(above + at, row + at, below + at, 4, out + at, noise);
    }
  }
#else
  (void)lanes;
#endif
  for (; x < width; ++x) {
    const std::size_t at = 4 * static_cast<std::size_t>(x);
    smoothPoint(above != nullptr ? above + at : nullptr, row + at, below != nullptr ? below + at : nullptr, out + at,
                noise);
  }
}

}  // namespace

const PointGrid& DepthSmoothing::smooth(const PointGrid& grid, const NoiseModel& noise) {
  const std::size_t width = static_cast<std::size_t>(grid.width);
  result_points_.resize(grid.size() * 4);
  // The row pass runs one row ahead of the column pass, into a ring of three rows: the frame
  // is read once and written once, and the rows in between stay in the cache.
  rows_.resize(3 * width * 4);
  const auto ring = [&](int y) { return rows_.data() + static_cast<std::size_t>(y % 3) * width * 4; };
  // Four or eight points at a time where the input has four floats a point (PCL's layout); a
  // packed x y z grid goes pixel by pixel through both passes, which the tests compare.
  const int lanes = !fourPixelsAtATime(grid) ? 1 : width_ == VectorWidth::kWidest && cpuHasAvx() ? 8 : 4;
  const auto smoothRow = [&](int y) {
    smoothAlongRow(grid.data + static_cast<std::size_t>(y) * width * grid.stride, grid.stride, grid.width, lanes,
                   ring(y), noise);
  };
  if (grid.height > 0) smoothRow(0);
  for (int y = 0; y < grid.height; ++y) {
    const bool has_below = y + 1 < grid.height;
    if (has_below) smoothRow(y + 1);
    smoothAcrossRows(y > 0 ? ring(y - 1) : nullptr, ring(y), has_below ? ring(y + 1) : nullptr, grid.width, lanes,
                     result_points_.data() + static_cast<std::size_t>(y) * width * 4, noise);
  }
  result_ = grid;
  result_.data = result_points_.data();
  result_.stride = 4;
  return result_;
}

}  // namespace floodplane
