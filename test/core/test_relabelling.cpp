// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// Sec. III-B, after the floods: the relabelling of segments that Eq. 4 takeovers cut apart.
// Hand-made label images (string art) over a pinhole grid: a segment cut in two becomes two
// segments with the sums of their own pixels, one still connected stays whole, crumbs are
// released, and new pieces get the neighbour edges they have in the image (Eq. 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "flood/relabelling.h"
#include "models/plane_candidates.h"
#include "support/pinhole_grid.h"

namespace floodplane {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr double kFocal = test::kPinholeFocal;

using Grid = test::PinholeGrid;

// A label image from string art: '.' is 0, digits are labels.
std::vector<std::int32_t> labelsFrom(const std::vector<std::string>& rows) {
  std::vector<std::int32_t> labels;
  for (const std::string& row : rows)
    for (const char c : row) labels.push_back(c == '.' ? 0 : c - '0');
  return labels;
}

// The frame's segments as the floods leave them: segment k owns the pixels labelled k (its
// sums), its criterion that of its plane; `lost` lists those a later flood took pixels from.
struct Frame {
  Grid grid;
  std::vector<std::int32_t> labels;
  std::vector<Segment> segments;
  std::vector<SegmentEdge> edges;
  Tolerances tolerances;

  Frame(
      const std::vector<std::string>& art, const std::vector<std::int32_t>& lost,
      const std::function<double(int, int)>& depth = [](int, int) { return 2.0; })
      : grid(static_cast<int>(art[0].size()), static_cast<int>(art.size()), depth), labels(labelsFrom(art)) {
    Params params;
    params.distance_threshold = 0.01;
    tolerances = Tolerances(params, {}, 1.0 / kFocal, grid.data.size() / 3);
    const std::int32_t count = labels.empty() ? 1 : *std::max_element(labels.begin(), labels.end()) + 1;
    segments.assign(static_cast<std::size_t>(count), Segment());
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (labels[i] == 0) continue;
      segments[static_cast<std::size_t>(labels[i])].sums.add(grid.point(i));
    }
    for (std::int32_t s = 1; s < count; ++s)
      segments[s].criterion = planeCriterion(segments[s].sums.fit(), tolerances, static_cast<float>(1.0 / kFocal));
    for (const std::int32_t s : lost) segments[s].lost_pixels = true;
  }

  void relabel(int subsampling = 1) { Relabelling().run(grid.grid(), subsampling, labels, segments, edges); }

  // The sums of the pixels labelled `label` now, from the points.
  PlaneSums sumsOf(std::int32_t label) const {
    PlaneSums sums;
    for (std::size_t i = 0; i < labels.size(); ++i)
      if (labels[i] == label) sums.add(grid.point(i));
    return sums;
  }
  std::vector<std::string> art() const {
    std::vector<std::string> rows;
    for (int y = 0; y < grid.height; ++y) {
      std::string row;
      for (int x = 0; x < grid.width; ++x) {
        const std::int32_t l = labels[grid.index(x, y)];
        row += l == 0 ? '.' : static_cast<char>('0' + l);
      }
      rows.push_back(row);
    }
    return rows;
  }
  bool hasEdge(std::int32_t a, std::int32_t b) const {
    return std::any_of(edges.begin(), edges.end(), [&](const SegmentEdge& e) {
      return (e.first == a && e.second == b) || (e.first == b && e.second == a);
    });
  }
};

void expectSameSums(const PlaneSums& actual, const PlaneSums& expected) {
  EXPECT_DOUBLE_EQ(actual.count, expected.count);
  EXPECT_NEAR(actual.sx, expected.sx, 1e-9);
  EXPECT_NEAR(actual.sy, expected.sy, 1e-9);
  EXPECT_NEAR(actual.sz, expected.sz, 1e-9);
  EXPECT_NEAR(actual.sxx, expected.sxx, 1e-9);
  EXPECT_NEAR(actual.syz, expected.syz, 1e-9);
  EXPECT_NEAR(actual.szz, expected.szz, 1e-9);
}

// Segment 1 covered the whole frame; segment 2's flood took a column through its middle.
const std::vector<std::string> kCutInTwo = {
    "1111211111",  //
    "1111211111",  //
    "1111211111",  //
    "1111211111",  //
    "1111211111",  //
};

