// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// The rules pcd_segment applies before and after segmenting, without running it.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <iterator>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "ordered_batch.h"
#include "output_paths.h"
#include "planes_json.h"
#include "track_summary.h"

namespace {

TEST(OutputPaths, PutsOutputsOfADirectoryRunUnderTheInputsName) {
  const auto paths = pcd_segment::outputPaths("/data/frame.7.pcd", "out", false);
  EXPECT_EQ(paths.pcd, "out/frame.7.labels.pcd");
  EXPECT_EQ(paths.png, "out/frame.7.labels.png");
  EXPECT_EQ(paths.json, "out/frame.7.planes.json");
  EXPECT_EQ(paths.objects, "out/frame.7.objects.pcd");
}

TEST(OutputPaths, PutsPngAndJsonNextToASingleOutputFileWithItsStem) {
  const auto paths = pcd_segment::outputPaths("in.pcd", "res/scene.pcd", true);
  EXPECT_EQ(paths.pcd, "res/scene.pcd");
  EXPECT_EQ(paths.png, "res/scene.png");
  EXPECT_EQ(paths.json, "res/scene.json");
  EXPECT_EQ(paths.objects, "res/scene.objects.pcd");
}

TEST(OutputPaths, MakesASinglePngOutputTheLabelImageWithNoCloud) {
  const auto paths = pcd_segment::outputPaths("in.pcd", "res/scene.PNG", true);
  EXPECT_EQ(paths.pcd, "");
  EXPECT_EQ(paths.png, "res/scene.PNG");
  EXPECT_EQ(paths.json, "res/scene.json");
  EXPECT_EQ(paths.overlay, "res/scene.overlay.png");
  EXPECT_EQ(paths.snapshot, "res/scene.snapshot.png");
  EXPECT_TRUE(pcd_segment::namesLabelImage("a/b.png"));
  EXPECT_FALSE(pcd_segment::namesLabelImage("a/b.pcd"));
  EXPECT_FALSE(pcd_segment::namesLabelImage("a.png/b"));
}

TEST(PixelBox, SpansTheColumnsAndRowsOfTheIndices) {
  // Width 10: index 23 is column 3 of row 2, index 47 column 7 of row 4, 50 column 0 of row 5.
  const pcd_segment::PixelBox box = pcd_segment::pixelBox({23, 47, 50}, 10);
  EXPECT_EQ(box.min_column, 0);
  EXPECT_EQ(box.max_column, 7);
  EXPECT_EQ(box.min_row, 2);
  EXPECT_EQ(box.max_row, 5);
  const pcd_segment::PixelBox empty = pcd_segment::pixelBox({}, 10);
  EXPECT_LT(empty.max_column, empty.min_column);
}

TEST(ReportJson, HoldsTheParametersAndEveryPlane) {
  pcd_segment::Report report;
  report.input = "a.pcd";
  report.width = 4;
  report.height = 3;
  report.params.seed_size = 0.125;
  report.segmentation_ms = 2.5;
  pcd_segment::PlaneRecord plane;
  plane.id = 1;
  plane.normal[2] = -1.0f;
  plane.d = 2.0f;
  plane.inliers = 7;
  plane.boundary_box = {1, 2, 0, 1};
  report.planes = {plane};
  const auto json = pcd_segment::reportJson(report);
  EXPECT_EQ(json["parameters"]["seed_size"], 0.125);
  EXPECT_EQ(json["segmentation_ms"], 2.5);
  ASSERT_EQ(json["planes"].size(), 1u);
  EXPECT_EQ(json["planes"][0]["inliers"], 7);
  EXPECT_EQ(json["planes"][0]["normal"][2], -1.0);
  EXPECT_EQ(json["planes"][0]["boundary_box"]["max_column"], 2);
  EXPECT_FALSE(json["planes"][0].contains("track")) << "no track key without --track";
  report.planes[0].track = 9;
  const auto tracked = pcd_segment::reportJson(report);
  EXPECT_EQ(tracked["planes"][0]["track"], 9);
  EXPECT_EQ(tracked["planes"][0].begin().key(), "id");
  EXPECT_EQ(std::next(tracked["planes"][0].begin()).key(), "track");
}

TEST(OutputPaths, PutsTheTrackSummaryInTheOutputDirectoryOrNextToTheOutputFile) {
  EXPECT_EQ(pcd_segment::tracksPath("out", false), "out/tracks.json");
  EXPECT_EQ(pcd_segment::tracksPath("res/scene.pcd", true), "res/scene.tracks.json");
}

// A 4 x 4 frame with plane k on row k, its normal along axis axes[k], 1 m from the camera.
floodplane::Segmentation frameOf(const std::vector<int>& axes) {
  floodplane::Segmentation frame;
  frame.width = frame.height = 4;
  frame.labels.assign(16, 0);
  for (std::size_t k = 0; k < axes.size(); ++k) {
    floodplane::SegmentedPlane plane;
    plane.fit.normal = Eigen::Vector3d::Unit(axes[k]);
    plane.fit.offset = 1.0;
    plane.fit.centroid = -plane.fit.offset * plane.fit.normal;  // on the plane, as a fit's
    plane.inlier_count = 4;
    for (std::size_t x = 0; x < 4; ++x) frame.labels[k * 4 + x] = static_cast<std::uint32_t>(k + 1);
    frame.planes.push_back(plane);
  }
  return frame;
}

TEST(TrackSummary, KeepsEveryTrackWithTheFilesItWasFirstAndLastSeenIn) {
  floodplane::PlaneTracker::Options options;
  options.max_lost_frames = 0;  // a track lost once is dropped by the tracker, not by the summary
  floodplane::PlaneTracker tracker(options);
  pcd_segment::TrackSummary summary;
  tracker.update(frameOf({0, 1}));
  summary.addFrame("a.pcd", tracker);
  tracker.update(frameOf({0}));
  summary.addFrame("b.pcd", tracker);
  tracker.update(frameOf({0}));
  summary.addFrame("c.pcd", tracker);
  EXPECT_EQ(tracker.tracks().size(), 1u);

  EXPECT_EQ(summary.frames(), (std::vector<std::string>{"a.pcd", "b.pcd", "c.pcd"}));
  const std::vector<pcd_segment::TrackRecord> tracks = summary.tracks();
  ASSERT_EQ(tracks.size(), 2u);
  EXPECT_EQ(tracks[0].id, 1u);
  EXPECT_EQ(tracks[0].first_frame, "a.pcd");
  EXPECT_EQ(tracks[0].last_frame, "c.pcd");
  EXPECT_EQ(tracks[0].frames_seen, 3u);
  EXPECT_EQ(tracks[1].id, 2u);
  EXPECT_EQ(tracks[1].last_frame, "a.pcd");
  EXPECT_EQ(tracks[1].frames_seen, 1u);
  EXPECT_TRUE(tracks[1].smoothed_normal.isApprox(Eigen::Vector3d::UnitY()));

  const auto json = summary.json();
  EXPECT_EQ(json["frame_count"], 3);
  EXPECT_EQ(json["track_count"], 2);
  EXPECT_EQ(json["tracks"][1]["id"], 2);
  EXPECT_EQ(json["tracks"][1]["first_frame"], "a.pcd");
  EXPECT_EQ(json["tracks"][1]["smoothed_normal"][1], 1.0);
  EXPECT_EQ(json["tracks"][1]["smoothed_offset"], 1.0);
  EXPECT_EQ(json["tracks"][0]["frames_seen"], 3);
}

TEST(TrackSummary, RefusesAFrameTheTrackerDidNotTake) {
  floodplane::PlaneTracker tracker;
  pcd_segment::TrackSummary summary;
  EXPECT_THROW(summary.addFrame("a.pcd", tracker), std::logic_error);
  tracker.update(frameOf({0}));
  tracker.update(frameOf({0}));
  EXPECT_THROW(summary.addFrame("b.pcd", tracker), std::logic_error);
}

// The items finish in reverse order (the first sleeps longest), yet are reported in order,
// each once, with its own result; every thread that works makes its one worker, and no more
// threads work than there are jobs.
TEST(RunInOrder, ReportsItemsInOrderWhateverOrderTheyFinishIn) {
  constexpr std::size_t kItems = 12;
  std::mutex mutex;
  std::vector<std::thread::id> worker_threads;
  std::set<std::thread::id> work_threads;
  std::vector<std::size_t> reported;
  std::vector<std::string> results;
  pcd_segment::runInOrder(
      kItems, 3,
      [&]() {
        std::lock_guard<std::mutex> lock(mutex);
        worker_threads.push_back(std::this_thread::get_id());
        return std::this_thread::get_id();
      },
      [&](std::thread::id& worker, std::size_t i) {
        EXPECT_EQ(worker, std::this_thread::get_id()) << "a worker is its own thread's";
        {
          std::lock_guard<std::mutex> lock(mutex);
          work_threads.insert(std::this_thread::get_id());
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(2 * static_cast<int>(kItems - i)));
        return "item " + std::to_string(i);
      },
      [&](std::size_t i, std::string& result) {
        reported.push_back(i);
        results.push_back(result);
      });
  ASSERT_EQ(reported.size(), kItems);
  for (std::size_t i = 0; i < kItems; ++i) {
    EXPECT_EQ(reported[i], i);
    EXPECT_EQ(results[i], "item " + std::to_string(i));
  }
  EXPECT_EQ(worker_threads.size(), work_threads.size());
  EXPECT_EQ(std::set<std::thread::id>(worker_threads.begin(), worker_threads.end()), work_threads);
  EXPECT_LE(work_threads.size(), 3u);
}

// Items run at once on several threads, and never more than 2 * jobs items ahead of the last
// report: a slow first item holds the rest back.
TEST(RunInOrder, RunsOnThreadsAndKeepsAtMostTwiceTheJobsWaiting) {
  constexpr unsigned kJobs = 2;
  std::mutex mutex;
  std::size_t reported = 0;
  std::size_t furthest_ahead = 0;
  std::set<std::thread::id> work_threads;
  pcd_segment::runInOrder(
      20, kJobs, []() { return 0; },
      [&](int&, std::size_t i) {
        {
          std::lock_guard<std::mutex> lock(mutex);
          furthest_ahead = std::max(furthest_ahead, i + 1 - reported);
          work_threads.insert(std::this_thread::get_id());
        }
        if (i == 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        return i;
      },
      [&](std::size_t, std::size_t&) {
        std::lock_guard<std::mutex> lock(mutex);
        ++reported;
      });
  EXPECT_EQ(reported, 20u);
  EXPECT_LE(furthest_ahead, 2 * kJobs);
  EXPECT_EQ(work_threads.size(), kJobs);
}

// -j N means N items at once, also beyond the machine's cores (a batch waiting on a network
// file system, say): four items that each wait for all four to have started all start.
TEST(RunInOrder, RunsAsManyItemsAtOnceAsJobsBeyondTheCores) {
  constexpr unsigned kJobs = 4;
  std::mutex mutex;
  std::condition_variable started_changed;
  std::size_t started = 0;
  std::size_t all_started = 0;
  pcd_segment::runInOrder(
      kJobs, kJobs, []() { return 0; },
      [&](int&, std::size_t) {
        std::unique_lock<std::mutex> lock(mutex);
        ++started;
        started_changed.notify_all();
        // Bounded: with fewer threads than jobs the others never start and this gives up.
        const bool all = started_changed.wait_for(lock, std::chrono::seconds(5), [&] { return started == kJobs; });
        return all ? 1 : 0;
      },
      [&](std::size_t, int& all) { all_started += static_cast<std::size_t>(all); });
  EXPECT_EQ(all_started, kJobs);
}

// An item's failure is its result: the others are reported after it, in order.
TEST(RunInOrder, GoesOnPastAnItemWhoseResultIsAnError) {
  std::vector<std::string> reports;
  pcd_segment::runInOrder(
      6, 2, []() { return 0; },
      [](int&, std::size_t i) { return i == 2 ? std::string("error") : "item " + std::to_string(i); },
      [&](std::size_t, std::string& result) { reports.push_back(result); });
  EXPECT_EQ(reports, (std::vector<std::string>{"item 0", "item 1", "error", "item 3", "item 4", "item 5"}));
}

// One job: everything on the calling thread, in order, without threads.
TEST(RunInOrder, RunsOnTheCallingThreadWithOneJob) {
  const std::thread::id caller = std::this_thread::get_id();
  std::vector<std::size_t> order;
  bool all_on_caller = true;
  pcd_segment::runInOrder(
      5, 1, []() { return 0; },
      [&](int&, std::size_t i) {
        all_on_caller = all_on_caller && std::this_thread::get_id() == caller;
        order.push_back(i);
        return i;
      },
      [&](std::size_t i, std::size_t& result) { EXPECT_EQ(result, i); });
  EXPECT_TRUE(all_on_caller);
  EXPECT_EQ(order, (std::vector<std::size_t>{0, 1, 2, 3, 4}));
}

}  // namespace
