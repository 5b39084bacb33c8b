// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The contours of the output (OMPS's boundary indices): Moore-neighbour tracing of a labelled
// region's outer boundary.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "segmenter/region_boundary.h"

namespace floodplane {
namespace {

// A label image from string art: '.' is 0, digits are labels.
struct Labels {
  int width = 0;
  int height = 0;
  std::vector<std::uint32_t> data;

  explicit Labels(const std::vector<std::string>& rows)
      : width(static_cast<int>(rows[0].size())), height(static_cast<int>(rows.size())) {
    for (const std::string& row : rows)
      for (char c : row) data.push_back(c == '.' ? 0u : static_cast<std::uint32_t>(c - '0'));
  }
  // The first pixel of `label` in raster order.
  std::size_t first(std::uint32_t label) const {
    for (std::size_t i = 0; i < data.size(); ++i)
      if (data[i] == label) return i;
    ADD_FAILURE() << "no pixel with label " << label;
    return 0;
  }
  std::vector<int> trace(std::uint32_t label) const {
    std::vector<int> contour;
    traceRegionBoundary(data.data(), width, height, label, first(label), contour);
    return contour;
  }
  int index(int x, int y) const { return y * width + x; }
};

using Pixels = std::vector<std::pair<int, int>>;

Pixels toXY(const std::vector<int>& contour, int width) {
  Pixels xy;
  for (int i : contour) xy.emplace_back(i % width, i / width);
  return xy;
}

// Consecutive pixels, and the last and the first, are 8-neighbours (and distinct).
void expectClosedEightConnectedChain(const Pixels& xy) {
  ASSERT_FALSE(xy.empty());
  if (xy.size() == 1) return;
  for (std::size_t k = 0; k < xy.size(); ++k) {
    const auto [x0, y0] = xy[k];
    const auto [x1, y1] = xy[(k + 1) % xy.size()];
    const int dx = std::abs(x1 - x0), dy = std::abs(y1 - y0);
    EXPECT_TRUE(dx <= 1 && dy <= 1 && dx + dy > 0)
        << "step " << k << ": (" << x0 << ", " << y0 << ") -> (" << x1 << ", " << y1 << ")";
  }
}

// Twice the signed area by the shoelace formula; positive for clockwise on screen (y down).
long twiceSignedArea(const Pixels& xy) {
  long area = 0;
  for (std::size_t k = 0; k < xy.size(); ++k) {
    const auto [x0, y0] = xy[k];
    const auto [x1, y1] = xy[(k + 1) % xy.size()];
    area += static_cast<long>(x0) * y1 - static_cast<long>(x1) * y0;
  }
  return area;
}

TEST(TraceRegionBoundary, GivesTheBorderOfARectangleClockwiseFromItsFirstPixel) {
  const Labels labels({
      "......",
      ".1111.",
      ".1111.",
      ".1111.",
      "......",
  });
  const Pixels xy = toXY(labels.trace(1), labels.width);
  const Pixels expected = {{1, 1}, {2, 1}, {3, 1}, {4, 1}, {4, 2}, {4, 3}, {3, 3}, {2, 3}, {1, 3}, {1, 2}};
  EXPECT_EQ(xy, expected);
  expectClosedEightConnectedChain(xy);
  EXPECT_GT(twiceSignedArea(xy), 0) << "clockwise on screen";
}

TEST(TraceRegionBoundary, VisitsEachBorderPixelOfARectangleOnce) {
  // 2w + 2h - 4 border pixels for a w x h rectangle; the interior never appears.
  Labels labels(std::vector<std::string>(9, std::string(12, '.')));
  for (int y = 2; y <= 7; ++y)
    for (int x = 3; x <= 10; ++x) labels.data[labels.index(x, y)] = 4;
  const std::vector<int> contour = labels.trace(4);
  EXPECT_EQ(contour.size(), 2u * 8 + 2u * 6 - 4);
  EXPECT_EQ(std::set<int>(contour.begin(), contour.end()).size(), contour.size());
  for (const auto& [x, y] : toXY(contour, labels.width)) {
    EXPECT_TRUE(x == 3 || x == 10 || y == 2 || y == 7) << "(" << x << ", " << y << ") is interior";
  }
  expectClosedEightConnectedChain(toXY(contour, labels.width));
}

TEST(TraceRegionBoundary, GivesASinglePixelOnce) {
  const Labels labels({
      "...",
      ".2.",
      "...",
  });
  EXPECT_EQ(labels.trace(2), std::vector<int>{labels.index(1, 1)});
}

TEST(TraceRegionBoundary, AppendsToTheContourItIsGiven) {
  const Labels labels({"2"});
  std::vector<int> contour = {42};
  traceRegionBoundary(labels.data.data(), labels.width, labels.height, 2, 0, contour);
  EXPECT_EQ(contour, (std::vector<int>{42, 0}));
}

TEST(TraceRegionBoundary, TracesARegionThatFillsTheWholeGrid) {
  const Labels labels({
      "333",
      "333",
      "333",
  });
  const Pixels xy = toXY(labels.trace(3), labels.width);
  const Pixels expected = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_EQ(xy, expected);
}

TEST(TraceRegionBoundary, StaysInsideTheGridAtTheRightAndBottomBorders) {
  // An L in the bottom-right corner: its pixels on the last row and column have neighbours
  // beyond the grid, which count as outside.
  const Labels labels({
      "....",
      "...1",
      "..11",
  });
  const Pixels xy = toXY(labels.trace(1), labels.width);
  const Pixels expected = {{3, 1}, {3, 2}, {2, 2}};
  EXPECT_EQ(xy, expected);
  expectClosedEightConnectedChain(xy);
}

TEST(TraceRegionBoundary, GivesOnlyTheOuterBoundaryOfARegionWithAHole) {
  // A 7 x 7 square with a one-pixel hole: the outer ring of 24 pixels, not the 8 pixels
  // around the hole.
  Labels labels(std::vector<std::string>(9, std::string(9, '.')));
  for (int y = 1; y <= 7; ++y)
    for (int x = 1; x <= 7; ++x) labels.data[labels.index(x, y)] = 5;
  labels.data[labels.index(4, 4)] = 0;
  const Pixels xy = toXY(labels.trace(5), labels.width);
  EXPECT_EQ(xy.size(), 24u);
  for (const auto& [x, y] : xy) {
    EXPECT_TRUE(x == 1 || x == 7 || y == 1 || y == 7) << "(" << x << ", " << y << ") is not on the outer border";
  }
  expectClosedEightConnectedChain(xy);
}

TEST(TraceRegionBoundary, IgnoresNeighbouringRegionsOfOtherLabels) {
  const Labels labels({
      "11122",
      "11222",
      "11122",
  });
  const Pixels xy = toXY(labels.trace(1), labels.width);
  const Pixels expected = {{0, 0}, {1, 0}, {2, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_EQ(xy, expected);
  expectClosedEightConnectedChain(xy);
}

TEST(TraceRegionBoundary, VisitsAOnePixelNeckTwice) {
  // Two 2 x 2 blocks joined only at a corner (8-connected): the path goes out through the
  // neck and back, so (1, 1) and (2, 2) appear twice.
  const Labels labels({
      "11..",
      "11..",
      "..11",
      "..11",
  });
  const Pixels xy = toXY(labels.trace(1), labels.width);
  const Pixels expected = {{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 2}, {3, 3}, {2, 3}, {2, 2}, {1, 1}, {0, 1}};
  EXPECT_EQ(xy, expected);
  expectClosedEightConnectedChain(xy);
}

TEST(TraceRegionBoundary, WalksAOnePixelWideLineThereAndBack) {
  const Labels labels({
      ".....",
      ".777.",
      ".....",
  });
  const Pixels xy = toXY(labels.trace(7), labels.width);
  const Pixels expected = {{1, 1}, {2, 1}, {3, 1}, {2, 1}};
  EXPECT_EQ(xy, expected);
}

TEST(TraceRegionBoundary, FollowsAConcaveOutline) {
  // A U: the boundary runs down into the notch and back up.
  const Labels labels({
      "1.1",
      "1.1",
      "111",
  });
  const Pixels xy = toXY(labels.trace(1), labels.width);
  const Pixels expected = {{0, 0}, {0, 1}, {1, 2}, {2, 1}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  EXPECT_EQ(xy, expected);
  expectClosedEightConnectedChain(xy);
}

}  // namespace
}  // namespace floodplane
