// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-B's relabelling: union-find and the splitting of a label into its 4-connected
// pieces after later floods took pixels from it.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "flood/component_splitter.h"
#include "util/union_find.h"

namespace floodplane {
namespace {

// --- UnionFind -------------------------------------------------------------------------------

TEST(UnionFind, StartsWithEveryElementItsOwnSet) {
  UnionFind sets;
  sets.reset(5);
  for (std::int32_t i = 0; i < 5; ++i) EXPECT_EQ(sets.find(i), i);
}

TEST(UnionFind, UniteJoinsTwoSetsAndReturnsTheirRoot) {
  UnionFind sets;
  sets.reset(4);
  const std::int32_t root = sets.unite(1, 3);
  EXPECT_EQ(sets.find(1), root);
  EXPECT_EQ(sets.find(3), root);
  EXPECT_NE(sets.find(0), root);
  EXPECT_NE(sets.find(2), root);
  EXPECT_NE(sets.find(0), sets.find(2));
}

TEST(UnionFind, IsTransitive) {
  UnionFind sets;
  sets.reset(6);
  sets.unite(0, 1);
  sets.unite(4, 5);
  EXPECT_NE(sets.find(1), sets.find(4));
  sets.unite(1, 4);
  EXPECT_EQ(sets.find(0), sets.find(5));
  EXPECT_NE(sets.find(2), sets.find(0));
  EXPECT_NE(sets.find(3), sets.find(0));
}

TEST(UnionFind, UnitingTwoMembersOfOneSetChangesNothing) {
  UnionFind sets;
  sets.reset(3);
  const std::int32_t root = sets.unite(0, 1);
  EXPECT_EQ(sets.unite(1, 0), root);
  EXPECT_EQ(sets.find(2), 2);
}

TEST(UnionFind, TheSmallerRootWinsBetweenEqualSizesWhateverTheArgumentOrder) {
  UnionFind a, b;
  a.reset(4);
  b.reset(4);
  EXPECT_EQ(a.unite(2, 3), 2);
  EXPECT_EQ(b.unite(3, 2), 2);
}

TEST(UnionFind, TheLargerSetsRootSurvives) {
  UnionFind sets;
  sets.reset(5);
  sets.unite(3, 4);                // {3, 4}, root 3
  EXPECT_EQ(sets.unite(0, 4), 3);  // {0} joins the larger set, despite 0 < 3
  EXPECT_EQ(sets.find(0), 3);
}

TEST(UnionFind, FindStaysCorrectWhilePathsAreCompressed) {
  // A tree of depth three: 7 -> 6 -> 4 -> 0. Finding the deepest element halves its path;
  // every later find must still give the same root, for every element.
  UnionFind sets;
  sets.reset(9);
  sets.unite(0, 1);
  sets.unite(2, 3);
  sets.unite(4, 5);
  sets.unite(6, 7);
  sets.unite(0, 2);
  sets.unite(4, 6);
  sets.unite(0, 4);
  for (int repeat = 0; repeat < 3; ++repeat) {
    EXPECT_EQ(sets.find(7), 0);
    for (std::int32_t i = 0; i < 8; ++i) EXPECT_EQ(sets.find(i), 0) << "element " << i;
    EXPECT_EQ(sets.find(8), 8);
  }
}

TEST(UnionFind, AddAppendsASingleton) {
  UnionFind sets;
  sets.reset(0);
  EXPECT_EQ(sets.add(), 0);
  EXPECT_EQ(sets.add(), 1);
  EXPECT_EQ(sets.find(1), 1);
  sets.unite(0, 1);
  EXPECT_EQ(sets.find(1), 0);
}

TEST(UnionFind, ResetForgetsEarlierUnions) {
  UnionFind sets;
  sets.reset(3);
  sets.unite(0, 2);
  sets.reset(3);
  EXPECT_EQ(sets.find(2), 2);
}

// --- ComponentSplitter -------------------------------------------------------------------------

// A label image from string art: '.' is 0, digits and letters are labels (a = 10, ...).
struct Labels {
  int width = 0;
  int height = 0;
  std::vector<std::int32_t> data;

