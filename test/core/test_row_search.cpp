// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// findInRow and findUnlabelledNextToLabelled: the label scans' four-at-a-time searches must
// find what a pixel-by-pixel loop finds, wherever in a group of four the answer lies and
// however the row ends.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "util/row_search.h"

namespace floodplane {
namespace {

int pixelByPixel(const std::vector<std::int32_t>& row, int x, int x_end, std::int32_t label, bool equal) {
  while (x <= x_end && (row[static_cast<std::size_t>(x)] == label) != equal) ++x;
  return x;
}

TEST(RowSearch, FindsTheFirstMatchAtEveryOffsetOfAGroupOfFour) {
  for (int at = 0; at < 13; ++at) {
    std::vector<std::int32_t> row(13, 7);
    row[static_cast<std::size_t>(at)] = 3;
    EXPECT_EQ(findInRow(row.data(), 0, 12, 3, true), at);
    EXPECT_EQ(findInRow(row.data(), 0, 12, 7, false), at);
  }
}

TEST(RowSearch, ReturnsOnePastTheEndWhenNothingIsFound) {
  const std::vector<std::int32_t> row(11, 5);
  EXPECT_EQ(findInRow(row.data(), 0, 10, 4, true), 11);
  EXPECT_EQ(findInRow(row.data(), 0, 10, 5, false), 11);
  EXPECT_EQ(findInRow(row.data(), 3, 6, 4, true), 7);  // a range inside the row
  EXPECT_EQ(findInRow(row.data(), 6, 5, 5, true), 6);  // an empty range
}

TEST(RowSearch, NeverLooksPastTheRangeEnd) {
  // The matches lie just after x_end: they must not be found.
  const std::vector<std::int32_t> row = {1, 1, 1, 1, 1, 1, 2, 2, 2, 2};
  EXPECT_EQ(findInRow(row.data(), 0, 5, 2, true), 6);
  EXPECT_EQ(findInRow(row.data(), 1, 4, 1, false), 5);
}

TEST(RowSearch, AgreesWithAPixelByPixelScanOnRandomRows) {
  std::mt19937 random(42);
  std::uniform_int_distribution<int> label(0, 2);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<std::int32_t> row(1 + trial % 37);
    for (std::int32_t& l : row) l = label(random) == 0 ? 0 : 1;  // runs of both
    const int width = static_cast<int>(row.size());
    const int x = trial % width;
    const int x_end = width - 1 - (trial / 7) % (width - x);
    for (const bool equal : {true, false}) {
      ASSERT_EQ(findInRow(row.data(), x, x_end, 1, equal), pixelByPixel(row, x, x_end, 1, equal))
          << "trial " << trial << " equal " << equal;
    }
  }
}

TEST(RowSearch, WorksForUnsignedLabels) {
  const std::vector<std::uint32_t> row = {4, 4, 4, 4, 4, 0, 4};
  EXPECT_EQ(findInRow(row.data(), 0, 6, 0u, true), 5);
  EXPECT_EQ(findInRow(row.data(), 5, 6, 0u, false), 6);
}

TEST(RowSearch, FindsUnlabelledPixelsNextToLabelledOnesAsPixelByPixel) {
#if FLOODPLANE_SIMD
  // Every pattern of zero and non-zero labels over the four pixels, their left and right
  // neighbours and the four above and below (14 labels), with non-zero labels that differ in
  // sign and size; against the definition, pixel by pixel.
  const std::uint32_t nonzero[] = {1u, 0x80000000u, 0xffffffffu, 12345u};
  for (unsigned pattern = 0; pattern < (1u << 14); ++pattern) {
    const auto label = [&](int bit) { return (pattern >> bit) & 1u ? nonzero[(pattern + bit) % 4] : 0u; };
    std::uint32_t row[6], above[4], below[4];  // row[1 .. 4] are the four pixels
    for (int j = 0; j < 6; ++j) row[j] = label(j);
    for (int j = 0; j < 4; ++j) above[j] = label(6 + j), below[j] = label(10 + j);
    int expected = 0;
    for (int j = 0; j < 4; ++j) {
      const std::uint32_t* p = row + 1 + j;
      if (*p == 0 && (p[-1] | p[1] | above[j] | below[j]) != 0) expected |= 1 << j;
    }
    ASSERT_EQ(unlabelledNextToLabelled(row + 1, above, below), expected) << pattern;
  }
#else
  GTEST_SKIP() << "built without SIMD: there is no four-at-a-time search to compare";
#endif
}

// The definition of findUnlabelledNextToLabelled, pixel by pixel.
int unlabelledNextToLabelledPixelByPixel(const std::vector<std::uint32_t>& row, const std::uint32_t* above,
                                         const std::uint32_t* below, int x, int width) {
  for (; x < width; ++x) {
    const std::size_t i = static_cast<std::size_t>(x);
    const std::uint32_t left = x > 0 ? row[i - 1] : 0u, right = x + 1 < width ? row[i + 1] : 0u;
    if (row[i] == 0 && (left | right | above[i] | below[i]) != 0) return x;
  }
  return width;
}

TEST(RowSearch, FindsUnlabelledPixelsNextToLabelledOnesFromEveryStart) {
  // Random rows of every width up to 21 and a frame's, sparsely to densely labelled, with rows
  // above and below or without (the row itself passed instead); from every start.
  std::mt19937 rng(17);
  for (const double labelled : {0.05, 0.3, 0.7, 0.95}) {
    std::bernoulli_distribution is_labelled(labelled);
    std::vector<int> widths = {640};
    for (int w = 1; w <= 21; ++w) widths.push_back(w);
    for (const int w : widths) {
      for (int trial = 0; trial < 20; ++trial) {
        std::vector<std::uint32_t> rows[3];
        for (auto& r : rows) {
          r.resize(static_cast<std::size_t>(w));
          for (auto& label : r) label = is_labelled(rng) ? 1u + static_cast<std::uint32_t>(rng() % 3u) : 0u;
        }
        const std::uint32_t* above = trial % 3 == 0 ? rows[1].data() : rows[0].data();
        const std::uint32_t* below = trial % 4 == 0 ? rows[1].data() : rows[2].data();
        for (int x = 0; x <= w; ++x)
          ASSERT_EQ(findUnlabelledNextToLabelled(rows[1].data(), above, below, x, w),
                    unlabelledNextToLabelledPixelByPixel(rows[1], above, below, x, w))
              << "width " << w << ", start " << x << ", labelled " << labelled;
      }
    }
  }
}

}  // namespace
}  // namespace floodplane
