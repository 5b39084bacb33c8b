#pragma once

#include <cstddef>

#include "distance_function.h"
#include "floodplane/plane_sums.h"
#include "floodplane/point_grid.h"

#if defined(__SSE2__) && !defined(FLOODPLANE_NO_SIMD)
#include <emmintrin.h>
#include <xmmintrin.h>
#define FLOODPLANE_POINT_LANES 1
#else
#define FLOODPLANE_POINT_LANES 0
#endif

namespace floodplane {

// Define FLOODPLANE_NO_SIMD to build the pixel-by-pixel code everywhere (as on CPUs without
// SSE2), e.g. to check that both give the same results.

/// Whether the loops that take four neighbouring pixels of a row at once can run on a grid:
/// they need SSE2 (every x86-64 CPU has it) and load the four floats at the start of each
/// point, so a point must have at least four (PCL's point types do; a packed x y z grid
/// does not, and is handled pixel by pixel). Elsewhere the same loops run pixel by pixel.
inline bool fourPixelsAtATime(const PointGrid& grid) { return FLOODPLANE_POINT_LANES && grid.stride >= 4; }

#if FLOODPLANE_POINT_LANES
/// Four points of a grid, x y z across the lanes of three SSE registers. Every operation
/// here is the scalar one of Vec3 / distance_function.h, in the same order, so a result
/// lane is bit for bit what the scalar code computes for that point.
struct PointLanes {
  __m128 x, y, z;

  /// From four points loaded as (x, y, z, anything) each.
  static PointLanes transpose(__m128 a, __m128 b, __m128 c, __m128 d) {
    _MM_TRANSPOSE4_PS(a, b, c, d);
    return {a, b, c};
  }
  /// Points first .. first + 3 of a grid with fourPixelsAtATime(grid).
  static PointLanes load(const PointGrid& grid, std::size_t first) {
    return transpose(_mm_loadu_ps(grid.point(first)), _mm_loadu_ps(grid.point(first + 1)),
                     _mm_loadu_ps(grid.point(first + 2)), _mm_loadu_ps(grid.point(first + 3)));
  }

  /// Vec3::squaredNorm: (x x + y y) + z z.
  __m128 squaredNorm() const { return _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, x), _mm_mul_ps(y, y)), _mm_mul_ps(z, z)); }
  /// planeDistance: |((n_x x + n_y y) + n_z z) + d|.
  __m128 planeDistance(const Vec3& normal, float offset) const {
    const __m128 xy = _mm_add_ps(_mm_mul_ps(_mm_set1_ps(normal.x), x), _mm_mul_ps(_mm_set1_ps(normal.y), y));
    const __m128 dot = _mm_add_ps(xy, _mm_mul_ps(_mm_set1_ps(normal.z), z));
    return _mm_andnot_ps(_mm_set1_ps(-0.0f), _mm_add_ps(dot, _mm_set1_ps(offset)));
  }
};

/// nearerRangeSq lane by lane: MINPS returns its first operand when that is the smaller and
/// the second otherwise (NaN included), as p_sq < q_sq ? p_sq : q_sq does.
inline __m128 nearerRangeSq(__m128 p_sq, __m128 q_sq) { return _mm_min_ps(p_sq, q_sq); }

/// FloodCriterion::planeTolerance lane by lane, for ranges that are not NaN: MAXPS and
/// std::max differ only there.
inline __m128 planeTolerance(const FloodCriterion& c, __m128 range_sq) {
  return _mm_max_ps(_mm_set1_ps(c.plane_threshold), _mm_mul_ps(_mm_set1_ps(c.plane_noise_factor), range_sq));
}

/// Plane sums of points taken four at a time (PointLanes), in two double lanes per sum;
/// addTo() adds them to a PlaneSums. The one place where lanes are summed.
class LaneSums {
 public:
  void add(const PointLanes& p) {
    add(_mm_cvtps_pd(p.x), _mm_cvtps_pd(p.y), _mm_cvtps_pd(p.z));
    add(_mm_cvtps_pd(_mm_movehl_ps(p.x, p.x)), _mm_cvtps_pd(_mm_movehl_ps(p.y, p.y)),
        _mm_cvtps_pd(_mm_movehl_ps(p.z, p.z)));
    count_ += 4.0;
  }
  void addTo(PlaneSums& sums) const {
    const auto total = [](__m128d a) { return _mm_cvtsd_f64(_mm_add_sd(a, _mm_unpackhi_pd(a, a))); };
    sums.count += count_;
    sums.sx += total(sx_);
    sums.sy += total(sy_);
    sums.sz += total(sz_);
    sums.sxx += total(sxx_);
    sums.sxy += total(sxy_);
    sums.sxz += total(sxz_);
    sums.syy += total(syy_);
    sums.syz += total(syz_);
    sums.szz += total(szz_);
  }

 private:
  void add(__m128d x, __m128d y, __m128d z) {
    sx_ = _mm_add_pd(sx_, x);
    sy_ = _mm_add_pd(sy_, y);
    sz_ = _mm_add_pd(sz_, z);
    sxx_ = _mm_add_pd(sxx_, _mm_mul_pd(x, x));
    sxy_ = _mm_add_pd(sxy_, _mm_mul_pd(x, y));
    sxz_ = _mm_add_pd(sxz_, _mm_mul_pd(x, z));
    syy_ = _mm_add_pd(syy_, _mm_mul_pd(y, y));
    syz_ = _mm_add_pd(syz_, _mm_mul_pd(y, z));
    szz_ = _mm_add_pd(szz_, _mm_mul_pd(z, z));
  }
  __m128d sx_ = _mm_setzero_pd(), sy_ = sx_, sz_ = sx_, sxx_ = sx_, sxy_ = sx_, sxz_ = sx_, syy_ = sx_, syz_ = sx_,
          szz_ = sx_;
  double count_ = 0.0;
};
#endif

/// Adds points first .. first + n - 1 of a grid to the sums: four at a time into vector
/// accumulators where fourPixelsAtATime(grid), as PlaneSums::addRun otherwise and for the
/// rest. The same sums but for the order of the additions.
inline void addRunToSums(PlaneSums& sums, const PointGrid& grid, std::size_t first, std::size_t n) {
#if FLOODPLANE_POINT_LANES
  if (fourPixelsAtATime(grid) && n >= 4) {
    LaneSums lanes;
    std::size_t done = 0;
    for (; done + 4 <= n; done += 4) lanes.add(PointLanes::load(grid, first + done));
    lanes.addTo(sums);
    first += done;
    n -= done;
  }
#endif
  sums.addRun(grid.point(first), grid.stride, n);
}

}  // namespace floodplane