TEST(Relabelling, SplitsASegmentCutInTwoIntoTwoSegments) {
  Frame f(kCutInTwo, {1});
  f.relabel();
  // The first piece in raster order keeps the label; the other is the next new segment.
  EXPECT_EQ(f.art(), (std::vector<std::string>{"1111233333", "1111233333", "1111233333", "1111233333", "1111233333"}));
  ASSERT_EQ(f.segments.size(), 4u);
  expectSameSums(f.segments[1].sums, f.sumsOf(1));
  expectSameSums(f.segments[3].sums, f.sumsOf(3));
  EXPECT_DOUBLE_EQ(f.segments[1].sums.count, 20.0);
  EXPECT_DOUBLE_EQ(f.segments[3].sums.count, 25.0);
  // Segment 2 did not lose pixels: untouched.
  EXPECT_DOUBLE_EQ(f.segments[2].sums.count, 5.0);
}

TEST(Relabelling, GivesTheNewPieceTheCriterionOfTheSegmentItCameFrom) {
  Frame f(kCutInTwo, {1});
  const FloodCriterion before = f.segments[1].criterion;
  f.relabel();
  ASSERT_EQ(f.segments.size(), 4u);
  const Segment& piece = f.segments[3];
  EXPECT_EQ(piece.criterion.offset, before.offset);
  EXPECT_EQ(piece.criterion.normal.z, before.normal.z);
  EXPECT_FALSE(piece.lost_pixels);
}

TEST(Relabelling, GivesTheNewPieceAnEdgeToTheSegmentItTouches) {
  Frame f(kCutInTwo, {1});
  f.edges.emplace_back(1, 2);  // the flood of 2 recorded its edge to 1
  f.relabel();
  EXPECT_TRUE(f.hasEdge(3, 2));
  EXPECT_FALSE(f.hasEdge(3, 1));  // the two pieces do not touch
  // Edges are only added: the one the flood recorded stays.
  EXPECT_EQ(f.edges.front(), SegmentEdge(1, 2));
  // Along a run the neighbour is one segment: one edge per run, not one per pixel.
  EXPECT_LE(f.edges.size(), 1u + 5u);
}

TEST(Relabelling, GivesNoEdgeWhereTheNeighbourIsNoThreeDimensionalNeighbour) {
  // Segment 2 is a column half a metre in front: pixel neighbours, but not 3-D neighbours
  // (Eq. 3).
  Frame f(kCutInTwo, {1}, [](int u, int) { return u == 4 ? 1.5 : 2.0; });
  f.relabel();
  ASSERT_EQ(f.segments.size(), 4u);
  EXPECT_FALSE(f.hasEdge(3, 2));
  EXPECT_TRUE(f.edges.empty());
}

TEST(Relabelling, LeavesASegmentThatLostPixelsButIsStillConnectedWhole) {
  const std::vector<std::string> art = {
      "1111111111",  //
      "1112221111",  //
      "1112221111",  //
      "1111111111",  //
  };
  Frame f(art, {1});
  const PlaneSums before = f.segments[1].sums;
  f.relabel();
  EXPECT_EQ(f.art(), art);
  EXPECT_EQ(f.segments.size(), 3u);
  expectSameSums(f.segments[1].sums, before);
  EXPECT_TRUE(f.edges.empty());
}

TEST(Relabelling, DoesNotSplitASegmentThatLostNoPixels) {
  // Two pieces of one label that no takeover made (not flagged): not the relabelling's to split.
  const std::vector<std::string> art = {
      "11122111",  //
      "11122111",  //
      "11122111",  //
      "11122111",  //
      "11122111",  //
      "11122111",  //
  };
  Frame f(art, {});
  f.relabel();
  EXPECT_EQ(f.art(), art);
  EXPECT_EQ(f.segments.size(), 3u);
}

TEST(Relabelling, TreatsDiagonalContactAsACut) {
  const std::vector<std::string> art = {
      "11112222",  //
      "11112222",  //
      "11112222",  //
      "11112222",  //
      "22221111",  //
      "22221111",  //
      "22221111",  //
      "22221111",  //
  };
  Frame f(art, {1});
  f.relabel();
  ASSERT_EQ(f.segments.size(), 4u);
  EXPECT_EQ(f.labels[f.grid.index(0, 0)], 1);
  EXPECT_EQ(f.labels[f.grid.index(7, 7)], 3);
  EXPECT_DOUBLE_EQ(f.segments[1].sums.count, 16.0);
  EXPECT_DOUBLE_EQ(f.segments[3].sums.count, 16.0);
}

