// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
// A node's report on its stream: the frames of each window between reports, their rate and
// times, totals since the start, and the level: ok while frames come and are read, warn when
// none come or some are skipped, error when every message is skipped. The clock is the test's.

#include "stream_status.h"

#include <gtest/gtest.h>

#include <string>

namespace {

using floodplane::conversion::StatusLevel;
using floodplane::conversion::StreamReport;
using floodplane::conversion::StreamStatus;

TEST(StreamStatus, ReportsTheWindowsFramesWithTheirRateAndTimes) {
  StreamStatus status(10.0);
  status.frameSegmented(20.0, 3);
  status.frameSegmented(40.0, 4);
  status.frameSegmented(30.0, 5);
  const StreamReport report = status.report(12.0);
  EXPECT_EQ(report.level, StatusLevel::ok);
  EXPECT_EQ(report.summary, "segmenting 1.5 frames a second, 30.0 ms each");
  EXPECT_DOUBLE_EQ(report.window_seconds, 2.0);
  EXPECT_EQ(report.frames, 3u);
  EXPECT_EQ(report.skipped, 0u);
  EXPECT_DOUBLE_EQ(report.frequency, 1.5);
  EXPECT_DOUBLE_EQ(report.mean_time_ms, 30.0);
  EXPECT_DOUBLE_EQ(report.max_time_ms, 40.0);
  EXPECT_EQ(report.last_planes, 5u);
  EXPECT_EQ(report.total_frames, 3u);
  EXPECT_TRUE(report.last_problem.empty());
}

TEST(StreamStatus, StartsANewWindowAtEachReportAndKeepsTheTotals) {
  StreamStatus status(0.0);
  status.frameSegmented(50.0, 2);
  status.messageSkipped("the cloud is not organized");
  status.report(1.0);
  status.frameSegmented(10.0, 7);
  const StreamReport report = status.report(3.0);
  EXPECT_EQ(report.level, StatusLevel::ok);
  EXPECT_DOUBLE_EQ(report.window_seconds, 2.0);
  EXPECT_EQ(report.frames, 1u);
  EXPECT_EQ(report.skipped, 0u);
  EXPECT_DOUBLE_EQ(report.frequency, 0.5);
  EXPECT_DOUBLE_EQ(report.max_time_ms, 10.0);
  EXPECT_EQ(report.last_planes, 7u);
  EXPECT_EQ(report.total_frames, 2u);
  EXPECT_EQ(report.total_skipped, 1u);
  EXPECT_TRUE(report.last_problem.empty());
}

TEST(StreamStatus, WarnsWhenNoFrameCame) {
  StreamStatus status(5.0);
  status.frameSegmented(12.0, 4);
  status.report(6.0);
  const StreamReport report = status.report(8.5);
  EXPECT_EQ(report.level, StatusLevel::warn);
  EXPECT_EQ(report.summary, "no frame in the last 2.5 s");
  EXPECT_EQ(report.frames, 0u);
  EXPECT_DOUBLE_EQ(report.frequency, 0.0);
  EXPECT_DOUBLE_EQ(report.mean_time_ms, 0.0);
  EXPECT_DOUBLE_EQ(report.max_time_ms, 0.0);
  EXPECT_EQ(report.last_planes, 4u);  // the last frame's, from the window before
}

TEST(StreamStatus, IsIdleNotWarningWhenNoOneListensAndNoFrameCame) {
  StreamStatus status(5.0);
  const StreamReport idle = status.report(6.0, true);
  EXPECT_EQ(idle.level, StatusLevel::ok);
  EXPECT_EQ(idle.summary, "idle: no subscriber to its outputs");
  EXPECT_EQ(idle.frames, 0u);
  // Frames that came before the last subscriber left are reported as frames.
  status.frameSegmented(12.0, 4);
  const StreamReport busy = status.report(7.0, true);
  EXPECT_EQ(busy.level, StatusLevel::ok);
  EXPECT_EQ(busy.frames, 1u);
  EXPECT_EQ(busy.summary.rfind("segmenting ", 0), 0u) << busy.summary;
  // Skipped messages are reported whatever the subscribers.
  status.messageSkipped("points: the cloud is not organized");
  EXPECT_EQ(status.report(8.0, true).level, StatusLevel::error);
}

TEST(StreamStatus, WarnsWhenSomeMessagesWereSkipped) {
  StreamStatus status(0.0);
  status.frameSegmented(12.0, 4);
  status.messageSkipped("points: the cloud has no z field");
  status.messageSkipped("image_rect: depth image encoding 'mono8': floodplane reads 16UC1");
  status.frameSegmented(14.0, 4);
  const StreamReport report = status.report(1.0);
  EXPECT_EQ(report.level, StatusLevel::warn);
  EXPECT_EQ(report.summary,
            "2 of 4 messages of the last 1.0 s skipped: image_rect: depth image encoding 'mono8': floodplane reads "
            "16UC1");
  EXPECT_EQ(report.skipped, 2u);
  EXPECT_EQ(report.last_problem, "image_rect: depth image encoding 'mono8': floodplane reads 16UC1");
}

TEST(StreamStatus, IsAnErrorWhenEveryMessageWasSkipped) {
  StreamStatus status(0.0);
  status.messageSkipped("points: the cloud is not organized");
  const StreamReport report = status.report(2.0);
  EXPECT_EQ(report.level, StatusLevel::error);
  EXPECT_EQ(report.summary, "every message of the last 2.0 s skipped (1): points: the cloud is not organized");
  EXPECT_EQ(report.frames, 0u);
  EXPECT_EQ(report.total_skipped, 1u);
}

TEST(StreamStatus, ReportsAWindowOfNoLengthWithoutDividingByIt) {
  StreamStatus status(4.0);
  status.frameSegmented(12.0, 1);
  const StreamReport report = status.report(4.0);
  EXPECT_DOUBLE_EQ(report.window_seconds, 0.0);
  EXPECT_DOUBLE_EQ(report.frequency, 0.0);
  EXPECT_DOUBLE_EQ(report.mean_time_ms, 12.0);
}

}  // namespace
