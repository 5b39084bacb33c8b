// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "eval/tracking_metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace floodplane::eval {

namespace {

double per100(std::size_t count, std::size_t total) {
  return total == 0 ? std::numeric_limits<double>::quiet_NaN()
                    : 100.0 * static_cast<double>(count) / static_cast<double>(total);
}

// The best predicted id of one present ground-truth plane.
struct Candidate {
  std::uint32_t id = 0;
  std::size_t overlap = 0;
};

}  // namespace

double TrackingScores::switchesPer100PlaneFrames() const { return per100(id_switches, plane_frames); }

double TrackingScores::lostPer100PlaneFrames() const { return per100(lost, plane_frames); }

double TrackingScores::keptShare() const {
  return re_entries == 0 ? std::numeric_limits<double>::quiet_NaN()
                         : static_cast<double>(re_entries_kept) / static_cast<double>(re_entries);
}

TrackingEvaluator::TrackingEvaluator(const TrackingOptions& options) : options_(options) {
  if (!(options.min_fraction > 0.0 && options.min_fraction <= 1.0)) {
    throw std::invalid_argument("TrackingEvaluator: min_fraction must be in (0, 1], got " +
                                std::to_string(options.min_fraction));
  }
  if (!(options.min_iou > 0.0 && options.min_iou <= 1.0)) {
    throw std::invalid_argument("TrackingEvaluator: min_iou must be in (0, 1], got " + std::to_string(options.min_iou));
  }
  if (options.max_gap < 0) {
    throw std::invalid_argument("TrackingEvaluator: max_gap must not be negative, got " +
                                std::to_string(options.max_gap));
  }
}

void TrackingEvaluator::addFrame(const std::vector<std::uint32_t>& ground_truth,
                                 const std::vector<std::uint32_t>& predicted, const std::vector<std::uint8_t>& valid) {
  if (predicted.size() != ground_truth.size() || valid.size() != ground_truth.size()) {
    throw std::invalid_argument(
        "TrackingEvaluator::addFrame: ground_truth, predicted and valid must have one size (got " +
        std::to_string(ground_truth.size()) + ", " + std::to_string(predicted.size()) + ", " +
        std::to_string(valid.size()) + ")");
  }
  std::map<std::uint32_t, std::size_t> plane_pixels;
  std::unordered_map<std::uint32_t, std::size_t> id_pixels;
  std::unordered_map<std::uint64_t, std::size_t> overlaps;  // (plane << 32 | id) -> |g n p|
  for (std::size_t i = 0; i < ground_truth.size(); ++i) {
    if (valid[i] == 0) continue;
    if (ground_truth[i] != 0) ++plane_pixels[ground_truth[i]];
    if (predicted[i] != 0) ++id_pixels[predicted[i]];
    if (ground_truth[i] != 0 && predicted[i] != 0) {
      ++overlaps[static_cast<std::uint64_t>(ground_truth[i]) << 32 | predicted[i]];
    }
  }
  std::map<std::uint32_t, Candidate> candidates;
  for (const auto& [key, overlap] : overlaps) {
    const auto plane = static_cast<std::uint32_t>(key >> 32);
    const auto id = static_cast<std::uint32_t>(key & 0xffffffffU);
    Candidate& best = candidates[plane];
    if (overlap > best.overlap || (overlap == best.overlap && id < best.id)) best = {id, overlap};
  }

  const auto min_pixels =
      static_cast<std::size_t>(std::ceil(options_.min_fraction * static_cast<double>(ground_truth.size())));
  const auto present = [&](std::uint32_t plane) {
    const auto found = plane_pixels.find(plane);
    return found != plane_pixels.end() && found->second >= min_pixels;
  };
  for (auto& [plane, history] : planes_) {
    if (present(plane)) continue;
    ++history.absent_frames;
    history.re_entry_pending = false;
    if (history.absent_frames > options_.max_gap) history.remembered = false;
  }
  for (const auto& [plane, pixels] : plane_pixels) {
    if (pixels < min_pixels) continue;
    const Candidate candidate = candidates[plane];
    const std::size_t union_pixels = pixels + (candidate.id == 0 ? 0 : id_pixels[candidate.id]) - candidate.overlap;
    const bool matched = candidate.id != 0 &&
                         static_cast<double>(candidate.overlap) >= options_.min_iou * static_cast<double>(union_pixels);
    presentPlane(planes_[plane], matched, candidate.id);
  }
  ++scores_.frames;
}

void TrackingEvaluator::presentPlane(PlaneHistory& history, bool matched, std::uint32_t track_id) {
  if (history.absent_frames > 0 && history.remembered) {
    ++scores_.re_entries;
    history.re_entry_pending = true;
  }
  history.absent_frames = 0;
  ++scores_.plane_frames;
  if (!matched) {
    ++scores_.lost;
    return;
  }
  ++scores_.matched;
  const bool switched = history.remembered && history.remembered_id != track_id;
  scores_.id_switches += switched ? 1 : 0;
  if (history.re_entry_pending) {
    ++(switched ? scores_.re_entries_switched : scores_.re_entries_kept);
    history.re_entry_pending = false;
  }
  history.remembered = true;
  history.remembered_id = track_id;
}

}  // namespace floodplane::eval
