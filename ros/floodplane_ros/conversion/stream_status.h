// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a node says about its stream of frames, without ROS: how many it segmented and how
// many messages it skipped since its last report, how often frames came and how long each
// took, with a level and a one-line summary, as a camera driver reports its stream on
// /diagnostics (diagnostic_msgs/DiagnosticStatus).

#include <cstddef>
#include <cstdint>
#include <string>

namespace floodplane::conversion {

/// A report's level, with diagnostic_msgs/DiagnosticStatus's values.
enum class StatusLevel : std::uint8_t { ok = 0, warn = 1, error = 2 };

/// The stream over one window: from the last report (or the start) to this one.
struct StreamReport {
  StatusLevel level = StatusLevel::ok;
  std::string summary;            ///< one line: what the node is doing, or what is wrong
  double window_seconds = 0.0;    ///< the window's length [s]
  std::size_t frames = 0;         ///< frames segmented in the window (frames without planes too)
  std::size_t skipped = 0;        ///< messages skipped in the window (unreadable: an error was logged)
  double frequency = 0.0;         ///< frames segmented a second in the window [Hz]
  double mean_time_ms = 0.0;      ///< mean time per frame in the window [ms]; 0 without frames
  double max_time_ms = 0.0;       ///< longest time per frame in the window [ms]; 0 without frames
  std::size_t last_planes = 0;    ///< planes in the last frame segmented (in this window or before)
  std::size_t total_frames = 0;   ///< frames segmented since the start
  std::size_t total_skipped = 0;  ///< messages skipped since the start
  std::string last_problem;       ///< why the window's last skipped message was; empty when none was
};

/// Counts a node's frames between reports. Times are seconds on any monotonic clock.
///
/// The level of a window: error when every message in it was skipped (the node segments
/// nothing: a wrong topic type or encoding), warn when some were, or when no frame came at all
/// (no camera publishing, a wrong topic name) while the node listened, ok otherwise. A node
/// that no one listens to listens to no input (it is lazy): a window without frames is then ok
/// (idle), not a warning.
class StreamStatus {
 public:
  explicit StreamStatus(double start_seconds) : window_start_(start_seconds) {}

  /// A frame segmented in `time_ms`, with `planes` planes.
  void frameSegmented(double time_ms, std::size_t planes);
  /// A message skipped because of `problem` (the reason logged for it).
  void messageSkipped(const std::string& problem);

  /// The report of the window that ends at `now`; the next window starts there. `idle`: no
  /// output has a subscriber now (so a lazy node subscribes no input).
  StreamReport report(double now_seconds, bool idle = false);

 private:
  double window_start_;
  std::size_t frames_ = 0;
  std::size_t skipped_ = 0;
  double time_sum_ms_ = 0.0;
  double time_max_ms_ = 0.0;
  std::size_t last_planes_ = 0;
  std::size_t total_frames_ = 0;
  std::size_t total_skipped_ = 0;
  std::string last_problem_;
};

}  // namespace floodplane::conversion
