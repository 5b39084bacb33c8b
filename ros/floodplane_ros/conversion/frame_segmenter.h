// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a node does with a frame, without ROS: one Segmenter for the stream (head starts) and,
// when tracking is on, a PlaneTracker over its segmentations. A ROS 1 nodelet and a later
// ROS 2 node hold one each and only convert messages around it.

#include <cstdint>
#include <optional>
#include <vector>

#include "floodplane/params.h"
#include "floodplane/plane_tracker.h"
#include "floodplane/point_grid.h"
#include "floodplane/segmenter.h"

namespace floodplane::conversion {

/// What a node's parameters set.
struct SegmentationSettings {
  Params params;
  /// Each frame continues the one before (Segmenter::Options::head_start): a node gets a
  /// stream from one sensor.
  bool head_start = true;
  /// Planes get track ids that persist over frames (PlaneTracker), published as their labels.
  bool tracking = false;
};

/// A length parameter where 0 (or less) means "derived from the frame's noise", as Params'
/// unset lengths are: dynamic_reconfigure has no unset value.
std::optional<double> lengthOrDerived(double metres);

class FrameSegmenter {
 public:
  explicit FrameSegmenter(const SegmentationSettings& settings = SegmentationSettings());

  /// Takes new settings from the next frame on. Throws std::invalid_argument naming the
  /// parameter (Params::problem) and keeps the old settings when one is unusable. Turning
  /// tracking on starts with no tracks.
  void setSettings(const SegmentationSettings& settings);
  const SegmentationSettings& settings() const { return settings_; }

  /// Segments the next frame of the stream. The result is valid until the next call.
  ///
  /// A frame without a finite point (all NaN: a covered lens, a depth image of zeros; or no
  /// pixel at all) is a frame with no planes, not an error, as everywhere in floodplane: its
  /// result has the grid's size, every label 0 and no plane. The library does not see it, so
  /// the stream's noise model stays the last real frame's (such a frame says nothing about the
  /// noise); with tracking, the tracker sees a frame without planes.
  const Segmentation& segment(const PointGrid& grid);

  /// The track id of each plane of the last frame; empty when tracking is off.
  const std::vector<std::uint32_t>& trackIds() const { return track_ids_; }

 private:
  SegmentationSettings settings_;
  Segmenter segmenter_;
  PlaneTracker tracker_;
  std::vector<std::uint32_t> track_ids_;
  Segmentation empty_;  // the result of a frame without a finite point
};

}  // namespace floodplane::conversion
