// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The one SIMD switch of the core. Loops that take four neighbouring pixels of a row at once
// are written with the small types below, so that no other file uses intrinsics. The CMake
// option FLOODPLANE_SIMD=OFF defines FLOODPLANE_NO_SIMD (a private definition of every target
// that compiles the core's sources); then, as on CPUs without SSE2, every such loop runs pixel
// by pixel. Every lane operation here is the scalar one of Vec3 / flood_criterion.h in the
// same order, so a lane holds, bit for bit, what the scalar code computes for its pixel. The
// lanes of the models (the noise model's tolerances, plane sums) are theirs: depth_noise.h,
// lane_sums.h.

#include <cstddef>
#include <cstdint>

#include "floodplane/point_grid.h"
#include "util/vec3.h"

#if defined(__SSE2__) && !defined(FLOODPLANE_NO_SIMD)
#include <emmintrin.h>
#include <xmmintrin.h>
#define FLOODPLANE_SIMD 1
#else
#define FLOODPLANE_SIMD 0
#endif

// Eight-lane (AVX) loops, chosen at run time: Debian's PCL, and so the core, is built for
// baseline x86-64, where SSE2 is all there is. Only functions marked FLOODPLANE_TARGET_AVX use
// the eight-lane types, and they run only where cpuHasAvx() says so. AVX only, not AVX2 or
// FMA: the loops need no integer lanes, and with FMA the compiler could fuse a multiply and
// an add that the scalar code rounds apart.
#if FLOODPLANE_SIMD && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define FLOODPLANE_AVX 1
#define FLOODPLANE_TARGET_AVX __attribute__((target("avx")))
#else
#define FLOODPLANE_AVX 0
#endif

// A small SIMD helper written once for four and eight lanes: inlined into its caller, so that
// the eight-lane copy is compiled for AVX as the FLOODPLANE_TARGET_AVX function that calls it.
#if defined(__GNUC__) || defined(__clang__)
#define FLOODPLANE_SIMD_INLINE inline __attribute__((always_inline))
#else
#define FLOODPLANE_SIMD_INLINE inline
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

/// Whether this CPU (and its operating system) runs AVX instructions; false where the core has
/// no eight-lane loops (FLOODPLANE_AVX == 0). Asked once.
bool cpuHasAvx();

#if FLOODPLANE_SIMD

/// The result of a comparison in four lanes.
struct Mask4 {
  __m128 bits;

  bool all() const { return _mm_movemask_ps(bits) == 0xf; }
  bool any() const { return _mm_movemask_ps(bits) != 0; }
  /// The first lane that is set (4 when none is).
  int firstSet() const {
    const unsigned m = static_cast<unsigned>(_mm_movemask_ps(bits));
    return m ? __builtin_ctz(m) : 4;
  }
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

  // A point's four floats in one register (x y z w), for sums over points (block_grid.cpp).
  /// (y, z, x, w): with *this, the products x y, y z, z x in one multiplication.
  Float4 rotated() const { return {_mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 0, 2, 1))}; }
  /// Whether lanes 0-2 (x y z) are finite numbers.
  bool firstThreeFinite() const {
    return (_mm_movemask_ps(_mm_cmpord_ps(_mm_sub_ps(v, v), _mm_setzero_ps())) & 7) == 7;
  }
  /// Lane j.
  float lane(int j) const {
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, v);
    return lanes[j];
  }
};

/// Whether the four 32-bit labels from `labels` on all equal `value`.
inline bool allLabelsEqual(const std::int32_t* labels, std::int32_t value) {
  const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(four, _mm_set1_epi32(value))) == 0xffff;
}
/// Whether any of the four 32-bit labels from `labels` on equals `value`.
template <class Label>
bool anyLabelEquals(const Label* labels, Label value) {
  const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(four, _mm_set1_epi32(static_cast<std::int32_t>(value)))) != 0;
}
/// Whether any of the four 32-bit labels from `labels` on differs from `value`.
template <class Label>
bool anyLabelDiffers(const Label* labels, Label value) {
  const __m128i four = _mm_loadu_si128(reinterpret_cast<const __m128i*>(labels));
  return _mm_movemask_epi8(_mm_cmpeq_epi32(four, _mm_set1_epi32(static_cast<std::int32_t>(value)))) != 0xffff;
}

