#pragma once

#include <cstdint>
#include <type_traits>

#if defined(__SSE2__) && !defined(FLOODPLANE_NO_SIMD)
#include <emmintrin.h>
#define FLOODPLANE_ROW_SEARCH_SSE2 1
#endif

namespace floodplane {

/// The first x in [x, x_end] of a row of 32-bit labels where the label is `label` (`equal`)
/// or is not (!`equal`); x_end + 1 if there is none. Four labels at a time where SSE2 is
/// there: the label scans (components of a segment in its bounding box, unlabelled pixels to
/// refine) pass over long runs of pixels that do not interest them.
template <class Label>
int findInRow(const Label* row, int x, int x_end, Label label, bool equal) {
  static_assert(sizeof(Label) == 4 && std::is_integral_v<Label>, "32-bit labels");
#if defined(FLOODPLANE_ROW_SEARCH_SSE2)
  const __m128i wanted = _mm_set1_epi32(static_cast<std::int32_t>(label));
  const int nothing_found = equal ? 0 : 0xffff;  // movemask of a block without what we look for
  for (; x + 3 <= x_end; x += 4) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(row + x));
    if (_mm_movemask_epi8(_mm_cmpeq_epi32(block, wanted)) != nothing_found) break;
  }
#endif
  while (x <= x_end && (row[x] == label) != equal) ++x;
  return x;
}

}  // namespace floodplane
