// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Plane tracking quality against ground truth: whether a ground-truth plane keeps
// one track id over a sequence of frames. Fed frame by frame, in order, with the ground-truth
// label image, the valid mask and the predicted label image holding track ids (0: no plane).
// Plain arrays, no PCL, no I/O. bench/track_sequences.py counts the same in Python from label
// PCDs; this file is the reference for the definitions.
//
// Definitions (all sizes count valid pixels only):
// - Present: a ground-truth plane g (label != 0) is present in a frame when it has at least
//   ceil(min_fraction * N) valid pixels there, N the frame's pixel count (valid or not). Each
//   present plane in a frame is one plane-frame. Absent: not present (out of view, hidden, or
//   too small).
// - Match: in a frame where g is present, its candidate is the predicted id p != 0 with the
//   largest |g n p| (the smaller id on a tie). g is matched to p when
//   IoU = |g n p| / |g u p| >= min_iou, else unmatched. (With min_iou > 0.5 no predicted id can
//   match two planes.)
// - Remembered id: the id g was matched to the last time it was matched. It is forgotten when
//   g is absent for more than max_gap frames in a row (a tracker may forget a surface that long
//   out of view), so the next match after that is a fresh start, never a switch. Frames in which
//   g is present but unmatched do not make it forget.
// - Id switch: a plane-frame in which g is matched to an id other than its remembered id.
// - Lost: a plane-frame in which g is unmatched.
// - Re-entry: g present again after 1..max_gap absent frames in a row, having a remembered id.
//   It is decided at g's first matched frame from its return on (before it is absent again):
//   kept when that match has the remembered id, switched otherwise (that frame is also an id
//   switch). A re-entry that is not matched before g is absent again, or before the sequence
//   ends, is neither (re_entries - kept - switched of them).
// The first appearance of a plane is not a re-entry; nor is a return after a longer absence.

#include <cstddef>
#include <cstdint>
#include <map>
#include <vector>

namespace floodplane::eval {

struct TrackingOptions {
  /// A ground-truth plane is present in a frame with at least this share of its pixels, in
  /// (0, 1]: 0.01 is 3072 pixels at 640x480.
  double min_fraction = 0.01;
  /// The IoU from which a plane is matched to its candidate track id, in (0, 1].
  double min_iou = 0.5;
  /// The longest absence, in frames, after which a plane's remembered id still counts (a
  /// re-entry): the tracker's memory, 29 for "leaves the view for under 30 frames".
  int max_gap = 29;
};

struct TrackingScores {
  std::size_t frames = 0;
  std::size_t plane_frames = 0;  ///< present ground-truth planes summed over frames
  std::size_t matched = 0;       ///< plane-frames matched to a track id
  std::size_t id_switches = 0;
  std::size_t lost = 0;  ///< plane-frames unmatched; matched + lost == plane_frames
  std::size_t re_entries = 0;
  std::size_t re_entries_kept = 0;
  std::size_t re_entries_switched = 0;

  /// id_switches per 100 plane-frames; NaN without plane-frames.
  double switchesPer100PlaneFrames() const;
  /// lost per 100 plane-frames; NaN without plane-frames.
  double lostPer100PlaneFrames() const;
  /// re_entries_kept / re_entries; NaN without re-entries.
  double keptShare() const;
};

/// Counts the figures above over a sequence given one frame at a time.
class TrackingEvaluator {
 public:
  /// Throws std::invalid_argument for options outside their ranges.
  explicit TrackingEvaluator(const TrackingOptions& options = TrackingOptions());

  /// The next frame: row-major label images of one size (frames may differ in size), `valid[i]
  /// != 0` for the pixels that count (pass a pixel as invalid when its ground-truth point is
  /// NaN). Throws std::invalid_argument if the three vectors differ in size.
  void addFrame(const std::vector<std::uint32_t>& ground_truth, const std::vector<std::uint32_t>& predicted,
                const std::vector<std::uint8_t>& valid);

  const TrackingScores& scores() const { return scores_; }

 private:
  // What is known of one ground-truth plane between frames.
  struct PlaneHistory {
    bool remembered = false;  // remembered_id is set
    std::uint32_t remembered_id = 0;
    int absent_frames = 0;          // absent frames in a row up to the last frame
    bool re_entry_pending = false;  // returned after a short absence, not matched since
  };

  // Counts one plane-frame of a present plane and updates its history.
  void presentPlane(PlaneHistory& history, bool matched, std::uint32_t track_id);

  TrackingOptions options_;
  TrackingScores scores_;
  std::map<std::uint32_t, PlaneHistory> planes_;
};

}  // namespace floodplane::eval