/// Which of the four labels from `labels` on differ from the four from `other` on, neither of
/// the two being 0: bit j for label j. With `other` the next label (labels + 1) or the one
/// below (labels + width), the pixels where a border between two segments starts.
template <class Label>
int segmentBorderLanes(const Label* labels, const Label* other) {
  const auto load = [](const Label* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
  const __m128i zero = _mm_setzero_si128();
  const __m128i a = load(labels), b = load(other);
  const __m128i unlabelled = _mm_or_si128(_mm_cmpeq_epi32(a, zero), _mm_cmpeq_epi32(b, zero));
  const __m128i same_or_unlabelled = _mm_or_si128(_mm_cmpeq_epi32(a, b), unlabelled);
  return ~_mm_movemask_ps(_mm_castsi128_ps(same_or_unlabelled)) & 0xf;
}

/// Which of the four labels from `row` on are 0 with a label other than 0 among their four
/// neighbours: row[-1 .. 4], `above` and `below` (the same columns of the rows around; pass
/// `row` itself for a row that is not there). Bit j for label j.
inline int unlabelledNextToLabelled(const std::uint32_t* row, const std::uint32_t* above, const std::uint32_t* below) {
  const auto load = [](const std::uint32_t* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
  const __m128i zero = _mm_setzero_si128();
  const __m128i neighbours =
      _mm_or_si128(_mm_or_si128(load(row - 1), load(row + 1)), _mm_or_si128(load(above), load(below)));
  const __m128i candidates = _mm_andnot_si128(_mm_cmpeq_epi32(neighbours, zero), _mm_cmpeq_epi32(load(row), zero));
  return _mm_movemask_ps(_mm_castsi128_ps(candidates));
}

/// Four points of a grid, x y z across the lanes.
struct PointLanes {
  Float4 x, y, z;

  /// Points first .. first + 3 of a grid with fourPixelsAtATime(grid).
  static PointLanes load(const PointGrid& grid, std::size_t first) {
    return transpose(grid.point(first), grid.point(first + 1), grid.point(first + 2), grid.point(first + 3));
  }
  /// From four points of which four floats each are readable (x, y, z, anything).
  /// Points first, first + stride, first + 2 stride, first + 3 stride (floats), of which four
  /// floats each are readable (x, y, z, anything): PointLanes8::load's four-lane twin.
  static PointLanes load(const float* first, std::size_t stride) {
    return transpose(first, first + stride, first + 2 * stride, first + 3 * stride);
  }
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

#endif  // FLOODPLANE_SIMD

#if FLOODPLANE_AVX

/// The result of a comparison in eight lanes.
struct Mask8 {
  __m256 bits;
};

/// Eight floats: Float4's operations, each lane's the same IEEE operation.
struct Float8 {
  __m256 v;

  FLOODPLANE_TARGET_AVX static Float8 broadcast(float x) { return {_mm256_set1_ps(x)}; }
  FLOODPLANE_TARGET_AVX Float8 operator+(Float8 o) const { return {_mm256_add_ps(v, o.v)}; }
  FLOODPLANE_TARGET_AVX Float8 operator-(Float8 o) const { return {_mm256_sub_ps(v, o.v)}; }
  FLOODPLANE_TARGET_AVX Float8 operator*(Float8 o) const { return {_mm256_mul_ps(v, o.v)}; }
  FLOODPLANE_TARGET_AVX Float8 operator/(Float8 o) const { return {_mm256_div_ps(v, o.v)}; }
  FLOODPLANE_TARGET_AVX Float8 abs() const { return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), v)}; }
  /// a < b, false where either is NaN.
  FLOODPLANE_TARGET_AVX Mask8 operator<(Float8 o) const { return {_mm256_cmp_ps(v, o.v, _CMP_LT_OQ)}; }
  /// a <= b, false where either is NaN.
  FLOODPLANE_TARGET_AVX Mask8 operator<=(Float8 o) const { return {_mm256_cmp_ps(v, o.v, _CMP_LE_OQ)}; }
  /// mask ? a : b lane by lane. (Not BLENDVPS: GCC 12 rewrites it as a comparison of the
  /// mask's sign bits, which AVX has no eight-lane integer instruction for, and goes lane by lane.)
  FLOODPLANE_TARGET_AVX static Float8 select(Mask8 mask, Float8 a, Float8 b) {
    return {_mm256_or_ps(_mm256_and_ps(mask.bits, a.v), _mm256_andnot_ps(mask.bits, b.v))};
  }
};

