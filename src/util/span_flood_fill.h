// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <cstddef>
#include <vector>

/// For a visitor's join(): it runs once or twice per pixel of every flood, from three places
/// in the fill, and GCC does not inline a function of its size there by itself.
#if defined(__GNUC__) || defined(__clang__)
#define FLOODPLANE_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FLOODPLANE_ALWAYS_INLINE inline
#endif

namespace floodplane {

/// A run of pixels still to scan: row `y` over columns [x_begin, x_end], reached from row
/// y - direction, which is inside the region over the same columns (a "shadow" in the
/// terms of Sec. III-A and Fishkin/Heckbert). `direction` is the paper's kappa.
struct Shadow {
  int y;
  int x_begin;
  int x_end;
  int direction;  ///< +1: parent row is above, -1: parent row is below
};

/// joinRun as a loop over join, for visitors that decide one pixel at a time.
template <class Visitor>
int joinRunPixelByPixel(Visitor& visitor, std::size_t from, int step, int max) {
  int joined = 0;
  std::size_t pixel = from;
  while (joined < max) {
    const std::size_t next = step > 0 ? pixel + 1 : pixel - 1;
    if (!visitor.join(pixel, next)) break;
    pixel = next;
    ++joined;
  }
  return joined;
}

/// Scanline ("span") flood fill of Sec. III-A. Grows a 4-connected region from a pixel that
/// is already in it, a span at a time, so that each pixel is examined about once instead of
/// four times as in the naive recursive fill.
///
/// The visitor decides membership. `visitor.join(from, to)` examines pixel `to` (a linear
/// index) reached from its 4-neighbour `from`, which is in the region; it returns true and
/// marks `to` when `to` joins, and returns false for a pixel already in the region. Each
/// pixel of a span is decided by one comparison, with its left or right neighbour; the first
/// pixel of a span found in a shadow, with its neighbour in the parent row.
///
/// Spans are grown by `visitor.joinRun(from, step, max)`: it joins the pixels from + step,
/// from + 2 step, ... (step = +1 or -1: along the row) each from its predecessor, as
/// join would, up to `max` of them, stops at the first that does not join and returns how
/// many joined. A visitor that decides pixel by pixel gets it from joinRunPixelByPixel; one
/// that can decide several pixels at once (SIMD) does so there.
///
/// `visitor.prefetch(first, last)` is told of the pixels first..last (a shadow) when they are
/// queued: a fill moves from row to row, and each new row's pixels are a cache miss that the
/// visitor can ask the memory for while the fill works on the rows queued after it.
///
/// `shadows` is scratch space; pass the same vector every time to avoid allocation.
template <class Visitor>
void spanFloodFill(int width, int height, int seed_x, int seed_y, Visitor& visitor, std::vector<Shadow>& shadows) {
  const auto index = [width](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  };
  // Extends the span through (x, y) to the left and right, one comparison per pixel.
  const auto extendSpan = [&](int x, int y, int& left, int& right) {
    left = x - visitor.joinRun(index(x, y), -1, x);
    right = x + visitor.joinRun(index(x, y), +1, width - 1 - x);
  };
  const auto push = [&](int y, int x_begin, int x_end, int direction) {
    if (y >= 0 && y < height) {
      shadows.push_back({y, x_begin, x_end, direction});
      visitor.prefetch(index(x_begin, y), index(x_end, y));
    }
  };

  shadows.clear();
  int left = 0;
  int right = 0;
  extendSpan(seed_x, seed_y, left, right);
  push(seed_y + 1, left, right, +1);
  push(seed_y - 1, left, right, -1);

  while (!shadows.empty()) {
    const Shadow shadow = shadows.back();
    shadows.pop_back();
    const int y = shadow.y;
    const int parent_y = y - shadow.direction;
    int x = shadow.x_begin;
    while (x <= shadow.x_end) {
      if (!visitor.join(index(x, parent_y), index(x, y))) {
        ++x;
        continue;
      }
      extendSpan(x, y, left, right);
      push(y + shadow.direction, left, right, shadow.direction);
      // The span may reach past its parent; those parts cast shadows back ("turns", Fig. 2).
      if (left < shadow.x_begin) push(parent_y, left, shadow.x_begin - 1, -shadow.direction);
      if (right > shadow.x_end) push(parent_y, shadow.x_end + 1, right, -shadow.direction);
      // right + 1 failed against its left neighbour; it may still join from the parent row.
      x = right + 1;
    }
  }
}

}  // namespace floodplane
