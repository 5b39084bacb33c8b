// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "segmenter/region_boundary.h"

#include "floodplane/segmentation.h"

namespace floodplane {

namespace {
// Clockwise on screen with y down: E, SE, S, SW, W, NW, N, NE.
constexpr int kDx[8] = {1, 1, 0, -1, -1, -1, 0, 1};
constexpr int kDy[8] = {0, 1, 1, 1, 0, -1, -1, -1};
}  // namespace

void traceRegionBoundary(const std::uint32_t* labels, int width, int height, std::uint32_t label, std::size_t start,
                         std::vector<int>& contour) {
  const auto inside = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < width && y < height && labels[static_cast<std::size_t>(y) * width + x] == label;
  };
  const int start_x = static_cast<int>(start % static_cast<std::size_t>(width));
  const int start_y = static_cast<int>(start / static_cast<std::size_t>(width));
  contour.push_back(static_cast<int>(start));

  // From (x, y), whose neighbour in direction `backtrack` is outside, the next boundary
  // pixel clockwise; returns its direction or -1 for an isolated pixel.
  const auto next = [&](int x, int y, int backtrack) {
    for (int k = 1; k <= 8; ++k) {
      const int d = (backtrack + k) & 7;
      if (inside(x + kDx[d], y + kDy[d])) return d;
    }
    return -1;
  };

  // The start is a pixel whose west neighbour is outside (the first pixel in raster order, or
  // the left end of a row of the region).
  const int first = next(start_x, start_y, 4);
  if (first < 0) return;
  int x = start_x, y = start_y, direction = first;
  // Every boundary pixel is entered at most from each of 8 directions; the bound only
  // guards against a malformed `start`.
  const std::size_t step_limit = 8 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height) + 8;
  for (std::size_t step = 0; step < step_limit; ++step) {
    x += kDx[direction];
    y += kDy[direction];
    // The pixel examined just before the move, seen from the new position.
    const int backtrack = (direction & 1) ? (direction + 5) & 7 : (direction + 6) & 7;
    const int following = next(x, y, backtrack);
    // Jacob's criterion: back at the start, about to repeat the first move.
    if (x == start_x && y == start_y && following == first) return;
    contour.push_back(y * width + x);
    direction = following;
  }
}

void Segmentation::boundary(std::size_t plane, std::vector<int>& contour) const {
  traceRegionBoundary(labels.data(), width, height, static_cast<std::uint32_t>(plane + 1), planes[plane].first_pixel,
                      contour);
}

}  // namespace floodplane
