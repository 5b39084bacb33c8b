#pragma once
// The one SIMD switch of the core. Loops that take four neighbouring pixels of a row at once
// are written with the small types below, so that no other file uses intrinsics. The CMake
// option FLOODPLANE_SIMD=OFF defines FLOODPLANE_NO_SIMD (a private definition of every target
// that compiles the core's sources); then, as on CPUs without SSE2, every such loop runs pixel
// by pixel. Every lane operation here is the scalar one of Vec3 / distance_function.h in the
// same order, so a lane holds, bit for bit, what the scalar code computes for its pixel.

#include <cstddef>
#include <cstdint>

#include "depth_noise.h"
#include "floodplane/point_grid.h"
#include "plane_sums.h"
#include "vec3.h"

#if defined(__SSE2__) && !defined(FLOODPLANE_NO_SIMD)
#include <emmintrin.h>
#include <xmmintrin.h>
#define FLOODPLANE_SIMD 1
#else
#define FLOODPLANE_SIMD 0
#endif

namespace floodplane {

/// Asks the memory for the cache lines of [begin, end) ahead of their use (a hint, no effect on
/// results; nothing where the compiler has no prefetch builtin).
template <class T>
inline void prefetchRange(const T* begin, const T* end) {
#if defined(__GNUC__) || defined(__clang__)
  constexpr std::size_t kCacheLine = 64;
  const char* last = reinterpret_cast<const char*>(end) - 1;
  for (const char* p = reinterpret_cast<const char*>(begin); p <= last; p += kCacheLine) __builtin_prefetch(p);
  __builtin_prefetch(last);
#else
  (void)begin;
  (void)end;
#endif
}

/// Whether the core was built with the four-pixel loops (defined in a source file of the core,
/// so that callers see the core's setting, not their own).
bool simdEnabled();

/// Whether the four-pixel loops can run on a grid: they need SIMD and load the four floats at
/// the start of each point, so a point must have at least four (PCL's point types do; a packed
/// x y z grid does not, and is handled pixel by pixel).
inline bool fourPixelsAtATime(const PointGrid& grid) { return FLOODPLANE_SIMD && grid.stride >= 4; }

#if FLOODPLANE_SIMD

/// The result of a comparison in four lanes.
struct Mask4 {
  __m128 bits;

  bool all() const { return _mm_movemask_ps(bits) == 0xf; }
  /// How many lanes are set from lane 0 up before the first that is not.
  int leadingLanes() const { return __builtin_ctz(~static_cast<unsigned>(_mm_movemask_ps(bits))); }
  /// How many lanes are set from lane 3 down before the first that is not.
  int trailingLanes() const { return __builtin_clz(~(static_cast<unsigned>(_mm_movemask_ps(bits)) << 28)); }
  Mask4 operator&(Mask4 o) const { return {_mm_and_ps(bits, o.bits)}; }
  Mask4 operator|(Mask4 o) const { return {_mm_or_ps(bits, o.bits)}; }
  /// Writes `label` to the lanes where the mask is set and 0 elsewhere.
  void storeLabels(std::uint32_t* out, std::uint32_t label) const {
    const __m128i value = _mm_set1_epi32(static_cast<std::int32_t>(label));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_and_si128(_mm_castps_si128(bits), value));
  }
};

/// Four floats.
struct Float4 {
  __m128 v;

  static Float4 load(const float* p) { return {_mm_loadu_ps(p)}; }
  static Float4 broadcast(float x) { return {_mm_set1_ps(x)}; }
  void store(float* p) const { _mm_storeu_ps(p, v); }
  Float4 operator+(Float4 o) const { return {_mm_add_ps(v, o.v)}; }
  Float4 operator-(Float4 o) const { return {_mm_sub_ps(v, o.v)}; }
  Float4 operator*(Float4 o) const { return {_mm_mul_ps(v, o.v)}; }
  Float4 operator/(Float4 o) const { return {_mm_div_ps(v, o.v)}; }
  Float4 abs() const { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), v)}; }
  Float4 sqrt() const { return {_mm_sqrt_ps(v)}; }
  /// a < b ? a : b lane by lane (MINPS returns its second operand when either is NaN, as
  /// the conditional does).
  static Float4 min(Float4 a, Float4 b) { return {_mm_min_ps(a.v, b.v)}; }
  /// std::max(a, b) lane by lane for lanes that are not NaN (MAXPS and std::max differ there).
  static Float4 max(Float4 a, Float4 b) { return {_mm_max_ps(a.v, b.v)}; }
  /// a < b, false where either is NaN.
  Mask4 operator<(Float4 o) const { return {_mm_cmplt_ps(v, o.v)}; }
  /// a <= b, false where either is NaN.
  Mask4 operator<=(Float4 o) const { return {_mm_cmple_ps(v, o.v)}; }
  /// mask ? a : b lane by lane.
  static Float4 select(Mask4 mask, Float4 a, Float4 b) {
    return {_mm_or_ps(_mm_and_ps(mask.bits, a.v), _mm_andnot_ps(mask.bits, b.v))};
  }
};