  explicit Labels(const std::vector<std::string>& rows)
      : width(static_cast<int>(rows[0].size())), height(static_cast<int>(rows.size())) {
    for (const std::string& row : rows)
      for (char c : row) data.push_back(c == '.' ? 0 : c <= '9' ? c - '0' : c - 'a' + 10);
  }
  std::int32_t at(int x, int y) const { return data[static_cast<std::size_t>(y) * width + x]; }
  // Splits `label` as the relabelling does: from its runs, collected in one pass.
  std::vector<std::int32_t> split(ComponentSplitter& splitter, std::int32_t label, std::int32_t& next) {
    std::vector<bool> wanted(static_cast<std::size_t>(label) + 1, false);
    wanted[static_cast<std::size_t>(label)] = true;
    RunsByLabel runs;
    runs.collect(data.data(), width, height, wanted);
    return splitter.split(data.data(), width, runs.runs(label), runs.count(label), label, next);
  }
  std::vector<std::string> art() const {
    std::vector<std::string> rows;
    for (int y = 0; y < height; ++y) {
      std::string row;
      for (int x = 0; x < width; ++x) {
        const std::int32_t v = at(x, y);
        row += v == 0 ? '.' : v < 10 ? static_cast<char>('0' + v) : static_cast<char>('a' + v - 10);
      }
      rows.push_back(row);
    }
    return rows;
  }
};

TEST(ComponentSplitter, KeepsAUShapeAsOnePiece) {
  // The two arms start as separate provisional sets and meet only in the bottom row.
  Labels labels({
      ".......",
      ".1...1.",
      ".1...1.",
      ".11111.",
      ".......",
  });
  const Labels before = labels;
  ComponentSplitter splitter;
  std::int32_t next = 5;
  const std::vector<std::int32_t> created = labels.split(splitter, 1, next);
  EXPECT_TRUE(created.empty());
  EXPECT_EQ(next, 5);
  EXPECT_EQ(labels.art(), before.art());
}

TEST(ComponentSplitter, KeepsACombWhoseTeethJoinOnlyInTheLastRowAsOnePiece) {
  // Three provisional sets are chained together only at the bottom: the second pass must
  // follow the unions to one root.
  Labels labels({
      "1.1.1",
      "1.1.1",
      "11111",
  });
  const Labels before = labels;
  ComponentSplitter splitter;
  std::int32_t next = 2;
  EXPECT_TRUE(labels.split(splitter, 1, next).empty());
  EXPECT_EQ(next, 2);
  EXPECT_EQ(labels.art(), before.art());
}

TEST(ComponentSplitter, SplitsTwoBlobsAndNumbersTheSecondFromNextLabel) {
  Labels labels({
      "11....",
      "11..11",
      "....11",
  });
  ComponentSplitter splitter;
  std::int32_t next = 7;
  const std::vector<std::int32_t> created = labels.split(splitter, 1, next);
  EXPECT_EQ(created, std::vector<std::int32_t>{7});
  EXPECT_EQ(next, 8);
  EXPECT_EQ(labels.art(), (std::vector<std::string>{
                              "11....",
                              "11..77",
                              "....77",
                          }));
}

TEST(ComponentSplitter, TreatsDiagonalContactAsTwoPieces) {
  Labels labels({
      "1.",
      ".1",
  });
  ComponentSplitter splitter;
  std::int32_t next = 3;
  const std::vector<std::int32_t> created = labels.split(splitter, 1, next);
  EXPECT_EQ(created, std::vector<std::int32_t>{3});
  EXPECT_EQ(next, 4);
  EXPECT_EQ(labels.art(), (std::vector<std::string>{"1.", ".3"}));
}

TEST(ComponentSplitter, NumbersNewPiecesInRasterOrderOfTheirFirstPixel) {
  // Three pieces; the first in raster order keeps the label even though it is the smallest,
  // and the piece whose first pixel comes next gets next_label.
  ComponentSplitter splitter;
  std::int32_t next = 4;
  Labels three({
      "..2.....",
      "......22",
      "2222..2.",
      "2.....2.",
  });
  const std::vector<std::int32_t> made = three.split(splitter, 2, next);
  EXPECT_EQ(made, (std::vector<std::int32_t>{4, 5}));
  EXPECT_EQ(next, 6);
  EXPECT_EQ(three.art(), (std::vector<std::string>{
                             "..2.....",
                             "......44",
                             "5555..4.",
                             "5.....4.",
                         }));
}

TEST(ComponentSplitter, LeavesPixelsOfOtherLabelsUntouched) {
  // Segment 3 cut in two by segment 5, which took the middle column; 0 and 9 stay as well.
  Labels labels({
      "33533",
      "33533",
      "9.5..",
  });
  ComponentSplitter splitter;
  std::int32_t next = 10;
  const std::vector<std::int32_t> created = labels.split(splitter, 3, next);
  EXPECT_EQ(created, std::vector<std::int32_t>{10});
  EXPECT_EQ(labels.art(), (std::vector<std::string>{
                              "335aa",
                              "335aa",
                              "9.5..",
                          }));
}

TEST(ComponentSplitter, HandlesPiecesAtTheGridBorder) {
  // Pieces in the grid's corners: first and last row and column.
  Labels labels({
      "1...1",
      ".....",
      "1...1",
  });
  ComponentSplitter splitter;
  std::int32_t next = 2;
  const std::vector<std::int32_t> created = labels.split(splitter, 1, next);
  EXPECT_EQ(created, (std::vector<std::int32_t>{2, 3, 4}));
  EXPECT_EQ(labels.art(), (std::vector<std::string>{
                              "1...2",
                              ".....",
                              "3...4",
                          }));
}

TEST(ComponentSplitter, CanBeReusedAcrossCallsAndImageSizes) {
  ComponentSplitter splitter;
  Labels big({
      "1.1.1.1",
      ".......",
      "1.1.1.1",
  });
  std::int32_t next = 2;
  EXPECT_EQ(big.split(splitter, 1, next).size(), 7u);
  Labels small({
      "11",
      "11",
  });
  next = 2;
  EXPECT_TRUE(small.split(splitter, 1, next).empty());
  EXPECT_EQ(small.art(), (std::vector<std::string>{"11", "11"}));
}

TEST(ComponentSplitter, DoesNothingForAnAbsentLabel) {
  Labels labels({"1.1"});
  ComponentSplitter splitter;
  std::int32_t next = 2;
  EXPECT_TRUE(labels.split(splitter, 4, next).empty());
  EXPECT_EQ(next, 2);
  EXPECT_EQ(labels.art(), std::vector<std::string>{"1.1"});
}

// The relabelling finds the runs of every segment to split in one pass (RunsByLabel) and
// splits each from its runs; that must give what collecting each segment's runs afresh just
// before its split gives, in the same order, on images where segments interleave, skip rows
// and meet the borders, also after earlier splits have renumbered pixels.
TEST(ComponentSplitter, SplittingFromRunsCollectedOnceEqualsCollectingThemBeforeEachSplit) {
  std::uint32_t state = 12345;
  const auto random = [&state](std::uint32_t n) {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) % n;
  };
  for (int image = 0; image < 20; ++image) {
    const int width = 5 + static_cast<int>(random(40)), height = 3 + static_cast<int>(random(30));
    const std::int32_t labels_used = 1 + static_cast<std::int32_t>(random(6));
    std::vector<std::int32_t> afresh(static_cast<std::size_t>(width) * height);
    // Blobs: each pixel copies its left or upper neighbour most of the time.
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        const std::size_t i = static_cast<std::size_t>(y) * width + x;
        const std::uint32_t r = random(10);
        afresh[i] = r < 4 && x > 0   ? afresh[i - 1]
                    : r < 8 && y > 0 ? afresh[i - static_cast<std::size_t>(width)]
                                     : static_cast<std::int32_t>(random(static_cast<std::uint32_t>(labels_used) + 1));
      }
    }
    std::vector<std::int32_t> once = afresh;
    std::vector<bool> wanted(static_cast<std::size_t>(labels_used) + 1, false);
    for (std::int32_t label = 1; label <= labels_used; ++label)
      wanted[static_cast<std::size_t>(label)] = random(4) != 0;
    RunsByLabel runs_once;
    runs_once.collect(once.data(), width, height, wanted);
    ComponentSplitter once_splitter, afresh_splitter;
    std::int32_t next_once = labels_used + 1, next_afresh = labels_used + 1;
    for (std::int32_t label = 1; label <= labels_used; ++label) {
      if (!wanted[static_cast<std::size_t>(label)]) continue;
      std::vector<bool> only(static_cast<std::size_t>(label) + 1, false);
      only[static_cast<std::size_t>(label)] = true;
      RunsByLabel runs_now;
      runs_now.collect(afresh.data(), width, height, only);
      const std::size_t smallest = 1 + random(3);
      EXPECT_EQ(once_splitter.split(once.data(), width, runs_once.runs(label), runs_once.count(label), label, next_once,
                                    smallest),
                afresh_splitter.split(afresh.data(), width, runs_now.runs(label), runs_now.count(label), label,
                                      next_afresh, smallest))
          << "image " << image << ", label " << label;
      EXPECT_EQ(once_splitter.releasedPixels(), afresh_splitter.releasedPixels());
      ASSERT_EQ(once_splitter.runs().size(), afresh_splitter.runs().size());
      for (std::size_t r = 0; r < afresh_splitter.runs().size(); ++r) {
        const ComponentSplitter::Run &a = once_splitter.runs()[r], &b = afresh_splitter.runs()[r];
        EXPECT_EQ(std::tie(a.y, a.x_begin, a.x_end, a.set), std::tie(b.y, b.x_begin, b.x_end, b.set));
      }
    }
    EXPECT_EQ(next_once, next_afresh);
    EXPECT_EQ(once, afresh) << "image " << image;
  }
}

}  // namespace
}  // namespace floodplane
