// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Plane sums of points four at a time (the SIMD switch: util/simd.h).

#include <cstddef>

#include "floodplane/point_grid.h"
#include "models/plane_sums.h"
#include "util/simd.h"

namespace floodplane {

#if FLOODPLANE_SIMD
/// Plane sums of points taken four at a time (PointLanes), in two double lanes per sum;
/// addTo() adds them to a PlaneSums. The one place where lanes are summed.
class LaneSums {
 public:
  void add(const PointLanes& p) {
    add(_mm_cvtps_pd(p.x.v), _mm_cvtps_pd(p.y.v), _mm_cvtps_pd(p.z.v));
    add(_mm_cvtps_pd(_mm_movehl_ps(p.x.v, p.x.v)), _mm_cvtps_pd(_mm_movehl_ps(p.y.v, p.y.v)),
        _mm_cvtps_pd(_mm_movehl_ps(p.z.v, p.z.v)));
    count_ += 4.0;
  }
  /// Adds the points of the lanes where `members` is set.
  void add(const PointLanes& p, Mask4 members) {
    const Float4 zero = Float4::broadcast(0.f);
    add(PointLanes{Float4::select(members, p.x, zero), Float4::select(members, p.y, zero),
                   Float4::select(members, p.z, zero)});
    count_ -= 4.0 - static_cast<double>(__builtin_popcount(static_cast<unsigned>(_mm_movemask_ps(members.bits))));
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
#endif  // FLOODPLANE_SIMD

/// Adds points first .. first + n - 1 of a grid to the sums: four at a time into vector
/// accumulators where fourPixelsAtATime(grid), as PlaneSums::addRun otherwise and for the
/// rest. The same sums but for the order of the additions.
inline void addRunToSums(PlaneSums& sums, const PointGrid& grid, std::size_t first, std::size_t n) {
#if FLOODPLANE_SIMD
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
