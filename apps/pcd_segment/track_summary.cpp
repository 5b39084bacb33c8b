// SPDX-FileCopyrightText: 2026 The floodplane authors
// SPDX-License-Identifier: BSD-3-Clause
#include "track_summary.h"

#include <stdexcept>

#include "floodplane/version.h"

namespace pcd_segment {

void TrackSummary::addFrame(const std::string& file, const floodplane::PlaneTracker& tracker) {
  if (tracker.frameCount() != frames_.size() + 1) {
    throw std::logic_error("TrackSummary::addFrame: the tracker has taken " + std::to_string(tracker.frameCount()) +
                           " frames, the summary " + std::to_string(frames_.size() + 1));
  }
  const std::size_t frame = frames_.size();
  frames_.push_back(file);
  for (const floodplane::PlaneTrack& track : tracker.tracks()) {
    if (track.last_frame != frame) continue;  // lost in this frame: its record stands
    TrackRecord& record = tracks_[track.id];
    record.id = track.id;
    record.first_frame = frames_.at(track.first_frame);
    record.last_frame = file;
    record.frames_seen = track.frames_seen;
    record.smoothed_normal = track.smoothed_normal;
    record.smoothed_offset = track.smoothed_offset;
  }
}

std::vector<TrackRecord> TrackSummary::tracks() const {
  std::vector<TrackRecord> records;
  records.reserve(tracks_.size());
  for (const auto& [id, record] : tracks_) records.push_back(record);
  return records;
}

nlohmann::ordered_json TrackSummary::json() const {
  nlohmann::ordered_json tracks = nlohmann::ordered_json::array();
  for (const auto& [id, record] : tracks_) {
    const Eigen::Vector3d& n = record.smoothed_normal;
    tracks.push_back({
        {"id", record.id},
        {"first_frame", record.first_frame},
        {"last_frame", record.last_frame},
        {"frames_seen", record.frames_seen},
        {"smoothed_normal", {n.x(), n.y(), n.z()}},
        {"smoothed_offset", record.smoothed_offset},
    });
  }
  return {
      {"floodplane_version", FLOODPLANE_VERSION_STRING},
      {"frame_count", frames_.size()},
      {"frames", frames_},
      {"track_count", tracks_.size()},
      {"tracks", tracks},
  };
}

}  // namespace pcd_segment