/// static_cast<float>(factor * noise.sigma(double(range_sq))) lane by lane: the noise in
/// double, as the scalar code takes it.
inline Float4 scaledSigma(const DepthNoise& noise, double factor, Float4 range_sq) {
  const __m128d constant = _mm_set1_pd(noise.constant), quadratic = _mm_set1_pd(noise.quadratic),
                scale = _mm_set1_pd(factor);
  const auto half = [&](__m128d r2) { return _mm_mul_pd(scale, _mm_add_pd(constant, _mm_mul_pd(quadratic, r2))); };
  const __m128 low = _mm_cvtpd_ps(half(_mm_cvtps_pd(range_sq.v)));
  const __m128 high = _mm_cvtpd_ps(half(_mm_cvtps_pd(_mm_movehl_ps(range_sq.v, range_sq.v))));
  return {_mm_movelh_ps(low, high)};
}

/// Whether the four 32-bit labels from `labels` on all equal `value`.
inline bool allLabelsEqual(const std::int32_t* labels, std::int32_t value) {
  const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(block, _mm_set1_epi32(value))) == 0xffff;
}
/// Whether any of the four 32-bit labels from `labels` on equals `value`.
template <class Label>
bool anyLabelEquals(const Label* labels, Label value) {
  const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(block, _mm_set1_epi32(static_cast<std::int32_t>(value)))) != 0;
}
/// Whether any of the four 32-bit labels from `labels` on differs from `value`.
template <class Label>
bool anyLabelDiffers(const Label* labels, Label value) {
  const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(block, _mm_set1_epi32(static_cast<std::int32_t>(value)))) != 0xffff;
}

/// Four points of a grid, x y z across the lanes.
struct PointLanes {
  Float4 x, y, z;

  /// Points first .. first + 3 of a grid with fourPixelsAtATime(grid).
  static PointLanes load(const PointGrid& grid, std::size_t first) {
    return transpose(grid.point(first), grid.point(first + 1), grid.point(first + 2), grid.point(first + 3));
  }
  /// From four points of which four floats each are readable (x, y, z, anything).
  static PointLanes transpose(const float* a, const float* b, const float* c, const float* d) {
    __m128 pa = _mm_loadu_ps(a), pb = _mm_loadu_ps(b), pc = _mm_loadu_ps(c), pd = _mm_loadu_ps(d);
    _MM_TRANSPOSE4_PS(pa, pb, pc, pd);
    return {{pa}, {pb}, {pc}};
  }

  /// Stores the four points as x y z 0, four floats each, from `out` on.
  void storePoints(float* out) const {
    __m128 a = x.v, b = y.v, c = z.v, d = _mm_setzero_ps();
    _MM_TRANSPOSE4_PS(a, b, c, d);
    _mm_storeu_ps(out, a);
    _mm_storeu_ps(out + 4, b);
    _mm_storeu_ps(out + 8, c);
    _mm_storeu_ps(out + 12, d);
  }

  /// Vec3::squaredNorm: (x x + y y) + z z.
  Float4 squaredNorm() const { return (x * x + y * y) + z * z; }
  /// squaredEuclideanDistance: the squared norm of the difference.
  Float4 squaredDistance(const PointLanes& o) const {
    const Float4 dx = x - o.x, dy = y - o.y, dz = z - o.z;
    return (dx * dx + dy * dy) + dz * dz;
  }
  /// Vec3::dot with a normal: (n_x x + n_y y) + n_z z.
  Float4 dot(const Vec3& normal) const {
    return (Float4::broadcast(normal.x) * x + Float4::broadcast(normal.y) * y) + Float4::broadcast(normal.z) * z;
  }
};

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