TEST(Relabelling, SplitsEverySegmentThatFellApartAndNumbersThePiecesInSegmentOrder) {
  // Segment 3 cut both 1 and 2 in two.
  const std::vector<std::string> art = {
      "111131111",  //
      "111131111",  //
      "111131111",  //
      "111131111",  //
      "333333333",  //
      "222232222",  //
      "222232222",  //
      "222232222",  //
      "222232222",  //
  };
  Frame f(art, {1, 2});
  f.relabel();
  ASSERT_EQ(f.segments.size(), 6u);
  EXPECT_EQ(f.labels[f.grid.index(8, 0)], 4);  // 1's right piece
  EXPECT_EQ(f.labels[f.grid.index(8, 8)], 5);  // 2's right piece
  EXPECT_EQ(f.labels[f.grid.index(0, 8)], 2);
  for (std::int32_t s = 1; s <= 5; ++s) {
    SCOPED_TRACE(s);
    expectSameSums(f.segments[static_cast<std::size_t>(s)].sums, f.sumsOf(s));
  }
  EXPECT_TRUE(f.hasEdge(4, 3));
  EXPECT_TRUE(f.hasEdge(5, 3));
  EXPECT_FALSE(f.hasEdge(4, 5));
}

// A 2 x 2 crumb chipped off segment 1: 4 pixels.
const std::vector<std::string> kCrumb = {
    "11111111",  //
    "11111111",  //
    "11111111",  //
    "22222222",  //
    "22222211",  //
    "22222211",  //
};

TEST(Relabelling, ReleasesCrumbsSmallerThanSixteenPixels) {
  Frame f(kCrumb, {1});
  f.relabel();
  EXPECT_EQ(f.segments.size(), 3u);  // no new segment
  EXPECT_EQ(f.labels[f.grid.index(7, 5)], 0);
  EXPECT_EQ(f.labels[f.grid.index(6, 4)], 0);
  // What is left of segment 1 has the sums of its pixels.
  expectSameSums(f.segments[1].sums, f.sumsOf(1));
  EXPECT_DOUBLE_EQ(f.segments[1].sums.count, 24.0);
}

TEST(Relabelling, CountsCrumbsInFullResolutionPixelsWhenSubsampled) {
  // At s = 2 a sample stands for four pixels: the 4-sample crumb is 16 pixels, a piece.
  Frame two(kCrumb, {1});
  two.relabel(2);
  ASSERT_EQ(two.segments.size(), 4u);
  EXPECT_EQ(two.labels[two.grid.index(7, 5)], 3);
  EXPECT_DOUBLE_EQ(two.segments[3].sums.count, 4.0);
  // At s = 4 nothing is released, a single sample neither.
  const std::vector<std::string> single = {
      "1111",  //
      "2222",  //
      "2221",  //
  };
  Frame four(single, {1});
  four.relabel(4);
  ASSERT_EQ(four.segments.size(), 4u);
  EXPECT_EQ(four.labels[four.grid.index(3, 2)], 3);
  EXPECT_DOUBLE_EQ(four.segments[3].sums.count, 1.0);
}

TEST(Relabelling, DoesNothingWithoutSegments) {
  // An empty frame, and a frame with no segment.
  Frame empty({""}, {});
  EXPECT_EQ(empty.grid.width, 0);
  empty.relabel();
  EXPECT_EQ(empty.segments.size(), 1u);
  EXPECT_TRUE(empty.edges.empty());

  Frame holes({"....", "...."}, {}, [](int, int) { return static_cast<double>(kNaN); });
  holes.relabel();
  EXPECT_EQ(holes.art(), (std::vector<std::string>{"....", "...."}));
  EXPECT_EQ(holes.segments.size(), 1u);
}

TEST(Relabelling, LeavesAOnePixelSegmentAlone) {
  Frame f({"1"}, {1});
  f.relabel(4);
  EXPECT_EQ(f.art(), (std::vector<std::string>{"1"}));
  EXPECT_EQ(f.segments.size(), 2u);
  EXPECT_DOUBLE_EQ(f.segments[1].sums.count, 1.0);
}

TEST(Relabelling, GivesNoEdgesAcrossHoles) {
  // The frame has no returns: pieces still split by the labels, but no hole is a 3-D
  // neighbour of anything.
  Frame f(kCutInTwo, {1}, [](int, int) { return static_cast<double>(kNaN); });
  f.relabel();
  ASSERT_EQ(f.segments.size(), 4u);
  EXPECT_DOUBLE_EQ(f.segments[3].sums.count, 25.0);
  EXPECT_TRUE(f.edges.empty());
}

TEST(Relabelling, CanBeRunAgainOnTheNextFrame) {
  Relabelling relabelling;
  for (int frame = 0; frame < 2; ++frame) {
    Frame f(kCutInTwo, {1});
    relabelling.run(f.grid.grid(), 1, f.labels, f.segments, f.edges);
    EXPECT_EQ(f.segments.size(), 4u) << "frame " << frame;
    EXPECT_EQ(f.labels[f.grid.index(9, 4)], 3) << "frame " << frame;
  }
}

}  // namespace
}  // namespace floodplane
