// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "stream_status.h"

#include <algorithm>
#include <cstdio>

namespace floodplane::conversion {
namespace {

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

void StreamStatus::frameSegmented(double time_ms, std::size_t planes) {
  ++frames_;
  ++total_frames_;
  time_sum_ms_ += time_ms;
  time_max_ms_ = std::max(time_max_ms_, time_ms);
  last_planes_ = planes;
}

void StreamStatus::messageSkipped(const std::string& problem) {
  ++skipped_;
  ++total_skipped_;
  last_problem_ = problem;
}

StreamReport StreamStatus::report(double now_seconds, bool idle) {
  StreamReport report;
  report.window_seconds = std::max(0.0, now_seconds - window_start_);
  report.frames = frames_;
  report.skipped = skipped_;
  report.frequency = report.window_seconds > 0.0 ? static_cast<double>(frames_) / report.window_seconds : 0.0;
  report.mean_time_ms = frames_ > 0 ? time_sum_ms_ / static_cast<double>(frames_) : 0.0;
  report.max_time_ms = time_max_ms_;
  report.last_planes = last_planes_;
  report.total_frames = total_frames_;
  report.total_skipped = total_skipped_;
  report.last_problem = last_problem_;

  const std::string window = fixed(report.window_seconds, 1) + " s";
  if (skipped_ > 0 && frames_ == 0) {
    report.level = StatusLevel::error;
    report.summary =
        "every message of the last " + window + " skipped (" + std::to_string(skipped_) + "): " + last_problem_;
  } else if (skipped_ > 0) {
    report.level = StatusLevel::warn;
    report.summary = std::to_string(skipped_) + " of " + std::to_string(skipped_ + frames_) + " messages of the last " +
                     window + " skipped: " + last_problem_;
  } else if (frames_ == 0 && idle) {
    report.level = StatusLevel::ok;
    report.summary = "idle: no subscriber to its outputs";
  } else if (frames_ == 0) {
    report.level = StatusLevel::warn;
    report.summary = "no frame in the last " + window;
  } else {
    report.level = StatusLevel::ok;
    report.summary =
        "segmenting " + fixed(report.frequency, 1) + " frames a second, " + fixed(report.mean_time_ms, 1) + " ms each";
  }

  window_start_ = now_seconds;
  frames_ = 0;
  skipped_ = 0;
  time_sum_ms_ = 0.0;
  time_max_ms_ = 0.0;
  last_problem_.clear();
  return report;
}

}  // namespace floodplane::conversion
