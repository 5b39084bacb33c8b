// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// A node's stream of frames: the library's own results frame by frame (with head starts),
// track ids from the library's tracker, frames without a finite point answered with no planes
// (not an error) without touching the stream's noise model, tiny frames segmented as the
// library segments them, and unusable settings refused.

#include "frame_segmenter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/test_scenes.h"
#include "floodplane/plane_tracker.h"
#include "floodplane/segmenter.h"

namespace {

using floodplane::PlaneTracker;
using floodplane::Segmentation;
using floodplane::Segmenter;
using floodplane::conversion::FrameSegmenter;
using floodplane::conversion::lengthOrDerived;
using floodplane::conversion::SegmentationSettings;

// Frames of the room corner with Kinect-like noise, each with its own noise pattern.
std::vector<floodplane::test::RenderedGrid> noisyFrames(int count) {
  std::vector<floodplane::test::RenderedGrid> frames;
  for (int i = 0; i < count; ++i) {
    frames.push_back(floodplane::test::render(
        floodplane::test::kinectView(160, 120), floodplane::test::roomCorner(),
        [](double range) { return 0.0015 * range * range; }, static_cast<unsigned>(7 + i)));
  }
  return frames;
}

void expectSame(const Segmentation& actual, const Segmentation& expected) {
  EXPECT_EQ(actual.labels, expected.labels);
  ASSERT_EQ(actual.planes.size(), expected.planes.size());
  for (std::size_t k = 0; k < actual.planes.size(); ++k) {
    EXPECT_EQ(actual.planes[k].inlier_count, expected.planes[k].inlier_count);
    EXPECT_EQ(actual.planes[k].fit.normal, expected.planes[k].fit.normal);
    EXPECT_EQ(actual.planes[k].fit.offset, expected.planes[k].fit.offset);
  }
  EXPECT_EQ(actual.stats.head_start, expected.stats.head_start);
}

TEST(FrameSegmenter, GivesTheLibrarysResultsFrameByFrameWithHeadStarts) {
  const auto frames = noisyFrames(3);
  FrameSegmenter node;
  Segmenter library;
  Segmenter::Options options;
  options.head_start = true;
  for (const auto& frame : frames) {
    const Segmentation& expected = library.segment(frame.grid(), options);
    expectSame(node.segment(frame.grid()), expected);
    EXPECT_GE(expected.planes.size(), 3u);
    EXPECT_TRUE(node.trackIds().empty());
  }
  // The frames after the first continued from the one before.
  EXPECT_TRUE(node.segment(frames[0].grid()).stats.head_start);
}

// A frame without a finite point: every label 0, no plane, the grid's size.
void expectNoPlanes(const Segmentation& result, int width, int height) {
  EXPECT_EQ(result.width, width);
  EXPECT_EQ(result.height, height);
  EXPECT_EQ(result.labels, std::vector<std::uint32_t>(static_cast<std::size_t>(width * height), 0u));
  EXPECT_TRUE(result.planes.empty());
}

struct NaNFrame {
  std::vector<float> xyz;
  floodplane::PointGrid grid;
  NaNFrame(int width, int height)
      : xyz(3 * static_cast<std::size_t>(width * height), std::numeric_limits<float>::quiet_NaN()) {
    grid.data = xyz.empty() ? nullptr : xyz.data();
    grid.width = width;
    grid.height = height;
  }
};

TEST(FrameSegmenter, GivesAFrameWithoutFinitePointsNoPlanesAndLeavesTheNoiseModelAsItWas) {
  const auto frames = noisyFrames(2);
  FrameSegmenter node;
  Segmenter library;
  Segmenter::Options options;
  options.head_start = true;
  library.segment(frames[0].grid(), options);
  node.segment(frames[0].grid());

  expectNoPlanes(node.segment(NaNFrame(160, 120).grid), 160, 120);
  // The next frame continues from frame 0 (the library never saw the empty one): the same
  // planes as the library's, with frame 0's noise model.
  const Segmentation& next = node.segment(frames[1].grid());
  expectSame(next, library.segment(frames[1].grid(), options));
  EXPECT_TRUE(next.stats.head_start);
}

TEST(FrameSegmenter, GivesFramesWithoutPixelsNoPlanes) {
  FrameSegmenter node;
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{0, 0}, {0, 1}, {5, 0}}) {
    expectNoPlanes(node.segment(NaNFrame(width, height).grid), width, height);
  }
}