/// Eight points as x, y, z across lanes: lanes 0-3 hold points 0-3, lanes 4-7 points 4-7.
struct PointLanes8 {
  Float8 x, y, z;

  /// Points first, first + stride, ..., first + 7 stride (floats), of which four floats each
  /// are readable (x, y, z, anything).
  FLOODPLANE_TARGET_AVX static PointLanes8 load(const float* first, std::size_t stride) {
    const __m256 a = loadPair(first, stride, 0), b = loadPair(first, stride, 1), c = loadPair(first, stride, 2),
                 d = loadPair(first, stride, 3);
    // _MM_TRANSPOSE4_PS in each half.
    const __m256 ab_low = _mm256_unpacklo_ps(a, b), cd_low = _mm256_unpacklo_ps(c, d);
    const __m256 ab_high = _mm256_unpackhi_ps(a, b), cd_high = _mm256_unpackhi_ps(c, d);
    return {{_mm256_shuffle_ps(ab_low, cd_low, 0x44)},
            {_mm256_shuffle_ps(ab_low, cd_low, 0xee)},
            {_mm256_shuffle_ps(ab_high, cd_high, 0x44)}};
  }

  /// Stores the eight points as x y z 0, four floats each, from `out` on.
  FLOODPLANE_TARGET_AVX void storePoints(float* out) const {
    const __m256 zero = _mm256_setzero_ps();
    const __m256 xy_low = _mm256_unpacklo_ps(x.v, y.v), z0_low = _mm256_unpacklo_ps(z.v, zero);
    const __m256 xy_high = _mm256_unpackhi_ps(x.v, y.v), z0_high = _mm256_unpackhi_ps(z.v, zero);
    const __m256 p04 = _mm256_shuffle_ps(xy_low, z0_low, 0x44), p15 = _mm256_shuffle_ps(xy_low, z0_low, 0xee);
    const __m256 p26 = _mm256_shuffle_ps(xy_high, z0_high, 0x44), p37 = _mm256_shuffle_ps(xy_high, z0_high, 0xee);
    _mm256_storeu_ps(out, _mm256_permute2f128_ps(p04, p15, 0x20));       // points 0, 1
    _mm256_storeu_ps(out + 8, _mm256_permute2f128_ps(p26, p37, 0x20));   // points 2, 3
    _mm256_storeu_ps(out + 16, _mm256_permute2f128_ps(p04, p15, 0x31));  // points 4, 5
    _mm256_storeu_ps(out + 24, _mm256_permute2f128_ps(p26, p37, 0x31));  // points 6, 7
  }

  /// Vec3::squaredNorm: (x x + y y) + z z.
  FLOODPLANE_TARGET_AVX Float8 squaredNorm() const { return (x * x + y * y) + z * z; }

 private:
  // Points j (low half) and j + 4 (high half).
  FLOODPLANE_TARGET_AVX static __m256 loadPair(const float* first, std::size_t stride, std::size_t j) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(first + j * stride)),
                                _mm_loadu_ps(first + (j + 4) * stride), 1);
  }
};

#endif  // FLOODPLANE_AVX

}  // namespace floodplane
