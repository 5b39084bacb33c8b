#pragma once

#include <cstdint>
#include <type_traits>

#include "simd.h"

namespace floodplane {

/// The first x in [x, x_end] of a row of 32-bit labels where the label is `label` (`equal`)
/// or is not (!`equal`); x_end + 1 if there is none. Four labels at a time where SIMD is
/// there: the label scans (components of a segment in its bounding box, unlabelled pixels to
/// refine) pass over long runs of pixels that do not interest them.
template <class Label>
int findInRow(const Label* row, int x, int x_end, Label label, bool equal) {
  static_assert(sizeof(Label) == 4 && std::is_integral_v<Label>, "32-bit labels");
#if FLOODPLANE_SIMD
  for (; x + 3 <= x_end; x += 4) {
    if (equal ? anyLabelEquals(row + x, label) : anyLabelDiffers(row + x, label)) break;
  }
#endif
  while (x <= x_end && (row[x] == label) != equal) ++x;
  return x;
}

}  // namespace floodplane