TEST(FrameSegmenter, SegmentsTinyFramesAsTheLibraryDoes) {
  FrameSegmenter node;
  Segmenter library;
  Segmenter::Options options;
  options.head_start = true;
  // Fewer than three points hold no plane; four already may.
  for (const auto& [width, height] : std::vector<std::pair<int, int>>{{1, 1}, {1, 2}, {2, 1}, {2, 2}, {3, 2}}) {
    floodplane::test::Pinhole tiny;
    tiny.width = width;
    tiny.height = height;
    const auto frame = floodplane::test::render(tiny, {floodplane::test::frontalPlane(1.0)});
    const Segmentation& result = node.segment(frame.grid());
    expectSame(result, library.segment(frame.grid(), options));
    if (width * height < 3) expectNoPlanes(result, width, height);
  }
}

TEST(FrameSegmenter, ShowsTheTrackerAFrameWithoutFinitePointsAsOneWithoutPlanes) {
  const auto frames = noisyFrames(2);
  SegmentationSettings settings;
  settings.tracking = true;
  FrameSegmenter node(settings);
  Segmenter library;
  PlaneTracker tracker;
  Segmenter::Options options;
  options.head_start = true;
  Segmentation nothing;
  nothing.width = 160;
  nothing.height = 120;
  nothing.labels.assign(160 * 120, 0);

  node.segment(frames[0].grid());
  EXPECT_EQ(node.trackIds(), tracker.update(library.segment(frames[0].grid(), options)));
  node.segment(NaNFrame(160, 120).grid);
  EXPECT_EQ(node.trackIds(), tracker.update(nothing));
  EXPECT_TRUE(node.trackIds().empty());
  node.segment(frames[1].grid());
  EXPECT_EQ(node.trackIds(), tracker.update(library.segment(frames[1].grid(), options)));
  ASSERT_FALSE(node.trackIds().empty());
}

TEST(FrameSegmenter, GivesTheLibrarysTrackIdsWhenTracking) {
  const auto frames = noisyFrames(3);
  SegmentationSettings settings;
  settings.tracking = true;
  FrameSegmenter node(settings);
  Segmenter library;
  PlaneTracker tracker;
  Segmenter::Options options;
  options.head_start = true;
  for (const auto& frame : frames) {
    const std::vector<std::uint32_t> expected = tracker.update(library.segment(frame.grid(), options));
    node.segment(frame.grid());
    EXPECT_EQ(node.trackIds(), expected);
  }
  ASSERT_FALSE(node.trackIds().empty());
  // Three frames of the same corner: the same three tracks throughout.
  EXPECT_EQ(*std::max_element(node.trackIds().begin(), node.trackIds().end()), node.trackIds().size());
}

TEST(FrameSegmenter, StartsWithNoTracksWhenTrackingIsTurnedOnAgain) {
  const auto frames = noisyFrames(2);
  SegmentationSettings settings;
  settings.tracking = true;
  FrameSegmenter node(settings);
  node.segment(frames[0].grid());
  settings.tracking = false;
  node.setSettings(settings);
  node.segment(frames[1].grid());
  EXPECT_TRUE(node.trackIds().empty());
  // A corner seen by a much moved camera would keep no id; after the reset ids start at 1.
  settings.tracking = true;
  node.setSettings(settings);
  node.segment(frames[1].grid());
  ASSERT_FALSE(node.trackIds().empty());
  EXPECT_EQ(*std::min_element(node.trackIds().begin(), node.trackIds().end()), 1u);
}

TEST(FrameSegmenter, TakesNewParametersFromTheNextFrame) {
  const auto frames = noisyFrames(1);
  FrameSegmenter node;
  SegmentationSettings settings;
  settings.params.subsampling = 2;
  settings.head_start = false;
  node.setSettings(settings);
  Segmenter library(settings.params);
  expectSame(node.segment(frames[0].grid()), library.segment(frames[0].grid()));
}

TEST(FrameSegmenter, RefusesUnusableParametersAndKeepsItsOwn) {
  FrameSegmenter node;
  SegmentationSettings settings;
  settings.params.subsampling = 3;
  settings.tracking = true;
  EXPECT_THROW(node.setSettings(settings), std::invalid_argument);
  EXPECT_EQ(node.settings().params.subsampling, floodplane::Params().subsampling);
  EXPECT_FALSE(node.settings().tracking);
}

TEST(FrameSegmenter, TakesZeroAndLessAsADerivedLength) {
  EXPECT_FALSE(lengthOrDerived(0.0).has_value());
  EXPECT_FALSE(lengthOrDerived(-0.5).has_value());
  EXPECT_EQ(lengthOrDerived(0.02), 0.02);
}

}  // namespace
