// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// tracks.json of pcd_segment --track: every track of the sequence, with the files it was first
// and last seen in. No PCL here: the tracker's records in, JSON out.

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "floodplane/plane_tracker.h"

namespace pcd_segment {

/// What tracks.json says about one track.
struct TrackRecord {
  std::uint32_t id = 0;
  std::string first_frame;  ///< the input it was first seen in, as given on the command line
  std::string last_frame;   ///< the input it was last seen in
  std::size_t frames_seen = 0;
  Eigen::Vector3d smoothed_normal = Eigen::Vector3d::UnitZ();  ///< unit, in the camera frame when last seen
  double smoothed_offset = 0.0;                                ///< d [m] of n . p + d = 0
};

/// The tracks of a sequence, kept as its frames go by: also those the tracker has since
/// dropped (lost for longer than it keeps them), so the summary covers the whole sequence.
class TrackSummary {
 public:
  /// Takes the tracker's tracks after it took the frame read from `file`. Throws
  /// std::logic_error when the tracker took another number of frames than this was given.
  void addFrame(const std::string& file, const floodplane::PlaneTracker& tracker);
  /// The inputs that were segmented, in sequence order (the tracker's frame indices).
  const std::vector<std::string>& frames() const { return frames_; }
  /// Every track, by increasing id.
  std::vector<TrackRecord> tracks() const;
  /// The summary: version, frames, and per track id, first and last frame (file), frames
  /// seen, smoothed normal and offset.
  nlohmann::ordered_json json() const;

 private:
  std::vector<std::string> frames_;
  std::map<std::uint32_t, TrackRecord> tracks_;
};

}  // namespace pcd_segment
