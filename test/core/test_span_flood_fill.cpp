// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-A: the span flood fill finds exactly the 4-connected region and examines each
// pixel about once, where a four-neighbour fill examines it four times.
#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <string>
#include <vector>

#include "util/span_flood_fill.h"

namespace floodplane {
namespace {

// A binary image from string art: '#' is inside.
struct Mask {
  int width = 0;
  int height = 0;
  std::vector<bool> inside;

  explicit Mask(const std::vector<std::string>& rows)
      : width(static_cast<int>(rows[0].size())), height(static_cast<int>(rows.size())) {
    for (const std::string& row : rows)
      for (char c : row) inside.push_back(c == '#');
  }
  Mask(int w, int h, bool value) : width(w), height(h), inside(static_cast<std::size_t>(w) * h, value) {}
};

// The visitor: joins pixels that are inside the mask; counts every examination.
struct CountingVisitor {
  const Mask& mask;
  std::vector<bool> in_region;
  std::size_t attempts = 0;

  explicit CountingVisitor(const Mask& m) : mask(m), in_region(m.inside.size(), false) {}
  bool join(std::size_t from, std::size_t to) {
    ++attempts;
    EXPECT_TRUE(in_region[from]) << "joined from a pixel outside the region";
    if (in_region[to] || !mask.inside[to]) return false;
    in_region[to] = true;
    return true;
  }
  int joinRun(std::size_t from, int step, int max) { return joinRunPixelByPixel(*this, from, step, max); }
  void prefetch(std::size_t first, std::size_t last) const {
    // A shadow: pixels of one row of the grid.
    EXPECT_LE(first, last);
    EXPECT_LT(last, mask.inside.size());
    EXPECT_EQ(first / static_cast<std::size_t>(mask.width), last / static_cast<std::size_t>(mask.width));
  }
};

// Reference: breadth-first four-neighbour fill; returns the region and counts examinations.
std::vector<bool> naiveFill(const Mask& mask, int x, int y, std::size_t& attempts) {
  std::vector<bool> region(mask.inside.size(), false);
  std::deque<std::pair<int, int>> queue{{x, y}};
  region[static_cast<std::size_t>(y) * mask.width + x] = true;
  attempts = 0;
  while (!queue.empty()) {
    const auto [px, py] = queue.front();
    queue.pop_front();
    const int dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nx = px + dx[k], ny = py + dy[k];
      if (nx < 0 || ny < 0 || nx >= mask.width || ny >= mask.height) continue;
      ++attempts;
      const std::size_t i = static_cast<std::size_t>(ny) * mask.width + nx;
      if (region[i] || !mask.inside[i]) continue;
      region[i] = true;
      queue.emplace_back(nx, ny);
    }
  }
  return region;
}

std::size_t countTrue(const std::vector<bool>& v) {
  std::size_t n = 0;
  for (bool b : v) n += b;
  return n;
}

CountingVisitor fill(const Mask& mask, int x, int y) {
  CountingVisitor visitor(mask);
  visitor.in_region[static_cast<std::size_t>(y) * mask.width + x] = true;
  std::vector<Shadow> shadows;
  spanFloodFill(mask.width, mask.height, x, y, visitor, shadows);
  return visitor;
}

TEST(SpanFloodFill, ExaminesEachPixelOfAFullRectangleOnce) {
  const Mask mask(640, 480, true);
  const CountingVisitor visitor = fill(mask, 320, 240);
  EXPECT_EQ(countTrue(visitor.in_region), mask.inside.size());
  // The seed is in the region from the start; every other pixel is examined exactly once.
  EXPECT_EQ(visitor.attempts, mask.inside.size() - 1);
  std::size_t naive_attempts = 0;
  naiveFill(mask, 320, 240, naive_attempts);
  EXPECT_GT(static_cast<double>(naive_attempts),
            3.9 * static_cast<double>(mask.inside.size()));  // the four-neighbour fill
}

TEST(SpanFloodFill, FindsTheSameRegionAsAFourNeighbourFillOnAMaze) {
  const Mask mask({
      "#########.##########",
      "#.......#.#........#",
      "#.#####.#.#.######.#",
      "#.#...#.###.#....#.#",
      "#.#.#.#.....#.##.#.#",
      "#.#.#.#######.#..#.#",
      "#...#.........#.##.#",
      "#####.#########....#",
      "......#.....########",
      "####..#.###.........",
  });
  std::size_t naive_attempts = 0;
  const std::vector<bool> expected = naiveFill(mask, 0, 0, naive_attempts);
  const CountingVisitor visitor = fill(mask, 0, 0);
  EXPECT_EQ(visitor.in_region, expected);
  EXPECT_LT(visitor.attempts, naive_attempts);
}

TEST(SpanFloodFill, StaysOutOfPixelsOnlyDiagonallyConnected) {
  const Mask mask({
      "##..",
      "##..",
      "..##",
      "..##",
  });
  const CountingVisitor visitor = fill(mask, 0, 0);
  EXPECT_EQ(countTrue(visitor.in_region), 4u);
  EXPECT_FALSE(visitor.in_region[2 * 4 + 2]);
}

TEST(SpanFloodFill, ExaminesPixelsAboutOnceOnIrregularShapes) {
  // A disc with holes and a ragged border: the span fill stays far below four examinations
  // per pixel (the paper: "a little more than one time on average").
  Mask mask(200, 150, false);
  for (int y = 0; y < mask.height; ++y) {
    for (int x = 0; x < mask.width; ++x) {
      const double dx = x - 100, dy = y - 75;
      const bool in_disc = dx * dx + dy * dy < 70.0 * 70.0 + 300.0 * std::sin(x * 0.7) * std::cos(y * 0.5);
      const bool in_hole = (x / 10 + y / 10) % 7 == 0 && x % 10 > 3 && y % 10 > 3;
      mask.inside[static_cast<std::size_t>(y) * mask.width + x] = in_disc && !in_hole;
    }
  }
  std::size_t naive_attempts = 0;
  const std::vector<bool> expected = naiveFill(mask, 100, 75, naive_attempts);
  const CountingVisitor visitor = fill(mask, 100, 75);
  ASSERT_EQ(visitor.in_region, expected);
  const double per_pixel = static_cast<double>(visitor.attempts) / static_cast<double>(countTrue(expected));
  EXPECT_LT(per_pixel, 1.6);
  EXPECT_GT(static_cast<double>(naive_attempts) / static_cast<double>(countTrue(expected)), 3.5);
}

TEST(SpanFloodFill, FillsARingAroundAHole) {
  const Mask mask({
      "###",
      "#.#",
      "###",
  });
  const CountingVisitor visitor = fill(mask, 0, 0);
  EXPECT_EQ(countTrue(visitor.in_region), 8u);  // the middle row has two spans
}

TEST(SpanFloodFill, WorksOnSinglePixelsRowsAndColumns) {
  const Mask pixel(1, 1, true);
  EXPECT_EQ(fill(pixel, 0, 0).attempts, 0u);
  const Mask row(7, 1, true);
  const CountingVisitor in_row = fill(row, 3, 0);
  EXPECT_EQ(countTrue(in_row.in_region), 7u);
  EXPECT_EQ(in_row.attempts, 6u);
  const Mask column(1, 9, true);
  const CountingVisitor in_column = fill(column, 0, 8);
  EXPECT_EQ(countTrue(in_column.in_region), 9u);
  EXPECT_EQ(in_column.attempts, 8u);
}

}  // namespace
}  // namespace floodplane
