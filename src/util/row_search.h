// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "util/simd.h"

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

/// The first x in [x, width) of a row of labels (0: unlabelled) where the label is 0 and that
/// of a 4-neighbour is not: row[x - 1] and row[x + 1] (none beyond the row's ends), above[x]
/// and below[x] (pass `row` itself for a row the image does not have); `width` if there is
/// none. Four pixels at a time where SIMD is there: most unlabelled pixels of a frame (holes,
/// clutter, far walls) have no labelled neighbour.
inline int findUnlabelledNextToLabelled(const std::uint32_t* row, const std::uint32_t* above,
                                        const std::uint32_t* below, int x, int width) {
  while (x < width) {
#if FLOODPLANE_SIMD
    // Away from the row's ends, where the left and right neighbours of all four exist.
    if (x > 0 && x + 4 < width) {
      const int found = unlabelledNextToLabelled(row + x, above + x, below + x);
      if (found != 0) return x + __builtin_ctz(static_cast<unsigned>(found));
      x += 4;
      continue;
    }
#endif
    const std::uint32_t left = x > 0 ? row[x - 1] : 0u, right = x + 1 < width ? row[x + 1] : 0u;
    if (row[x] == 0 && (left | right | above[x] | below[x]) != 0) return x;
    ++x;
  }
  return width;
}

/// Calls f(label, begin, end) for every maximal run [begin, end) of one label in
/// row[x_begin .. x_last], left to right. The passes over a label image go run by run: it is
/// mostly long runs of one label, so their work is one lookup a run.
template <class Label, class F>
void forEachRunInRow(const Label* row, int x_begin, int x_last, F&& f) {
  for (int x = x_begin; x <= x_last;) {
    const int end = findInRow(row, x, x_last, row[x], false);
    f(row[x], x, end);
    x = end;
  }
}

/// forEachRunInRow over labels[begin, end) as one line (runs may cross row ends), with
/// f(label, begin, end) in indices of `labels`.
template <class Label, class F>
void forEachRun(const Label* labels, std::size_t begin, std::size_t end, F&& f) {
  constexpr std::size_t kLongestScan = std::numeric_limits<int>::max();  // findInRow counts in int
  std::size_t i = begin;
  while (i < end) {
    const std::size_t scan = std::min(end - i, kLongestScan);
    const std::size_t run_end =
        i + static_cast<std::size_t>(findInRow(labels + i, 0, static_cast<int>(scan) - 1, labels[i], false));
    f(labels[i], i, run_end);
    i = run_end;
  }
}

}  // namespace floodplane
